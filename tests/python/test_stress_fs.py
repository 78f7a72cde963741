"""Issue 21: Kulhawy's stress-based factor of safety (limit_equilibrium.stress_circle, stress_polyline,
critical_circle(method="stress")), checked against closed forms without YADE.

The field: an infinite slope, ground y = x tan(beta), every stress a function of the depth d normal to
the ground only (sigma_nn = gamma d cos(beta), tau = gamma d sin(beta) on planes parallel to it, and any
K times sigma_nn along them): in equilibrium with the weight whatever K."""
import math

import numpy as np
import pytest

from conftest import load_limit_equilibrium

le = load_limit_equilibrium()

BETA = math.radians(30.0)
GAMMA = 20.0
GROUND = [(-60.0, -60.0 * math.tan(BETA)), (60.0, 60.0 * math.tan(BETA))]


def infinite_slope_field(K, beta=BETA, gamma=GAMMA):
    """(x, y) -> (sxx, syy, sxy) [kPa, compression positive] of the infinite slope."""
    e_s = np.array([-math.cos(beta), -math.sin(beta)])  # along the ground, downhill
    e_n = np.array([math.sin(beta), -math.cos(beta)])  # normal to it, into the ground

    def field(x, y):
        d = np.asarray(x) * math.sin(beta) - np.asarray(y) * math.cos(beta)
        s_nn, tau = gamma * math.cos(beta) * d, gamma * math.sin(beta) * d
        s_ss = K * s_nn
        t = lambda a, b: np.multiply.outer(a, b)  # noqa: E731
        sig = (s_ss[..., None, None] * t(e_s, e_s) + s_nn[..., None, None] * t(e_n, e_n)
               + tau[..., None, None] * (t(e_s, e_n) + t(e_n, e_s)))
        return np.array([sig[..., 0, 0], sig[..., 1, 1], sig[..., 0, 1]])

    return field


def _soil(phi, c=10.0):
    return le.Slope(GROUND, le.Layer(c=c, phi=phi, gamma=GAMMA))


@pytest.mark.parametrize("K", [0.3, 1.0, 2.5])
@pytest.mark.parametrize("circle", [(0.0, 20.0, 22.0), (-5.0, 15.0, 20.0), (8.0, 30.0, 33.0)])
def test_undrained_circle_equals_bishop_for_any_field_in_equilibrium(K, circle):
    """phi = 0: the normal stresses act through the centre, so Σ tau l R is the weight's moment and the
    stress-based FS is Bishop's (= Fellenius's) exactly, whatever the horizontal stresses (K)."""
    soil = _soil(0.0)
    kul = le.stress_circle(soil, circle, infinite_slope_field(K), n=4000)
    bishop = le.bishop_circle(soil, circle, n=4000)
    assert kul.fs == pytest.approx(bishop.fs, rel=2e-5), (kul, bishop)
    assert kul.shear == pytest.approx(bishop.shear, rel=2e-5)


def test_frictional_surface_parallel_to_the_ground_gives_the_infinite_slope_ratio():
    """A long surface parallel to the ground at depth d normal to it (sigma_n = gamma d cos(beta), tau =
    gamma d sin(beta) on it): (c + gamma d cos tan phi) / (gamma d sin), the closed form of the infinite
    slope, from the field alone. 4 km long, so that its two 1 m ends weigh 0.2 %: on the 80 m surface this
    test had, they moved the FS by 3.7 % (1.097 against 1.0577), which the vertical-depth formula taken at
    the normal depth (1.0963) hid."""
    d, phi, c = 4.0, 25.0, 10.0
    X = 2000.0

    def g(x):
        return x * math.tan(BETA)

    soil = le.Slope([(-X - 10, g(-X - 10)), (X + 10, g(X + 10))], le.Layer(c=c, phi=phi, gamma=GAMMA))
    off = d / math.cos(BETA)  # vertical offset of the parallel line
    surface = [(-X - 1, g(-X - 1)), (-X, g(-X) - off), (X, g(X) - off), (X + 1, g(X + 1))]
    tp = math.tan(math.radians(phi))
    closed = (c + GAMMA * d * math.cos(BETA) * tp) / (GAMMA * d * math.sin(BETA))
    for K in (0.5, 2.0):  # the stress along the surface (K) does not act on it
        r = le.stress_polyline(soil, surface, infinite_slope_field(K), n=8000)
        assert r.fs == pytest.approx(closed, rel=3e-3), (K, r.fs, closed)
    # the field is total stress: the slope's pore pressure comes off sigma_n, once. ru: u = ru gamma z (z =
    # off, the vertical depth); a phreatic line parallel to the ground h_w above the surface: u = gamma_w h_w
    ground = soil.surface
    for wet, u in ((dict(ru=0.3), 0.3 * GAMMA * off),
                   (dict(phreatic=[(x, y - off + 2.0) for x, y in ground]), le.GAMMA_W * 2.0)):
        ws = le.Slope(ground, le.Layer(c=c, phi=phi, gamma=GAMMA), **wet)
        r = le.stress_polyline(ws, surface, infinite_slope_field(0.5), n=8000)
        closed_u = (c + (GAMMA * d * math.cos(BETA) - u) * tp) / (GAMMA * d * math.sin(BETA))
        assert r.fs == pytest.approx(closed_u, rel=3e-3), (wet, r.fs, closed_u)


def test_frictional_circle_takes_the_stresses_normal_to_its_base():
    """phi > 0 on a circle: the lateral stress (K) counts through sigma_n on the inclined bases, and each
    base's sigma_n, tau are the field's tensor turned to the base (here summed by hand, independently of
    the slices' sliding-direction bookkeeping), tension bases with c alone."""
    phi, c = 25.0, 10.0
    soil = _soil(phi, c)
    circle = le.Circle(-5.0, 15.0, 20.0)
    tp = math.tan(math.radians(phi))
    fs = {}

    def tensile(x, y):  # 30 kPa of isotropic tension added: the shallow bases open
        return infinite_slope_field(0.3)(x, y) - np.array([30.0, 30.0, 0.0])[:, None]

    for K, field in ((0.3, infinite_slope_field(0.3)), (2.5, infinite_slope_field(2.5)), ("tension", tensile)):
        r = le.stress_circle(soil, circle, field, n=2000)
        sl = r.slices
        sxx, syy, sxy = field(sl.x, sl.y_base)
        ux, uy = (sl.x - circle.xc) / circle.R, (sl.y_base - circle.yc) / circle.R  # outward: into the ground
        sn = sxx * ux * ux + syy * uy * uy + 2 * sxy * ux * uy
        wx, wy = -(sxx * ux + sxy * uy), -(sxy * ux + syy * uy)  # traction on the mass (outward normal u)
        tau = -(uy * wx - ux * wy)  # against the sliding: clockwise about the centre, towards -x at the bottom
        expected = np.sum((c + np.maximum(sn, 0) * tp) * sl.l) / np.sum(tau * sl.l)
        assert r.fs == pytest.approx(expected, rel=1e-9), (K, r.fs, expected)
        fs[K] = r.fs
        assert ("in tension" in r.notes) == bool(np.any(sn < 0)), (K, r.notes)
    assert fs[2.5] > 1.01 * fs[0.3] and "in tension" in r.notes


def test_critical_circle_stress_method_and_min_depth():
    soil = _soil(20.0)
    field = infinite_slope_field(0.5)
    kw = dict(x_range=(-20, 20), y_range=(10, 40), nx=6, ny=6, r_range=(8, 50), nr=8)
    free = le.critical_circle(soil, method="stress", stress=field, **kw)
    deep = le.critical_circle(soil, method="stress", stress=field, min_depth=6.0, **kw)
    assert free.best.method == "stress field (circle)" and free.fs > 0
    assert float(np.max(soil.ground(deep.best.slices.x) - deep.best.slices.y_base)) >= 6.0
    assert deep.fs >= free.fs


def test_bad_stress_input_is_refused_with_what_is_wrong():
    soil = _soil(20.0)
    circle = (0.0, 20.0, 22.0)
    with pytest.raises(ValueError, match="must return"):
        le.stress_circle(soil, circle, lambda x, y: (x, y))
    with pytest.raises(ValueError, match="not finite at"):
        le.stress_circle(soil, circle, lambda x, y: (x * np.nan, y, y))
    with pytest.raises(ValueError, match="holds no shear"):
        le.stress_circle(soil, circle, lambda x, y: (0 * x + 100.0, 0 * x + 100.0, 0 * x))  # isotropic
    kw = dict(x_range=(-20, 20), y_range=(10, 40), nx=2, ny=2, r_range=(8, 50), nr=2)
    with pytest.raises(ValueError, match="needs stress="):
        le.critical_circle(soil, method="stress", **kw)
    with pytest.raises(ValueError, match="is for method='stress'"):
        le.critical_circle(soil, method="bishop", stress=infinite_slope_field(1.0), **kw)
    with pytest.raises(ValueError, match="min_depth"):
        le.critical_circle(soil, method="bishop", min_depth=-1.0, **kw)


def test_a_slope_facing_the_other_way_gives_the_same_fs():
    """The mirror image (ground falling towards +x, the mass sliding towards +x): the same FS."""
    field = infinite_slope_field(0.7)

    def mirrored(x, y):
        sxx, syy, sxy = field(-np.asarray(x), np.asarray(y))
        return np.array([sxx, syy, -sxy])

    for phi in (0.0, 25.0):
        soil = _soil(phi)
        flipped = le.Slope([(-x, y) for x, y in reversed(GROUND)], le.Layer(c=10.0, phi=phi, gamma=GAMMA))
        a = le.stress_circle(soil, (-5.0, 15.0, 20.0), field, n=2000)
        b = le.stress_circle(flipped, (5.0, 15.0, 20.0), mirrored, n=2000)
        assert b.slices.direction == -a.slices.direction
        assert b.fs == pytest.approx(a.fs, rel=1e-9), (a, b)


# -- the blocks' field (safety.StressField) in the stress method: what a new user ran into ---------------------
def _block_field(beta=BETA, spacing=1.0, reach=None, depth=30.0):
    """A StressField of the infinite slope's stresses sampled at a grid of 'centroids' from *depth* below the
    ground up to it (the blocks' region), as safety.stress_field() builds it from a settled slope."""
    from yade_rbsm.le_bridge import StressField
    xs = np.arange(-50.0, 50.0 + 1e-9, spacing)
    pts = np.array([(x, x * math.tan(beta) - d) for x in xs for d in np.arange(0.5 * spacing, depth, spacing)])
    vals = np.array(infinite_slope_field(0.5)(pts[:, 0], pts[:, 1])).T
    return StressField(pts, vals, reach=reach)


def test_stress_field_takes_numbers_and_arrays_of_any_shape_and_nan():
    f = _block_field()
    sxx, syy, sxy = f(0.0, -5.0)  # numbers in, numbers out
    assert np.ndim(sxx) == 0 and float(syy) == pytest.approx(infinite_slope_field(0.5)(0.0, -5.0)[1], rel=1e-9)
    assert np.shape(f(np.zeros((2, 3)), np.full((2, 3), -5.0))) == (3, 2, 3)
    s = f(np.array([np.nan, 0.0, np.inf]), np.array([-5.0, np.nan, -5.0]))  # was an IndexError of scipy's
    assert np.isnan(s).all()


def test_stress_field_of_collinear_blocks_is_refused_with_what_is_wrong():
    from yade_rbsm.le_bridge import StressField
    with pytest.raises(ValueError, match="on one line"):  # was scipy's QhullError ("initial simplex is flat")
        StressField([(0.0, -0.5), (1.0, -0.5), (2.0, -0.5)], np.zeros((3, 3)))


def test_stress_field_is_not_finite_beyond_the_blocks():
    """The nearest block's stress is taken only within *reach* of the centroids: a circle running far below
    the blocks (no base= in the search, or a limit-equilibrium ground wider than the block model) used
    to get the nearest block's stress there, silently (the 2:1 RBSM slope without base=: 1.185 against
    Bishop's 1.372 on a circle 7.3 m under the blocks)."""
    f = _block_field(reach=1.0)
    assert np.isfinite(f(0.0, -30.4)).all() and np.isnan(f(0.0, -35.0)).all()
    assert np.isfinite(_block_field()(0.0, -35.0)).all()  # without reach: the nearest block everywhere
    soil = _soil(20.0)
    thin = _block_field(reach=1.0, depth=5.0)  # blocks down to 5 m under the ground
    with pytest.raises(ValueError, match="outside the stress field"):
        le.stress_circle(soil, (-5.0, 30.0, 45.0), thin)  # 19 m deep
    kw = dict(x_range=(-20, 20), y_range=(10, 60), nx=6, ny=6, r_range=(8, 60), nr=10)
    for field in (f, thin):
        r = le.critical_circle(soil, method="stress", stress=field, **kw)
        assert np.isfinite(field(r.best.slices.x, r.best.slices.y_base)).all()
    with pytest.raises(ValueError, match="run outside the stress field"):  # every circle: say why
        le.critical_circle(soil, method="stress", stress=thin, x_range=(-5, 5), y_range=(28, 32), nx=2, ny=2,
                           r_range=(40, 45), nr=2)


def test_search_reports_a_broken_field_and_too_deep_min_depth():
    """critical_circle used to skip every circle on any ValueError: a field returning the wrong shape gave
    'no valid trial circle in the search space', and so did a min_depth deeper than the slope."""
    soil = _soil(20.0)
    kw = dict(x_range=(-20, 20), y_range=(10, 40), nx=3, ny=3, r_range=(8, 50), nr=3)
    with pytest.raises(ValueError, match="must return"):
        le.critical_circle(soil, method="stress", stress=lambda x, y: (x, y), **kw)
    with pytest.raises(ValueError, match="min_depth"):
        le.critical_circle(soil, method="stress", stress=infinite_slope_field(0.5), min_depth=500.0, **kw)


def test_stress_field_refuses_ids_that_are_not_body_ids():
    """ids=[5.7] was taken as body 5 and ids="12" as bodies 1 and 2 (a new user's trial); refused before
    the scene is read."""
    from yade_rbsm.le_bridge import stress_field
    for bad, what in (([5.7], "5.7"), ("12", "'12'"), ([-1], "-1"), (7, "7")):
        with pytest.raises(ValueError, match="stress_field") as e:
            stress_field(O=object(), ids=bad)
        assert what in str(e.value), (bad, str(e.value))
    with pytest.raises(ValueError, match="stress_field"):
        stress_field(O=object(), ids=[3, float("nan")])


def test_fe_elastic_field_of_a_slope_is_in_equilibrium_and_feeds_the_stress_method():
    """scripts/fe_stress_fs.py (GetFEM, plane strain, the stress at triangle centroids): the overburden
    under the crest, and with phi = 0 the stress FS on a circle equals Bishop's (the field is in
    equilibrium with the weight: measured 0.44785 against 0.44798), so the comparison it prints rests on a
    right field."""
    import importlib.util
    import os
    path = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "fe_stress_fs.py")
    spec = importlib.util.spec_from_file_location("fe_stress_fs", path)
    fe = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(fe)
    from yade_rbsm.le_bridge import StressField
    L = 10.0  # a 45 deg face, H = 10 m
    pts, sig = fe.fe_stress([(12, 0), (12 + L, 10), (32 + L, 10), (32 + L, 0)], 0.5, 100e3, 0.3, 20.0)
    field = StressField(pts, sig, reach=0.5)
    sxx, syy, sxy = field(30.0, 1.0)  # under the crest, 9 m deep
    assert syy == pytest.approx(20.0 * 9.0, rel=0.06) and 0.3 * syy < sxx < 0.5 * syy
    soil = le.Slope([(0, 0), (12, 0), (12 + L, 10), (32 + L, 10)], le.Layer(c=10.0, phi=0.0, gamma=20.0))
    circle = (10.0, 14.3, 14.2)
    assert le.stress_circle(soil, circle, field, n=400).fs == pytest.approx(le.bishop_circle(soil, circle, n=400).fs, rel=0.002)


def test_candidate_circles_are_tried_besides_the_grid():
    """critical_circle(candidates=...): a circle off the grid (e.g. Bishop's, for the stress method) is tried
    after the grid and kept where it is lower; the grid's search, refinement included, is unchanged (tried
    first, the candidates moved the refinement elsewhere and raised the FS of 8 of 36 study runs)."""
    soil = _soil(20.0)
    field = infinite_slope_field(0.5)
    kw = dict(x_range=(-20, 20), y_range=(10, 40), nx=3, ny=3, r_range=(8, 50), nr=3)
    grid = le.critical_circle(soil, method="stress", stress=field, **kw)
    fine = le.critical_circle(soil, method="stress", stress=field, x_range=(-20, 20), y_range=(10, 40), nx=9, ny=9,
                              r_range=(8, 50), nr=15)
    assert fine.fs < grid.fs  # the coarse grid misses it
    both = le.critical_circle(soil, method="stress", stress=field, candidates=[fine.circle, (0.0, 20.0, 22.0)], **kw)
    assert both.fs == fine.fs and both.circle == fine.circle
    assert both.n_tried == grid.n_tried + 2
    assert le.critical_circle(soil, method="stress", stress=field, candidates=[(50.0, 80.0, 1.0)], **kw).fs == grid.fs
    refined = dict(kw, refine=2)
    alone = le.critical_circle(soil, method="stress", stress=field, **refined)
    for cand in [(alone.circle.xc + 3.0, alone.circle.yc + 3.0, alone.circle.R + 3.0), (0.0, 20.0, 22.0)]:
        fs = le.stress_circle(soil, cand, field).fs
        assert le.critical_circle(soil, method="stress", stress=field, candidates=[cand], **refined).fs == min(fs, alone.fs)
    assert le.stress_circle(soil, (0.0, 20.0, 22.0), field).fs > alone.fs  # (one of them higher)
    # a candidate better than the coarse grid's first level but worse than its refinement, far from the latter:
    # tried first, it would take the refinement to its own neighbourhood
    first = le.critical_circle(soil, method="stress", stress=field, **kw).fs
    lure = None
    for xc in np.linspace(-20, 20, 9):
        for yc in np.linspace(10, 40, 7):
            for R in np.linspace(8, 50, 15):
                if math.hypot(xc - alone.circle.xc, yc - alone.circle.yc) < 8:
                    continue
                try:
                    fs = le.stress_circle(soil, (xc, yc, R), field).fs
                except ValueError:
                    continue
                if alone.fs < fs < first and (lure is None or fs < lure[0]):
                    lure = (fs, (xc, yc, R))
    assert lure is not None
    assert le.critical_circle(soil, method="stress", stress=field, candidates=[lure[1]], **refined).fs == alone.fs
    with pytest.raises(ValueError, match="radius"):
        le.critical_circle(soil, method="stress", stress=field, candidates=[(0.0, 20.0, -1.0)], **kw)
