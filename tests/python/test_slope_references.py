"""Issue 21, the parts without YADE: a firm base at toe level (builders and circle search), Spencer's
method, and the Mohr-Coulomb fit of the calibration.

Reference slope: Griffiths & Lane (1999, Geotechnique 49(3), example 1): H = 10 m, 2:1 face, c' = 10
kPa, phi' = 20 deg, gamma = 20 kN/m3, firm base at toe level (D = 1); Bishop & Morgenstern's (1960)
charts give FS = 1.380, their finite-element strength reduction 1.4."""
import math

import pytest

from conftest import load_limit_equilibrium
from verification import record

le = load_limit_equilibrium()
from yade_rbsm import calibration, slope  # noqa: E402  (pure Python parts)

GL = [(0, 0), (12, 0), (32, 10), (52, 10)]


def _gl(phi=20.0):
    return le.Slope(GL, le.Layer(c=10.0, phi=phi, gamma=20.0))


def _search(s, **kw):
    return le.critical_circle(s, (10, 40), (10, 50), nx=16, ny=16, refine=3, r_range=(5, 60), nr=23, **kw)


def test_firm_base_at_toe_level_bishop_matches_the_charts():
    free = _search(_gl())
    based = _search(_gl(), base=0.0)
    record("Limit equilibrium", "Griffiths & Lane's 2:1 slope on a firm base: Bishop's critical circle", based.fs, 1.380,
           "slope stability charts (firm base at the toe)", rtol=0.005)
    assert based.fs == pytest.approx(1.380, rel=0.005), str(based)
    c = based.circle
    assert c.yc - c.R >= -1e-9 or not (based.best.slices.x_entry <= c.xc <= based.best.slices.x_exit)
    # without the base the search finds deeper circles, which are (slightly) more critical
    assert free.fs < based.fs and free.circle.yc - free.circle.R < -0.1


def test_spencer_equals_the_moment_methods_without_friction_and_is_close_to_bishop():
    circle = _search(_gl(), base=0.0).circle
    s0 = le.Slope(GL, le.Layer(c=10.0, phi=0.0, gamma=20.0))
    f = le.fellenius_circle(s0, circle).fs
    assert le.bishop_circle(s0, circle).fs == pytest.approx(f, rel=1e-12)
    assert le.spencer_circle(s0, circle).fs == pytest.approx(f, rel=1e-9)
    b, sp = le.bishop_circle(_gl(), circle), le.spencer_circle(_gl(), circle)
    assert sp.fs == pytest.approx(b.fs, rel=0.01)  # Spencer and Bishop within 1 % on circles
    assert sp.fs == pytest.approx(1.380, rel=0.01)
    assert "theta" in sp.notes


def test_spencer_refuses_a_circle_that_misses():
    with pytest.raises(ValueError):
        le.spencer_circle(_gl(), le.Circle(100.0, 50.0, 1.0))


@pytest.mark.parametrize("build", [
    lambda s: slope.brick_blocks(s, 0.0, 2.0, 1.0),
    lambda s: slope.column_blocks(s, 0.0, 2.0),
])
def test_builders_accept_a_firm_base_at_toe_level(build):
    sb = build(GL)
    area = sum(b.area for b in sb.free)
    assert area + sb.dropped_area == pytest.approx(300.0, rel=1e-12) and sb.slope_area == pytest.approx(300.0)
    assert all(b.area > 0 for b in sb.blocks)
    assert all(min(y for _, y in b.vertices) >= -1e-12 for b in sb.free)
    walls = [b for b in sb.blocks if b.kind == "wall"]
    assert len(walls) == 1 and min(x for x, _ in walls[0].vertices) == 52.0  # no zero-height wall at the toe


def test_builders_still_refuse_a_ground_below_or_on_the_base_inside():
    with pytest.raises(ValueError, match="above the base"):
        slope.brick_blocks([(0, 1), (10, 0), (20, 5)], 0.0, 2.0, 1.0)
    with pytest.raises(ValueError, match="above the base"):
        slope.brick_blocks([(0, 1), (10, -1), (20, 5)], 0.0, 2.0, 1.0)


def test_slope_polygon_leaves_out_the_toe_flat():
    poly = slope.slope_polygon(GL, 0.0)
    assert sorted(poly) == [(12.0, 0.0), (32.0, 10.0), (52.0, 0.0), (52.0, 10.0)]
    assert slope.polygon_area(poly) == pytest.approx(300.0)  # counter-clockwise


def test_mohr_coulomb_fit_recovers_c_and_phi():
    c, phi = 7e3, math.radians(33.0)
    kp = (1 + math.sin(phi)) / (1 - math.sin(phi))
    s3 = [1e4, 3e4, 6e4]
    s1 = [kp * x + 2 * c * math.sqrt(kp) for x in s3]
    cf, phif, kpf, q, misfit = calibration.fit_mohr_coulomb(s3, s1)
    assert cf == pytest.approx(c, rel=1e-9) and phif == pytest.approx(phi, rel=1e-9) and misfit < 1e-12
    with pytest.raises(ValueError, match="no friction"):
        calibration.fit_mohr_coulomb(s3, [5e4, 5e4, 5e4])
    with pytest.raises(ValueError, match="at least two"):
        calibration.fit_mohr_coulomb([1e4], [3e4])


def test_calibration_inverse_interpolates_and_refuses_outside():
    rows = []
    for tj in (0.01, 0.2, 0.4):
        for cj in (0.0, 5e3, 1e4):
            # a made-up linear map joint -> assembly: tan phi_M = 0.49 + 1.5 tan phi_j, c_M = 4 kPa + 0.8 c_j
            rows.append(dict(tan_phi_j=tj, c_j=cj, phi_macro=math.degrees(math.atan(0.49 + 1.5 * tj)),
                             c_macro=4e3 + 0.8 * cj, misfit=0))
    cal = calibration.Calibration(dict(cohesion=1e4), rows)
    cj, tj = cal.joint_strength(4e3 + 0.8 * 7e3, 0.49 + 1.5 * 0.3)  # linear interpolation of a linear map: exact
    assert cj == pytest.approx(7e3, rel=1e-9) and tj == pytest.approx(0.3, rel=1e-9)
    with pytest.raises(ValueError, match="outside the calibrated"):
        cal.joint_strength(1e4, math.tan(math.radians(20)))  # below the assemblies' 26 deg
