"""Earthquake records in the block model, and Newmark's rigid sliding block for comparison.

A record is the horizontal acceleration of the ground (the fixed base) along +x over time. With the rigid base
(the default) the model is run in the frame of its base: every block feels gravity plus the inertial acceleration
−a_g(t) (d'Alembert), so displacements are relative to the base, as a slope engineer reads them, and the base
stays where it was drawn: the same motion as prescribing the base's acceleration. The load is NewtonIntegrator's
gravity, set before every step by the engine :func:`apply` installs (a PyRunner labelled ``earthquake``), so
O.energy's gravWork counts the inertial force's work and the balance of an undamped run still closes. A rigid base
reflects every wave that comes down to it. With ``base="compliant"`` (:mod:`quiet_base`) the model is in the
ground's frame, its base blocks are let go on Lysmer's dashpots with the record as a stress input, and waves
leave through the base (the base's work is O.energy's baseWork).

Newmark (1965): a rigid block on a plane of dip ψ with friction φ, under a horizontal inertial acceleration a(t)
out of the face, slides down the plane while a > a_y = g tan(φ − ψ) (the yield acceleration, kh at FS = 1), with
s̈ = (a − a_y) cos(φ − ψ)/cos φ, until its sliding velocity is zero again (:func:`newmark`).
"""
import bisect
import csv
import json
import math

from .checks import number

G = 9.81
TAG = "yade_rbsm.earthquake"
LABEL = "earthquake"


class Record:
    """A ground-acceleration history: times *t* [s] (increasing) and accelerations *a* [m/s²] along +x
    (``units="g"``: in g). Zero before its first and after its last time."""

    def __init__(self, t, a, units="m/s2", name="record"):
        if units not in ("m/s2", "g"):
            raise ValueError("Record %r: units must be 'm/s2' or 'g' (got %r)" % (name, units))
        t, a = [float(x) for x in t], [float(x) for x in a]
        if len(t) < 2 or len(t) != len(a):
            raise ValueError("Record %r: needs at least two (time, acceleration) pairs of equal count (got %d times, "
                             "%d accelerations)" % (name, len(t), len(a)))
        for i, (ti, ai) in enumerate(zip(t, a)):
            if not (math.isfinite(ti) and math.isfinite(ai)):
                raise ValueError("Record %r: row %d is not a finite number (t %r, a %r)" % (name, i, ti, ai))
            if i and ti <= t[i - 1]:
                raise ValueError("Record %r: times must increase (row %d: %g after %g)" % (name, i, ti, t[i - 1]))
        scale = G if units == "g" else 1.0
        self.t, self.a, self.name = t, [x * scale for x in a], name

    @classmethod
    def sine(cls, amplitude, frequency, duration, start=0.0, dt=None, units="g", name=None):
        """A sine of *amplitude* (in *units*) and *frequency* [Hz] lasting *duration* [s] from *start*."""
        amplitude = number("Record.sine", "amplitude", amplitude, 0, None)
        frequency = number("Record.sine", "frequency", frequency, 0, None, low_open=True)
        duration = number("Record.sine", "duration", duration, 0, None, low_open=True)
        dt = dt or 1.0 / (frequency * 200)
        n = int(math.ceil(duration / dt))
        t = [start + i * duration / n for i in range(n + 1)]
        a = [amplitude * math.sin(2 * math.pi * frequency * (ti - start)) for ti in t]
        return cls(t, a, units, name or "sine %g %s, %g Hz, %g s" % (amplitude, units, frequency, duration))

    @classmethod
    def from_csv(cls, path, time="t", acceleration="a", units="g"):
        """A record from a CSV file with a header row naming the *time* and *acceleration* columns (lines starting
        with # before it are comments)."""
        with open(path, newline="") as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        if not rows or time not in rows[0] or acceleration not in rows[0]:
            raise ValueError("Record %s: needs columns %r and %r in its header (found %s)"
                             % (path, time, acceleration, ", ".join(rows[0]) if rows else "no rows"))
        try:
            return cls([r[time] for r in rows], [r[acceleration] for r in rows], units, name=path)
        except ValueError as e:
            raise ValueError(str(e).replace("Record %r" % path, "Record %s" % path)) from None

    @classmethod
    def synthetic(cls):
        """A 6 s synthetic record shipped with the plugin (PGA 0.3 g; data/synthetic_record.csv says how it was made):
        for trying a model, not for design."""
        import os
        return cls.from_csv(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "synthetic_record.csv"))

    def _sample_before(self, time):
        """The index lo of the samples t[lo] <= time < t[lo + 1] (t[0] < time < t[-1])."""
        return bisect.bisect_right(self.t, time) - 1

    def at(self, time):
        """The ground acceleration at *time* [m/s²] (linear between samples, 0 outside the record)."""
        t = self.t
        if time <= t[0] or time >= t[-1]:
            return 0.0
        lo = self._sample_before(time)
        w = (time - t[lo]) / (t[lo + 1] - t[lo])
        return self.a[lo] + w * (self.a[lo + 1] - self.a[lo])

    def velocity(self, time):
        """The ground velocity at *time* [m/s]: the acceleration of :meth:`at` integrated exactly from the record's
        start (a nonzero first sample is a step there); constant after its end (a record not corrected for its
        baseline leaves the ground moving)."""
        t, a = self.t, self.a
        if not hasattr(self, "_v"):  # the velocity at each sample, by the trapezoid rule (exact: a is linear)
            self._v = [0.0]
            for i in range(1, len(t)):
                self._v.append(self._v[-1] + 0.5 * (a[i - 1] + a[i]) * (t[i] - t[i - 1]))
        if time <= t[0]:
            return 0.0
        if time >= t[-1]:
            return self._v[-1]
        lo = self._sample_before(time)
        h = time - t[lo]
        return self._v[lo] + a[lo] * h + 0.5 * (a[lo + 1] - a[lo]) / (t[lo + 1] - t[lo]) * h * h

    @property
    def duration(self):
        return self.t[-1]

    @property
    def pga(self):
        """Peak ground acceleration [m/s²]."""
        return max(abs(x) for x in self.a)

    def to_json(self):
        return json.dumps(dict(t=self.t, a=self.a, name=self.name))

    @classmethod
    def from_json(cls, text):
        d = json.loads(text)
        return cls(d["t"], d["a"], name=d["name"])

    def __repr__(self):
        return "Record(%r: %d samples, %g s, PGA %.3g g)" % (self.name, len(self.t), self.duration, self.pga / G)


_active = {}  # the record of the scene's engine, parsed once (key: the tag's text)


def apply(record, direction=1, start=None, base="rigid", impedance=None, base_ids=None):
    """Shakes the scene's base with *record* (a :class:`Record` of ground acceleration) along the model's +x
    (*direction* +1) or −x (−1), from O.time (or *start*, the scene time of the record's zero): installs the
    engine, keeps the record in O.tags (a saved scene goes on shaking after O.load). ``apply(None)`` stops it and
    gives the static gravity back (a compliant base is fixed again where it stands). Returns the engine.

    *base*: ``"rigid"`` (the model in its base's frame) or ``"compliant"`` (:mod:`quiet_base`: the fixed blocks at
    the model's bottom, or *base_ids*, let go on dashpots of *impedance* = (ρ c_p, ρ c_s) [Pa·s/m], by default the
    base material's; the record is then an outcrop motion)."""
    from yade import O, wrapper
    from . import mpi, omega, quiet_base, slope_scene
    if record is not None and not isinstance(record, Record):
        raise ValueError("earthquake: give a yade_rbsm.earthquake.Record (Record.sine, Record.from_csv, Record(t, a)); "
                         "got %r" % (record,))
    if direction not in (1, -1):
        raise ValueError("earthquake: direction must be +1 or -1 (the record's positive acceleration along the model's "
                         "+x or -x), got %r" % (direction,))
    if base not in ("rigid", "compliant"):
        raise ValueError("earthquake: base must be 'rigid' (the model in its base's frame) or 'compliant' (Lysmer's "
                         "absorbing base), got %r" % (base,))
    if base == "rigid" and (impedance is not None or base_ids is not None):
        raise ValueError("earthquake: impedance and base_ids are for base='compliant'")
    start = O.time if start is None else number("earthquake", "start", start)
    if record is not None and base == "compliant" and mpi.distributed():
        raise ValueError("earthquake: a compliant base is not available under yade.mpy yet (its base blocks' forces are "
                         "set from Python on one rank): use base='rigid' or run serially")
    # (checked first: a refused record leaves the one shaking the scene in place)
    previous = json.loads(O.tags[TAG]).get("base") if shaking(O) else None
    if previous:  # a compliant base fixed again where it stands, as before it was let go (also to be let go again)
        quiet_base.hold(O, previous)
    try:
        quiet = quiet_base.describe(O, quiet_base.base_blocks(O, base_ids), impedance) \
            if record is not None and base == "compliant" else None
    except ValueError:
        if previous:  # refused: the compliant base shaking the scene goes on
            quiet_base.let_go(O, previous)
        raise
    O.engines = [e for e in O.engines if getattr(e, "label", "") != LABEL]
    g0 = slope_scene.static_gravity()
    omega.newton(O).gravity = tuple(g0)
    if record is None:
        if TAG in O.tags.keys():
            O.tags[TAG] = ""  # (YADE's tags cannot be deleted: empty is none)
        return None
    if quiet is not None:
        quiet_base.let_go(O, quiet)
    O.tags[TAG] = json.dumps(dict(record=json.loads(record.to_json()), direction=direction, start=start, g0=list(g0),
                                  base=quiet))
    engine = wrapper.PyRunner(command="import yade_rbsm.earthquake as _eq; _eq.step()", iterPeriod=1, label=LABEL)
    O.engines = omega.before_newton(list(O.engines), engine)
    if quiet is None:
        step()  # the gravity of the coming step (the compliant base measures its reactions in the step)
    return engine


def step():
    """The engine's command. Rigid base: gravity = static gravity − direction · a_g(t) x̂ at the middle of the
    coming step. Compliant base: the base blocks' reactions and dashpots (:func:`quiet_base.apply_tractions`)."""
    from yade import O
    from . import omega, quiet_base
    text = shaking(O)
    if not text:
        return
    if text not in _active:
        _active.clear()
        d = json.loads(text)
        _active[text] = (Record(d["record"]["t"], d["record"]["a"], name=d["record"]["name"]), d["direction"], d["start"],
                         d["g0"], d.get("base"))
    record, direction, start, g0, base = _active[text]
    if base is None:
        a = record.at(O.time + 0.5 * O.dt - start)
        omega.newton(O).gravity = (g0[0] - direction * a, g0[1], g0[2])
        return
    if base["reaction"] is None:  # the first step: the forces that held the base as it stood
        base["reaction"] = quiet_base.static_reaction(O, base, g0)
        d = json.loads(text)
        d["base"] = base
        O.tags[TAG] = json.dumps(d)
        _active[O.tags[TAG]] = _active.pop(text)
    power = quiet_base.apply_tractions(O, base, (direction * record.velocity(O.time - start), 0.0))
    if O.trackEnergy:
        O.energy[quiet_base.ENERGY] = (O.energy[quiet_base.ENERGY] if quiet_base.ENERGY in O.energy.keys() else 0.0) \
            - power * O.dt


def shaking(O):
    """The scene's record as kept in O.tags (JSON), or "" when no earthquake shakes it."""
    return O.tags[TAG] if TAG in O.tags.keys() else ""


def active_record():
    """(Record, direction, start) of the scene's earthquake, or None."""
    from yade import O
    if not shaking(O):
        return None
    d = json.loads(O.tags[TAG])
    return Record(d["record"]["t"], d["record"]["a"], name=d["record"]["name"]), d["direction"], d["start"]


def yield_coefficient(fs_of, kh_start=0.1, kh_max=1.0, rtol=0.01, trials=None):
    """k_y, the kh at which fs_of(kh) = 1, by regula falsi kept off the ends (bisection past a trial that slid:
    fs_of returns 0 there, no FS to interpolate), refined by extending the two measured trials nearest it
    (FS(kh) is smooth below k_y). 0 if fs_of(0) <= 1; ValueError if FS > 1 at kh_max. *trials* (a list) gets
    each [kh, FS]."""
    trials = [] if trials is None else trials

    def excess(k):
        fs = fs_of(k)
        trials.append([k, fs])
        return fs - 1.0

    lo, f_lo = 0.0, excess(0.0)
    if f_lo <= 0:
        return 0.0
    kh = kh_start
    f_hi = excess(kh)
    while f_hi > 0 and kh < kh_max:
        lo, f_lo, kh = kh, f_hi, min(2 * kh, kh_max)
        f_hi = excess(kh)
    if f_hi > 0:
        raise ValueError("yield acceleration: FS is %.3f at kh_max = %g: no yield below it" % (f_hi + 1, kh_max))
    hi = kh
    while hi - lo > rtol * hi:
        if f_hi == -1.0:  # hi slid away: halve
            k = 0.5 * (lo + hi)
        else:
            k = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
            k = min(max(k, lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo))
        f = excess(k)
        if f > 0:
            lo, f_lo = k, f
        else:
            hi, f_hi = k, f
    measured = sorted(t for t in trials if t[1] > 1.0)
    if len(measured) >= 2:
        (k1, fs1), (k2, fs2) = measured[-2:]
        if fs2 < fs1:
            return min(max(k2 + (1.0 - fs2) * (k2 - k1) / (fs2 - fs1), lo), hi)
    return 0.5 * (lo + hi)


class NewmarkResult:
    """Newmark's sliding block: *displacement* [m] at the end, *time*, *velocity*, *sliding* histories."""

    def __init__(self, time, displacement, velocity, ay):
        self.time, self.history, self.velocity, self.ay = time, displacement, velocity, ay
        self.displacement = displacement[-1]

    def __repr__(self):
        return "NewmarkResult(displacement %.4g m, yield acceleration %.4g g)" % (self.displacement, self.ay / G)


def newmark(record, ky=None, psi=None, phi=None, direction=1, face=1, dt=None, g=G, extra=1.0):
    """Newmark's rigid sliding block under *record*, applied along the model's x as :func:`apply` does (*direction*)
    to a slope whose face looks to +x (*face* +1) or −x (−1): the inertial acceleration out of the face is
    a(t) = −direction · face · a_g(t). Give the
    block's plane, *psi* and *phi* in degrees (a_y = g tan(φ − ψ), sliding acceleration (a − a_y) cos(φ − ψ)/cos φ
    along the plane), or *ky* alone (Newmark's original: a − a_y, displacement along the ground). Downslope
    sliding only. Integrates at *dt* (default: a tenth of the record's smallest sample step, at most 10⁶ steps) up
    to the record's end plus *extra* s. Returns a :class:`NewmarkResult` (displacement along the plane [m])."""
    if psi is not None and phi is not None:
        ay = g * math.tan(math.radians(phi - psi))
        factor = math.cos(math.radians(phi - psi)) / math.cos(math.radians(phi))
        if ky is not None and abs(ky - ay / g) > 1e-9:
            raise ValueError("newmark: give ky or (psi, phi), not both (they disagree: %g against %g)" % (ky, ay / g))
    elif ky is not None and psi is None and phi is None:
        ay, factor = number("newmark", "ky", ky, 0, None) * g, 1.0
    else:
        raise ValueError("newmark: give ky, or psi and phi (degrees)")
    span = record.duration + number("newmark", "extra", extra, 0)
    # a tenth of the record's sampling, but at most a million steps (a jump written as two samples 1e-9 s apart)
    dt = number("newmark", "dt", dt, 0, low_open=True) if dt is not None else max(
        min(b - a for a, b in zip(record.t, record.t[1:])) / 10, span * 1e-6)
    n = int(math.ceil(span / dt))
    s = v = 0.0
    times, disp, vel = [0.0], [0.0], [0.0]
    for i in range(n):
        t = i * dt
        # mid-point rule: the acceleration over the step at its middle
        a = -direction * face * record.at(t + 0.5 * dt)
        acc = (a - ay) * factor
        if v > 0 or acc > 0:
            v_new = v + acc * dt
            if v_new < 0:  # stops within the step: the part it moved until then
                s += 0.5 * v * v / -acc if acc < 0 else 0.0
                v = 0.0
            else:
                s += 0.5 * (v + v_new) * dt
                v = v_new
        times.append(t + dt)
        disp.append(s)
        vel.append(v)
    return NewmarkResult(times, disp, vel, ay)
