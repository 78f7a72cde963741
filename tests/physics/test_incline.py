"""Block on an incline (seed paper verification; issue 3 "Block on an incline").

The incline is modelled by tilting gravity by psi: g = (g sinψ, -g cosψ). Block 4 x 0.5 m (or 4 x 0.2 m
for the cohesive cases), density 2000, E = 1e8, ν = 0.2, on a fixed 100 x 1 m ground; contact damping
ξ = 0.3 (the normal bounce of the dropped block; shear damping is off while slipping), dt = 1e-5.

Closed forms compared:
* frictional (c = 0): sticks for ψ < φ (displacement below 1e-3 m, an elastic shear of the springs, and no
  acceleration); slides with a = g(sinψ − cosψ tanφ) within 1 % (a from a least-squares fit of the
  velocity over the second half of the run, so the start-up transient is excluded).
* cohesive bonded joint (c on ℓ = 4 m, unit thickness), gravity tilted slowly (quasi-static ramp):
  - whole-joint limit (the issue's): m g sinψc = c ℓ t + m g cosψc tanφ;
  - point-wise limit ψ1 ≤ ψc: the joint is integrated at 2 Gauss points and each point breaks (brittle,
    c → 0) when τ = c + σn tanφ at that point. The overturning moment of the tilted weight
    M = m g sinψ·H/2 makes the (linear) normal traction smaller at the upslope point,
    σn = N/ℓ − 2√3·M/ℓ² there (2-point Gauss rule, x = ±ℓ/(2√3)), so the first point breaks at ψ1, then
    the other one follows and the block slides.
  The test requires: holding (all points intact, displacement < 1e-3 m) at ψ1 − 2°, the first break
  within 0.5 % of ψ1 (ramp resolution ψ/500) and sliding (joint broken, displacement > 1 cm) at ψc + 2°.
"""
from math import radians, degrees, sin, cos, tan, sqrt

import pytest

from conftest import run_scene
from verification import record

G = 9.81
PHI = 30.0


def a_closed_form(psi, phi=PHI):
    return G * (sin(radians(psi)) - cos(radians(psi)) * tan(radians(phi)))


def bisect(f, lo=0.0, hi=radians(89)):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return degrees(lo)


def cohesive_limits(c, L, H, phi=PHI, rho=2000.0):
    W = rho * L * H * G
    t = tan(radians(phi))
    whole = bisect(lambda a: W * sin(a) - c * L - W * cos(a) * t)
    point = bisect(lambda a: W * sin(a) / L - c - t * (W * cos(a) / L - 2 * sqrt(3) * W * sin(a) * (H / 2) / L ** 2))
    return whole, point


def test_sticks_below_friction_angle():
    r = run_scene("incline", {"psi": 25, "phi": PHI})
    print("psi=25: disp", r["disp"], "a", r["a"])
    assert abs(r["disp"]) < 1e-3
    assert abs(r["a"]) < 1e-3


@pytest.mark.parametrize("psi", [35, 40])
def test_slides_with_closed_form_acceleration(psi):
    r = run_scene("incline", {"psi": psi, "phi": PHI})
    a_cf = a_closed_form(psi)
    print("psi=%g: a_num=%.6g a_cf=%.6g rel.err=%.2e" % (psi, r["a"], a_cf, r["a"] / a_cf - 1))
    record("Blocks and joints", "block sliding down a %g° incline, φ = %g°: acceleration" % (psi, PHI), r["a"], a_cf,
           "g (sin ψ − cos ψ tan φ)", rtol=0.01, unit="m/s²")
    assert r["a"] == pytest.approx(a_cf, rel=0.01)


def test_slides_with_closed_form_acceleration_four_points():
    """The same slide with nIP = 4: a joint of more than two points keeps them in a heap block of its own
    (RbsmPhys.morePoints), the law reads them there."""
    r = run_scene("incline", {"psi": 40, "phi": PHI, "nIP": 4})
    a_cf = a_closed_form(40)
    print("psi=40, nIP=4: a_num=%.6g a_cf=%.6g rel.err=%.2e" % (r["a"], a_cf, r["a"] / a_cf - 1))
    assert r["a"] == pytest.approx(a_cf, rel=0.01)


C, L, H = 787.0, 4.0, 0.2   # psi_c = 40.0 deg, psi_1 = 38.44 deg


def test_cohesive_joint_holds_below_limit():
    whole, point = cohesive_limits(C, L, H)
    psi = point - 2.0
    r = run_scene("incline", {"mode": "ramp", "psi": psi, "c": C, "L": L, "H": H, "ramp": 50000, "hold": 20000})
    print("psi=%.3f (psi1=%.3f, psic=%.3f):" % (psi, point, whole), r)
    assert r["broke_deg"] is None and r["nIntact"] == 2
    assert abs(r["disp"]) < 1e-3


def test_cohesive_joint_breaks_at_closed_form_tilt_and_slides():
    whole, point = cohesive_limits(C, L, H)
    psi = whole + 2.0
    r = run_scene("incline", {"mode": "ramp", "psi": psi, "c": C, "L": L, "H": H, "ramp": 50000, "hold": 20000})
    print("ramp to %.3f: first break at %s deg; point-wise closed form %.4f, whole-joint %.4f" % (psi, r["broke_deg"], point, whole), r)
    assert r["broke_deg"] is not None
    record("Blocks and joints", "a cohesive joint on a slowly tilted incline: tilt at the first break", r["broke_deg"], point,
           "point-wise Mohr–Coulomb limit", rtol=0.005, unit="°")
    assert r["broke_deg"] == pytest.approx(point, rel=0.005)
    assert r["broke_deg"] <= whole
    assert not r["nIntact"]
    assert r["disp"] > 0.01 and r["vel"] > 0
