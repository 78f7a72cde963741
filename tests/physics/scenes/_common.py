"""Shared pieces of the physics scenes (imported inside a yade script: yade's names are passed in)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from yadescene import MARKER, emit, params  # noqa: E402,F401 (re-exported to the scenes)


def kinetic_energy(O, ids=None):
    """Σ ½ m v² + ½ I ω² (planar: I = inertia[2], ω = angVel[2]) of the non-fixed bodies."""
    e = 0.0
    for b in O.bodies:
        if ids is not None and b.id not in ids:
            continue
        s = b.state
        if s.blockedDOFs == "xyzXYZ":
            continue
        e += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * s.inertia[2] * s.angVel[2] ** 2
    return e


def lsq_slope(t, v):
    """Least-squares slope of v(t)."""
    n = len(t)
    mt, mv = sum(t) / n, sum(v) / n
    return sum((a - mt) * (b - mv) for a, b in zip(t, v)) / sum((a - mt) ** 2 for a in t)


class FrozenShare:
    """Share of the contact-steps that used frozen kinematics (RbsmGeom.frozenSteps > 0, i.e.
    Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance > 0): call sample(O) after each step."""

    def __init__(self):
        self.frozen = self.total = 0

    def sample(self, O):
        for i in O.interactions:
            if i.isReal:
                self.total += 1
                self.frozen += i.geom.frozenSteps > 0

    def share(self):
        return self.frozen / self.total if self.total else 0.0
