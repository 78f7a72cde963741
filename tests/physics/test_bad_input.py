"""Bad input (issue 3 "Bad input"): every case of scenes/badinput.py must raise ValueError or
RuntimeError whose message names the problem (keywords below), and leave the scene unchanged:
len(O.bodies) the same before and after, and the existing block's vertices untouched.
Tried: non-convex, clockwise, repeated vertex, collinear vertices, zero area, 2 and 0 vertices, NaN and
inf vertex, density 0 / < 0 (RbsmMat constructor and set afterwards), thickness 0 / < 0 / NaN,
frictionAngle < 0, = 90°, = 100°, cohesion < 0, tensileStrength < 0, and clockwise vertices assigned to an
existing block's Polygon2D (its previous vertices must be kept)."""
from conftest import run_scene
from yadescene import bad_input_tests

KEYWORDS = {
    "nonconvex": ["convex"], "clockwise": ["clockwise"], "repeated": ["repeated", "degenerate"],
    "collinear": ["collinear", "degenerate"], "zero_area": ["degenerate", "area", "collinear"],
    "two_vertices": ["3 vertices"], "no_vertices": ["3 vertices"], "nan_vertex": ["nan"], "inf_vertex": ["inf"],
    "density_zero_ctor": ["density"], "density_negative_ctor": ["density"], "density_zero_set": ["density"],
    "thickness_zero": ["thickness"], "thickness_negative": ["thickness"], "thickness_nan": ["thickness"],
    "phi_negative": ["frictionangle"], "phi_90": ["frictionangle"], "phi_100": ["frictionangle"],
    "cohesion_negative": ["cohesion"], "tensile_negative": ["tensilestrength"], "reshape_clockwise": ["clockwise"],
}


def _unchanged(r):
    assert r["n1"] == r["n0"]
    assert r["shape_unchanged"], "the existing block's vertices were changed by the rejected assignment"


results, test_bad_input_rejected_scene_unchanged = bad_input_tests(run_scene, KEYWORDS, ("ValueError", "RuntimeError"),
                                                                   _unchanged)
