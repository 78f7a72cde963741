"""No silent pass-through (issue 17): pairs the dispatchers cannot handle are errors or reports, never an
abort or a silent pass-through.

* A hand-built Polygon2D with FrictMat: engines() raises ValueError naming the body; added after engines(),
  RbsmPairCheck reports the material pair without IPhys functor before the blocks touch, and without
  RbsmPairCheck Ig2_Polygon2D_Polygon2D_RbsmGeom refuses the contact; one ERROR naming both bodies and the
  material, the run stopped after that step (before issue 17: abort, "Undefined or ambiguous IPhys dispatch", rc 134).
* A Box falling on a block in mixed_engines(): RbsmPairCheck reports "Polygon2D and Box" once, naming the
  bodies and the missing functor, and stops the run (stopRun) or lets it go on (stopRun=False).
* A hand-written loop without Ig2_Polygon2D_Sphere_ScGeom: the sphere-block pair is reported the same way.
* A hand-written loop without Ip2_RbsmMat_FrictMat_FrictPhys: reported (and the run stopped) while the sphere
  falls towards the block, before the contact at which YADE would end the process (rc 134 before).
"""
from conftest import run_scene


def errors(out):
    return [l for l in out.splitlines() if "yade-rbsm: ERROR" in l]


def test_engines_refuse_a_block_without_rbsm_material():
    r = run_scene("dispatch", {"case": "hand_frict_before"})
    print(r)
    assert "Polygon2D bodies need an RbsmMat: body #1 (FrictMat)" in r["error"], r


def test_a_block_without_rbsm_material_is_reported_not_aborted():
    r, out = run_scene("dispatch", {"case": "hand_frict_after"}, output=True)
    e = errors(out)
    print(r, e)
    assert len(e) == 1 and "#1 (Polygon2D, FrictMat) are about to touch" in e[0] and "Ip2_RbsmMat_FrictMat_" in e[0], e
    assert r["iter"] < 2000, r
    # without RbsmPairCheck: the geometry functor refuses the contact
    r, out = run_scene("dispatch", {"case": "hand_frict_after", "pairCheck": False}, output=True)
    e = errors(out)
    print(r, e)
    assert len(e) == 1 and "bodies #0 and #1" in e[0] and "body #1 (a Polygon2D block) has a FrictMat" in e[0], e
    assert r["iter"] < 2000, r  # stopped after the step that met the pair


def test_block_next_to_a_box_is_reported_and_stops():
    r, out = run_scene("dispatch", {"case": "box"}, output=True)
    e = errors(out)
    print(r, e)
    assert r["reported"] == ["Polygon2D Box"], r
    assert len(e) == 1 and "Polygon2D and Box" in e[0] and "Ig2_Polygon2D_Box_" in e[0] and "#0" in e[0] and "#1" in e[0], e
    assert r["iter"] < 10000


def test_block_next_to_a_box_can_go_on():
    r, out = run_scene("dispatch", {"case": "box", "stopRun": False}, output=True)
    e = errors(out)
    print(r, e)
    assert len(e) == 1 and "the run goes on" in e[0], e
    assert r["iter"] == 10000 and r["y"] < -1, r  # reported once; the box fell through the block


def test_missing_geometry_functor_in_a_hand_written_loop():
    r, out = run_scene("dispatch", {"case": "no_ig2"}, output=True)
    e = errors(out)
    print(r, e)
    assert r["reported"] == ["Polygon2D Sphere"] and len(e) == 1 and "Ig2_Polygon2D_Sphere_" in e[0], (r, e)
    assert r["iter"] < 2000


def test_missing_physics_functor_in_a_hand_written_loop_is_reported_before_the_abort():
    r, out = run_scene("dispatch", {"case": "no_ip2"}, output=True)
    e = errors(out)
    print(r, e)
    assert r["reported"] == ["RbsmMat FrictMat"] and len(e) == 1, (r, e)
    assert "#0 (Polygon2D, RbsmMat) and #1 (Sphere, FrictMat) are about to touch" in e[0] and "Ip2_RbsmMat_FrictMat_" in e[0], e
    assert r["iter"] < 5000 and r["y"] > 0.2, r  # stopped before the contact
