"""The time stepper on a block joint with a Wall that is not fixed and has no mass (utils.wall gives it
none): next's RbsmTimeStepper counts the joints on walls (RbsmGeom, h2 = 0), and a free wall end without
mass made its Gershgorin estimate throw "free body needs mass > 0" at every step. As RbsmGeom's reduced
mass does, such a wall counts as infinite mass: a wall fixed in the plane only ('xyZ', 'xyzZ') gives the
same O.dt, criticalDt and motion as utils.wall's fixed one, and a wall with every DOF free still runs."""
import pytest

from conftest import run_scene


@pytest.mark.parametrize("dofs", ["xyzZ", "xyZ"])
def test_massless_wall_fixed_in_the_plane_is_a_fixed_wall(dofs):
    ref = run_scene("wall_dt", {})
    r = run_scene("wall_dt", {"wallDofs": dofs})
    print(ref, r)
    assert ref["blockedDOFs"] == "xyzXYZ" and r["blockedDOFs"] == dofs and r["wallMass"] == 0
    assert r["iter"] == ref["iter"] == 200 and r["finite"], r
    assert ref["criticalDt"] < float("inf") and r["criticalBody"] == ref["criticalBody"] == 1, r
    assert r["criticalDt"] == pytest.approx(ref["criticalDt"], rel=1e-12)
    assert r["dt"] == pytest.approx(ref["dt"], rel=1e-12)
    assert r["dy"] == pytest.approx(ref["dy"], rel=1e-9, abs=1e-12)


def test_massless_free_wall_does_not_stop_the_stepper():
    r = run_scene("wall_dt", {"wallDofs": ""})
    print(r)
    assert r["iter"] == 200 and r["finite"] and r["dt"] > 0, r
