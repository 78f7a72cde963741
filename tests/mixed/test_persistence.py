"""A saved mixed scene loads and goes on like the uninterrupted run (issue 17): a block sliding on a Wall
with a sphere on it and a sphere on a Facet (RbsmGeom/RbsmPhys on the wall, ScGeom/FrictPhys for the
spheres), O.save / O.load (xml and binary) at step 100 of 300, while everything slides: the same contacts of the same classes and
positions within 1e-9 m (the RBSM scenes' persistence test explains why not bitwise: YADE saves only the
real interactions and adds forces in another order after a load)."""
import pytest

from conftest import run_scene


@pytest.mark.parametrize("fmt", ["xml", "bin"])
def test_mixed_scene_continues_after_load(fmt):
    ref = run_scene("persist", {"steps": 300})
    r = run_scene("persist", {"steps": 300, "split": 100, "fmt": fmt})
    print(ref["classes"], r["classes"])
    assert r["iter"] == ref["iter"] == 300
    assert r["classes"] == ref["classes"]
    assert any("RbsmGeom" in c for c in r["classes"]) and any("ScGeom" in c for c in r["classes"])
    worst = max(abs(a - b) for p, q in zip(r["pos"], ref["pos"]) for a, b in zip(p, q))
    print("largest position difference", worst)
    assert worst < 1e-9
