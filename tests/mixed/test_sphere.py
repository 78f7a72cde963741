"""A YADE sphere on a Polygon2D block (issue 17): Ig2_Polygon2D_Sphere_ScGeom, Ip2_RbsmMat_FrictMat_FrictPhys
and YADE's Law2_ScGeom_FrictPhys_CundallStrack (sphericalBodies=False), against closed forms.

* rest: a sphere (r = 0.2 m, FrictMat or RbsmMat, explicit engines or mixed_engines()) dropped on a fixed
  block settles; the block carries its weight (1e-6), the normal is +y, kn is YADE's rule 2 k1 k2/(k1 + k2).
* incline: gravity tilted by ψ, the sphere's rotation blocked so that it slides: a = g(sin ψ − cos ψ tan φ)
  within 1 % (least squares over the second half of 4000 steps, 6.4 s); below φ it sticks (the
  elastic shear of the undamped spring, 2 m g sinψ/ks = 0.4 mm, and no acceleration).
* pair: a free block and a free sphere pressed together off-centre, sliding and spinning: the forces YADE
  holds for the two bodies are equal and opposite and their moments about the origin cancel (1e-9 of the
  scale), every step of 50; the block gets a torque.
"""
from math import radians, sin, cos, tan

import pytest

from conftest import run_scene

G = 9.81


@pytest.mark.parametrize("grain,engines", [("frict", "explicit"), ("rbsm", "explicit"), ("frict", "mixed")])
def test_sphere_resting_on_a_block_carries_its_weight(grain, engines):
    r = run_scene("sphere", {"mode": "rest", "grain": grain, "engines": engines})
    print(r)
    assert r["geom"] == "ScGeom" and r["phys"] == "FrictPhys" and r["id1"] == 0
    assert abs(r["fblock"][1] + r["weight"]) < 1e-6 * r["weight"], r
    assert abs(r["fblock"][0]) < 1e-9 * r["weight"]
    assert abs(r["normal"][1] - 1) < 1e-12
    assert abs(r["kn"] - r["kn_expected"]) < 1e-9 * r["kn_expected"]


@pytest.mark.parametrize("psi", [30, 40])
def test_sphere_slides_down_an_inclined_block(psi):
    r = run_scene("sphere", {"mode": "incline", "psi": psi, "phi": 20})
    a = G * (sin(radians(psi)) - cos(radians(psi)) * tan(radians(20)))
    print(psi, r, a)
    assert r["contact"]
    assert abs(r["a"] - a) < 0.01 * a, (r["a"], a)


def test_sphere_sticks_below_the_friction_angle():
    r = run_scene("sphere", {"mode": "incline", "psi": 15, "phi": 20})
    print(r)
    assert abs(r["a"]) < 1e-3 and abs(r["disp"]) < 1e-3, r


def test_sphere_block_forces_are_a_symmetric_pair():
    r = run_scene("sphere", {"mode": "pair"})
    print(r)
    assert r["fscale"] > 1.0 and abs(r["tblock"]) > 0
    assert r["fsum"] < 1e-9 * r["fscale"], r
    assert r["msum"] < 1e-9 * r["mscale"], r
