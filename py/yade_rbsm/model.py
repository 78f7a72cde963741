"""A block slope analysed in stages, as UDEC's model and SOLVE are, in YADE's own ``O``
(``slope.SlopeModel``)::

    m = slope.SlopeModel(slope.jointset_blocks(surface, base, sets=[A, B]), rock)
    m.build()             # blocks into O.bodies, engines(), every joint bonded at the rock's strength
    m.settle()            # in-situ stress: gravity to an unbalanced-force ratio of 1e-4
    m.give_joint_sets()   # the joints' own strength, and equilibrium again
    r = m.fos()           # slope.fos(): strength reduction and the estimates beside it
    m.set_water(line)     # water in the joints (then equilibrium again); m.set_seismic(kh) a pseudo-static load
    m.run(2.0)            # dynamic stage: no damping, the run-out (optionally at strengths / F)
    print(m)              # the stages, what each ran and found
    m.report("out/report.md")

The estimates (``contact_fs(polyline)``, ``limit_equilibrium(...)``, ``probe()``, ``fos()``) record their
factors of safety, gathered by ``fs_table()``; ``watch(ids)`` records yade.plot series through the stages
(``save_plot``); ``run(..., chunks=, snapshots=, vtk=)`` writes as it goes (dynamic_stage.py); under
yade.mpy ``build(distribute=True)`` splits the slope before bonding (scripts/landslide_slope.py uses all).
Each stage is recorded (:class:`Stage`: its name, settings, figures, wall time) in ``O.tags``, so a
scene saved with ``O.save`` keeps its history: ``SlopeModel.resume()`` after ``O.load`` continues it.
The steps scripts wrote by hand (the bonding step, the friction held while settling, the damping
switched off for the dynamic stage, the progress line by simulated time) are inside the stages.
"""
import json
import math
import time
from dataclasses import asdict, dataclass, field
from typing import Dict, List

from .checks import count, number

__all__ = ["Stage", "SlopeModel"]

_TAG = "yade_rbsm.stages"
_BLOCKS_TAG = "yade_rbsm.slope_blocks"
_PROGRESS = "rbsmStageProgress"  # the label of a stage's own progress line (PyRunner)


@dataclass
class Stage:
    name: str
    settings: Dict[str, object] = field(default_factory=dict)
    figures: Dict[str, object] = field(default_factory=dict)
    time: float = 0.0  # O.time at its end [s]
    wall: float = 0.0  # [s]
    estimates: List[list] = field(default_factory=list)  # [method, FS or None, note]: rows of fs_table()

    def __str__(self):
        def fmt(v):
            return ("%.4g" % v) if isinstance(v, float) else str(v)
        return "%-16s %s  (t = %.4g s, %.1f s wall)" % (
            self.name, ", ".join("%s %s" % (k, fmt(v)) for k, v in self.figures.items()), self.time, self.wall)


class _Blocks:
    """What fos() reads of the builder's SlopeBlocks, kept with the scene: pattern, ground, base."""

    def __init__(self, d):
        self.pattern, self.surface, self.base = d["pattern"], [tuple(p) for p in d["surface"]], d["base"]


class SlopeModel:
    """A slope in stages (module docstring). *blocks*: a SlopeBlocks from a builder (None with
    :meth:`resume`); *material*: the RbsmMat of the blocks (of the fixed ones too, with layers)."""

    def __init__(self, blocks=None, material=None, thickness=1.0):
        self.sb, self.material, self.thickness = blocks, material, thickness
        self.stages: List[Stage] = []

    # --- the record -----------------------------------------------------------------------------
    def _record(self, name, settings, figures, w0, estimates=()):
        from yade import O
        st = Stage(name, settings, figures, O.time, time.time() - w0, [list(r) for r in estimates])
        self.stages.append(st)
        O.tags[_TAG] = json.dumps([asdict(s) for s in self.stages], default=str)
        return st

    @classmethod
    def resume(cls):
        """The model of the scene in O (after O.load): its stages and what fos() needs of its blocks."""
        from yade import O
        from .monitor import saved_monitor
        m = cls()
        if _TAG in O.tags.keys():
            m.stages = [Stage(**d) for d in json.loads(O.tags[_TAG])]
        if _BLOCKS_TAG in O.tags.keys():
            m.sb = _Blocks(json.loads(O.tags[_BLOCKS_TAG]))
        free = _blocks(O)
        m.material = free[0].material if free else None  # (limit equilibrium reads the blocks' material)
        m.monitor = saved_monitor(O)  # watch()'s recorder, saved in O.engines: save_plot() goes on with it
        return m

    def __repr__(self):
        if not self.stages:
            return "SlopeModel(no stage run yet)"
        return "SlopeModel, %d stage(s):\n  " % len(self.stages) + "\n  ".join(str(s) for s in self.stages)

    def report(self, path=None):
        """The stages as Markdown (written to *path* if given); returns the text."""
        out = ["# Slope analysis", "", "| stage | settings | figures | t [s] | wall [s] |", "|---|---|---|---|---|"]
        for s in self.stages:
            out.append("| %s | %s | %s | %.4g | %.1f |" % (
                s.name, ", ".join("%s = %s" % kv for kv in s.settings.items()),
                ", ".join("%s = %s" % (k, ("%.4g" % v) if isinstance(v, float) else v) for k, v in s.figures.items()),
                s.time, s.wall))
        rows = [r for s in self.stages for r in s.estimates]
        if rows:
            out += ["", "## Factors of safety", "", "| method | FS | note |", "|---|---|---|"]
            out += ["| %s | %s | %s |" % (m, "-" if f is None else "%.3f" % f, note) for m, f, note in rows]
        text = "\n".join(out) + "\n"
        if path:
            with open(path, "w") as f:
                f.write(text)
        return text

    # --- the stages -----------------------------------------------------------------------------
    def build(self, distribute=False, dt=None, bond_dt=None, **engines_kw):
        """The blocks into O.bodies, ``O.engines = engines(**engines_kw)``, every joint bonded (the joint
        sets keep the rock's strength until :meth:`give_joint_sets`), the crack joints broken.
        *distribute*: under yade.mpy (:func:`yade_rbsm.mpi.start`), the free blocks cut into vertical
        slices, one per worker, before the joints are made (yade.mpy would make joints across its borders
        anew, unbonded). *dt*: a fixed O.dt [s], refused above the stable step; by default the time stepper
        keeps O.dt at its safety x the critical step as the joints change. *bond_dt*: the step [s] of the
        bonding step (default the stepper's): a tiny one (1e-6) makes the joints before gravity has moved
        the blocks by g dt^2. (It changes the path, and with it a jointed slope's strength-reduction FS by a
        few per cent: 1.09 to 1.17 on the tutorial's slope for bonding steps of 0.001 to 0.8 x critical.)"""
        from yade import O
        from . import mpi, slope
        from .scene import critical_time_step, engines, time_stepper
        if self.sb is None or self.material is None:
            raise ValueError("SlopeModel.build: give the blocks and the material (SlopeModel(blocks, material))")
        w0 = time.time()
        slope.build_scene(self.sb, self.material, thickness=self.thickness)
        O.engines = engines(**engines_kw)
        figures = dict(blocks=len(self.sb.free), fixed=len(self.sb.blocks) - len(self.sb.free))
        if distribute:
            if mpi.distributed() is None:
                raise ValueError("SlopeModel.build: distribute=True needs yade.mpy's ranks (yade_rbsm.mpi.start(n) first)")
            slices = mpi.decompose_by_x()
            mpi.distribute()
            figures.update(ranks=mpi.distributed().numThreads, slices=[[round(a, 3), round(b, 3)] for a, b in slices])
            if mpi.rank() == 0:
                print("yade.mpy: %d ranks; free blocks cut into %d vertical slices (centroids x in %s), fixed blocks on "
                      "rank 0" % (figures["ranks"], len(slices), ", ".join("[%.2f, %.2f]" % r for r in slices)), flush=True)
        stepper = time_stepper()
        set_dt = stepper.setDt
        if bond_dt is not None:  # the bonding step at a step of its own, then the stepper's
            stepper.setDt, O.dt = False, number("SlopeModel.build", "bond_dt", bond_dt, 0, low_open=True)
        figures["joints"], figures["broken"] = slope.bond_and_break(self.sb, give_sets=False)
        figures["critical_dt"] = critical_time_step()
        if dt is not None:
            stepper.setDt = False
            O.dt = number("SlopeModel.build", "dt", dt, 0, low_open=True)  # (the stepper refuses it above the limit)
        elif bond_dt is not None:
            O.dt, stepper.setDt = stepper.safetyFactor * figures["critical_dt"] * (1 - 1e-9), set_dt
        figures["dt"] = O.dt
        O.tags[_BLOCKS_TAG] = json.dumps(dict(pattern=self.sb.pattern, surface=[list(p) for p in self.sb.surface],
                                              base=self.sb.base))
        return self._record("build", dict(engines_kw, distribute=distribute, dt=dt, bond_dt=bond_dt), figures, w0)

    def settle(self, tol=1e-4, max_steps=100000, density_scaling=True, hold_friction=None, damping=0.7, check=200,
               reset_displacements=True, progress=10.0, name="in-situ"):
        """Gravity to an unbalanced-force ratio below *tol* (:func:`slope.settle`, NewtonIntegrator *damping*,
        density scaling by default: the same equilibrium in fewer steps). *hold_friction*: tan(phi) of every
        joint held at this value during the stage, then given back (a slope that fails at its own friction
        reaches its initial stress state). *reset_displacements*: displacements count from the settled state
        (State.refPos, UDEC's RESET disp). A line every *progress* s of wall time (None: none)."""
        from yade import O, Vector3
        from . import mpi, omega, slope
        w0 = time.time()
        free = _blocks(O)
        before = {b.id: Vector3(b.state.pos) for b in free}  # (a copy: state.pos is the body's own)
        held = []
        if hold_friction is not None:
            hold_friction = number("SlopeModel.settle", "hold_friction", hold_friction, 0, low_open=True)
            held = [(I, I.phys.tanPhi) for I in omega.joints(O)]
            for I, _ in held:
                I.phys.tanPhi = hold_friction
        last = [time.time()]

        def line(steps, ratio):
            if progress is not None and time.time() - last[0] >= progress and mpi.rank() == 0:
                last[0] = time.time()
                print("  %s: step %d, unbalanced-force ratio %.2e (to %g), %.0f s wall" % (name, steps, ratio, tol,
                                                                                          last[0] - w0), flush=True)
        try:
            ok, steps, ratio = slope.settle(tol=tol, max_steps=max_steps, check=check, damping=damping, progress=line,
                                            density_scaling=density_scaling)
        finally:
            for I, tan_phi in held:
                if I.isReal:
                    I.phys.tanPhi = tan_phi
        moved = max(((O.bodies[i].state.pos - p).norm() for i, p in before.items()
                     if O.bodies[i] is not None and mpi.owned(O.bodies[i])), default=0.0)
        moved = -mpi.allreduce_min([-moved])[0]  # (yade.mpy: the largest over the ranks, each its own blocks)
        size = sorted(2 * b.shape.circumradius for b in free)[len(free) // 2] if free else 0.0
        if reset_displacements:
            for b in O.bodies:
                b.state.refPos = b.state.pos
        figures = dict(converged=bool(ok), steps=steps, unbalanced=ratio, max_displacement=moved)
        if ok and moved > 0.1 * size and hold_friction is None:  # (kept: fos() says it of the FS it finds after)
            figures["failed"] = ("settled, but a block moved %.3g m on the way (%.0f %% of the median block size): the "
                                 "slope failed at these strengths and came to rest elsewhere" % (moved, 100 * moved / size))
        st = self._record(name, dict(tol=tol, density_scaling=density_scaling, hold_friction=hold_friction, damping=damping),
                          figures, w0)
        if not ok:
            print("SlopeModel.%s: not settled in %d steps (unbalanced-force ratio %.2e > %g): the slope may be failing "
                  "at these strengths" % (name, steps, ratio, tol), flush=True)
        elif "failed" in figures:
            print("SlopeModel.%s: WARNING: %s" % (name, figures["failed"]), flush=True)
        return st

    def give_joint_sets(self, **settle):
        """The joint sets' own strength (:func:`slope.give_joint_sets`), then equilibrium again (:meth:`settle`
        with the arguments *settle*, e.g. tol, max_steps)."""
        from . import slope
        w0 = time.time()
        n = slope.give_joint_sets(self.sb) if getattr(self.sb, "joint_sets", None) else 0
        self._record("joint strengths", {}, dict(joints_given=n), w0)
        return self.settle(**dict(dict(name="equilibrium"), **settle))

    def set_water(self, phreatic, joints="sets", unit_weight=9810.0, settle=True, open_water=False):
        """Water in the joints (:func:`slope.set_water`; *open_water*: on the blocks' free faces too), then
        equilibrium again (*settle*: True, or a dict of :meth:`settle`'s arguments); recorded."""
        from . import slope
        w0 = time.time()
        wet = slope.set_water(phreatic, joints=joints, unit_weight=unit_weight, open_water=open_water)
        self._record("water", dict(phreatic=[list(p) for p in phreatic] if phreatic is not None else None, joints=joints,
                                   open_water=open_water), dict(joints_wet=wet), w0)
        return self._settle_again(settle) if settle and phreatic is not None else self.stages[-1]

    def set_seismic(self, kh, kv=0.0, towards=1, settle=True):
        """The pseudo-static load (:func:`slope.set_seismic`), then equilibrium under it (*settle*: a load
        applied at once would also shake the slope, twice the static effect on an elastic spring; True, or a dict
        of :meth:`settle`'s arguments); recorded."""
        from . import slope
        w0 = time.time()
        g = slope.set_seismic(kh, kv=kv, towards=towards)
        st = self._record("pseudo-static", dict(kh=kh, kv=kv, towards=towards), dict(gravity=list(g)), w0)
        return self._settle_again(settle) if settle else st

    def set_earthquake(self, record, direction=1, base="rigid", impedance=None, base_ids=None):
        """A ground-acceleration history (:class:`earthquake.Record`) along the model's +x (*direction* +1) or −x
        for the dynamic stages that follow (:func:`earthquake.apply`); None stops it. *base* ``"rigid"``: the model
        runs in its base's frame, displacements relative to the base; ``"compliant"``: the base blocks are let go on
        Lysmer's absorbing dashpots (*impedance*, *base_ids*: :mod:`quiet_base`), displacements are absolute.
        Recorded."""
        from . import earthquake
        w0 = time.time()
        earthquake.apply(record, direction=direction, base=base, impedance=impedance, base_ids=base_ids)
        figures = dict(pga_g=record.pga / earthquake.G, record_duration=record.duration) if record is not None else {}
        return self._record("earthquake", dict(record=getattr(record, "name", None), direction=direction, base=base),
                            figures, w0)

    def yield_acceleration(self, towards=1, rtol=0.01, kh_start=0.1, kh_max=1.0, settle=None, **fos_kw):
        """The yield acceleration k_y: the horizontal pseudo-static coefficient (towards the face, *towards*) at
        which the factor of safety is 1, by regula falsi on FS(kh) − 1 to *rtol* of k_y. Each FS is
        :func:`slope.fos` (*fos_kw*; default rtol 0.002) after settling under kh (*settle*: settle's arguments) from
        the state it was called in, which it leaves as it was. A slope that cannot settle under kh counts as
        failing. Returns k_y (0 if the slope fails statically); recorded with the trials."""
        from yade import O
        from . import slope as sl
        from .earthquake import yield_coefficient
        from .fos import _scale, fos
        rtol = number("SlopeModel.yield_acceleration", "rtol", rtol, 0, 0.5, low_open=True)
        kh_max = number("SlopeModel.yield_acceleration", "kh_max", kh_max, 0, 1, low_open=True)
        kh = number("SlopeModel.yield_acceleration", "kh_start", kh_start, 0, kh_max, low_open=True)
        fos_kw = dict(dict(rtol=0.002, probe=False), **fos_kw)
        settle_kw = dict(dict(tol=1e-4, max_steps=60000, check=200), **(settle or {}))
        w0, mark, trials = time.time(), "rbsm_yield_acceleration", []
        O.saveTmp(mark)
        ids = [b.id for b in _blocks(O)]
        d_fail = fos_kw.get("d_fail") or 0.05 * _scale(ids)[0]  # fos()'s runaway displacement

        def fs_under(k):  # FS under kh = k, from the state the method was called in (0: it slid)
            O.loadTmp(mark)
            before = {i: O.bodies[i].state.pos for i in ids}
            sl.set_seismic(k, towards=towards)
            sl.settle(**settle_kw)
            moved = max((O.bodies[i].state.pos - before[i]).norm() for i in ids)
            fs = 0.0  # a slope that slid while kh came on fails there (settled elsewhere, jammed: not this slope)
            if moved < d_fail:
                try:
                    fs = fos(self.sb, **fos_kw).fs
                except ValueError:  # out of equilibrium under kh: it fails there
                    pass
            return fs

        try:
            k_y = yield_coefficient(fs_under, kh_start=kh, kh_max=kh_max, rtol=rtol, trials=trials)
        finally:
            O.loadTmp(mark)
        self._record("yield acceleration", dict(towards=towards, rtol=rtol), dict(ky=k_y, trials=len(trials)), w0,
                     [["yield acceleration k_y = %.4g (kh at FS = 1)" % k_y, None, "%d trials: %s" % (
                         len(trials), ", ".join("kh %.4g FS %.3f" % (k, f) for k, f in trials))]])
        return k_y

    def _settle_again(self, settle):
        return self.settle(**dict(dict(name="equilibrium"), **(settle if isinstance(settle, dict) else {})))

    # --- factors of safety (rank 0 of a merged scene under yade.mpy) ------------------------------
    def fos(self, **kw):
        """:func:`slope.fos` on the current state (the scene is left as it was); recorded, its estimates
        among :meth:`fs_table`'s rows."""
        from .fos import fos
        w0 = time.time()
        r = fos(self.sb, **kw)
        since = self.stages[max([i for i, s in enumerate(self.stages) if s.name == "build"] or [0]):]
        failed = [s for s in since if "failed" in s.figures]
        if failed:  # the mass that came to rest has an FS of its own; the slope as built had one below 1
            r.warnings.append("the slope failed in the stage %r (%s): this FS is that of the mass where it came to rest, "
                              "not of the slope as built, whose FS at these strengths is below 1"
                              % (failed[0].name, failed[0].figures["failed"]))
        rows = [["RBSM " + k if k.startswith(("strength reduction", "contact forces")) else k, e["fs"], e["note"]]
                for k, e in r.estimates.items()]
        self._record("factor of safety", dict(kw), dict(fs=r.fs, method=r.method, conclusive=r.conclusive,
                                                        warnings=len(r.warnings)), w0, rows)
        return r

    def contact_fs(self, polyline, name="slip polyline"):
        """FS from the joint forces along *polyline* (:func:`safety.contact_fs`: the joints on it, shear
        strength over shear force); recorded as "RBSM contact forces, *name*". Returns the ContactFS. The
        row says how much of the polyline's length inside the slope the joints cover: a polyline that
        crosses blocks is read only where it runs along joints (:meth:`stress_fs` reads it everywhere)."""
        from .safety import contact_fs
        w0 = time.time()
        r = contact_fs(polyline)
        inside = length_inside(polyline, self.sb) if self.sb is not None else 0.0
        cover = r.length / inside if inside > 0 else float("nan")
        note = "T = %.1f kN/m, N = %.1f kN/m, %d joints" % (r.shear, r.normal, r.n_joints)
        if cover < 0.8:  # (the rest crosses blocks, whose strength is not in this FS; a plane of bricks: 89 %)
            note += "; they cover %.0f %% of its %.3g m in the slope (the rest crosses blocks: see stress_fs)" % (
                100 * cover, inside)
        self._record("contact forces", dict(name=name), dict(fs=r.fs, shear=r.shear, normal=r.normal, joints=r.n_joints,
                                                              length=r.length, cover=cover), w0,
                     [["RBSM contact forces, " + name, r.fs, note]])
        return r

    def stress_fs(self, polyline=None, circle=None, name=None, n=50):
        """FS along any *polyline* ``[(x, y), ...]`` or *circle* (xc, yc, R), through blocks or along joints:
        Kulhawy's stress-based factor of safety from the blocks' own stresses (:func:`safety.stress_field`,
        Love-Weber from their joint forces, linear between the blocks' centroids), the strength along the
        surface the blocks' material's (c + sigma_n tan phi, limit equilibrium's slices of the same ground).
        For a continuum cut into blocks this reads the state the joints carry where a slip surface crosses
        the blocks; the surface's ends may lie on or above the ground. Recorded as "RBSM block stresses, *name*";
        returns the limit_equilibrium.Result (``fs``, ``normal``, ``shear`` in kN/m)."""
        from . import limit_equilibrium as le
        from .safety import le_slope, stress_field
        if (polyline is None) == (circle is None):
            raise ValueError("SlopeModel.stress_fs: give one of polyline= or circle= (got %s)"
                             % ("both" if polyline is not None else "neither"))
        if self.sb is None or self.material is None:
            raise ValueError("SlopeModel.stress_fs: the model has no blocks yet (build() first)")
        if name is not None and not isinstance(name, str):
            raise ValueError("SlopeModel.stress_fs: name must be a string (the table's row), got %r" % (name,))
        if circle is not None:
            from .contact_safety import _check_circle
            circle = _check_circle(circle)  # (xc, yc, R): numbers, R > 0, named if not
        w0 = time.time()
        kh, kv = _pseudo_static()
        soil = le_slope(self.sb.surface, self.material, kh=kh, kv=kv)
        field = stress_field()
        if circle is not None:
            r = le.stress_circle(soil, circle, field, n)
            name = name or "circle"
        else:
            r = le.stress_polyline(soil, polyline, field, n)
            name = name or "polyline"
        note = "T = %.1f kN/m, N = %.1f kN/m, c %.3g kPa, phi %.1f deg of the blocks' material" % (
            r.shear, r.normal, soil.layers[0].c, soil.layers[0].phi)
        self._record("block stresses", dict(name=name, circle=list(circle) if circle is not None else None,
                                            polyline=[list(p) for p in polyline] if polyline is not None else None),
                     dict(fs=r.fs, shear=r.shear, normal=r.normal), w0, [["RBSM block stresses, " + name, r.fs, note]])
        return r

    def limit_equilibrium(self, polyline=None, circle=None, toe=None, search=None, n=50, g=9.81, c=None, phi=None):
        """Limit equilibrium on the blocks' ground (gamma = rho g of their material; :func:`safety.le_slope`):
        Fellenius on *polyline*, Fellenius and Bishop on *circle* (xc, yc, R) and their critical circles
        through *toe* over the centre grid *search* (dict of x_range, y_range, nx, ny, refine). The strength
        along the surfaces: *c* [Pa] and *phi* [rad], by default the blocks' material's (for a slope cut by
        joint sets the intact rock's, which the rows then say). Under a pseudo-static load (:meth:`set_seismic`)
        the slices carry its kh, kv (towards the sliding side). Recorded; returns {method: Result, SearchResult
        or the message of its failure}."""
        from . import slope
        from .safety import le_slope, limit_equilibrium_summary
        w0 = time.time()
        kh, kv = _pseudo_static()
        soil = le_slope(self.sb.surface, self.material, g=g, c=c, phi=phi, kh=kh, kv=kv)
        lem = limit_equilibrium_summary(soil, circle=circle, polyline=polyline, toe=toe, search=search, n=n)
        rock = c is None and phi is None and bool(getattr(self.sb, "joint_sets", None) or slope.joint_sets())
        rows = [[k, None if isinstance(v, str) else v.fs, _le_note(v) + ("; the intact rock's c, phi" if rock else "")]
                for k, v in lem.items()]
        layer = soil.layers[0]
        settings = dict(circle=[round(v, 6) for v in circle] if circle else None, search=search,
                        c_kPa=layer.c, phi_deg=round(layer.phi, 4), kh=kh, kv=kv, strength="given" if not (c is None and phi is None)
                        else ("the intact rock's" if rock else "the blocks' material's"))
        self._record("limit equilibrium", settings, {k: r[1] for k, r in zip(lem, rows)}, w0, rows)
        return lem

    def probe(self, steps=300):
        """The surface of slipping joints: an undamped *steps*-step probe from the current state (then
        restored) collects the joints that slip (:func:`safety.probe_slipping_surface`); its FS from the
        contact forces of the current state and by Fellenius along it continued to the ground
        (:func:`safety.slip_surface_fs`). Recorded; returns the SlipSurfaceFS, or None if nothing slipped."""
        from .safety import le_slope, probe_slipping_surface, slip_surface_fs
        w0 = time.time()
        ss, found, rows = probe_slipping_surface(steps=steps, damping=0.0), None, []
        if ss is not None:
            found = slip_surface_fs(ss, slope=le_slope(self.sb.surface, self.material))
            fel = found.fellenius
            rows = [["RBSM contact forces, found surface", found.contact.fs, "T = %.1f kN/m, N = %.1f kN/m, %s" % (
                found.contact.shear, found.contact.normal, found.note())],
                    ["Fellenius, found surface", None if isinstance(fel, str) else fel.fs, _le_note(fel)]]
        self._record("slipping surface", dict(steps=steps), dict(joints=len(ss.joints) if ss else 0,
                                                                  length=ss.length if ss else 0.0), w0, rows)
        return found

    def fs_table(self, extra=()):
        """Every factor of safety the stages found, then the rows *extra* (method, FS, note), as a table."""
        from .safety import fs_table
        return fs_table([tuple(r) for s in self.stages for r in s.estimates] + list(extra))

    # --- the dynamic stage ------------------------------------------------------------------------
    def watch(self, ids, period=200, progress=10.0):
        """Record the displacement of blocks *ids*, the kinetic energy, the unbalanced-force ratio and the
        numbers of slipping and open joints every *period* steps through the stages that follow (yade.plot,
        :class:`Monitor`, saved with :meth:`save_plot`), with a progress line every *progress* s of wall time."""
        from .monitor import Monitor
        self.monitor = Monitor(ids=ids, period=period, progress=progress)
        return self.monitor

    def save_plot(self, base, title="RBSM slope"):
        """The watched series as *base*.png and *base*.txt (:meth:`watch`); returns the paths."""
        if getattr(self, "monitor", None) is None:
            raise ValueError("SlopeModel.save_plot: nothing was recorded; call watch(ids) before the stages to plot")
        return self.monitor.save(base, title)

    def run(self, duration, strength_factor=None, damping=0.0, progress=10.0, period=200, chunks=1, snapshots=None,
            slip=None, vtk=None, vtk_every=None, energy=True):
        """Dynamic stage of *duration* [s] of simulated time with NewtonIntegrator *damping* (0: none),
        optionally with the joint sets' strength divided by *strength_factor* (a trigger), in *chunks*
        parts: after each, a line (largest displacement, slipping and open joints) and, with *snapshots* (a
        path prefix), a PNG (*prefix*_0_before.png, then _k_during.png, the last _k_after.png; *slip*: a
        polyline drawn on them). *vtk*: a directory for a VTK series of the blocks and joints, written every
        *vtk_every* s of simulated time (default at the chunks' ends). *energy* (undamped, serial): the
        balance of O.energy over the stage (from the end of its first step) is printed and recorded.
        A progress line by simulated time. Under yade.mpy every rank calls it; the scene is merged on
        rank 0 after each chunk, where the lines, PNGs and VTK files are made. Recorded: the largest and
        the mean displacement of the free blocks (since the last settle)."""
        from yade import O
        from . import mpi, omega, slope
        from .dynamic_stage import DynamicOutputs
        from .monitor import Monitor
        duration = number("SlopeModel.run", "duration", duration, 0, low_open=True)
        chunks = count("SlopeModel.run", "chunks", chunks)
        w0 = time.time()
        if strength_factor is not None:
            slope.apply_joint_sets(F=strength_factor)
        omega.newton(O).damping = damping
        ids = [b.id for b in _blocks(O)]
        split = mpi.distributed() is not None
        mon = getattr(self, "monitor", None)
        if not split:
            if mon is None:  # a progress line only, for this stage
                mon = Monitor(ids=[], period=period, progress=progress, reset=False, name="_rbsm_progress",
                              label=_PROGRESS)
            mon.mark(" dynamic stage")
            mon.target(time=duration)
        out = DynamicOutputs(ids, snapshots, slip, vtk, vtk_every, energy and damping == 0 and not split)
        t0, iter0, figures, shown = O.time, O.iter, {}, [time.time()]
        if out.energy:  # O.energy's terms are set by a step: the balance counts from the end of the first
            mpi.run(1)
            out.started()
        for k in range(chunks):
            t_end = t0 + duration * (k + 1) / chunks
            while O.time < t_end * (1 - 1e-12):  # as settle does: an error of a step raises (O.run can lose it)
                mpi.run(max(1, min(500, int((t_end - O.time) / O.dt) + 1)))
                if split and progress is not None and mpi.rank() == 0 and time.time() - shown[0] >= progress:
                    shown[0] = time.time()  # (serially the Monitor's line; yade.mpy's ranks run no PyRunner of ours)
                    done = min(1.0, (O.time - t0) / duration)
                    print("progress: step %d  %.4f s of the stage's %.4g s, %3.0f%%, about %.0f s left" % (
                        O.iter, O.time - t0, duration, 100 * done, (shown[0] - w0) * (1 - done) / max(done, 1e-9)),
                          flush=True)
            if split:
                mpi.merge()
            if mpi.rank() == 0:
                figures = out.chunk(k, chunks, O.time - t0, w0)
        figures.update(out.finish())
        O.engines = [e for e in O.engines if getattr(e, "label", "") != _PROGRESS]
        if split:  # (collective) the ranks' clocks, which the sync engine keeps together
            states = mpi.rank_states()
            figures["ranks_at"] = [[t, i] for t, i, _ in states]
            if mpi.rank() == 0:
                print("yade.mpy: ranks at t = %s s after %s steps" % (", ".join("%.9g" % t for t, i, dt in states),
                                                                     ", ".join(str(i) for t, i, dt in states)), flush=True)
        return self._record("dynamic", dict(duration=duration, strength_factor=strength_factor, damping=damping),
                            dict(figures, steps=O.iter - iter0), w0)

    def to_json(self, path=None, blocks=False):
        """The stages (and with *blocks* every free block's displacement since the last settle and its
        rotation [rad]) as JSON, written to *path* if given; returns the text."""
        from yade import O
        from . import mpi
        d = dict(stages=[asdict(s) for s in self.stages])
        if blocks:
            d.update(time=O.time, iter=O.iter, dt=O.dt, ranks=mpi.distributed().numThreads if mpi.distributed() else 1)
            d["displacement"] = {str(b.id): list(b.state.pos - b.state.refPos)[:2] for b in _blocks(O)}
            d["rotation"] = {str(b.id): b.state.ori.toAxisAngle()[1] * b.state.ori.toAxisAngle()[0][2]
                             for b in _blocks(O)}
        text = json.dumps(d, indent=1, default=str)
        if path:
            with open(path, "w") as f:
                f.write(text + "\n")
        return text


def _pseudo_static():
    """(kh, kv) of the scene's pseudo-static load (slope.set_seismic), (0, 0) without one or while a record shakes."""
    from yade import O
    from . import earthquake, omega, slope_scene
    if earthquake.shaking(O) or slope_scene._STATIC_GRAVITY_TAG not in O.tags.keys():
        return 0.0, 0.0
    g0 = slope_scene.static_gravity()
    gm = math.sqrt(sum(v * v for v in g0))
    gx, gy = omega.newton(O).gravity[0], omega.newton(O).gravity[1]
    return abs(gx) / gm, 1.0 + gy / gm


def length_inside(polyline, sb):
    """Length [m] of *polyline* inside the slope of the blocks *sb* (its polygon, or ground and base)."""
    from .joint_sets import _inside_length
    from .slope import slope_polygon
    region = getattr(sb, "polygon", None) or slope_polygon(sb.surface, sb.base)
    return sum(_inside_length(seg, region) for seg in zip(polyline[:-1], polyline[1:]))


def _blocks(O):
    """The free Polygon2D blocks (not yade.mpy's Subdomain bodies)."""
    from . import omega
    return [b for b in omega.free_bodies(O) if type(b.shape).__name__ == "Polygon2D"]


def _le_note(v):
    """The note of a limit-equilibrium row: its forces, its circle, or why it failed."""
    if isinstance(v, str):
        return "failed: " + v
    if hasattr(v, "n_valid"):  # SearchResult
        return "%s; %d of %d toe circles valid%s" % (v.circle, v.n_valid, v.n_tried,
                                                      "".join("; WARNING: " + w for w in v.warnings))
    note = "T = %.1f kN/m, N = %.1f kN/m" % (v.shear, v.normal)
    return note + (", %s" % v.surface if type(v.surface).__name__ == "Circle" else "")
