"""Bad input: each case below is tried on a scene holding one valid block; returns, per case, the
exception type and message (or None) and len(O.bodies) before and after.
Tried: non-convex, clockwise, repeated vertex, collinear vertices, all collinear (zero area), 2 and 0
vertices, NaN and inf vertex, density 0 and < 0 (in RbsmMat and set later), thickness 0, < 0 and NaN,
frictionAngle < 0, = 90°, > 90°, cohesion < 0, tensileStrength < 0, and setting clockwise vertices on an
existing block's shape (the old vertices must stay)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, nan, inf, pi
from _common import params, emit
from yade_rbsm import polygon2d

good = RbsmMat(young=1e8, poisson=0.2, density=2000)
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], good))
SQ = [(0, 2), (1, 2), (1, 3), (0, 3)]


def mat_set(**kw):
    m = RbsmMat(young=1e8, poisson=0.2, density=2000)
    for k, v in kw.items():
        setattr(m, k, v)
    return m


def reshape():
    s = O.bodies[0].shape
    try:
        s.vertices = [(-0.5, -0.5), (-0.5, 0.5), (0.5, 0.5), (0.5, -0.5)]
    finally:
        O.bodies[0].shape  # noqa
    return None


cases = {
    "nonconvex": lambda: O.bodies.append(polygon2d([(0, 2), (2, 2), (1, 2.5), (2, 4), (0, 4)], good)),
    "clockwise": lambda: O.bodies.append(polygon2d([(0, 2), (0, 3), (1, 3), (1, 2)], good)),
    "repeated": lambda: O.bodies.append(polygon2d([(0, 2), (1, 2), (1, 2), (1, 3), (0, 3)], good)),
    "collinear": lambda: O.bodies.append(polygon2d([(0, 2), (0.5, 2), (1, 2), (1, 3), (0, 3)], good)),
    "zero_area": lambda: O.bodies.append(polygon2d([(0, 2), (1, 2), (2, 2)], good)),
    "two_vertices": lambda: O.bodies.append(polygon2d([(0, 2), (1, 2)], good)),
    "no_vertices": lambda: O.bodies.append(polygon2d([], good)),
    "nan_vertex": lambda: O.bodies.append(polygon2d([(0, 2), (nan, 2), (1, 3), (0, 3)], good)),
    "inf_vertex": lambda: O.bodies.append(polygon2d([(0, 2), (1, 2), (1, inf), (0, 3)], good)),
    "density_zero_ctor": lambda: O.bodies.append(polygon2d(SQ, RbsmMat(young=1e8, density=0))),
    "density_negative_ctor": lambda: O.bodies.append(polygon2d(SQ, RbsmMat(young=1e8, density=-1))),
    "density_zero_set": lambda: O.bodies.append(polygon2d(SQ, mat_set(density=0))),
    "thickness_zero": lambda: O.bodies.append(polygon2d(SQ, good, thickness=0)),
    "thickness_negative": lambda: O.bodies.append(polygon2d(SQ, good, thickness=-1)),
    "thickness_nan": lambda: O.bodies.append(polygon2d(SQ, good, thickness=nan)),
    "phi_negative": lambda: O.bodies.append(polygon2d(SQ, RbsmMat(frictionAngle=-0.1))),
    "phi_90": lambda: O.bodies.append(polygon2d(SQ, RbsmMat(frictionAngle=pi / 2))),
    "phi_100": lambda: O.bodies.append(polygon2d(SQ, mat_set(frictionAngle=radians(100)))),
    "cohesion_negative": lambda: O.bodies.append(polygon2d(SQ, RbsmMat(cohesion=-1))),
    "tensile_negative": lambda: O.bodies.append(polygon2d(SQ, mat_set(tensileStrength=-1))),
    "reshape_clockwise": reshape,
}
out = {}
for name, f in cases.items():
    n0 = len(O.bodies)
    v0 = [tuple(v) for v in O.bodies[0].shape.vertices]
    try:
        f()
        exc = None
    except Exception as e:  # noqa: BLE001 - the test inspects the type
        exc = (type(e).__name__, str(e))
    out[name] = {"exc": exc, "n0": n0, "n1": len(O.bodies),
                 "shape_unchanged": [tuple(v) for v in O.bodies[0].shape.vertices] == v0}
emit(out)
