"""Uniform-strain patch tests on a 4 x 4 grid of bonded unit square blocks (issue 3 "patch tests").

An affine displacement field (translation of each block centroid, no block rotation) is imposed in one
step (positions X + u(X), velocities u/dt since the shear spring is incremental) with no integrator, and
the joint tractions are compared with the continuum ones, for plane strain and plane stress
(E = 3e10, ν = 0.25):
* uniaxial strain ε_xx = ε, ε_yy = 0: σn = −E′ε on joints normal to x (compression positive, so a
  compressive ε < 0 gives σn = E′|ε| > 0; a tensile ε gives tension, the joints are bonded with
  σt = 1 GPa), σn = 0 on joints normal to y, τ = 0 everywhere;
  E′ = E/(1−ν²) (plane stress), E(1−ν)/((1+ν)(1−2ν)) (plane strain) - Kawai's kn = E′/(h1+h2).
* pure shear γ (u = (γ/2·y, γ/2·x)): |τ| = Gγ, G = E/(2(1+ν)), on every joint, σn = 0.
Tolerance: relative 1e-9 of the expected traction (round-off), absolute 1e-9·E′|ε| for zero tractions.
Corner-to-corner neighbours (diagonal blocks) may form contacts of tiny length: under uniaxial strain
they must carry no traction; under pure shear the anti-diagonal squares really overlap at their corners
by γa/2 (rigid blocks), so those contacts (length ≤ γa) are only checked to stay that small.
"""
import pytest

from conftest import run_scene

E, NU = 3e10, 0.25


def e_prime(plane_strain):
    return E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) if plane_strain else E / (1 - NU ** 2)


def edge_joints(r):
    full = [j for j in r["joints"] if j["length"] > 0.5]
    assert r["n0"] >= 24 and len(full) == 24, "4x4 grid must have 24 edge joints"
    return full, [j for j in r["joints"] if j["length"] <= 0.5]


@pytest.mark.parametrize("plane_strain", [True, False], ids=["plane_strain", "plane_stress"])
@pytest.mark.parametrize("eps", [-1e-4, 2e-5], ids=["compression", "tension"])
def test_uniaxial_strain(plane_strain, eps):
    r = run_scene("patch", {"mode": "uniaxial", "strain": eps, "planeStrain": plane_strain, "E": E, "nu": NU})
    full, small = edge_joints(r)
    expected = -e_prime(plane_strain) * eps
    zero = 1e-9 * abs(expected)
    worst = 0.0
    for j in full:
        if abs(j["normal"][0]) > 0.5:     # joint normal to x
            for s in j["sn"]:
                worst = max(worst, abs(s / expected - 1))
                assert s == pytest.approx(expected, rel=1e-9), j
        else:                              # joint normal to y
            assert all(abs(s) <= zero for s in j["sn"]), j
        assert all(abs(t) <= zero for t in j["tau"]), j
        assert all(j["intact"]), j
    for j in small:
        assert all(abs(s) <= zero for s in j["sn"] + j["tau"]), j
    print("E'=%.6g expected sigma_n=%.6g worst relative error %.2e" % (e_prime(plane_strain), expected, worst))


@pytest.mark.parametrize("plane_strain", [True, False], ids=["plane_strain", "plane_stress"])
def test_pure_shear(plane_strain):
    gamma = 1e-4
    r = run_scene("patch", {"mode": "shear", "strain": gamma, "planeStrain": plane_strain, "E": E, "nu": NU})
    full, small = edge_joints(r)
    expected = E / (2 * (1 + NU)) * gamma
    zero = 1e-9 * expected
    worst = 0.0
    for j in full:
        for t in j["tau"]:
            worst = max(worst, abs(abs(t) / expected - 1))
            assert abs(t) == pytest.approx(expected, rel=1e-9), j
        assert all(abs(s) <= zero for s in j["sn"]), j
    for j in small:
        # anti-diagonal neighbours overlap at their corners by γa/2 in pure shear (rigid squares, no
        # rotation): a genuine contact of length ≈ γa/2, not a joint of the patch; it must stay that small.
        assert j["length"] <= gamma, j
    print("G*gamma=%.6g worst relative error %.2e" % (expected, worst))
