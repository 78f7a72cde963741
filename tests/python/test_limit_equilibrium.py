"""Tests of py/yade_rbsm/limit_equilibrium.py (pure Python, no YADE).

Each test states what it compares.  Units: m, kN/m^3, kPa, kN/m.
"""

import math

import numpy as np
import pytest

from conftest import load_limit_equilibrium
from verification import record

le = load_limit_equilibrium()
Layer, Slope, Circle = le.Layer, le.Slope, le.Circle


def tand(a):
    return math.tan(math.radians(a))


# ---------------------------------------------------------------------------
# published worked example
# ---------------------------------------------------------------------------
def _verruijt_slope():
    # homogeneous slope, height 4.5 m, inclination 1:2 (vertical:horizontal),
    # on a 2 m foundation of the same soil (model 18 m wide, 6.5 m high);
    # toe at (0, 0), crest at (9, 4.5).  The source text does not give the
    # horizontal position of the slope inside the 18 m model: 4 m in front
    # of the toe and 5 m behind the crest are chosen here (the critical
    # circle, exiting ~1.3 m behind the crest, stays well inside).
    return Slope(
        [(-4.0, 0.0), (0.0, 0.0), (9.0, 4.5), (14.0, 4.5)],
        Layer(c=5.0, phi=20.0, gamma=16.0, name="slope"),
    )


def test_published_verruijt_bishop_critical_circle():
    """Published: code_aster validation manual V6.03.006 (test case ssnp006,
    "Reference problem" and "Benchmark solution" pages), which takes its
    reference from the Plaxis 2D verification case, itself citing Verruijt's
    simplified-Bishop program: homogeneous slope 4.5 m high, slope 1:2, model
    18 m x 6.5 m (2 m foundation), gamma = 16 kN/m^3, phi = 20 deg,
    c = 5 kPa, dry.  Bishop simplified with a grid of centres gives the
    critical FS = 1.534 (Plaxis SRM: 1.54).

    Compared: our critical Bishop FS over a grid of centres with the circle
    through the toe (and an unrestricted radius check on a coarser grid)
    must be within +-0.02 of 1.534.  The tolerance covers the unpublished
    slice count / grid of the reference program (about 1 %); the circle is
    not allowed below the 2 m foundation.
    """
    s = _verruijt_slope()
    toe = le.critical_circle(s, (-4, 10), (5, 16), nx=15, ny=15, through=(0.0, 0.0),
                             method="bishop", n=50, refine=3)
    record("Limit equilibrium", "Verruijt's 1:2 slope (code_aster ssnp006, Plaxis): Bishop's critical circle through the toe",
           toe.fs, 1.534, "Verruijt's simplified Bishop, as published", tolerance="±0.02")
    assert toe.fs == pytest.approx(1.534, abs=0.02)
    assert toe.best.slices.y_base.min() > -2.0  # stays in the 2 m foundation
    free = le.critical_circle(s, (-2, 8), (5, 14), nx=7, ny=7, r_range=(4, 16), nr=25,
                              method="bishop", n=50, refine=2)
    assert free.fs == pytest.approx(1.534, abs=0.02)
    # Fellenius is the more conservative method for this slope (known
    # property of the ordinary method for c-phi soils)
    fel = le.critical_circle(s, (-4, 10), (5, 16), nx=15, ny=15, through=(0.0, 0.0),
                             method="fellenius", n=50, refine=3)
    assert 1.3 < fel.fs < toe.fs


# ---------------------------------------------------------------------------
# closed forms
# ---------------------------------------------------------------------------
def _infinite_slope(beta, z, length, c, phi, gamma):
    t = math.tan(math.radians(beta))
    L = length
    ground = [(-1.0, -t), (L + 1.0, (L + 1.0) * t)]
    # slip surface parallel to the ground at vertical depth z, with short
    # steep end segments that daylight at x = 0 and x = L
    d = 0.05 * z  # horizontal extent of the end segments
    slip = [(0.0, 0.0), (d, d * t - z), (L - d, (L - d) * t - z), (L, L * t)]
    return Slope(ground, Layer(c=c, phi=phi, gamma=gamma)), slip


@pytest.mark.parametrize("beta,phi,c", [(20.0, 30.0, 0.0), (30.0, 35.0, 0.0), (25.0, 20.0, 8.0)])
def test_infinite_slope_limit(beta, phi, c):
    """Compares Fellenius on a long planar surface parallel to the ground
    (length/depth = 500) with the infinite-slope closed form
    FS = c / (gamma z cos^2(beta) tan(beta)) + tan(phi)/tan(beta) (dry).
    The end segments contribute O(z/L); tolerance 0.5 %."""
    z, gamma, L = 2.0, 18.0, 1000.0
    s, slip = _infinite_slope(beta, z, L, c, phi, gamma)
    r = le.fellenius_polyline(s, slip, n=200)
    b = math.radians(beta)
    exact = c / (gamma * z * math.cos(b) ** 2 * math.tan(b)) + tand(phi) / tand(beta)
    assert r.fs == pytest.approx(exact, rel=5e-3)


def _wedge(c=10.0, phi=30.0, gamma=20.0, **kw):
    # 45 deg slope, height 10 m, toe at (0,0), crest at (10,10); faces -x
    ground = [(-10.0, 0.0), (0.0, 0.0), (10.0, 10.0), (30.0, 10.0)]
    return Slope(ground, Layer(c=c, phi=phi, gamma=gamma), **kw)


def _wedge_hand(c, phi, gamma, u_l=0.0):
    # planar slip from the toe (0,0) to (20,10): theta = atan(1/2)
    th = math.atan2(10.0, 20.0)
    W = gamma * 0.5 * 10.0 * 10.0  # triangle (0,0),(10,10),(20,10): area 50 m^2
    L = math.hypot(20.0, 10.0)
    N = W * math.cos(th) - u_l
    T = W * math.sin(th)
    return (c * L + N * tand(phi)) / T, N, T


@pytest.mark.parametrize("c,phi", [(10.0, 30.0), (0.0, 35.0), (25.0, 0.0)])
def test_planar_wedge_hand_calculation(c, phi):
    """Compares fellenius_polyline on a single planar surface through a
    homogeneous 45-deg wedge with the hand calculation of the wedge
    (W = gamma * 50 m^2, FS = (c L + W cos(theta) tan(phi)) / (W sin(theta))),
    including the totals sum N' and sum T (exact: slices are trapezoids)."""
    s = _wedge(c=c, phi=phi)
    r = le.fellenius_polyline(s, [(0.0, 0.0), (20.0, 10.0)], n=37)
    fs, N, T = _wedge_hand(c, phi, 20.0)
    assert r.fs == pytest.approx(fs, rel=1e-10)
    assert r.normal == pytest.approx(N, rel=1e-10)
    assert r.shear == pytest.approx(T, rel=1e-10)
    assert r.n_slices >= 37


def test_planar_wedge_mirrored_gives_same_result():
    """The same wedge mirrored about x = 0 (slope facing +x) must give the
    same FS, sum N and sum T (sliding direction detected automatically)."""
    s = Slope([(-30.0, 10.0), (-10.0, 10.0), (0.0, 0.0), (10.0, 0.0)], Layer(10.0, 30.0, 20.0))
    r = le.fellenius_polyline(s, [(-20.0, 10.0), (0.0, 0.0)])
    fs, N, T = _wedge_hand(10.0, 30.0, 20.0)
    assert (r.fs, r.normal, r.shear) == pytest.approx((fs, N, T), rel=1e-10)
    assert r.slices.direction == +1


def test_slip_polyline_extending_above_ground_is_clipped():
    """A slip line drawn beyond the ground (ends above it) is clipped where
    it daylights: same result as the exact toe-to-crest line."""
    s = _wedge()
    r = le.fellenius_polyline(s, [(-2.0, 1.0), (0.0, 0.0), (24.0, 12.0)])
    fs, _, _ = _wedge_hand(10.0, 30.0, 20.0)
    assert r.fs == pytest.approx(fs, rel=1e-10)
    assert r.slices.x_entry == pytest.approx(0.0, abs=1e-9)
    assert r.slices.x_exit == pytest.approx(20.0, abs=1e-9)


def test_two_layer_wedge_weight_and_base_strength():
    """Two layers: top layer (gamma 18) above y = 5, lower layer (gamma 22,
    c = 4, phi = 25) below.  Compared with the hand calculation: the wedge
    triangle (0,0),(10,10),(20,10) is split by y = 5 into a lower triangle
    of area 12.5 m^2 and an upper trapezoid of 37.5 m^2; the base from
    (0,0) to (20,10) lies in the lower layer up to y = 5 and in the top
    layer above (c = 2, phi = 33)."""
    top = Layer(c=2.0, phi=33.0, gamma=18.0, name="top")
    low = Layer(c=4.0, phi=25.0, gamma=22.0, top=[(-50, 5.0), (50, 5.0)], name="low")
    s = Slope([(-10.0, 0.0), (0.0, 0.0), (10.0, 10.0), (30.0, 10.0)], [top, low])
    r = le.fellenius_polyline(s, [(0.0, 0.0), (20.0, 10.0)], n=40)
    th = math.atan(0.5)
    W = 18.0 * 37.5 + 22.0 * 12.5
    # weights per layer of base: split the base at x = 10 (y = 5)
    # part x in [0,10]: column above base from y=x/2 to ground y=x (x<=10)
    #   lower layer part of it weighs gamma_low*area(y<5) + gamma_top*area(y>5)
    A_low_lo = 12.5 + 0.0  # region x in [0,10], between base and min(ground,5): tri(0,0),(5,5),(10,5) = 12.5
    A_top_lo = 50.0 / 2 - 12.5  # region x in [0,10] between base and ground is 25 m^2
    W_lo = 22.0 * A_low_lo + 18.0 * A_top_lo
    W_hi = W - W_lo
    L_half = math.hypot(10.0, 5.0)
    res = (4.0 * L_half + W_lo * math.cos(th) * tand(25.0)
           + 2.0 * L_half + W_hi * math.cos(th) * tand(33.0))
    assert float(np.sum(r.slices.W)) == pytest.approx(W, rel=1e-10)
    assert r.fs == pytest.approx(res / (W * math.sin(th)), rel=1e-10)


def test_wedge_with_horizontal_phreatic_line():
    """Phreatic line at y = 4: u = gamma_w (4 - y) on the base below it.
    Hand calculation: sum(u l) = gamma_w * integral over the submerged base
    of (4 - y) dl = gamma_w * 0.5 * 4 * (4 / sin(theta))."""
    s = _wedge(phreatic=[(-50.0, 4.0), (50.0, 4.0)])
    r = le.fellenius_polyline(s, [(0.0, 0.0), (20.0, 10.0)], n=40)
    th = math.atan(0.5)
    ul = 9.81 * 0.5 * 4.0 * (4.0 / math.sin(th))
    fs, N, T = _wedge_hand(10.0, 30.0, 20.0, u_l=ul)
    assert r.fs == pytest.approx(fs, rel=1e-9)
    assert r.normal == pytest.approx(N, rel=1e-9)


def test_wedge_with_ru():
    """Pore-pressure ratio: u = ru W / b, so for a single base angle
    N' = W (cos(theta) - ru / cos(theta)); compared with the hand value."""
    ru = 0.3
    s = _wedge(ru=ru)
    r = le.fellenius_polyline(s, [(0.0, 0.0), (20.0, 10.0)])
    th = math.atan(0.5)
    W = 20.0 * 50.0
    fs, N, T = _wedge_hand(10.0, 30.0, 20.0, u_l=W * ru / math.cos(th))
    assert r.fs == pytest.approx(fs, rel=1e-10)
    assert r.normal == pytest.approx(N, rel=1e-10)


def test_table2_totals_consistency_c0():
    """Seed paper Table 2 gives FS from the slip-surface totals; for c = 0
    the module's FS must equal sum(N') tan(phi) / sum(T) exactly, for a
    multi-segment (block-joint-like) polyline with varying base angles.
    (Table 2 itself: 253 kN/m * tan 30 / 231 kN/m = 0.632, printed 0.63.)"""
    s = _wedge(c=0.0, phi=30.0)
    slip = [(0.0, 0.0), (6.0, 1.0), (14.0, 4.0), (18.0, 7.0), (20.0, 10.0)]
    r = le.fellenius_polyline(s, slip, n=60)
    assert r.fs == pytest.approx(r.normal * tand(30.0) / r.shear, rel=1e-12)
    assert 253.0 * tand(30.0) / 231.0 == pytest.approx(0.63, abs=0.005)
    table = le.results_table([r, ("RBSM (paper)", 217.0, 271.0, 0.72)], title="Table 2")
    assert "Fellenius (polyline)" in table and "217.0" in table and f"{r.fs:8.3f}" in table


# ---------------------------------------------------------------------------
# circles
# ---------------------------------------------------------------------------
CIRCLE = Circle(2.0, 15.0, 15.5)


def test_bishop_equals_fellenius_for_phi_zero():
    """For phi = 0, m_alpha = cos(alpha) and Bishop reduces to
    sum(c l) / sum(W sin alpha), the Fellenius value: both must agree to
    round-off on the same circle and slices."""
    s = _wedge(c=30.0, phi=0.0)
    f = le.fellenius_circle(s, CIRCLE, n=50)
    b = le.bishop_circle(s, CIRCLE, n=50)
    assert b.fs == pytest.approx(f.fs, rel=1e-12)
    assert b.iterations <= 2


def test_fs_proportional_to_c_for_phi_zero():
    """For phi = 0, FS is linear in c: tripling c triples FS (both methods)."""
    s1 = _wedge(c=10.0, phi=0.0)
    s3 = _wedge(c=30.0, phi=0.0)
    for fn in (le.fellenius_circle, le.bishop_circle):
        assert fn(s3, CIRCLE).fs == pytest.approx(3.0 * fn(s1, CIRCLE).fs, rel=1e-12)


def test_fellenius_circle_phi_zero_against_exact_moment_integral():
    """phi = 0 circle: FS = c R^2 theta / (gamma * first moment of the
    sliding area about the centre).  The area moment is computed here
    independently by a fine 2-D grid quadrature of the region between the
    ground and the circle; with 400 slices the agreement must be 0.2 %."""
    c, gamma = 30.0, 20.0
    s = _wedge(c=c, phi=0.0, gamma=gamma)
    r = le.fellenius_circle(s, CIRCLE, n=400)
    xe, xx = r.slices.x_entry, r.slices.x_exit
    ye, yx = float(s.ground(xe)), float(s.ground(xx))
    ang = lambda x, y: math.atan2(y - CIRCLE.yc, x - CIRCLE.xc)
    theta = abs(ang(xx, yx) - ang(xe, ye))
    gx = np.linspace(xe, xx, 1601)
    gy = np.linspace(-1.0, 11.0, 1601)
    X, Y = np.meshgrid(0.5 * (gx[1:] + gx[:-1]), 0.5 * (gy[1:] + gy[:-1]))
    inside = (Y < s.ground(X)) & ((X - CIRCLE.xc) ** 2 + (Y - CIRCLE.yc) ** 2 < CIRCLE.R ** 2)
    dA = (gx[1] - gx[0]) * (gy[1] - gy[0])
    moment = abs(float(np.sum((X - CIRCLE.xc)[inside])) * dA)
    exact = c * CIRCLE.R ** 2 * theta / (gamma * moment)
    assert r.fs == pytest.approx(exact, rel=2e-3)


def test_bishop_solution_satisfies_its_equation():
    """The converged Bishop FS must satisfy
    F = sum[(c b + (W - u b) tan phi)/m_alpha(F)] / sum(W sin alpha)
    to the stated tolerance (recomputed here from the returned slices), and
    differ from the Fellenius value (phi > 0)."""
    s = _wedge(c=10.0, phi=30.0, phreatic=[(-50, 3.0), (50, 6.0)])
    b = le.bishop_circle(s, CIRCLE, n=50, tol=1e-10)
    sl = b.slices
    m = np.cos(sl.alpha) + np.sin(sl.alpha) * sl.tan_phi / b.fs
    F = np.sum((sl.c * sl.b + (sl.W - sl.u * sl.b) * sl.tan_phi) / m) / np.sum(sl.W * np.sin(sl.alpha))
    assert F == pytest.approx(b.fs, rel=1e-8)
    f = le.fellenius_circle(s, CIRCLE, n=50)
    assert abs(b.fs - f.fs) > 0.01
    assert b.iterations >= 2
    assert b.resisting == pytest.approx(b.fs * b.shear, rel=1e-12)


def test_circle_slice_convergence():
    """FS with 50 slices within 0.5 % of FS with 800 slices."""
    s = _wedge()
    for fn in (le.fellenius_circle, le.bishop_circle):
        assert fn(s, CIRCLE, n=50).fs == pytest.approx(fn(s, CIRCLE, n=800).fs, rel=5e-3)


def test_circle_weight_equals_sliding_area_times_gamma():
    """sum(W) must equal gamma times the sliding-mass area measured by an
    independent grid quadrature (0.3 %)."""
    s = _wedge(gamma=20.0)
    sl = le.circle_slices(s, CIRCLE, n=200)
    gx = np.linspace(sl.x_entry, sl.x_exit, 1201)
    gy = np.linspace(-1.0, 11.0, 1201)
    X, Y = np.meshgrid(0.5 * (gx[1:] + gx[:-1]), 0.5 * (gy[1:] + gy[:-1]))
    inside = (Y < s.ground(X)) & ((X - CIRCLE.xc) ** 2 + (Y - CIRCLE.yc) ** 2 < CIRCLE.R ** 2)
    area = float(np.sum(inside)) * (gx[1] - gx[0]) * (gy[1] - gy[0])
    assert float(np.sum(sl.W)) == pytest.approx(20.0 * area, rel=3e-3)


@pytest.mark.parametrize("water", ["dry", "ru", "phreatic"])
def test_slices_equal_the_per_column_functions(water):
    """circle_slices asks the slope for every slice at once (arrays); its weights, pore pressures and
    base strengths equal, to the bit, Slope.column_weight, pore_pressure and layer_at asked slice by
    slice (numbers) on a two-layer slope with a layer top crossing the circles, for 300 random circles."""
    kw = {"dry": {}, "ru": {"ru": 0.25}, "phreatic": {"phreatic": [(0, -1), (20, 6), (40, 8)]}}[water]
    s = Slope([(0, 0), (10, 0), (20, 10), (40, 10)],
              [Layer(c=5.0, phi=30.0, gamma=19.0), Layer(c=20.0, phi=15.0, gamma=21.0, top=[(0, -2), (15, 3), (40, 4)])],
              **kw)
    rng = np.random.default_rng(7)
    cut = 0
    for xc, yc, R in zip(rng.uniform(5, 30, 300), rng.uniform(5, 30, 300), rng.uniform(5, 40, 300)):
        try:
            sl = le.circle_slices(s, Circle(xc, yc, R))
        except ValueError:
            continue
        cut += 1
        for i in range(sl.W.size):
            x, y, b = float(sl.x[i]), float(sl.y_base[i]), float(sl.b[i])
            W = s.column_weight(x, y, b)
            L = s.layer_at(x, y)
            assert (sl.W[i], sl.u[i], sl.c[i], sl.tan_phi[i]) == (W, s.pore_pressure(x, y, W, b), L.c, L.tan_phi)
    assert cut > 50


def test_critical_circle_is_deterministic_and_minimal():
    """Two identical searches return the same circle; the returned FS is
    not larger than any circle of the grid evaluated directly."""
    s = _wedge()
    a = le.critical_circle(s, (0, 10), (11, 20), nx=5, ny=5, r_range=(8, 20), nr=5, method="fellenius")
    b = le.critical_circle(s, (0, 10), (11, 20), nx=5, ny=5, r_range=(8, 20), nr=5, method="fellenius")
    assert (a.circle, a.fs) == (b.circle, b.fs)
    for xc in np.linspace(0, 10, 5):
        for yc in np.linspace(11, 20, 5):
            for R in np.linspace(8, 20, 5):
                try:
                    f = le.fellenius_circle(s, (xc, yc, R)).fs
                except ValueError:
                    continue
                assert a.fs <= f + 1e-12
    assert a.n_valid + a.n_skipped == a.n_tried == 125
    assert "critical circle" in str(a) and "FS =" in str(a.best)


# ---------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------
GOOD_G = [(-10.0, 0.0), (0.0, 0.0), (10.0, 10.0), (30.0, 10.0)]


@pytest.mark.parametrize(
    "kwargs,match",
    [
        (dict(c=-1.0, phi=30, gamma=20), "cohesion"),
        (dict(c=1.0, phi=90.0, gamma=20), "friction angle"),
        (dict(c=1.0, phi=-1.0, gamma=20), "friction angle"),
        (dict(c=1.0, phi=30, gamma=-20), "unit weight"),
        (dict(c=float("nan"), phi=30, gamma=20), "finite"),
        (dict(c=1.0, phi=float("inf"), gamma=20), "finite"),
        (dict(c="abc", phi=30, gamma=20), "real number"),
        (dict(c=1.0, phi=30, gamma=20, top=[(0, 1), (0, 2)]), "strictly increasing"),
    ],
)
def test_bad_layer(kwargs, match):
    """Layer rejects negative c / gamma, phi outside [0, 90), non-finite or
    non-numeric values, and a non-monotonic top boundary."""
    with pytest.raises(ValueError, match=match):
        Layer(**kwargs)


@pytest.mark.parametrize(
    "surface,kw,match",
    [
        ([(0, 0), (5, 1), (3, 2)], {}, "strictly increasing"),
        ([(0, 0), (0, 1), (3, 2)], {}, "strictly increasing"),
        ([(0, 0), (5, float("nan"))], {}, "non-finite"),
        ([(0, 0)], {}, "at least 2"),
        ([0, 1, 2], {}, r"\(x, y\)"),
        (GOOD_G, dict(ru=1.2), "ru"),
        (GOOD_G, dict(ru=0.2, phreatic=[(0, 1), (5, 1)]), "not both"),
        (GOOD_G, dict(phreatic=[(5, 1), (0, 1)]), "phreatic line"),
    ],
)
def test_bad_slope(surface, kw, match):
    """Slope rejects non-monotonic / vertical-step / non-finite / too short /
    malformed ground surfaces, ru outside [0,1), ru together with a phreatic
    line, and a non-monotonic phreatic line."""
    with pytest.raises(ValueError, match=match):
        Slope(surface, Layer(1.0, 30.0, 20.0), **kw)


def test_bad_layer_list():
    """Empty layer list and a lower layer without a top boundary."""
    with pytest.raises(ValueError, match="at least one layer"):
        Slope(GOOD_G, [])
    with pytest.raises(ValueError, match="only the first layer"):
        Slope(GOOD_G, [Layer(1, 30, 20), Layer(1, 30, 20)])


@pytest.mark.parametrize("n", [0, -3, 2.5, True])
def test_bad_slice_count(n):
    """Zero, negative, non-integer slice counts are refused."""
    with pytest.raises(ValueError, match="number of slices"):
        le.fellenius_circle(_wedge(), CIRCLE, n=n)


@pytest.mark.parametrize(
    "circle,match",
    [
        ((5.0, 40.0, 10.0), "misses the slope"),          # entirely above ground
        ((100.0, 5.0, 10.0), "misses the slope"),         # outside the x range
        ((10.0, 5.0, 6.0), "does not exit the ground surface twice"),  # centre below the ground
        ((5.0, 60.0, 61.0), "leaves the ground-surface x range"),      # too big for the model
        ((5.0, 5.0, -1.0), "radius"),
        ((float("nan"), 5.0, 3.0), "finite"),
    ],
)
def test_bad_circle(circle, match):
    """Circles that miss the slope, do not come back up through the ground,
    run past the ends of the ground definition, or are malformed."""
    with pytest.raises(ValueError, match=match):
        le.bishop_circle(_wedge(), circle)


def test_circle_cutting_ground_more_than_twice():
    """A two-hump ground surface cut by one circle gives two separate
    masses: refused."""
    s = Slope([(-20, 5), (-5, 5), (0, 0), (5, 5), (20, 5)], Layer(5, 30, 20))
    with pytest.raises(ValueError, match="more than twice"):
        le.fellenius_circle(s, (0.0, 20.0, 19.0))


def test_bishop_m_alpha_breakdown():
    """A circle exiting at a very steep negative base angle with high phi
    drives m_alpha below its limit: a ValueError naming m_alpha."""
    s = Slope([(-20, 8), (-4, 8), (0, 0), (10, 10), (40, 10)], Layer(0.0, 40.0, 20.0))
    with pytest.raises(ValueError, match="m_alpha"):
        le.bishop_circle(s, (-5.0, 10.0, 12.0))


@pytest.mark.parametrize(
    "slip,match",
    [
        ([(-5.0, 20.0), (40.0, 30.0)], "misses the slope"),
        ([(50.0, 0.0), (60.0, 0.0)], "misses the slope"),
        ([(0.0, 0.0), (20.0, 5.0)], "does not reach the ground"),   # ends inside the slope
        ([(5.0, 0.0), (2.0, 5.0)], "strictly increasing"),
        ([(0.0, 0.0), (20.0, float("inf"))], "non-finite"),
    ],
)
def test_bad_polyline(slip, match):
    """Polyline slip surfaces that miss the slope, stop inside it, are not
    left-to-right, or contain non-finite points."""
    with pytest.raises(ValueError, match=match):
        le.fellenius_polyline(_wedge(), slip)


def test_bad_search_arguments():
    """critical_circle: unknown method, both/neither radius definitions,
    empty search space."""
    s = _wedge()
    with pytest.raises(ValueError, match="method"):
        le.critical_circle(s, (0, 1), (20, 21), through=(0, 0), method="janbu")
    with pytest.raises(ValueError, match="exactly one"):
        le.critical_circle(s, (0, 1), (20, 21))
    with pytest.raises(ValueError, match="no valid trial circle"):
        le.critical_circle(s, (100, 110), (50, 60), nx=3, ny=3, r_range=(1, 2), nr=2)


def test_a_critical_circle_on_the_edge_of_its_search_space_says_so():
    """Issue 37, a new user's trial: y_range=(15, 45) gave a critical circle centred at y = 12.5 (the refinement
    re-grids around the best centre and may leave the ranges), without a word that the minimum may lie further
    out. Griffiths & Lane's slope: the reference search (centres up to 50 m, radii to 60 m) has no warning; a
    grid whose centres start above the critical one says which range to widen, and its FS is higher."""
    import os
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
    from reference_slopes import GAMMA, SLOPES, ground, search
    _, c, phi, _ = SLOPES["gl"]
    slope = Slope(ground("gl"), Layer(c=c, phi=phi, gamma=GAMMA))
    ref = le.critical_circle(slope, **search("gl"))
    assert ref.warnings == [] and "WARNING" not in str(ref)
    high = dict(search("gl"), y_range=(ref.circle.yc + 8, 50), refine=0)
    r = le.critical_circle(slope, **high)
    assert r.fs > ref.fs and any("y_range" in w for w in r.warnings), r.warnings
    assert "WARNING: a circle centred beyond y_range" in str(r)


# ---------------------------------------------------------------------------
# pseudo-static load: kh W horizontal in the sliding direction, kv W upwards (issue 40)
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("kh,kv,mirror", [(0.1, 0.0, False), (0.2, 0.05, False), (0.15, -0.1, True)])
def test_pseudo_static_planar_wedge_is_the_closed_form(kh, kv, mirror):
    """Fellenius on the wedge's plane with kh, kv: the closed form (c L + (W (1 - kv) cos th - kh W sin th) tan phi)
    / (W (1 - kv) sin th + kh W cos th), whichever way the slope faces."""
    c, phi, gamma = 10.0, 30.0, 20.0
    if mirror:
        s = Slope([(-30.0, 10.0), (-10.0, 10.0), (0.0, 0.0), (10.0, 0.0)], Layer(c, phi, gamma), kh=kh, kv=kv)
        r = le.fellenius_polyline(s, [(-20.0, 10.0), (0.0, 0.0)], n=23)
    else:
        r = le.fellenius_polyline(_wedge(c=c, phi=phi, kh=kh, kv=kv), [(0.0, 0.0), (20.0, 10.0)], n=23)
    th, W, L = math.atan2(10.0, 20.0), gamma * 50.0, math.hypot(20.0, 10.0)
    N = W * (1 - kv) * math.cos(th) - kh * W * math.sin(th)
    T = W * (1 - kv) * math.sin(th) + kh * W * math.cos(th)
    assert r.fs == pytest.approx((c * L + N * tand(phi)) / T, rel=1e-10)
    assert (r.normal, r.shear) == pytest.approx((N, T), rel=1e-10)
    record("Limit equilibrium", "planar wedge, kh %g, kv %g: Fellenius with the pseudo-static load" % (kh, kv), r.fs,
           (c * L + N * tand(phi)) / T, "hand calculation", rtol=1e-10)


def _mass_moments(s, circle, n=20000):
    """Area and centroid of the mass between the ground and the circle, by a fine midpoint rule (independent of the
    slices), and the arc length."""
    xs = np.linspace(circle.xc - circle.R, circle.xc + circle.R, n + 1)
    xm, dx = 0.5 * (xs[1:] + xs[:-1]), xs[1] - xs[0]
    low = circle.yc - np.sqrt(np.maximum(circle.R ** 2 - (xm - circle.xc) ** 2, 0))
    h = np.maximum(np.interp(xm, s.surface[:, 0], s.surface[:, 1]) - low, 0)
    A = float(np.sum(h) * dx)
    xbar = float(np.sum(h * xm) * dx) / A
    ybar = float(np.sum(h * (low + 0.5 * h)) * dx) / A
    inside = h > 0
    x0, x1 = xm[inside][0] - dx / 2, xm[inside][-1] + dx / 2
    arc = circle.R * (math.asin((x1 - circle.xc) / circle.R) - math.asin((x0 - circle.xc) / circle.R))
    return A, xbar, ybar, arc


@pytest.mark.parametrize("method", ["fellenius", "bishop", "spencer"])
def test_pseudo_static_circle_phi_zero_is_the_moment_balance(method):
    """phi = 0: Fellenius, Bishop and Spencer are all the moment balance about the centre, FS = c L R / (W (1 - kv) |x̄ - xc|
    + kh W (yc - ȳ)) with the sliding mass's centroid (x̄, ȳ) and arc length L computed without slices."""
    c, gamma, kh, kv = 30.0, 18.0, 0.15, 0.05
    s = _wedge(c=c, phi=0.0, gamma=gamma, kh=kh, kv=kv)
    circle = le.Circle(-2.0, 22.0, 22.3)
    fn = dict(fellenius=le.fellenius_circle, bishop=le.bishop_circle, spencer=le.spencer_circle)[method]
    r = fn(s, circle, n=400)
    A, xbar, ybar, arc = _mass_moments(s, circle)
    W = gamma * A
    closed = c * arc * circle.R / (W * (1 - kv) * abs(xbar - circle.xc) + kh * W * (circle.yc - ybar))
    assert r.fs == pytest.approx(closed, rel=2e-4)
    assert le.bishop_circle(_wedge(c=c, phi=0.0, gamma=gamma), circle, n=400).fs > r.fs  # the load lowers it


def test_pseudo_static_lowers_bishop_and_spencer():
    s0, s1 = _wedge(), _wedge(kh=0.1)
    circle = le.Circle(-2.0, 22.0, 22.3)
    assert le.bishop_circle(s1, circle).fs < le.bishop_circle(s0, circle).fs
    assert le.spencer_circle(s1, circle).fs < le.spencer_circle(s0, circle).fs
    assert le.critical_circle(s1, (-6, 6), (12, 26), nx=7, ny=7, through=(0, 0), method="bishop").fs < \
        le.critical_circle(s0, (-6, 6), (12, 26), nx=7, ny=7, through=(0, 0), method="bishop").fs
    for bad in (dict(kh=-0.1), dict(kh=1.0), dict(kv=1.0), dict(kh=float("nan"))):
        with pytest.raises(ValueError, match="kh|kv"):
            _wedge(**bad)


def _spencer_residuals(s, r, circle):
    """The whole sliding mass's equilibrium under Spencer's answer (F, theta), from the slices' own forces: the base
    normal N' from each slice's balance normal to its base with the interslice resultant Q at theta, the
    mobilised shear S = (c l + N' tan phi) / F; returns the sums of horizontal and vertical forces and the moment
    about the centre, each over the weight (and over W R). Computed here without Spencer's reduced equations."""
    sl = r.slices
    F, th = r.fs, math.radians(r.theta)
    a, d = sl.alpha, sl.alpha - th
    # the driving and normal loads of W (1 - kv) down and kh W in the sliding direction
    drive = sl.Wv * np.sin(a) + sl.kh * sl.W * np.cos(a)
    normal_load = sl.Wv * np.cos(a) - sl.kh * sl.W * np.sin(a)
    # Q from the two base-aligned balances: S - drive = Q cos d, N' = normal_load - u l - Q sin d
    Q = ((sl.c * sl.l + (normal_load - sl.u * sl.l) * sl.tan_phi) / F - drive) / (np.cos(d) + np.sin(d) * sl.tan_phi / F)
    Np = normal_load - sl.u * sl.l - Q * np.sin(d)
    S = (sl.c * sl.l + Np * sl.tan_phi) / F
    # every external force on the mass in the drawing's frame: the mass slides towards sl.direction
    k = sl.direction
    tx, ty = k * np.cos(a), -np.sin(a)  # along the base, the way the mass slides (down where alpha > 0)
    nx, ny = k * np.sin(a), np.cos(a)  # the base's normal, into the mass
    fx = k * sl.kh * sl.W + (Np + sl.u * sl.l) * nx - S * tx
    fy = -sl.Wv + (Np + sl.u * sl.l) * ny - S * ty
    # moments about the centre, (p - c) x f with each force at its point: W and kh W at the column's mid-height,
    # the base forces at the base's middle
    def moment(px, py, gx, gy):
        return (px - circle.xc) * gy - (py - circle.yc) * gx
    m = (moment(sl.x, sl.y_mid, k * sl.kh * sl.W, -sl.Wv)
         + moment(sl.x, sl.y_base, (Np + sl.u * sl.l) * nx - S * tx, (Np + sl.u * sl.l) * ny - S * ty))
    W = float(np.sum(sl.W))
    return float(np.sum(fx)) / W, float(np.sum(fy)) / W, float(np.sum(m)) / (W * circle.R)


@pytest.mark.parametrize("kh,kv,phi", [(0.0, 0.0, 30.0), (0.1, 0.0, 30.0), (0.2, 0.05, 20.0), (0.15, -0.1, 35.0)])
def test_pseudo_static_spencer_balances_forces_and_moments(kh, kv, phi):
    """Spencer with kh, kv: the mass is in equilibrium of horizontal and vertical forces and of moments about the
    centre with the slices' own forces (to 1e-8 of the weight), and its FS lies within 3 % of Bishop's (which
    balances moments only), as without the load."""
    s = _wedge(c=10.0, phi=phi, kh=kh, kv=kv)
    circle = le.Circle(-2.0, 22.0, 22.3)
    r = le.spencer_circle(s, circle, n=100)
    fx, fy, m = _spencer_residuals(s, r, circle)
    assert max(abs(fx), abs(fy), abs(m)) < 1e-8, (fx, fy, m)
    b = le.bishop_circle(s, circle, n=100).fs
    print("kh %g kv %g phi %g: Spencer %.5f (theta %.2f deg), Bishop %.5f" % (kh, kv, phi, r.fs, r.theta, b))
    assert r.fs == pytest.approx(b, rel=0.03)
    record("Limit equilibrium", "Spencer with kh %g, kv %g (phi %g): force and moment balance of the mass" % (kh, kv, phi),
           max(abs(fx), abs(fy), abs(m)), 0.0, "equilibrium (residual / W)", tolerance="residual < 1e-8 of W")
