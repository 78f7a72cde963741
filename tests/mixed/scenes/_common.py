"""Shared pieces of the mixed scenes (imported inside a yade script)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from yadescene import MARKER, emit, params  # noqa: E402,F401 (re-exported to the scenes)


def lsq_slope(t, v):
    """Least-squares slope of v(t)."""
    n = len(t)
    mt, mv = sum(t) / n, sum(v) / n
    return sum((a - mt) * (b - mv) for a, b in zip(t, v)) / sum((a - mt) ** 2 for a in t)


def pair_balance(O, id1, id2, x1, x2):
    """Force sum |F1 + F2| and moment sum about the origin |x1 × F1 + T1 + x2 × F2 + T2| (z only, the
    plane), with the scale max |F| and max |x × F + T|, of the forces YADE holds for two bodies after a
    step; x1, x2: the bodies' positions before it (where the law applied the forces)."""
    f1, f2, t1, t2 = O.forces.f(id1), O.forces.f(id2), O.forces.t(id1), O.forces.t(id2)
    m1, m2 = x1.cross(f1)[2] + t1[2], x2.cross(f2)[2] + t2[2]
    return {"fsum": (f1 + f2).norm(), "msum": abs(m1 + m2), "fscale": max(f1.norm(), f2.norm()), "mscale": max(abs(m1), abs(m2)),
            "f1": list(f1), "t1": list(t1)}
