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
   too if ``reduce_tensile``), sets ``refPos`` of the monitored blocks to their position and runs a
   damped stage (NewtonIntegrator ``damping``, default 0.7) in chunks of *check* steps.
3. **Failure criterion.** The trial *fails* if

   * the displacement of any monitored block (default: every free block) since the start of the
     trial exceeds ``d_fail`` (runaway), or
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

PyRunners in O.engines (monitor, VTK output) are switched off (``dead``) during the trials.
"""
import math
import time
from dataclasses import dataclass, field
from typing import List, Optional, Tuple

from .checks import count, number
from . import omega

__all__ = ["SRResult", "Trial", "strength_reduction", "trial", "reduce_strengths"]


@dataclass
class Trial:
    F: float
    failed: bool
    reason: str  # "converged", "runaway", "not converged"
    steps: int
    ratio: float
    dmax: float
    wall: float

    def __str__(self):
        return ("F = %.4f: %s (%s after %d steps, unbalanced ratio %.2e, max displacement %.3e m, %.1f s wall)"
                % (self.F, "FAILED" if self.failed else "stable", self.reason, self.steps, self.ratio, self.dmax,
                   self.wall))


@dataclass
class SRResult:
    fs: float
    lo: float  # largest stable F
    hi: float  # smallest failed F
    trials: List[Trial] = field(default_factory=list)
    criterion: str = ""

    def __str__(self):
        return ("strength reduction: FS = %.3f, bracket [%.4f stable, %.4f failed] after %d trials"
                % (self.fs, self.lo, self.hi, len(self.trials)))


class _Reference:
    """Strengths of the joints and materials of the reference state."""

    def __init__(self):
        from yade import O
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


def _free_ids():
    from yade import O
    return [b.id for b in omega.free_bodies(O)]


def _trial_args(where, F, tol, d_fail, max_steps, check, damping):
    return (number(where, "F", F, 0, low_open=True), number(where, "tol", tol, 0, low_open=True),
            number(where, "d_fail", d_fail, 0, low_open=True), count(where, "max_steps", max_steps),
            count(where, "check", check), number(where, "damping", damping, 0, 1, high_open=True))


def trial(F, ref, mark, ids=None, tol=1e-4, d_fail=0.05, max_steps=5000, check=100, damping=0.7,
          reduce_tensile=False, verbose=False):
    """One trial at factor *F* from the state saved under *mark* (see the module docstring).
    Returns a :class:`Trial`."""
    from yade import O, Vector3
    from .scene import advance
    from .slope import unbalanced_ratio
    F, tol, d_fail, max_steps, check, damping = _trial_args("trial", F, tol, d_fail, max_steps, check, damping)
    w0 = time.time()
    O.loadTmp(mark)
    omega.switch_off_pyrunners(O)
    omega.newton(O).damping = damping
    reduce_strengths(F, ref, reduce_tensile)
    ids = ids if ids is not None else _free_ids()
    start = {i: Vector3(O.bodies[i].state.pos) for i in ids}
    steps, ratio, dmax = 0, float("inf"), 0.0
    failed, reason = True, "not converged"
    below = 0
    while steps < max_steps:
        n = min(check, max_steps - steps)
        advance(n)
        steps += n
        dmax = max((O.bodies[i].state.pos - start[i]).norm() for i in ids)
        if dmax > d_fail:
            failed, reason = True, "runaway"
            break
        ratio = unbalanced_ratio()
        below = below + 1 if ratio < tol else 0
        if below >= 2:
            failed, reason = False, "converged"
            break
    t = Trial(F, failed, reason, steps, ratio, dmax, time.time() - w0)
    if verbose:
        print("  strength reduction trial " + str(t), flush=True)
    return t


def strength_reduction(start=1.0, grow=1.25, rtol=0.01, max_trials=30, ids=None, tol=1e-4, d_fail=0.05,
                       max_steps=5000, check=100, damping=0.7, reduce_tensile=False, verbose=True,
                       mark="rbsm_srm_reference", density_scaling=False):
    """Factor of safety by strength reduction on the current scene (see the module docstring).
    *density_scaling*: RbsmTimeStepper.densityScaling in every trial (fewer steps to the same
    equilibrium; restored at the end).

    *ids*: monitored blocks for the runaway criterion (default: all free blocks). Returns an
    :class:`SRResult`; raises RuntimeError if no bracket is found within *max_trials* trials."""
    from yade import O
    where = "strength_reduction"
    start, tol, d_fail, max_steps, check, damping = _trial_args(where, start, tol, d_fail, max_steps, check, damping)
    grow = number(where, "grow", grow, 1, low_open=True)
    rtol = number(where, "rtol", rtol, 0, low_open=True)
    max_trials = count(where, "max_trials", max_trials)
    from .scene import time_stepper
    stepper = time_stepper()
    if density_scaling and stepper is None:
        raise ValueError("strength_reduction: density_scaling needs RbsmTimeStepper in O.engines (yade_rbsm.engines())")
    old_scaling = stepper.densityScaling if stepper is not None else False
    if stepper is not None:
        stepper.densityScaling = bool(density_scaling)  # saved with the reference: on in every trial
    ref = _Reference()
    O.saveTmp(mark)
    trials = []
    kw = dict(ids=ids, tol=tol, d_fail=d_fail, max_steps=max_steps, check=check, damping=damping,
              reduce_tensile=reduce_tensile, verbose=verbose)
    crit = ("failure: displacement of a monitored block > %g m, or unbalanced-force ratio not < %g within %d "
            "steps (damping %g)" % (d_fail, tol, max_steps, damping))
    try:
        lo = hi = None
        F = float(start)
        while lo is None or hi is None:
            if len(trials) >= max_trials:
                raise RuntimeError("strength_reduction: no bracket after %d trials (%s)" % (len(trials), crit))
            t = trial(F, ref, mark, **kw)
            trials.append(t)
            if t.failed:
                hi = F if hi is None else min(hi, F)
                F = F / grow
            else:
                lo = F if lo is None else max(lo, F)
                F = F * grow
        while hi - lo > rtol * lo and len(trials) < max_trials:
            F = 0.5 * (lo + hi)
            t = trial(F, ref, mark, **kw)
            trials.append(t)
            if t.failed:
                hi = F
            else:
                lo = F
    finally:
        O.loadTmp(mark)
        stepper = time_stepper()  # (the loaded scene's)
        if stepper is not None:
            stepper.densityScaling = old_scaling
    return SRResult(0.5 * (lo + hi), lo, hi, trials, crit)
