"""Tests of the CGAL Voronoi slope blocks (py/yade_rbsm/voronoi.py, module yade_rbsm_tessellation).

Plain python3, no YADE: voronoi.py is loaded from its file (the package's __init__ imports yade).
What is checked on every tessellation (function check_tiling):
  * every block is accepted by Polygon2D's own check (rbsm::polygonProblem: convex,
    counter-clockwise, no repeated or collinear vertex) and has positive area;
  * the areas add up to the slope's area, computed exactly (fractions, shoelace), rel. 1e-9;
  * the blocks do not overlap: the area of their union (CGAL, exact) equals the sum of areas;
  * conforming joints: every edge is used by at most two blocks, in opposite directions, with the
    same vertex coordinates bit for bit; the edges used once lie on the slope's outline and their
    total length equals the outline's length (so no interior edge is left without its partner).
"""
import collections
import importlib.util
import math
import os
from fractions import Fraction

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
_spec = importlib.util.spec_from_file_location("rbsm_voronoi", os.path.join(SOURCE, "py", "yade_rbsm", "voronoi.py"))
vor = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(vor)
tess = vor._tess

BOX = [(0, 0), (30, 0), (30, 12), (0, 12)]
# base, toe, face, crest: a non-convex slope (reflex corner at the toe and at the crest edge)
SLOPE = [(0, 0), (60, 0), (60, 10), (35, 10), (20, 25), (0, 25)]
L_SHAPE = [(0, 0), (10, 0), (10, 2), (2, 2), (2, 10), (0, 10)]
# slope with collinear vertices (crest split where a crack will be) and far from the origin
COLLINEAR = [(1000, 500), (1040, 500), (1040, 506), (1028, 506), (1016, 518), (1008, 518), (1000, 518)]
NOTCHED = [(0, 0), (20, 0), (20, 8), (12, 8), (12, 4), (9, 4), (9, 8), (0, 8)]  # a notch from the top


def exact_area(poly):
    s = Fraction(0)
    n = len(poly)
    for i in range(n):
        x0, y0 = map(Fraction, poly[i])
        x1, y1 = map(Fraction, poly[(i + 1) % n])
        s += x0 * y1 - x1 * y0
    return abs(s) / 2


def on_segment(p, a, b, tol):
    ax, ay = a
    bx, by = b
    px, py = p
    ex, ey = bx - ax, by - ay
    L = math.hypot(ex, ey)
    cross = (ex * (py - ay) - ey * (px - ax)) / L
    t = (ex * (px - ax) + ey * (py - ay)) / (L * L)
    return abs(cross) <= tol and -tol / L <= t <= 1 + tol / L


def without_straight_vertices(poly):
    """The outline with the vertices where it goes straight on removed (exact test)."""
    v = list(poly)
    k = 0
    while k < len(v):
        (ax, ay), (bx, by), (cx, cy) = (map(Fraction, q) for q in (v[k - 1], v[k], v[(k + 1) % len(v)]))
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0:
            del v[k]
        else:
            k += 1
    return v


def perimeter(poly):
    return sum(math.dist(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))


def check_tiling(slope, blocks):
    assert blocks, "no block"
    size = max(max(p[0] for p in slope) - min(p[0] for p in slope), max(p[1] for p in slope) - min(p[1] for p in slope))
    for i, b in enumerate(blocks):
        assert tess.polygon_problem(b) == "", "block %d %s: %s" % (i, b, tess.polygon_problem(b))
        assert tess.signed_area(b) > 0
    total = sum(float(exact_area(b)) for b in blocks)
    area = float(exact_area(slope))
    assert total == pytest.approx(area, rel=1e-9)
    assert tess.union_area(blocks) == pytest.approx(total, rel=1e-9)
    directed = {}
    for i, b in enumerate(blocks):
        for k in range(len(b)):
            e = (tuple(b[k]), tuple(b[(k + 1) % len(b)]))
            assert e not in directed, "edge %s used twice in the same direction (blocks %d, %d)" % (e, directed.get(e), i)
            directed[e] = i
    boundary_length = 0.0
    shared = 0
    outline = without_straight_vertices(slope)
    for (a, b), i in directed.items():
        if (b, a) in directed:
            shared += 1
            continue
        # used once: must be on the slope's outline
        assert any(on_segment(a, outline[k], outline[(k + 1) % len(outline)], 1e-9 * size) and on_segment(b, outline[k], outline[(k + 1) % len(outline)], 1e-9 * size)
                   for k in range(len(outline))), "edge %s of block %d is neither shared nor on the slope outline" % ((a, b), i)
        boundary_length += math.dist(a, b)
    assert boundary_length == pytest.approx(perimeter(slope), rel=1e-9)
    return shared // 2


@pytest.mark.parametrize("slope", [BOX, SLOPE, L_SHAPE, COLLINEAR, NOTCHED], ids=["box", "slope", "L", "collinear", "notched"])
@pytest.mark.parametrize("seed", [0, 1, 2, 12345])
def test_tiling_random_sites(slope, seed):
    t = vor.voronoi_tessellation(slope, n=60, seed=seed)
    assert t.dropped == 0 and t.dropped_area == 0
    assert t.cells == 60
    joints = check_tiling(slope, t.blocks)
    assert joints >= len(t.blocks) - 1  # connected: at least a spanning tree of joints


@pytest.mark.parametrize("slope", [SLOPE, NOTCHED], ids=["slope", "notched"])
def test_tiling_dense_with_min_distance(slope):
    t = vor.voronoi_tessellation(slope, spacing=1.0, seed=3, min_distance=0.5)
    assert t.dropped == 0
    check_tiling(slope, t.blocks)
    # spacing: n = round(area / spacing^2)
    assert len(t.sites) == round(float(exact_area(slope)))


def test_nonconvex_pieces_are_split():
    # the reflex corners of the L and of the notch cut some cells into non-convex pieces
    splits = sum(vor.voronoi_tessellation(s, n=8, seed=k).split for s in (L_SHAPE, NOTCHED) for k in range(10))
    assert splits > 0


def test_clockwise_slope_gives_the_same_blocks():
    ccw = vor.voronoi_blocks(SLOPE, n=40, seed=9)
    cw = vor.voronoi_blocks(SLOPE[::-1], n=40, seed=9)
    assert cw == ccw


def test_deterministic_for_a_seed():
    a = vor.voronoi_tessellation(SLOPE, n=80, seed=42, min_distance=1.0)
    b = vor.voronoi_tessellation(SLOPE, n=80, seed=42, min_distance=1.0)
    assert a == b
    c = vor.voronoi_tessellation(SLOPE, n=80, seed=43, min_distance=1.0)
    assert c.blocks != a.blocks


def test_random_sites_inside_and_apart():
    pts = vor.random_sites(SLOPE, 300, seed=5, min_distance=1.0)
    assert len(pts) == 300
    for i, p in enumerate(pts):
        for q in pts[i + 1:]:
            assert math.dist(p, q) >= 1.0


def left_of_every_edge(b, p):
    x, y = p
    return all((b[(k + 1) % len(b)][0] - b[k][0]) * (y - b[k][1]) - (b[(k + 1) % len(b)][1] - b[k][1]) * (x - b[k][0]) > 0 for k in range(len(b)))


def test_each_block_holds_its_site():
    # convex slope: one block per cell, each strictly containing its site (sites strictly inside)
    t = vor.voronoi_tessellation(BOX, n=50, seed=11)
    assert len(t.blocks) == 50 and sorted(t.site) == list(range(50))
    for b, s in zip(t.blocks, t.site):
        assert left_of_every_edge(b, t.sites[s])


def test_grid_sites_give_squares():
    # cocircular sites (a square grid): the Delaunay triangulation is degenerate, the Voronoi
    # cells are exactly the unit squares around the sites
    sites = [(x + 0.5, y + 0.5) for x in range(6) for y in range(4)]
    t = vor.voronoi_tessellation([(0, 0), (6, 0), (6, 4), (0, 4)], sites=sites)
    assert len(t.blocks) == 24
    for b, s in zip(t.blocks, t.site):
        cx, cy = sites[s]
        assert sorted(b) == sorted([(cx - 0.5, cy - 0.5), (cx + 0.5, cy - 0.5), (cx + 0.5, cy + 0.5), (cx - 0.5, cy + 0.5)])
    check_tiling([(0, 0), (6, 0), (6, 4), (0, 4)], t.blocks)


def test_sites_outside_the_slope():
    # a site outside still owns the part of its cell inside the slope; a site far away owns nothing
    t = vor.voronoi_tessellation(BOX, sites=[(5, 5), (25, 5), (15, -3), (1000, 1000)])
    assert t.cells == 3
    check_tiling(BOX, t.blocks)


def test_single_site_gives_the_slope_itself():
    t = vor.voronoi_tessellation(SLOPE, n=1, seed=0)
    # the slope is not convex: one cell, cut into convex pieces
    check_tiling(SLOPE, t.blocks)
    assert t.cells == 1


def test_min_area_drops_small_pieces():
    t = vor.voronoi_tessellation(NOTCHED, n=100, seed=1)
    smallest = min(float(exact_area(b)) for b in t.blocks)
    big = vor.voronoi_tessellation(NOTCHED, n=100, seed=1, min_area=smallest * 1.0001)
    assert big.dropped >= 1
    assert big.dropped_area == pytest.approx(smallest * big.dropped, rel=0.5)
    assert sum(float(exact_area(b)) for b in big.blocks) + big.dropped_area == pytest.approx(float(exact_area(NOTCHED)), rel=1e-9)


@pytest.mark.parametrize("slope,message", [
    ([(0, 0), (1, 0)], "at least 3"),
    ([(0, 0), (1, 0), (float("nan"), 1)], "NaN"),
    ([(0, 0), (1, 0), (1, 0), (0, 1)], "repeats vertex"),
    ([(0, 0), (2, 2), (2, 0), (0, 2)], "not a simple polygon"),
    ([(0, 0), (1, 1), (2, 2)], "simple"),
    ("abc", "(x, y) pairs"),
    ([(0, 0), (1, 0, 3), (0, 1)], "(x, y) pairs"),
])
def test_bad_slope(slope, message):
    with pytest.raises(ValueError) as e:
        vor.voronoi_blocks(slope, n=5)
    assert message in str(e.value)
    assert "slope" in str(e.value)


@pytest.mark.parametrize("kwargs,message", [
    (dict(n=0), "n must be an integer > 0"),
    (dict(n=-3), "n must be an integer > 0"),
    (dict(n=2.5), "n must be an integer > 0"),
    (dict(n=True), "n must be an integer > 0"),
    (dict(), "exactly one of n, spacing, sites"),
    (dict(n=5, spacing=1.0), "exactly one of n, spacing, sites"),
    (dict(spacing=0), "spacing must be"),
    (dict(spacing=float("nan")), "spacing must be"),
    (dict(n=5, seed=-1), "seed must be"),
    (dict(n=5, seed=1.5), "seed must be"),
    (dict(n=5, min_distance=-1), "min_distance must be"),
    (dict(n=5, min_distance=float("inf")), "min_distance must be"),
    (dict(n=5, min_area=-1.0), "min_area must be"),
    (dict(sites=[]), "at least 1"),
    (dict(sites=[(1, 1), (2, float("nan"))]), "NaN"),
])
def test_bad_arguments(kwargs, message):
    with pytest.raises(ValueError) as e:
        vor.voronoi_tessellation(SLOPE, **kwargs)
    assert message in str(e.value)


def test_sites_that_do_not_fit():
    with pytest.raises(RuntimeError) as e:
        vor.voronoi_blocks(BOX, n=100, min_distance=10.0)
    assert "min_distance" in str(e.value)


def min_angle(t):
    out = []
    for k in range(3):
        a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
        u, v = (b[0] - a[0], b[1] - a[1]), (c[0] - a[0], c[1] - a[1])
        out.append(math.degrees(math.acos(max(-1.0, min(1.0, (u[0] * v[0] + u[1] * v[1]) / (math.hypot(*u) * math.hypot(*v)))))))
    return min(out)


@pytest.mark.parametrize("slope", [BOX, SLOPE, L_SHAPE, COLLINEAR, NOTCHED], ids=["box", "slope", "L", "collinear", "notched"])
@pytest.mark.parametrize("spacing", [1.5, 4.0])
def test_triangles_tile_the_slope(slope, spacing):
    """triangle_blocks (CGAL's Delaunay refinement, the blocks of plastic soil): a conforming tiling of the
    slope, convex or not, far from the origin or not, no edge longer than the spacing, no angle below 20 deg."""
    tris = vor.triangle_blocks(slope, spacing)
    assert all(len(t) == 3 for t in tris)
    check_tiling(slope, tris)
    assert max(math.dist(t[k], t[(k + 1) % 3]) for t in tris for k in range(3)) <= spacing * (1 + 1e-9)
    assert min(min_angle(t) for t in tris) >= 20.0
    area = float(exact_area(slope))
    assert len(tris) >= area / (math.sqrt(3) / 4 * spacing ** 2)  # (no triangle larger than the equilateral one)


@pytest.mark.parametrize("spacing", [0, -1.0, float("nan"), float("inf"), "1", None, True])
def test_triangles_refuse_a_bad_spacing(spacing):
    with pytest.raises(ValueError) as e:
        vor.triangle_blocks(SLOPE, spacing)
    assert "spacing must be a length > 0" in str(e.value)


def test_triangles_refuse_a_bad_slope():
    with pytest.raises(ValueError) as e:
        vor.triangle_blocks([(0, 0), (2, 2), (2, 0), (0, 2)], 1.0)
    assert "not a simple polygon" in str(e.value) and "slope" in str(e.value)


@pytest.mark.parametrize("slope,h", [(SLOPE, 3.0), (L_SHAPE, 1.0), (NOTCHED, 1.5)], ids=["slope", "L", "notched"])
def test_triangles_with_a_seed_are_another_mesh_of_the_same_slope(slope, h):
    """triangle_blocks(seed=): the interior vertices moved at random (the mesh's own scatter, as Voronoi seeds give):
    still a conforming tiling, the outline's vertices where they were, no angle below 15 deg, no edge beyond
    1.25 x the spacing; the same seed the same mesh, another seed another."""
    plain = vor.triangle_blocks(slope, h)
    one, again, two = (vor.triangle_blocks(slope, h, seed=s) for s in (1, 1, 2))
    assert one == again and one != two and len(one) == len(plain)
    on_outline = _outline_vertices(plain)
    for tris in (one, two):
        check_tiling(slope, tris)
        assert min(min_angle(t) for t in tris) >= 15.0
        assert max(math.dist(t[k], t[(k + 1) % 3]) for t in tris for k in range(3)) <= 1.25 * h
        assert on_outline <= {v for t in tris for v in t}
        moved = {v for t in tris for v in t} - {v for t in plain for v in t}
        assert len(moved) > 0.8 * (len({v for t in plain for v in t}) - len(on_outline))
    with pytest.raises(ValueError, match="seed must be an integer >= 0"):
        vor.triangle_blocks(slope, h, seed=-1)


def _outline_vertices(tris):
    """The vertices of edges that only one triangle has."""
    edges = collections.Counter(frozenset((t[k], t[(k + 1) % 3])) for t in tris for k in range(3))
    return {v for e, n in edges.items() if n == 1 for v in e}
