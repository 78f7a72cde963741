"""Factor of safety by strength reduction (shear strength reduction, SSR) on an RBSM scene.

Procedure (:func:`strength_reduction`)
--------------------------------------
1. The current scene is the reference state: it must be in equilibrium under gravity with the
   *real* joint strengths (e.g. after :func:`yade_rbsm.slope.settle`). It is saved in memory
   (``O.saveTmp``) together with the strength of every joint (``phys.tanPhi``, ``phys.cohesion``)
   and of every :yref:`RbsmMat` (``frictionAngle``, ``cohesion``; joints formed during a trial get
   their strength from the materials).
2. A *trial* at factor F (:func:`trial`) reloads that state, divides ``tanφ`` and ``c`` of every
   joint and every material by F (``tanφ_F = tanφ / F``, ``c_F = c / F``; the tensile strength
   too if ``reduce_tensile``) and runs a damped stage (NewtonIntegrator ``damping``, default 0.7) in
   chunks of *check* steps; after each chunk the contacts made along a joint set
   (:func:`yade_rbsm.slope.set_joint_strength`) get the set's strength divided by F
   (:func:`yade_rbsm.slope.apply_joint_sets`).
3. **Failure criterion.** The trial *fails* if

   * the blocks whose displacement since the start of the trial exceeds ``d_fail`` (monitored
     blocks, default: every free block) weigh more than ``mass_fraction`` of the monitored mass: a
     global mechanism (runaway). Fewer of them (a sliver at the toe, a block falling off the face)
     are a *local* failure: reported in the trial (``Trial.local``) and left out of the
     unbalanced-force ratio, not taken as the slope's failure (``mass_fraction=0``: any block), or
   * the unbalanced-force ratio (:func:`yade_rbsm.slope.unbalanced_ratio`, mean |contact force +
     m g| over the free blocks / mean |m g|) has not come below ``tol`` within ``max_steps`` steps
     (non-convergence);

   it is *stable* as soon as the ratio is below ``tol`` at two consecutive checks (every *check*
   steps; one low value may be a dynamic oscillation passing through zero) with no runaway. A block that slides with a net force ``ε·W`` keeps a ratio of order ε, so ``tol``
   bounds the resolution in F (for a block on a plane at ψ, F is resolved to about
   ``tol / sin ψ`` relatively); ``d_fail`` must be well above the elastic settlement and
   ``max_steps`` long enough for a stable slope to converge at the given damping.
4. Bracketing: from ``start`` (default 1), F is multiplied (stable) or divided (failed) by
   ``grow`` until a stable ``F_lo`` and a failed ``F_hi`` are found, then bisected until
   ``F_hi - F_lo <= rtol · F_lo``. The result is ``F = (F_lo + F_hi) / 2`` with its bracket.
5. The reference state is reloaded at the end (strengths and positions as before the call).

The reference state is checked: one step from it at its own strengths (then reloaded) gives its
unbalanced-force ratio (``SRResult.reference_ratio``). Above ``reference_tol`` (default 0.5; 1 is
free fall) nothing can be bracketed: ValueError naming it, instead of trials that all fail. A
smaller one is reported (a slope with FS < 1 is out of equilibrium at its real strengths). Its
blocks' rotation since they were built is checked too (``reference_rotation``, default 0.2 rad):
columns that toppled while settling are a collapsed pile, not the slope to reduce. With a *calibration*
(:class:`yade_rbsm.calibration.Calibration`) the strength reduced is the *assembly's*: trial F gives
every joint and material ``calibration.joint_strength(c/F, tanφ/F)`` of the soil's c, tanφ
(*soil*), instead of dividing the joints' own. *png*: a path prefix; the blocks coloured by their
displacement in the last stable and the first failed trial are drawn to ``<png>_stable.png`` and
``<png>_failed.png`` (the mechanism at the bracket's ends; a prefix ending in .png loses it); where plastic
deformable blocks are monitored, their plastic shear gained in the trial too, to ``<png>_stable_plastic.png`` and
``<png>_failed_plastic.png`` (the band). *png_line*: a polyline drawn dashed on them (e.g. limit equilibrium's
critical circle, :meth:`yade_rbsm.limit_equilibrium.Circle.polyline`). A failed trial also says how its moving
blocks moved (``Trial.mechanism``, ``SRResult.mechanism`` for the bracket's failed end): sliding,
toppling (blocks turning about their corners), or both. ``SRResult.warnings`` (printed when verbose)
says where the bracket may be the criterion's rather than the slope's: a failed end that only did not
converge within ``max_steps`` while nothing ran away (soft, slowly settling columns), or a stable end that
moved more than half of ``d_fail``.

PyRunners in O.engines (monitor, VTK output) are switched off (``dead``) during the trials.
"""
import math
import time
from dataclasses import dataclass, field
from typing import List, Optional, Tuple

from .checks import count, flag, number
from . import omega

__all__ = ["SRResult", "Trial", "strength_reduction", "trial", "reduce_strengths"]


@dataclass
class Trial:
    F: float
    failed: bool
    reason: str  # "converged", "runaway", "creeping" (a steady mechanism, see trial), "not converged"
    steps: int
    ratio: float
    dmax: float
    wall: float
    moving: float = 0.0  # mass fraction of the monitored blocks displaced more than d_fail
    local: List[int] = field(default_factory=list)  # ids of blocks that ran away alone (local failure)
    png: str = ""
    png_plastic: str = ""  # the plastic shear gained in the trial, where plastic blocks are monitored
    plastic_gain: dict = field(default_factory=dict)  # {block id: plastic shear gained in the trial}, plastic blocks
    mechanism: str = ""  # a failed trial's: "sliding", "sliding and rotating" or "toppling" (see _mechanism)
    rocking: float = 0.0  # its moving blocks' mass-weighted rotation x circumradius / displacement

    def __str__(self):
        loc = (", local failure of %d block(s) %s" % (len(self.local), self.local[:5])) if self.local else ""
        ratio = ("unbalanced ratio %.2e" % self.ratio) if math.isfinite(self.ratio) else "unbalanced ratio not reached"
        mech = (", mechanism: %s (rotation x size / displacement %.2f)" % (self.mechanism, self.rocking)
                if self.mechanism else "")
        return ("F = %.4f: %s (%s after %d steps, %s, max displacement %.3e m, mass moved beyond d_fail %.1f %%%s%s, "
                "%.1f s wall)" % (self.F, "FAILED" if self.failed else "stable", self.reason, self.steps, ratio,
                                  self.dmax, 100 * self.moving, loc, mech, self.wall))


@dataclass
class SRResult:
    fs: float
    lo: float  # largest stable F
    hi: float  # smallest failed F
    trials: List[Trial] = field(default_factory=list)
    criterion: str = ""
    reference_ratio: float = 0.0  # unbalanced-force ratio of the reference state at its own strengths
    warnings: List[str] = field(default_factory=list)  # where the bracket may be the criterion's (_warnings)

    @property
    def mechanism(self):
        """The mechanism of the failed end of the bracket (Trial.mechanism of the trial at *hi*)."""
        return next((t.mechanism for t in self.trials if t.F == self.hi and t.failed), "")

    def __str__(self):
        mech = self.mechanism
        return ("strength reduction: FS = %.3f, bracket [%.4f stable, %.4f failed] after %d trials%s"
                % (self.fs, self.lo, self.hi, len(self.trials), (", failing by %s" % mech) if mech else ""))


class _Reference:
    """Strengths of the joints and materials of the reference state (and the calibration that maps
    the soil's reduced strength to the joints')."""

    def __init__(self, calibration=None, soil=None):
        from yade import O
        self.calibration, self.soil = calibration, soil
        self.joints = {}
        for I in omega.joints(O):
            self.joints[(I.id1, I.id2)] = (I.phys.tanPhi, I.phys.cohesion, I.phys.tensileStrength)
        self.mats = {}
        for k, m in enumerate(O.materials):
            if type(m).__name__ == "RbsmMat":
                self.mats[k] = (m.frictionAngle, m.cohesion, m.tensileStrength)


def reduce_strengths(F, ref, reduce_tensile=False):
    """Divide tanφ and c of every joint and material by F (from the reference values *ref*)."""
    from yade import O
    F = number("reduce_strengths", "F", F, 0, low_open=True)
    if ref.calibration is not None:
        return _reduce_calibrated(F, ref)
    for k, (phi, c, t) in ref.mats.items():
        m = O.materials[k]
        m.frictionAngle = math.atan(math.tan(phi) / F)
        m.cohesion = c / F
        if reduce_tensile:
            m.tensileStrength = t / F
    for I in omega.joints(O):
        v = ref.joints.get((I.id1, I.id2))
        if v is None:
            continue
        I.phys.tanPhi = v[0] / F
        I.phys.cohesion = v[1] / F
        if reduce_tensile:
            I.phys.tensileStrength = v[2] / F


def _reduce_calibrated(F, ref):
    """Joints and materials get the joint strength that gives the assembly c/F, tanφ/F."""
    from yade import O
    c, phi = ref.soil
    cj, tj = ref.calibration.joint_strength(c / F, math.tan(phi) / F)
    for k in ref.mats:
        m = O.materials[k]
        m.frictionAngle = math.atan(tj)
        m.cohesion = cj
    for I in omega.joints(O):
        if (I.id1, I.id2) in ref.joints:
            I.phys.tanPhi = tj
            I.phys.cohesion = cj


def _free_ids():
    from yade import O
    return [b.id for b in omega.free_bodies(O)]


def _turned(q0, q1):
    """The angle [rad, 0..pi] a block turned by from orientation *q0* to *q1*."""
    angle = abs((q0.conjugate() * q1).toAxisAngle()[1])
    return min(angle, 2 * math.pi - angle)


def _mechanism(ids, start_ori, d, d_fail):
    """How the blocks that moved most in a trial (displaced more than half the largest displacement)
    moved, block by block: each block's rotation θ times its circumradius R over its displacement d,
    mass-weighted. A sliding block turns little (θR/d near 0, also in a rotational slide of a mass much
    larger than its blocks); a block toppling about its own corner has d = θ × (corner to centroid),
    θR/d near 1. It describes the blocks' motion, not the mass's: a column of stacked blocks toppling
    as one reads "sliding and rotating" (its upper blocks move more than they turn). Returns (name,
    index): "sliding" below 0.3, "toppling" above 0.7, "sliding and rotating" between; ("", 0) when
    nothing moved a tenth of *d_fail* (a trial that only did not converge has no mechanism to name)."""
    from yade import O
    dmax = max(d.values()) if d else 0.0
    if dmax <= 0.1 * d_fail:
        return "", 0.0
    num = den = 0.0
    for i in ids:
        if d[i] < 0.5 * dmax:
            continue
        s = O.bodies[i].state
        angle = _turned(start_ori[i], s.ori)
        num += s.mass * angle * O.bodies[i].shape.circumradius / d[i]
        den += s.mass
    rocking = num / den if den > 0 else 0.0
    return ("sliding" if rocking < 0.3 else "toppling" if rocking > 0.7 else "sliding and rotating"), rocking


def _trend(history):
    """"creeping" when the last quarter of the checks moved the monitored mass (mass-weighted mean
    displacement) at least 0.8 x as much as the quarter before, with an unbalanced-force ratio at least
    half of the quarter before's: a mechanism moving at a steady or growing rate (local damping caps
    its acceleration). "dying" when either decays; "unclear" with fewer than 8 checks. A stable slope
    still settling slowly has both decaying; a creeping one neither."""
    n = len(history)
    if n < 8:
        return "unclear"
    q = n // 4
    late = history[-1][0] - history[-1 - q][0]
    before = history[-1 - q][0] - history[-1 - 2 * q][0]
    ratio_now = sum(r for _, r in history[-q:]) / q
    ratio_before = sum(r for _, r in history[-2 * q:-q]) / q
    if late > 0 and late >= 0.8 * before and ratio_now >= 0.5 * ratio_before:
        return "creeping"
    return "dying"


def _trial_args(where, F, tol, d_fail, max_steps, check, damping):
    return (number(where, "F", F, 0, low_open=True), number(where, "tol", tol, 0, low_open=True),
            number(where, "d_fail", d_fail, 0, low_open=True), count(where, "max_steps", max_steps),
            count(where, "check", check), number(where, "damping", damping, 0, 1, high_open=True))


def trial(F, ref, mark, ids=None, tol=1e-4, d_fail=0.05, max_steps=5000, check=100, damping=0.7,
          reduce_tensile=False, verbose=False, mass_fraction=0.01, png=None, patience=4, png_line=None):
    """One trial at factor *F* from the state saved under *mark* (see the module docstring).
    Returns a :class:`Trial`; a failed one says how its moving blocks moved (Trial.mechanism).

    A trial neither converged nor run away after *max_steps* is judged by its history, as UDEC and FLAC
    users read theirs (:func:`_trend`): one whose motion dies out runs on (up to *patience* x
    *max_steps* in all: "converged" if it gets there), one whose blocks keep moving at an undiminished
    rate under an undiminished unbalanced force is a mechanism, failed as "creeping"; only what is still
    undecided then is "not converged" (and warned about)."""
    from yade import O, Quaternion, Vector3
    from .scene import advance
    from .slope import unbalanced_ratio
    F, tol, d_fail, max_steps, check, damping = _trial_args("trial", F, tol, d_fail, max_steps, check, damping)
    mass_fraction = number("trial", "mass_fraction", mass_fraction, 0, 1, high_open=True)
    patience = count("trial", "patience", patience)
    w0 = time.time()
    O.loadTmp(mark)
    omega.switch_off_pyrunners(O)
    omega.newton(O).damping = damping
    reduce_strengths(F, ref, reduce_tensile)
    ids = ids if ids is not None else _free_ids()
    start = {i: Vector3(O.bodies[i].state.pos) for i in ids}
    start_ori = {i: Quaternion(O.bodies[i].state.ori) for i in ids}
    start_shear = {i: O.bodies[i].state.plasticShear for i in ids if getattr(O.bodies[i].material, "plastic", False)}
    mass = {i: O.bodies[i].state.mass for i in ids}
    total = sum(mass.values()) or 1.0
    steps, ratio, dmax, moving = 0, float("inf"), 0.0, 0.0
    failed, reason = True, "not converged"
    below = 0
    local = []
    from .slope_scene import apply_joint_sets, joint_sets
    sets = joint_sets() if ref.calibration is None else []  # contacts made along a joint set get its strength
    history = []  # (mass-weighted mean displacement, unbalanced ratio) at every check
    budget = max_steps
    while steps < budget:
        n = min(check, budget - steps)
        advance(n)
        steps += n
        if sets:
            apply_joint_sets(F, reduce_tensile, sets)
        d = {i: (O.bodies[i].state.pos - start[i]).norm() for i in ids}
        dmax = max(d.values())
        away = [i for i in ids if d[i] > d_fail]
        moving = sum(mass[i] for i in away) / total
        if away and moving > mass_fraction:
            failed, reason, local = True, "runaway", []  # the moving blocks are the mechanism, not local
            break
        local = away
        ratio = unbalanced_ratio(ids=set(ids) - set(away)) if away else unbalanced_ratio()
        below = below + 1 if ratio < tol else 0
        if below >= 2:
            failed, reason = False, "converged"
            break
        history.append((sum(mass[i] * d[i] for i in ids) / total, ratio))
        if steps >= budget:
            trend = _trend(history)
            if trend == "creeping":
                failed, reason = True, "creeping"
                break
            if budget < patience * max_steps:  # dying out, or not clear yet: run on
                budget = min(patience * max_steps, budget + max_steps)
    t = Trial(F, failed, reason, steps, ratio, dmax, time.time() - w0, moving, sorted(local))
    if failed:
        t.mechanism, t.rocking = _mechanism(ids, start_ori, d, d_fail)
    t.plastic_gain = {i: O.bodies[i].state.plasticShear - v for i, v in start_shear.items()}
    if png:  # coloured by the trial's displacement: refPos at the trial's start for the drawing only
        from .snapshots import snapshot
        built = {i: Vector3(O.bodies[i].state.refPos) for i in ids}  # (joints_on needs the built pose)
        for i in ids:
            O.bodies[i].state.refPos = start[i]
        title = "strength reduction F = %.4f: %s (%s%s)" % (F, "failed" if failed else "stable", reason,
                                                             (", " + t.mechanism) if t.mechanism else "")
        t.png = snapshot(png, title=title, slip=png_line)
        if t.plastic_gain:  # the band
            t.png_plastic = snapshot(png[:-4] + "_plastic.png", title=title, slip=png_line, values=t.plastic_gain,
                                     label="plastic shear strain gained in the trial [-]")
        for i in ids:
            O.bodies[i].state.refPos = built[i]
    if verbose:
        print("  strength reduction trial " + str(t), flush=True)
    return t


def strength_reduction(start=1.0, grow=1.25, rtol=0.01, max_trials=30, ids=None, tol=1e-4, d_fail=0.05,
                       max_steps=5000, check=100, damping=0.7, reduce_tensile=False, verbose=True,
                       mark="rbsm_srm_reference", density_scaling=False, mass_fraction=0.01, reference_tol=0.5,
                       calibration=None, soil=None, png=None, reference_rotation=0.2, patience=4, png_line=None):
    """Factor of safety by strength reduction on the current scene (see the module docstring).
    *density_scaling*: RbsmTimeStepper.densityScaling in every trial (fewer steps to the same
    equilibrium; restored at the end).

    *ids*: monitored blocks for the runaway criterion (default: all free blocks). Returns an
    :class:`SRResult`; raises RuntimeError if no bracket is found within *max_trials* trials.
    *mass_fraction*, *reference_tol*, *calibration* with *soil* = (c [Pa], φ [rad]) and *png*: see
    the module docstring. *patience*: a trial still undecided at *max_steps* is judged by its history
    and runs on while its motion dies out, up to *patience* x *max_steps* (:func:`trial`). *reference_rotation* [rad]: the largest rotation of a monitored block since
    it was built (the pose build_scene gave it; State.refOri for other bodies) that the reference state may have; a slope whose blocks toppled or
    tumbled while settling is not the slope to reduce: ValueError naming the block, when the blocks
    rotated more weigh more than *mass_fraction* of the monitored mass (fewer are reported as local;
    None: no check)."""
    from yade import O
    from . import mpi
    where = "strength_reduction"
    if mpi.distributed() is not None:  # O.saveTmp/loadTmp of a split scene: YADE fails on the workers, rank 0 waits
        raise ValueError("strength_reduction: runs on one process: under yade.mpy merge the scene (yade_rbsm.mpi.merge()) "
                         "and call yade_rbsm.mpi.to_serial() on rank 0, then strength_reduction there")
    mpi.check_one_subdomain(where)
    start, tol, d_fail, max_steps, check, damping = _trial_args(where, start, tol, d_fail, max_steps, check, damping)
    grow = number(where, "grow", grow, 1, low_open=True)
    rtol = number(where, "rtol", rtol, 0, low_open=True)
    max_trials = count(where, "max_trials", max_trials)
    density_scaling = flag(where, "density_scaling", density_scaling)
    reduce_tensile = flag(where, "reduce_tensile", reduce_tensile)
    if png is not None and png.lower().endswith(".png"):  # a file name given for the prefix: x.png -> x_stable.png
        png = png[:-4]
    mass_fraction = number(where, "mass_fraction", mass_fraction, 0, 1, high_open=True)
    reference_tol = number(where, "reference_tol", reference_tol, 0, low_open=True)
    if (calibration is None) != (soil is None):
        raise ValueError("strength_reduction: give calibration and soil=(c, phi) together")
    if soil is not None:
        soil = (number(where, "soil cohesion", soil[0], 0), number(where, "soil friction angle", soil[1], 0,
                                                                    math.pi / 2, low_open=True, high_open=True))
    if not (ids if ids is not None else _free_ids()):
        raise ValueError("strength_reduction: no free blocks to monitor (empty scene, or every block fixed)")
    from . import omega
    if not any(omega.newton(O).gravity):  # every trial would be "stable": no mechanism without a weight
        raise ValueError("strength_reduction: NewtonIntegrator.gravity is zero: a slope has no weight to fail under")
    if reference_rotation is not None:
        reference_rotation = number(where, "reference_rotation", reference_rotation, 0, low_open=True)
        _check_rotation(ids if ids is not None else _free_ids(), reference_rotation, mass_fraction, verbose)
    ref = _Reference(calibration, soil)
    kinds = {v[:2] for v in ref.joints.values()}  # (tanPhi, cohesion)
    if calibration is not None and len(kinds) > 1:
        raise ValueError("strength_reduction: with a calibration every joint gets the calibrated strength of "
                         "the assembly, but the joints here have %d different strengths (joint sets from "
                         "set_joint_strength, layers of other materials): reduce them without calibration"
                         % len(kinds))
    from .scene import time_stepper
    stepper = time_stepper()
    if density_scaling and stepper is None:
        raise ValueError("strength_reduction: density_scaling needs RbsmTimeStepper in O.engines (yade_rbsm.engines())")
    old_scaling = stepper.densityScaling if stepper is not None else False
    if stepper is not None:
        stepper.densityScaling = bool(density_scaling)  # saved with the reference: on in every trial
    O.saveTmp(mark)
    r0 = _reference_ratio(mark, ids)
    if not r0 < reference_tol:
        O.loadTmp(mark)
        if stepper is not None:
            time_stepper().densityScaling = old_scaling
        raise ValueError("strength_reduction: the reference state is not near equilibrium (unbalanced-force ratio %.3g >= "
                         "reference_tol %.3g; 1 is free fall): settle it first (yade_rbsm.slope.settle)"
                         % (r0, reference_tol))
    if verbose and r0 > 10 * tol:
        print("  strength reduction: the reference state is not in equilibrium at its own strengths (unbalanced-force "
              "ratio %.2e): FS < 1, or not settled (strengths changed since settle, e.g. set_joint_strength: settle "
              "again)" % r0, flush=True)
    trials = []
    patience = count(where, "patience", patience)
    kw = dict(ids=ids, tol=tol, d_fail=d_fail, max_steps=max_steps, check=check, damping=damping,
              reduce_tensile=reduce_tensile, verbose=verbose, mass_fraction=mass_fraction, patience=patience,
              png_line=png_line)
    crit = ("failure: blocks displaced > %g m weigh > %g %% of the monitored mass, or the monitored mass creeping at an "
            "undiminished rate after %d steps, or unbalanced-force ratio not < %g within %d steps (damping %g)"
            % (d_fail, 100 * mass_fraction, max_steps, tol, patience * max_steps, damping))
    pngs = {}

    def run(F):
        if calibration is not None:
            try:
                calibration.joint_strength(soil[0] / F, math.tan(soil[1]) / F)
            except ValueError as e:
                raise RuntimeError("strength_reduction: trial F = %.4g is outside the calibration (%s); bracket so far: "
                                   "stable %s, failed %s; trials: %s" % (F, e, lo, hi, "; ".join(str(t) for t in trials))) \
                    from None
        try:
            t = trial(F, ref, mark, png=("%s_F%.4f.png" % (png, F)) if png else None, **kw)
        except RuntimeError as e:  # a report of the plugin stopped the run (a sliver spinning off, say)
            raise RuntimeError("strength_reduction: trial F = %.4g was stopped at step %d: %s. A block the model "
                               "cannot follow (named on stderr: a sliver? the builders' min_area) ends the strength "
                               "reduction; the trials before it: %s" % (F, O.iter, e, "; ".join(str(t) for t in trials)
                                                                        or "none")) from None
        pngs[F] = [t.png, t.png_plastic]
        return t
    try:
        lo = hi = None
        F = float(start)
        while lo is None or hi is None:
            if len(trials) >= max_trials:
                Fs = [t.F for t in trials]
                side = (("every trial stable, up to F = %.4g: no mechanism found (e.g. a pattern of only horizontal "
                         "and vertical joints stands as columns whatever the friction; see "
                         "docs/slope_factor_of_safety.md)" % max(Fs))
                        if lo is not None else ("every trial failed, down to F = %.4g: the reference state is not "
                                                "stable at any strength" % min(Fs)))
                raise RuntimeError("strength_reduction: no bracket after %d trials, %s (%s; reference state's "
                                   "unbalanced-force ratio %.2e)" % (len(trials), side, crit, r0))
            t = run(F)
            trials.append(t)
            if t.failed:
                hi = F if hi is None else min(hi, F)
                F = F / grow
            else:
                lo = F if lo is None else max(lo, F)
                F = F * grow
        while hi - lo > rtol * lo and len(trials) < max_trials:
            F = 0.5 * (lo + hi)
            t = run(F)
            trials.append(t)
            if t.failed:
                hi = F
            else:
                lo = F
    finally:
        O.loadTmp(mark)
        if png:
            _keep_bracket_pngs(png, pngs, lo, hi)
        stepper = time_stepper()  # (the loaded scene's)
        if stepper is not None:
            stepper.densityScaling = old_scaling
    result = SRResult(0.5 * (lo + hi), lo, hi, trials, crit, r0, _warnings(trials, lo, hi, d_fail, patience * max_steps))
    if verbose:
        for w in result.warnings:
            print("  strength reduction: WARNING: " + w, flush=True)
    return result


def _warnings(trials, lo, hi, d_fail, max_steps):
    """Where the bracket's ends are set by the failure criterion's parameters rather than by a
    mechanism: a failed end that did not converge within *max_steps* while nothing ran away, and a
    stable end that moved more than half of *d_fail*."""
    out = []
    t_hi = next((t for t in trials if t.F == hi and t.failed), None)
    t_lo = next((t for t in trials if t.F == lo and not t.failed), None)
    if t_hi is not None and t_hi.reason == "not converged" and t_hi.dmax < d_fail:
        out.append("the failed end F = %.4f only did not converge within %d steps (patience x max_steps; unbalanced ratio %.2e, "
                   "largest displacement %.3g m < d_fail = %g m): nothing ran away, and a slope still settling "
                   "slowly fails the same way; a longer max_steps may raise the FS"
                   % (t_hi.F, max_steps, t_hi.ratio, t_hi.dmax, d_fail))
    if t_lo is not None and t_lo.dmax > 0.5 * d_fail:
        out.append("the stable end F = %.4f moved %.3g m, more than half of d_fail = %g m, before it stopped: the FS "
                   "depends on d_fail here (a smaller one finds the onset of sliding, which limit equilibrium "
                   "gives; a larger one lets the slope move and stop, by hardening or jamming, before it counts as "
                   "failed)" % (t_lo.F, t_lo.dmax, d_fail))
    return out


def _check_rotation(ids, limit, mass_fraction, verbose):
    """ValueError if the blocks of *ids* that have rotated by more than *limit* [rad] since they were
    built weigh more than *mass_fraction* of them (the runaway criterion's share: a lone block that
    rolled off the face is local, and only reported)."""
    from yade import O
    from .slope_scene import _built_poses
    built = _built_poses()  # (not refPos, refOri: a script or SlopeModel.settle resets displacements)
    turned, total, mass = [], 0.0, 0.0
    for i in ids:
        s = O.bodies[i].state
        angle = _turned(built(i)[1], s.ori)
        total += s.mass
        if angle > limit:
            turned.append((angle, i))
            mass += s.mass
    if not turned:
        return
    angle, k = max(turned)
    s = O.bodies[k].state
    what = ("%d block(s) weighing %.2g %% of the monitored mass have rotated by more than reference_rotation = %.3g rad "
            "since they were built, block #%d by %.1f deg (it moved %.3g m)"
            % (len(turned), 100 * mass / total, limit, k, math.degrees(angle), (s.pos - built(k)[0]).norm()))
    if total > 0 and mass > mass_fraction * total:
        raise ValueError("strength_reduction: the reference state is not the slope that was built: %s: it toppled or "
                         "tumbled while settling (settle with stronger joints, a shorter step or stiffer blocks), or "
                         "pass reference_rotation=None to reduce this state as it is" % what)
    if verbose:
        print("  strength reduction: local in the reference state: %s" % what, flush=True)


def _reference_ratio(mark, ids):
    """Unbalanced-force ratio of the saved reference state at its own strengths: one step from it
    (O.forces is not saved, and may be stale: forces of strengths changed since), then the state
    is reloaded."""
    from yade import O
    from .scene import advance
    from .slope import unbalanced_ratio
    O.loadTmp(mark)
    advance(1)
    r = unbalanced_ratio(ids=set(ids) if ids is not None else None)
    O.loadTmp(mark)
    return r


def _keep_bracket_pngs(png, pngs, lo, hi):
    """<png>_stable.png and <png>_failed.png (and their _plastic twins) from the bracket's trials; the other
    trials' drawings go."""
    import os
    for F, paths in pngs.items():
        for path, twin in zip(paths, ("", "_plastic")):
            if not path:
                continue
            if F == lo:
                os.replace(path, png + "_stable%s.png" % twin)
            elif F == hi:
                os.replace(path, png + "_failed%s.png" % twin)
            else:
                os.remove(path)
