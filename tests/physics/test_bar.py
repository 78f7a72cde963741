"""A bar of blocks and a joint in tension (issue 3 "A column of blocks").

* Long-wave speed: a free-free bar of N = 100 bonded unit squares (E = 1e8, ν = 0.2, ρ = 2000, plane
  stress, no gravity) started in its fundamental mode, v_i = v0 cos(π x_i/L). The period of block 0's
  velocity (twice the time between its first two zero crossings) gives c_num = 2L/T, compared with the
  long-wave speed √(E′/ρ) within 3 % (the discrete chain's own dispersion error for this mode is
  1 − sin(π/2N)/(π/2N) ≈ 4e-5, so the check is much tighter than the tolerance in practice).
  Also checked: Kawai's joint stiffness kn·ℓ·t = E′·a·t/(h1+h2) = E′ for unit squares.
* Tension cut-off: one fixed and one kinematic block (thickness t = 0.5) joined by a bonded joint of
  σt = 1e5 Pa, ℓ = 1 m, pulled apart at 1e-2 m/s with dt = 1e-4 (the force grows by 1e-4 of its break
  value per step): the largest tension before the break equals σt·ℓ·t within 2 %; after the break the
  joint has no intact point (it is removed once open), and when pushed back into compression
  (it carries compression again) and pulled a second time it carries no tension at all.
"""
from math import sqrt

import pytest

from conftest import run_scene
from verification import record

E, NU, RHO = 1e8, 0.2, 2000.0


def test_long_wave_speed():
    r = run_scene("bar", {"mode": "mode1", "E": E, "nu": NU, "rho": RHO, "N": 100})
    e_prime = E / (1 - NU ** 2)
    c_cf = sqrt(e_prime / RHO)
    t1, t2 = r["crossings"][:2]
    T = 2 * (t2 - t1)
    c_num = 2 * r["L"] / T
    print("c_num=%.6g c_cf=%.6g rel.err=%.2e (T=%.6g s)" % (c_num, c_cf, c_num / c_cf - 1, T))
    record("Waves and elasticity", "rigid-block bar, 100 blocks: long-wave speed", c_num, c_cf, "√(E′/ρ), plane strain",
           rtol=0.03, unit="m/s")
    assert r["n_inter"] == 99 and r["n_intact"] == 99
    assert r["kn_l"] == pytest.approx(e_prime, rel=1e-9)
    assert c_num == pytest.approx(c_cf, rel=0.03)


def test_joint_opens_at_tensile_strength_and_stays_broken():
    st, t = 1e5, 0.5
    r = run_scene("bar", {"mode": "tension", "sigmaT": st, "thickness": t})
    print(r)
    assert r["intact0"] == [True, True]
    f_cf = st * r["length"] * r["thickness"]
    assert r["thickness"] == t and r["length"] == pytest.approx(1.0)
    print("max tension before break %.8g N vs sigma_t*l*t = %.8g N (rel.err %.2e)" % (r["maxT_before"], f_cf, r["maxT_before"] / f_cf - 1))
    assert r["broke_step"] is not None
    assert r["maxT_before"] == pytest.approx(f_cf, rel=0.02)
    # broken: no intact point left (or the open joint was removed)
    assert r["intact_after"] is None or not any(r["intact_after"])
    assert not r["intact_seen_after"]
    assert r["compression_after_push"] is not None and r["compression_after_push"] > 0
    assert r["maxT_after"] <= 1e-9 * f_cf
