"""Frozen contact kinematics (Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance > 0; pkg/rbsm/kernel/FrozenContact.hpp).

The speed option must keep the verification answers of the exact geometry. For updateTolerance = 1e-4 and
1e-3, the scenes of test_incline, test_energy and test_bar are run again and compared with the same closed
forms and tolerances:
* block on an incline: sticks at ψ = 25° < φ; slides with a = g(sinψ − cosψ tanφ) within 1 % at 35° and 40°;
* undamped elastic impact: kinetic + elastic energy constant within 1 %, rebound at ±v0 within 1 %;
* friction: the law's plastDissip equals the kinetic energy lost within 2 %, sliding distance v0²/(2 g tanφ)
  within 2 %;
* long-wave speed √(E′/ρ) of a bonded bar within 3 %.
A staggered wall of 45 bricks settled under gravity (tests/physics/scenes/wall.py) adds two comparisons:
* frictional joints: the base carries the whole weight (static equilibrium) within 1e-6;
* bonded joints (a linear elastic structure, whose equilibrium is unique): every joint's normal force equals
  the exact geometry's within 3·tol (relative, joints carrying more than 1 % of the largest force): the
  frozen contact length lags the exact one by at most the relative motion tol·(block diameter)
  (FrozenContact.hpp), i.e. 2.2·tol of a 0.2 m joint here; overlaps are second order.
Every scene must actually use the frozen kinematics (share of contact-steps with RbsmGeom.frozenSteps > 0
printed, and required above 50 % where the blocks move slowly).
"""
from math import radians, tan, sqrt

import pytest

from conftest import run_scene
from test_incline import a_closed_form, PHI

TOLS = [1e-4, 1e-3]


@pytest.mark.parametrize("ut", TOLS)
def test_incline_sticks_and_slides_with_closed_form(ut):
    r = run_scene("incline", {"psi": 25, "phi": PHI, "ut": ut})
    print("ut=%g psi=25: disp %g a %g frozen share %.3f" % (ut, r["disp"], r["a"], r["frozen_share"]))
    assert abs(r["disp"]) < 1e-3 and abs(r["a"]) < 1e-3
    assert r["frozen_share"] > 0.5
    for psi in (35, 40):
        r = run_scene("incline", {"psi": psi, "phi": PHI, "ut": ut})
        a_cf = a_closed_form(psi)
        print("ut=%g psi=%g: a_num=%.6g a_cf=%.6g rel.err=%.2e frozen share %.3f" % (ut, psi, r["a"], a_cf, r["a"] / a_cf - 1, r["frozen_share"]))
        assert r["a"] == pytest.approx(a_cf, rel=0.01)
        assert r["frozen_share"] > 0


@pytest.mark.parametrize("ut", TOLS)
def test_elastic_impact_conserves_energy(ut):
    r = run_scene("energy", {"mode": "impact", "ut": ut})
    E0 = r["E0"]
    dev = max(abs((k + e) / E0 - 1) for k, e in zip(r["ke"], r["el"]))
    print("ut=%g: max |KE+Eel-E0|/E0 = %.3e, v after %g %g, frozen share %.3f" % (ut, dev, r["vA"], r["vB"], r["frozen_share"]))
    assert sum(r["contact"]) > 100 and not r["contact"][-1]
    assert dev < 0.01
    assert r["vA"] == pytest.approx(-1.0, rel=0.01) and r["vB"] == pytest.approx(1.0, rel=0.01)
    assert r["frozen_share"] > 0


@pytest.mark.parametrize("ut", TOLS)
def test_friction_dissipation_equals_lost_kinetic_energy(ut):
    r = run_scene("energy", {"mode": "friction", "xi": 0.3, "xi_slide": 0.0, "ut": ut})
    d = r["d"]
    dist_cf = 1.0 / (2 * 9.81 * tan(radians(30)))
    print("ut=%g: KE lost %.6g J, plastDissip %.6g J (rel.err %.2e), dist %.6g vs %.6g, frozen share %.3f" % (
        ut, r["ke_lost"], d["plastDissip"], d["plastDissip"] / r["ke_lost"] - 1, r["dist"], dist_cf, r["frozen_share"]))
    assert r["ke_lost"] > 0.99 * r["ke0"]
    assert d["plastDissip"] == pytest.approx(r["ke_lost"], rel=0.02)
    assert r["dist"] == pytest.approx(dist_cf, rel=0.02)
    assert r["frozen_share"] > 0


@pytest.mark.parametrize("ut", TOLS)
def test_long_wave_speed(ut):
    E, NU, RHO = 1e8, 0.2, 2000.0
    r = run_scene("bar", {"mode": "mode1", "E": E, "nu": NU, "rho": RHO, "N": 100, "ut": ut})
    t1, t2 = r["crossings"][:2]
    c_num, c_cf = 2 * r["L"] / (2 * (t2 - t1)), sqrt(E / (1 - NU ** 2) / RHO)
    print("ut=%g: c_num=%.6g c_cf=%.6g rel.err=%.2e frozen share %.3f" % (ut, c_num, c_cf, c_num / c_cf - 1, r["frozen_share"]))
    assert r["n_inter"] == 99 and r["n_intact"] == 99
    assert c_num == pytest.approx(c_cf, rel=0.03)
    assert r["frozen_share"] > 0.5


WALL = {"steps": 4000, "dt": 1e-4}


@pytest.mark.parametrize("ut", TOLS)
def test_frictional_wall_base_carries_the_weight(ut):
    r = run_scene("wall", dict(WALL, ut=ut))
    print("ut=%g: reaction %.9g N, weight %.9g N, frozen share %.3f" % (ut, -r["reaction"], r["weight"], r["frozen_share"]))
    assert -r["reaction"] == pytest.approx(r["weight"], rel=1e-6)
    assert r["frozen_share"] > 0.5


@pytest.fixture(scope="module")
def bonded_wall_exact():
    return run_scene("wall", dict(WALL, bonded=True, ut=0.0))


@pytest.mark.parametrize("ut", TOLS)
def test_bonded_wall_joint_forces_match_exact_geometry(ut, bonded_wall_exact):
    ex = bonded_wall_exact
    r = run_scene("wall", dict(WALL, bonded=True, ut=ut))
    assert set(r["fn"]) == set(ex["fn"])
    fmax = max(abs(f) for f in ex["fn"].values())
    rel = max(abs(r["fn"][k] - f) / abs(f) for k, f in ex["fn"].items() if abs(f) > 0.01 * fmax)
    print("ut=%g: %d joints, largest relative difference of the normal forces %.3e (bound 3 tol = %.1e), frozen share %.3f"
          % (ut, len(ex["fn"]), rel, 3 * ut, r["frozen_share"]))
    assert -r["reaction"] == pytest.approx(r["weight"], rel=1e-6)
    assert rel <= 3 * ut
    assert r["frozen_share"] > 0.9


@pytest.mark.parametrize("ut", TOLS)
def test_runout_as_with_the_exact_geometry(ut):
    """Issue 34, item 9: the runout of a 1 x 0.5 m block sliding 10 m down a 30° incline onto a flat (contact
    damping 0.3; scenes/runout.py) with updateTolerance in the verified range is the exact geometry's within
    0.5 % (measured: 1e-4 -0.01 %, 1e-3 -0.06 %; beyond it, refused: 3e-3 +0.6 %, 1e-2 -5.2 % with +2.6 % of
    the work of gravity gained, 0.09 -30 % and +261 %)."""
    exact = run_scene("runout", {"L": 1, "H": 0.5, "xi": 0.3})
    r = run_scene("runout", {"L": 1, "H": 0.5, "xi": 0.3, "ut": ut})
    print("ut=%g: runout %.4f m, exact %.4f m (%+.3f %%)" % (ut, r["runout"], exact["runout"], 100 * (r["runout"] / exact["runout"] - 1)))
    assert r["stopped"] and r["runout"] == pytest.approx(exact["runout"], rel=5e-3)

