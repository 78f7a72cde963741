"""Bad input beyond tests/physics/scenes/badinput.py: a scene of a fixed base and two blocks (one step run,
joints exist); each case sets a wrong value (and, for engine attributes, which are checked when used, runs
one O.step()); returns per case the exception (type, message) or None, and whether the scene is unchanged
(number of bodies and interactions, every position and the blocks' vertices).
Tried: see CASES in tests/robustness/test_bad_input.py."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
from yade_rbsm import polygon2d, engines

nan, inf = float("nan"), float("inf")
good = RbsmMat(young=1e8, poisson=0.2, density=2000)
O.materials.append(good)
O.bodies.append(polygon2d([(-2, -1), (3, -1), (3, 0), (-2, 0)], good, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], good))
O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], good))
O.engines = engines()
O.dt = 1e-5
O.engines[3].setDt = False
O.step()
SQ = [(0, 5), (1, 5), (1, 6), (0, 6)]
ig2o = O.engines[2].geomDispatcher.functors[0]
lawo = O.engines[2].lawDispatcher.functors[0]
bo1 = O.engines[1].boundDispatcher.functors[0]
tso = O.engines[3]


def snapshot():
    return (len(O.bodies), sum(1 for i in O.interactions if i.isReal),
            [tuple(b.state.pos) for b in O.bodies], [[tuple(v) for v in b.shape.vertices] for b in O.bodies])


def mat(**kw):
    return RbsmMat(**kw)


def setmat(**kw):
    m = RbsmMat(young=1e8)
    for k, v in kw.items():
        setattr(m, k, v)
    return m


def attr_step(obj, name, value):
    old = getattr(obj, name)
    try:
        setattr(obj, name, value)
        O.step()
    finally:
        setattr(obj, name, old)


def setattr_(obj, name, value):
    setattr(obj, name, value)


cases = {
    "poly_self_intersecting": lambda: O.bodies.append(polygon2d([(0, 5), (1, 6), (1, 5), (0, 6)], good)),
    "poly_vertices_string": lambda: O.bodies.append(polygon2d("abc", good)),
    "poly_vertices_triples": lambda: O.bodies.append(polygon2d([(0, 5, 0), (1, 5, 0), (1, 6, 0)], good)),
    "poly_vertices_none": lambda: O.bodies.append(polygon2d(None, good)),
    "poly_material_none": lambda: O.bodies.append(polygon2d(SQ, None)),
    "poly_material_frictmat": lambda: O.bodies.append(polygon2d(SQ, FrictMat())),
    "poly_material_bad_label": lambda: O.bodies.append(polygon2d(SQ, "no-such-label")),
    "poly_thickness_inf": lambda: O.bodies.append(polygon2d(SQ, good, thickness=inf)),
    "poly_thickness_string": lambda: O.bodies.append(polygon2d(SQ, good, thickness="1")),
    "poly_huge_duplicate": lambda: O.bodies.append(polygon2d([(0, 5), (1, 5), (1, 6), (1, 6), (0, 6)], good)),
    "young_nan": lambda: O.bodies.append(polygon2d(SQ, mat(young=nan))),
    "young_inf": lambda: O.bodies.append(polygon2d(SQ, mat(young=inf))),
    "young_zero": lambda: O.bodies.append(polygon2d(SQ, mat(young=0))),
    "young_negative_set": lambda: O.bodies.append(polygon2d(SQ, setmat(young=-1e8))),
    "young_string": lambda: O.bodies.append(polygon2d(SQ, mat(young="1e8"))),
    "poisson_half": lambda: O.bodies.append(polygon2d(SQ, mat(poisson=0.5))),
    "poisson_minus_one": lambda: O.bodies.append(polygon2d(SQ, mat(poisson=-1))),
    "poisson_nan": lambda: O.bodies.append(polygon2d(SQ, setmat(poisson=nan))),
    "density_nan": lambda: O.bodies.append(polygon2d(SQ, mat(density=nan))),
    "density_inf": lambda: O.bodies.append(polygon2d(SQ, mat(density=inf))),
    "phi_nan": lambda: O.bodies.append(polygon2d(SQ, mat(frictionAngle=nan))),
    "cohesion_nan": lambda: O.bodies.append(polygon2d(SQ, setmat(cohesion=nan))),
    "cohesion_inf": lambda: O.bodies.append(polygon2d(SQ, mat(cohesion=inf))),
    "shape_off_centre": lambda: setattr_(O.bodies[1].shape, "vertices", [(0, 0), (1, 0), (1, 1), (0, 1)]),
    "shape_thickness_zero": lambda: setattr_(O.bodies[1].shape, "thickness", 0),
    "timestepper_safety_0": lambda: attr_step(tso, "safetyFactor", 0.0),
    "timestepper_safety_1_5": lambda: attr_step(tso, "safetyFactor", 1.5),
    "timestepper_safety_nan": lambda: attr_step(tso, "safetyFactor", nan),
    "timestepper_interval_0": lambda: attr_step(tso, "interval", 0),
    "ig2_nIP_0": lambda: attr_step(ig2o, "nIP", 0),
    "ig2_nIP_9": lambda: attr_step(ig2o, "nIP", 9),
    "ig2_interactionDistance_negative": lambda: attr_step(ig2o, "interactionDistance", -1.0),
    "ig2_hysteresis_negative": lambda: attr_step(ig2o, "hysteresis", -1.0),
    "ig2_updateTolerance_negative": lambda: attr_step(ig2o, "updateTolerance", -1e-4),
    "ig2_updateTolerance_nan": lambda: attr_step(ig2o, "updateTolerance", nan),
    "ig2_updateTolerance_large": lambda: attr_step(ig2o, "updateTolerance", 0.5),
    "ig2_updateTolerance_unverified": lambda: attr_step(ig2o, "updateTolerance", 0.01),
    "law_dampingRatio_negative": lambda: attr_step(lawo, "dampingRatio", -0.5),
    "law_dampingRatio_nan": lambda: attr_step(lawo, "dampingRatio", nan),
}
out = {}
for name, f in cases.items():
    s0 = snapshot()
    it0 = O.iter
    try:
        f()
        exc = None
    except Exception as e:  # noqa: BLE001 - the test inspects the type and message
        exc = (type(e).__name__, str(e))
    s1 = snapshot()
    # a case that ran a step: positions move by the dynamics, compare counts and shapes only
    stepped = O.iter != it0
    unchanged = s0[0] == s1[0] and s0[1] == s1[1] and s0[3] == s1[3] and (stepped or s0[2] == s1[2])
    out[name] = {"exc": exc, "unchanged": unchanged, "stepped": stepped}
emit(out)
