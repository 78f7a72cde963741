"""A block on a YADE Wall and on a YADE Facet behaves like a block on a fixed Polygon2D (issue 17):
Ig2_Polygon2D_Wall_RbsmGeom, Ig2_Polygon2D_Facet_RbsmGeom, the RBSM joint and Law2_RbsmGeom_RbsmPhys_MohrCoulomb.

The incline of tests/physics/test_incline.py (block 4 x 0.5 m, φ = 30°, gravity tilted by ψ, contact damping
0.3) with the ground a fixed block, a wall (axis 1) or a vertical facet crossing the plane, of RbsmMat or
FrictMat:
* slides at ψ = 35°, 40° with a = g(sin ψ − cos ψ tan φ) within 1 %, and within 0.1 % of the block-on-block
  run (the joint springs differ: the rigid boundary adds no compliance, kn = E′/h1 against E′/(h1 + h2));
* sticks at ψ = 25° (displacement below 1 mm, no acceleration);
* the joint is an RbsmGeom/RbsmPhys over the whole 4 m; the forces on block and boundary are an equal and
  opposite pair whose moments about the origin cancel (1e-9 of the scale) at the last step.
"""
import functools
from math import radians, sin, cos, tan

import pytest
from verification import record

from conftest import run_scene

G, PHI = 9.81, 30.0
GROUNDS = [("wall", "rbsm"), ("wall", "frict"), ("facet", "rbsm"), ("facet", "frict")]


@functools.lru_cache(maxsize=None)
def block_on_block(psi):
    return run_scene("boundary", {"ground": "block", "psi": psi, "phi": PHI})


def a_closed_form(psi):
    return G * (sin(radians(psi)) - cos(radians(psi)) * tan(radians(PHI)))


@pytest.mark.parametrize("psi", [35, 40])
@pytest.mark.parametrize("ground,mat", GROUNDS)
def test_slides_like_a_block_on_a_block(ground, mat, psi):
    ref = block_on_block(psi)
    r = run_scene("boundary", {"ground": ground, "groundMat": mat, "psi": psi, "phi": PHI})
    a = a_closed_form(psi)
    print(ground, mat, psi, "a", r["a"], "block on block", ref["a"], "closed form", a)
    assert r["geom"] == "RbsmGeom" and r["phys"] == "RbsmPhys" and abs(r["length"] - 4) < 1e-6, r
    record("Blocks with YADE's bodies", "a block sliding on a %s (%s), ψ %g°: acceleration" % (ground, mat, psi), r["a"], a,
           "g (sin ψ − cos ψ tan φ)", rtol=0.01, unit="m/s²")
    assert abs(r["a"] - a) < 0.01 * a
    assert abs(r["a"] - ref["a"]) < 1e-3 * a
    bal = r["balance"]
    assert bal["fsum"] < 1e-9 * bal["fscale"] and bal["msum"] < 1e-9 * bal["mscale"], bal


@pytest.mark.parametrize("ground,mat", GROUNDS)
def test_sticks_below_the_friction_angle(ground, mat):
    r = run_scene("boundary", {"ground": ground, "groundMat": mat, "psi": 25, "phi": PHI})
    print(ground, mat, r)
    assert r["geom"] == "RbsmGeom"
    assert abs(r["disp"]) < 1e-3 and abs(r["a"]) < 1e-3, r


def test_mixed_engines_run_a_block_on_a_wall():
    r = run_scene("boundary", {"ground": "wall", "groundMat": "frict", "psi": 35, "phi": PHI, "engines": "mixed"})
    a = a_closed_form(35)
    print(r, a)
    assert abs(r["a"] - a) < 0.01 * a
