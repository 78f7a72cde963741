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

Each stage is recorded (:class:`Stage`: its name, settings, figures, wall time) in ``O.tags``, so a
scene saved with ``O.save`` keeps its history: ``SlopeModel.resume()`` after ``O.load`` continues it.
The steps scripts wrote by hand (the bonding step, the friction held while settling, the damping
switched off for the dynamic stage, the progress line by simulated time) are inside the stages.
"""
import json
import time
from dataclasses import asdict, dataclass, field
from typing import Dict, List

from .checks import number

__all__ = ["Stage", "SlopeModel"]

_TAG = "yade_rbsm.stages"
_BLOCKS_TAG = "yade_rbsm.slope_blocks"


@dataclass
class Stage:
    name: str
    settings: Dict[str, object] = field(default_factory=dict)
    figures: Dict[str, object] = field(default_factory=dict)
    time: float = 0.0  # O.time at its end [s]
    wall: float = 0.0  # [s]

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
    def _record(self, name, settings, figures, w0):
        from yade import O
        st = Stage(name, settings, figures, O.time, time.time() - w0)
        self.stages.append(st)
        O.tags[_TAG] = json.dumps([asdict(s) for s in self.stages], default=str)
        return st

    @classmethod
    def resume(cls):
        """The model of the scene in O (after O.load): its stages and what fos() needs of its blocks."""
        from yade import O
        m = cls()
        if _TAG in O.tags.keys():
            m.stages = [Stage(**d) for d in json.loads(O.tags[_TAG])]
        if _BLOCKS_TAG in O.tags.keys():
            m.sb = _Blocks(json.loads(O.tags[_BLOCKS_TAG]))
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
        text = "\n".join(out) + "\n"
        if path:
            with open(path, "w") as f:
                f.write(text)
        return text

    # --- the stages -----------------------------------------------------------------------------
    def build(self, **engines_kw):
        """The blocks into O.bodies, ``O.engines = engines(**engines_kw)``, every joint bonded (the joint
        sets keep the rock's strength until :meth:`give_joint_sets`)."""
        from yade import O
        from . import slope
        from .scene import engines
        if self.sb is None or self.material is None:
            raise ValueError("SlopeModel.build: give the blocks and the material (SlopeModel(blocks, material))")
        w0 = time.time()
        slope.build_scene(self.sb, self.material, thickness=self.thickness)
        O.engines = engines(**engines_kw)
        joints, broken = slope.bond_and_break(self.sb, give_sets=False)
        O.tags[_BLOCKS_TAG] = json.dumps(dict(pattern=self.sb.pattern, surface=[list(p) for p in self.sb.surface],
                                              base=self.sb.base))
        return self._record("build", dict(engines_kw), dict(blocks=len(self.sb.free), joints=joints, broken=broken), w0)

    def settle(self, tol=1e-4, max_steps=100000, density_scaling=True, name="in-situ"):
        """Gravity to an unbalanced-force ratio below *tol* (:func:`slope.settle`, damped, with density
        scaling by default: the same equilibrium in fewer steps)."""
        from yade import O, Vector3
        from . import omega, slope
        w0 = time.time()
        free = omega.free_bodies(O)
        before = {b.id: Vector3(b.state.pos) for b in free}  # (a copy: state.pos is the body's own)
        ok, steps, ratio = slope.settle(tol=tol, max_steps=max_steps, check=200, density_scaling=density_scaling)
        moved = max(((O.bodies[i].state.pos - p).norm() for i, p in before.items()), default=0.0)
        size = sorted(2 * b.shape.circumradius for b in free)[len(free) // 2] if free else 0.0
        st = self._record(name, dict(tol=tol, density_scaling=density_scaling),
                          dict(converged=bool(ok), steps=steps, unbalanced=ratio, max_displacement=moved), w0)
        if not ok:
            print("SlopeModel.%s: not settled in %d steps (unbalanced-force ratio %.2e > %g): the slope may be failing "
                  "at these strengths" % (name, steps, ratio, tol), flush=True)
        elif moved > 0.1 * size:
            print("SlopeModel.%s: WARNING: settled, but a block moved %.3g m on the way (%.0f %% of the median block "
                  "size): the slope failed at these strengths and came to rest elsewhere" % (name, moved, 100 * moved / size),
                  flush=True)
        return st

    def give_joint_sets(self, tol=1e-4):
        """The joint sets' own strength (:func:`slope.give_joint_sets`), then equilibrium again."""
        from . import slope
        w0 = time.time()
        n = slope.give_joint_sets(self.sb) if getattr(self.sb, "joint_sets", None) else 0
        self._record("joint strengths", {}, dict(joints_given=n), w0)
        return self.settle(tol=tol, name="equilibrium")

    def set_water(self, phreatic, joints="sets", unit_weight=9810.0, settle=True):
        """Water in the joints (:func:`slope.set_water`), then equilibrium again (*settle*); recorded."""
        from . import slope
        w0 = time.time()
        wet = slope.set_water(phreatic, joints=joints, unit_weight=unit_weight)
        self._record("water", dict(phreatic=[list(p) for p in phreatic] if phreatic is not None else None, joints=joints),
                     dict(joints_wet=wet), w0)
        return self.settle(name="equilibrium") if settle and phreatic is not None else self.stages[-1]

    def set_seismic(self, kh, kv=0.0, towards=1, settle=True):
        """The pseudo-static load (:func:`slope.set_seismic`), then equilibrium under it (*settle*: a load
        applied at once would also shake the slope, twice the static effect on an elastic spring); recorded."""
        from . import slope
        w0 = time.time()
        g = slope.set_seismic(kh, kv=kv, towards=towards)
        st = self._record("pseudo-static", dict(kh=kh, kv=kv, towards=towards), dict(gravity=list(g)), w0)
        return self.settle(name="equilibrium") if settle else st

    def fos(self, **kw):
        """:func:`slope.fos` on the current state (the scene is left as it was); recorded."""
        from .fos import fos
        w0 = time.time()
        r = fos(self.sb, **kw)
        self._record("factor of safety", dict(kw), dict(fs=r.fs, method=r.method, conclusive=r.conclusive,
                                                        warnings=len(r.warnings)), w0)
        return r

    def run(self, duration, strength_factor=None, damping=0.0, progress=10.0, period=200):
        """Dynamic stage of *duration* [s] of simulated time with NewtonIntegrator *damping* (0: none),
        optionally with the joint sets' strength divided by *strength_factor* (a trigger); a progress line
        by simulated time. Recorded: the largest displacement and the mean of the free blocks'."""
        from yade import O
        from . import mpi, omega, slope
        from .monitor import Monitor
        duration = number("SlopeModel.run", "duration", duration, 0, low_open=True)
        w0 = time.time()
        if strength_factor is not None:
            slope.apply_joint_sets(F=strength_factor)
        omega.newton(O).damping = damping
        ids = [b.id for b in omega.free_bodies(O)]
        mon = Monitor(ids=[], period=period, progress=progress, reset=False)
        mon.target(time=duration)
        t_end = O.time + duration
        while O.time < t_end * (1 - 1e-12):  # as settle does: an error of a step raises (O.run can lose it)
            mpi.run(max(1, min(500, int((t_end - O.time) / O.dt) + 1)))
        d = [(O.bodies[i].state.pos - O.bodies[i].state.refPos).norm() for i in ids]
        return self._record("dynamic", dict(duration=duration, strength_factor=strength_factor, damping=damping),
                            dict(max_displacement=max(d) if d else 0.0, mean_displacement=sum(d) / len(d) if d else 0.0,
                                 steps=O.iter), w0)
