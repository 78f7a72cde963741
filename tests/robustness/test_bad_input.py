"""Bad input beyond tests/physics/test_bad_input.py (which covers non-convex, clockwise, repeated and
collinear vertices, zero area, 2 and 0 vertices, NaN/inf vertex, density 0/<0, thickness 0/<0/NaN,
friction angle <0/90°/100°, cohesion and tensile strength <0, reshaping clockwise).
scenes/badinput.py tries, on a scene with a base, two blocks and their joints (after one step):
self-intersecting (bow-tie) polygon; vertices a string, (x, y, z) triples, None; material None, a FrictMat,
an unknown label; thickness inf and "1"; a duplicate vertex; RbsmMat young NaN, inf, 0, < 0 (set later),
"1e8" (string); poisson 0.5, −1, NaN; density NaN, inf; frictionAngle NaN; cohesion NaN, inf; an existing
shape given off-centre vertices and thickness 0; RbsmTimeStepper safetyFactor 0, 1.5, NaN and interval 0;
Ig2 nIP 0 and 9, interactionDistance < 0, hysteresis < 0, updateTolerance < 0, NaN or > 1e-3 (issue 34, item 9: 0.01 and 0.09 ran, a runout off by −5 % and −30 %); Law2 dampingRatio < 0 and NaN (engine attributes
are checked when set). scenes/empty_vertices.py and the enlarge case run alone: they used to abort the
process (bugs 3 and 4, fixed).
Asserted per case: an exception (ValueError, TypeError or RuntimeError) whose message contains the
keywords below (the object/attribute and the problem), and the scene unchanged (bodies and real
interactions counted, positions (unless a step ran), every block's vertices).
Fixed bugs found by this file (kept as regression cases): 5 — an unknown material label raised
AttributeError from blocks.py; 6 — engine attributes (Ig2 nIP, interactionDistance, hysteresis, Law2
dampingRatio) were accepted silently; 3 — Polygon2D.vertices = [] was accepted and the next step aborted
YADE; 4 — Bo1_Polygon2D_Aabb.enlarge < 0 threw inside the collider's parallel loop (abort). All are now
refused when set, with a ValueError naming the attribute.
"""
import os
import subprocess

from conftest import run_scene, launcher, SCENES
from yadescene import bad_input_tests

KEYWORDS = {
    "poly_self_intersecting": ["degenerate", "self"], "poly_vertices_string": ["vertices"],
    "poly_vertices_triples": ["vertices"], "poly_vertices_none": ["vertices"],
    "poly_material_none": ["material"], "poly_material_frictmat": ["material", "rbsmmat"],
    "poly_material_bad_label": ["no-such-label"], "poly_thickness_inf": ["thickness"],
    "poly_thickness_string": ["thickness"], "poly_huge_duplicate": ["repeated"],
    "young_nan": ["young"], "young_inf": ["young"], "young_zero": ["young"], "young_negative_set": ["young"],
    "young_string": ["double", "young"], "poisson_half": ["poisson"], "poisson_minus_one": ["poisson"],
    "poisson_nan": ["poisson"], "density_nan": ["density"], "density_inf": ["density"], "phi_nan": ["frictionangle"],
    "cohesion_nan": ["cohesion"], "cohesion_inf": ["cohesion"], "shape_off_centre": ["centroid"],
    "shape_thickness_zero": ["thickness"], "timestepper_safety_0": ["safetyfactor"],
    "timestepper_safety_1_5": ["safetyfactor"], "timestepper_safety_nan": ["safetyfactor"],
    "timestepper_interval_0": ["interval"], "ig2_nIP_0": ["nip"], "ig2_nIP_9": ["nip"],
    "ig2_interactionDistance_negative": ["interactiondistance"], "ig2_hysteresis_negative": ["hysteresis"],
    "ig2_updateTolerance_negative": ["updatetolerance"], "ig2_updateTolerance_nan": ["updatetolerance"],
    "ig2_updateTolerance_large": ["updatetolerance"], "ig2_updateTolerance_unverified": ["updatetolerance", "0.001"],
    "law_dampingRatio_negative": ["dampingratio"], "law_dampingRatio_nan": ["dampingratio"],
}


def _unchanged(r):
    assert r["unchanged"]


results, test_bad_input_rejected_scene_unchanged = bad_input_tests(
    run_scene, KEYWORDS, ("ValueError", "RuntimeError", "TypeError"), _unchanged)


def run_alone(script_text_or_scene, tmp_path):
    p = subprocess.run([launcher(), "-n", "-x", script_text_or_scene], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, universal_newlines=True, timeout=120, cwd=str(tmp_path))
    return p.returncode, p.stdout


def test_empty_vertices_on_existing_shape(tmp_path):
    rc, out = run_alone(os.path.join(SCENES, "empty_vertices.py"), tmp_path)
    print(rc, out[-600:])
    assert "raised ValueError" in out and "Polygon2D.vertices" in out
    assert rc == 0


def test_bo1_enlarge_negative(tmp_path):
    f = tmp_path / "enlarge.py"
    f.write_text("from yade_rbsm import polygon2d, engines\n"
                 "m = RbsmMat(); O.materials.append(m)\n"
                 "O.bodies.append(polygon2d([(0,0),(1,0),(1,1),(0,1)], m))\n"
                 "try:\n    O.engines = engines(enlarge=-1.0)\n    O.step()\n    print('NO EXCEPTION')\n"
                 "except Exception as e:\n    print('raised', type(e).__name__, e)\n")
    rc, out = run_alone(str(f), tmp_path)
    print(rc, out[-600:])
    assert "raised" in out and "enlarge" in out
    assert rc == 0
