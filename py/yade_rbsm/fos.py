"""``slope.fos()``: the factor of safety of the current scene in one call, with the other estimates
beside it and a stated design value (UDEC's ``SOLVE fos``, with the answer explained).

What it runs, from the current (settled) state, which it leaves as it found it:

1. **Strength reduction** (:func:`yade_rbsm.strength_reduction.strength_reduction`) with defaults
   scaled to the slope: the runaway displacement ``d_fail`` is 5 % of the median block size, a trial's
   step budget follows the time a wave takes to cross the slope, and a trial still undecided at its
   budget is judged by its history (creeping: failed; dying out: runs on). Its bracket ends are then
   set by a mechanism or by equilibrium, not by a step budget; what is left undecided is a warning.
   For jointed rock, a stable end that slid more than half of the default ``d_fail`` and stopped makes
   the FS ``d_fail``'s: it is halved (up to *halvings* times) towards the onset of sliding.
2. **The surface of slipping joints** at the failed end of the bracket (a probe run at the reduced
   strength, then the state restored) and the factor of safety from the contact forces along it at the
   current strengths (:func:`yade_rbsm.safety.slip_surface_fs`).
3. For a continuum cut into blocks, with the builder's blocks (*sb*, a SlopeBlocks): **Bishop's critical
   circle** of limit equilibrium on the same ground with the blocks' material, and the **stress-based
   critical circle** (Kulhawy's method on the settled blocks' own stresses, :func:`yade_rbsm.safety.stress_field`)
   (for jointed rock that material is the intact rock's, and the circles mean nothing: not run unless asked).

The design value depends on the kind of slope: a **jointed rock** slope (bricks, columns, joint sets:
the joints are the rock mass's) is what rigid blocks model: strength reduction. A **continuum cut into
blocks** (Voronoi: a soil or a weak rock mass) is not: a band must zig-zag along rigid faces, and the
strength-reduction factor of safety is unconservative by 65-94 % (docs/slope_factor_of_safety.md) until
blocks are deformable; the design value is then limit equilibrium's, and it says so.
"""
import json
import math
import time
from dataclasses import dataclass, field
from typing import Dict, List

from .checks import count, flag, number

__all__ = ["FosResult", "fos"]

JOINTED, CONTINUUM = "jointed rock", "continuum cut into blocks"


@dataclass
class FosResult:
    """What :func:`fos` found: ``fs`` the design value and ``method`` the estimate it comes from,
    ``warnings`` (empty when the answer is conclusive), ``estimates`` {name: {"fs": value or None,
    "note": str}}, ``recommendation`` (why this value), ``strength_reduction`` (the SRResult),
    ``settings`` (what ran)."""
    fs: float
    method: str
    kind: str
    warnings: List[str] = field(default_factory=list)
    estimates: Dict[str, dict] = field(default_factory=dict)
    recommendation: str = ""
    settings: Dict[str, object] = field(default_factory=dict)
    wall: float = 0.0
    strength_reduction: object = None

    @property
    def conclusive(self):
        return not self.warnings

    def __repr__(self):
        return "FosResult(fs=%.3f by %s, %s, %s; %d other estimates)" % (
            self.fs, self.method, self.kind, "conclusive" if self.conclusive else "%d warning(s)" % len(self.warnings),
            len(self.estimates) - 1)

    def as_dict(self):
        sr = self.strength_reduction
        trials = [dict(F=t.F, failed=t.failed, reason=t.reason, steps=t.steps, dmax=t.dmax, mechanism=t.mechanism)
                  for t in (sr.trials if sr is not None else [])]
        return dict(fs=self.fs, method=self.method, kind=self.kind, conclusive=self.conclusive, warnings=self.warnings,
                    estimates=self.estimates, recommendation=self.recommendation, settings=self.settings,
                    wall=self.wall, trials=trials)

    def to_json(self, path=None):
        """The result as JSON (written to *path* if given); returns the text."""
        text = json.dumps(self.as_dict(), indent=1, default=str)
        if path:
            with open(path, "w") as f:
                f.write(text + "\n")
        return text

    def to_markdown(self, path=None):
        """A report: the design value and why, the estimates side by side, the strength-reduction trials,
        the warnings (written to *path* if given); returns the text."""
        out = ["# Factor of safety", "",
               "**FS = %.3f** (%s), a %s slope. %s" % (self.fs, self.method, self.kind, self.recommendation), "",
               "| method | FS | note |", "|---|---|---|"]
        for name, e in self.estimates.items():
            out.append("| %s | %s | %s |" % (name, "-" if e["fs"] is None else "%.3f" % e["fs"], e["note"]))
        sr = self.strength_reduction
        if sr is not None:
            out += ["", "Strength-reduction trials (%s):" % sr.criterion, "",
                    "| F | result | reason | steps | max displacement [m] | mechanism |", "|---|---|---|---|---|---|"]
            out += ["| %.4f | %s | %s | %d | %.3g | %s |" % (t.F, "failed" if t.failed else "stable", t.reason, t.steps,
                                                           t.dmax, t.mechanism or "") for t in sr.trials]
        out += ["", "Warnings: " + ("none (conclusive)" if not self.warnings else "")]
        out += ["- " + w for w in self.warnings]
        out += ["", "Settings: " + ", ".join("%s = %s" % kv for kv in sorted(self.settings.items())),
                "", "%.1f s wall." % self.wall]
        text = "\n".join(out) + "\n"
        if path:
            with open(path, "w") as f:
                f.write(text)
        return text


def _kind(sb, kind):
    if kind is not None:
        if kind not in (JOINTED, CONTINUUM):
            raise ValueError("fos: kind must be %r or %r (got %r)" % (JOINTED, CONTINUUM, kind))
        return kind, "given"
    pattern = getattr(sb, "pattern", None)
    if pattern in ("voronoi", "triangles"):  # a continuum cut into cells, not rock along its joints
        return CONTINUUM, "Voronoi blocks" if pattern == "voronoi" else "triangle blocks"
    if pattern is not None:
        return JOINTED, "%s blocks" % pattern
    return JOINTED, "assumed (no SlopeBlocks given: pass sb= or kind=)"


def _scale(ids):
    """(median block size [m], the slope's extent [m], P-wave speed [m/s]) of the free blocks."""
    from yade import O
    sizes = sorted(2 * O.bodies[i].shape.circumradius for i in ids)
    xs = [O.bodies[i].state.pos[0] for i in ids]
    ys = [O.bodies[i].state.pos[1] for i in ids]
    extent = max(max(xs) - min(xs), max(ys) - min(ys)) + sizes[-1]
    speeds = [math.sqrt(m.young / m.density) for m in {O.bodies[i].material for i in ids}
              if type(m).__name__ == "RbsmMat" and m.young > 0 and m.density > 0]
    return sizes[len(sizes) // 2], extent, max(speeds) if speeds else float("nan")


def fos(sb=None, kind=None, d_fail=None, max_steps=None, patience=4, tol=1e-4, rtol=0.01, probe=True,
        circle=None, density_scaling=False, verbose=False, reference_rotation=0.2, halvings=3):
    """The factor of safety of the current scene (module docstring): a :class:`FosResult` with ``fs``,
    ``warnings`` (empty when conclusive), the other ``estimates`` and ``to_json()``, ``to_markdown()``.

    *sb*: the SlopeBlocks the scene was built from (its pattern gives the kind of slope, its ground the
    limit-equilibrium comparison); *kind*: "jointed rock" or "continuum cut into blocks", to say it
    yourself. *d_fail* [m] (default 5 % of the median block size), *max_steps* (default: 20 wave
    crossings of the slope at the current O.dt, 2000 to 50 000), *patience*, *tol*, *rtol*,
    *density_scaling*: strength reduction's. *probe*: also the surface of slipping joints; *circle*: also
    Bishop's critical circle (with *sb*; default: for a continuum only, since for jointed rock the
    blocks' material is the intact rock's). *reference_rotation*: strength reduction's (None: no check of
    blocks that turned since they were built). *halvings*: with the default *d_fail*, how many times it is
    halved while the stable end of the bracket moved more than half of it (jointed rock: the FS is then
    the onset of sliding, not of the slope's stopping elsewhere). The scene is left as it was."""
    from yade import O
    from .strength_reduction import strength_reduction, _free_ids
    w0 = time.time()
    kind, why_kind = _kind(sb, kind)
    patience = count("fos", "patience", patience)
    tol, rtol = number("fos", "tol", tol, 0, low_open=True), number("fos", "rtol", rtol, 0, low_open=True)
    probe = flag("fos", "probe", probe)
    circle = (kind == CONTINUUM) if circle is None else flag("fos", "circle", circle)
    density_scaling = flag("fos", "density_scaling", density_scaling)
    ids = _free_ids()
    if not ids:
        raise ValueError("fos: no free blocks (build and settle a slope first)")
    size, extent, c = _scale(ids)
    halvings = count("fos", "halvings", halvings, 0) if d_fail is None else 0  # (a d_fail given is kept)
    d_fail = 0.05 * size if d_fail is None else number("fos", "d_fail", d_fail, 0, low_open=True)
    if max_steps is None:
        crossing = extent / (c * O.dt) if math.isfinite(c) and O.dt > 0 else 100.0
        max_steps = int(min(50000, max(2000, 20 * crossing)))
    max_steps = count("fos", "max_steps", max_steps)
    check = max(50, min(200, max_steps // 40))
    settings = dict(d_fail=round(d_fail, 6), max_steps=max_steps, patience=patience, tol=tol, rtol=rtol, check=check,
                    density_scaling=density_scaling, blocks=len(ids), kind_from=why_kind)
    def reduce(start, d_fail):
        return strength_reduction(start=start, grow=1.25, rtol=rtol, tol=tol, d_fail=d_fail, max_steps=max_steps,
                                  check=check, damping=0.7, density_scaling=density_scaling, patience=patience,
                                  verbose=verbose, reference_rotation=reference_rotation)
    # the blocks' stresses are read in the state given (strength reduction leaves it as it found it)
    stress_based = _stress_circle(sb, ids, size) if circle and sb is not None else None
    toppling = _goodman_bray(sb) if getattr(sb, "pattern", None) == "columns" else None
    sr, halved = reduce(1.0, d_fail), 0
    # A stable end that moved more than half of d_fail and stopped (a jointed slope that slides, then jams) makes
    # the FS d_fail's; halving d_fail homes in on the onset of sliding (the landslide example: 0.872, 0.859,
    # then 0.828 without the warning, limit equilibrium's planar wedge 0.825). Not for a continuum, whose
    # design value is limit equilibrium's.
    while kind == JOINTED and halved < halvings and _stable_end_moved(sr, d_fail):
        d_fail, halved = 0.5 * d_fail, halved + 1
        sr = reduce(sr.hi, d_fail)  # (stricter: the failed end fails again, and the search goes down from it)
    settings.update(d_fail=round(d_fail, 6), d_fail_halved=halved)
    warnings = list(sr.warnings)
    if sr.reference_ratio > 10 * tol and sr.fs >= 1:  # (below 1 it is the slope failing, as the FS says)
        warnings.append("the state reduced was not in equilibrium at its own strengths (unbalanced-force ratio %.2e) "
                        "though the FS found is %.3f >= 1: it was not settled (settle again after changing strengths)"
                        % (sr.reference_ratio, sr.fs))
    estimates = {"strength reduction": dict(fs=sr.fs, note="bracket [%.4f stable, %.4f failed], %d trials%s%s" % (
        sr.lo, sr.hi, len(sr.trials), (", failing by " + sr.mechanism) if sr.mechanism else "",
        (", d_fail halved %d x to %.3g m (a stable end slid, then stopped)" % (halved, d_fail)) if halved else ""))}
    if probe:
        estimates["contact forces, surface of slipping joints"] = _found_surface(sr, sb)
    if circle and sb is not None:
        estimates["Bishop, critical circle (blocks' material)"] = _bishop(sb, ids)
        estimates["stress-based, critical circle (blocks' stresses)"] = stress_based
    if toppling is not None:
        estimates["Goodman & Bray, toppling (rigid columns)"] = toppling
        gb = toppling["fs"]
        if gb is not None and sr.mechanism and "toppling" in sr.mechanism and sr.fs < 0.95 * gb:
            warnings.append("strength reduction fails by toppling at %.3f, %.0f %% below Goodman & Bray's rigid columns "
                            "(%.3f): elastic joints let a column turn before its weight bears on its base corner, and "
                            "the gap closes as the joints stiffen, about as kn^(-1/3) (the manual's factor-of-safety "
                            "guide: 1.14 to 2.53 for E 1 GPa to 100 TPa on Goodman & Bray's two columns, 2.57)"
                            % (sr.fs, 100 * (1 - sr.fs / gb), gb))
    fs, method = sr.fs, "strength reduction"
    if kind == JOINTED:
        recommendation = ("For jointed rock the joints are the rock mass's discontinuities and rigid blocks model "
                          "them: the design value is strength reduction's.")
    else:
        b = estimates.get("Bishop, critical circle (blocks' material)", {}).get("fs")
        recommendation = ("Rigid blocks cut from a continuum overestimate its strength (a shear band must follow "
                          "their faces: on Griffiths & Lane's slope +65 to +94 % with brittle joints, +110 % with ductile ones, "
                          "docs/slope_factor_of_safety.md); ")
        if b is not None:
            fs, method = b, "Bishop, critical circle (blocks' material)"
            recommendation += ("the design value is limit equilibrium's; strength reduction's and the blocks' own "
                               "stresses on their critical circle are shown beside it.")
            if sr.warnings:  # they qualify the estimate beside the design value, not the design value
                estimates["strength reduction"]["note"] += "; " + "; ".join(sr.warnings)
                warnings = [w for w in warnings if w not in sr.warnings]
        else:
            warnings.append("a continuum cut into blocks without limit equilibrium to compare (give sb=, the "
                            "SlopeBlocks): strength reduction's value is unconservative")
            recommendation += "without limit equilibrium (no sb=), strength reduction's value is given, and warned about."
    if verbose:
        print("fos: FS = %.3f by %s; %s" % (fs, method, recommendation), flush=True)
    return FosResult(fs, method, kind, warnings, estimates, recommendation, settings, time.time() - w0, sr)


def _stable_end_moved(sr, d_fail):
    """Whether the stable end of the bracket moved more than half of *d_fail* before it stopped."""
    return any(t.F == sr.lo and not t.failed and t.dmax > 0.5 * d_fail for t in sr.trials)


def _found_surface(sr, sb):
    """The contact-force FS along the joints that slip at the failed end's strength (probe, state restored)."""
    from yade import O
    from .safety import probe_slipping_surface, slip_surface_fs
    from .strength_reduction import _Reference, reduce_strengths
    mark = "rbsm_fos_probe"
    O.saveTmp(mark)
    try:
        reduce_strengths(sr.hi, _Reference())
        surface = probe_slipping_surface(steps=300)
    finally:
        O.loadTmp(mark)
    if surface is None or len(surface.polyline) < 2:
        return dict(fs=None, note="no joint slipped in a 300-step probe at F = %.4f" % sr.hi)
    try:
        r = slip_surface_fs(surface)
    except ValueError as e:
        return dict(fs=None, note=str(e))
    return dict(fs=r.contact.fs, note="%s, %.3g m, found at F = %.4f, forces of the current state" % (
        r.note(), surface.length, sr.hi))


def _search(sb, mat, **kw):
    """The critical circle of limit equilibrium on the blocks' ground with their material (keywords: method's)."""
    from . import limit_equilibrium as le
    from .safety import le_slope
    slope = le_slope(sb.surface, mat)
    xs = [p[0] for p in sb.surface]
    ys = [p[1] for p in sb.surface]
    H = max(ys) - sb.base
    # the grid of scripts/reference_slopes.py's searches, scaled: within 0.3 % of their minima on its four
    # slopes (0.8 s), where 9 x 9 x 9 centres and radii, refined once, stayed 1.2 to 2.5 % above them
    return le.critical_circle(slope, x_range=(min(xs), max(xs)), y_range=(max(ys), max(ys) + 3 * H), nx=12, ny=12,
                              r_range=(0.3 * H, 5 * H), nr=19, base=sb.base, refine=3, **kw)


def _bishop(sb, ids):
    from yade import O
    mat = O.bodies[ids[0]].material
    try:
        r = _search(sb, mat, method="bishop")
    except ValueError as e:
        return dict(fs=None, note=str(e))
    return dict(fs=r.fs, note="c %.3g kPa, phi %.1f deg of the blocks' material, %s%s" % (
        mat.cohesion / 1e3, math.degrees(mat.frictionAngle), r.circle, "".join("; WARNING: " + w for w in r.warnings)))


def _goodman_bray(sb):
    """Goodman & Bray's FS of a column slope (toppling.columns: flat-topped columns, one block each) at the joints'
    current friction (base joints: column on the foundation; sides: column on column) and the scene's gravity;
    a note instead where their method does not apply."""
    from yade import O
    from . import omega, toppling
    try:
        cols = toppling.columns(sb)
    except ValueError as e:
        return dict(fs=None, note="not Goodman & Bray's geometry: %s" % e)
    toe = -1 if toppling.toe_side(sb) == "left" else 1  # the direction of the toe along x (columns' own rule)
    gx, gy = omega.newton(O).gravity[0], omega.newton(O).gravity[1]
    psi = math.atan2(toe * gx, -gy)
    if not 0 < psi < 0.5 * math.pi:
        return dict(fs=None, note="gravity (%.3g, %.3g) does not lean towards the toe: Goodman & Bray's columns need "
                                  "it tilted by the base planes' dip" % (gx, gy))
    free = set(b.id for b in sb.free)
    tan = {"base": set(), "side": set()}
    for I in omega.joints(O):
        if I.id1 in free or I.id2 in free:
            if I.phys.cohesion > 0 or I.phys.tensileStrength > 0:
                return dict(fs=None, note="joint %d-%d has cohesion or tensile strength: Goodman & Bray's joints are "
                                          "frictional" % (I.id1, I.id2))
            tan["side" if I.id1 in free and I.id2 in free else "base"].add(I.phys.tanPhi)
    if len(tan["base"]) != 1 or len(tan["side"]) > 1:
        return dict(fs=None, note="the joints' friction is not one value on the bases and one on the sides")
    tb = tan["base"].pop()
    ts = tan["side"].pop() if tan["side"] else tb
    try:
        fs = toppling.goodman_bray_fs(cols, psi, math.atan(tb), math.atan(ts))
    except ValueError as e:
        return dict(fs=None, note=str(e))
    return dict(fs=fs, note="%d columns, base planes dipping %.2f deg, phi %.1f deg (bases) and %.1f deg (sides)" % (
        len(cols), math.degrees(psi), math.degrees(math.atan(tb)), math.degrees(math.atan(ts))))


def _stress_circle(sb, ids, size):
    """Kulhawy's critical circle on the blocks' own stresses (safety.stress_field): the state the joints carry,
    read on surfaces that cross the blocks; circles at least two blocks deep (a shallower one samples a block
    or two of the face)."""
    from yade import O
    from .safety import stress_field
    mat = O.bodies[ids[0]].material
    try:
        r = _search(sb, mat, method="stress", stress=stress_field(), min_depth=2 * size)
    except ValueError as e:
        return dict(fs=None, note=str(e))
    return dict(fs=r.fs, note="Kulhawy's method on the settled blocks' stresses, c %.3g kPa, phi %.1f deg, %s%s" % (
        mat.cohesion / 1e3, math.degrees(mat.frictionAngle), r.circle, "".join("; WARNING: " + w for w in r.warnings)))
