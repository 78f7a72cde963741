"""A–B vs B–A (issue 3: "swapping the two bodies gives equal and opposite forces").

A 2 x 1 square and a triangle in contact, no gravity, with relative sliding/spinning velocities
(scenes/pair.py), built once with the square as body 0 and once with the triangle as body 0; 20 steps of
1e-5 s, then one step without the integrator. Compared:
* within a run: O.forces.f on the two bodies equal and opposite (relative 1e-9 of |f|);
* between the runs: the force and torque on the square (and the normal-force history) equal to relative
  1e-9 (the same physics, only the ids swapped; round-off level).
Cases: 'edge' (a slightly tilted triangle edge on the square's top edge) and 'vertex' (a triangle vertex
pressed 0.5 mm into the top edge). The 'vertex' case also checks that the joint keeps carrying a
compressive force while the blocks overlap (separation < 0) - a vertex-into-edge contact.
"""
import pytest

from conftest import run_scene


def rel(a, b, scale):
    return max(abs(x - y) for x, y in zip(a, b)) / scale


@pytest.mark.parametrize("case", ["edge", "vertex"])
def test_ab_ba_equal_and_opposite(case):
    ab = run_scene("pair", {"order": "AB", "case": case})
    ba = run_scene("pair", {"order": "BA", "case": case})
    for r in (ab, ba):
        assert r["n_inter"] == 1
        # overlapping all along: the contact must push the blocks apart at every step
        for k, h in enumerate(r["history"]):
            assert h is not None and h[1] < 0, (k, h)
            assert h[0] > 0, "step %d: blocks overlap (separation %g) but normal force is %g" % (k + 1, h[1], h[0])
        f = r["square"]["f"]
        scale = max(abs(c) for c in f)
        assert scale > 0
        assert rel(f, [-c for c in r["triangle"]["f"]], scale) < 1e-9
    fs = max(abs(c) for c in ab["square"]["f"])
    print("%s: |f| AB %.12g BA %.12g; normal force step 1: AB %.12g BA %.12g" % (
        case, fs, max(abs(c) for c in ba["square"]["f"]), ab["history"][0][0], ba["history"][0][0]))
    assert rel(ab["square"]["f"], ba["square"]["f"], fs) < 1e-9
    assert rel(ab["square"]["t"], ba["square"]["t"], max(1e-300, max(abs(c) for c in ab["square"]["t"]))) < 1e-9
    for ha, hb in zip(ab["history"], ba["history"]):
        assert ha[0] == pytest.approx(hb[0], rel=1e-9)
