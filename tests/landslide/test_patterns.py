"""Slope builders beyond plain bricks (yade_rbsm.slope, pure Python + the CGAL module): Voronoi
blocks (voronoi_slope_blocks), columns on a stepped base (column_blocks), cracks along any polyline
(vertical, inclined, folded) and layers. For every pattern: the blocks tile the slope (total area =
slope area, closed form), every block is convex and counter-clockwise, every interior edge is
covered exactly (collinear, same length) by edges of neighbours, and the crack polylines are
followed by block edges on both sides."""
import math

import pytest

from conftest import load_slope

S = load_slope()
SURF = [(0, 2), (6, 2), (14, 12), (24, 12)]
PLANE = [(6, 2), (17, 2 + 11 * math.tan(math.radians(35)))]
VCRACK = [(17, PLANE[1][1]), (17, 11.5)]          # vertical, inside the slope
FOLDED = [(15, 11), (18, 8), (21, 10.5)]          # not x-monotone in slope terms: a V
STEPS = [(0, 0), (6, 0), (6, 1), (10, 1), (10, 2), (24, 2)]
LAYERS = [([(0, 0.5), (24, 4.5)], "weak"), ([(0, 1.0), (6, 1.8), (24, 9)], "mid"), (None, "strong")]  # tops below ground


def _overlap(a, b, c, d):
    ux, uy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(ux, uy)
    for r in (c, d):
        if abs(ux * (r[1] - a[1]) - uy * (r[0] - a[0])) > 1e-10 * L:
            return 0.0
    t = sorted(((r[0] - a[0]) * ux + (r[1] - a[1]) * uy) / L for r in (c, d))
    return max(0.0, min(L, t[1]) - max(0.0, t[0]))


def _on_boundary(a, b, poly):
    n = len(poly)
    L = math.dist(a, b)
    return any(_overlap(a, b, poly[i], poly[(i + 1) % n]) >= L * (1 - 1e-9) for i in range(n))


def _edges(blocks):
    return [(b.vertices[i], b.vertices[(i + 1) % len(b.vertices)], k)
            for k, b in enumerate(blocks) for i in range(len(b.vertices))]


def _check_tiling(sb):
    slope = [b for b in sb.blocks if b.kind == "slope"]
    area = sum(b.area for b in slope)
    assert area + sb.dropped_area == pytest.approx(sb.slope_area, rel=1e-12)
    assert abs(S.polygon_area(sb.polygon)) == pytest.approx(sb.slope_area, rel=1e-12)
    for b in slope:
        n = len(b.vertices)
        assert n >= 3 and S.polygon_area(b.vertices) > 0
        for i in range(n):
            p, q, r = b.vertices[i - 1], b.vertices[i], b.vertices[(i + 1) % n]
            assert (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]) > 0, b.vertices
    if sb.dropped_area > 0:
        return slope
    edges = _edges(slope)
    n = len(sb.polygon)
    for a, b, k in edges:
        if _on_boundary(a, b, sb.polygon):
            continue
        covered = sum(_overlap(a, b, d, c) for c, d, j in edges if j != k)
        covered += sum(_overlap(a, b, sb.polygon[i], sb.polygon[(i + 1) % n]) for i in range(n))  # e.g. a riser
        assert covered == pytest.approx(math.dist(a, b), rel=1e-9), (a, b)
    return slope


def _check_follows(slope, line):
    """Each segment of *line* is covered, on both sides, by block edges lying on it."""
    edges = _edges(slope)
    for a, b in zip(line[:-1], line[1:]):
        L = math.dist(a, b)
        dx, dy = b[0] - a[0], b[1] - a[1]
        left = right = 0.0
        for c, d, k in edges:
            o = _overlap(a, b, c, d)
            if o == 0:
                continue
            cx, cy = S.polygon_centroid(slope[k].vertices)
            if dx * (cy - a[1]) - dy * (cx - a[0]) > 0:
                left += o
            else:
                right += o
        assert left == pytest.approx(L, rel=1e-9) and right == pytest.approx(L, rel=1e-9), (a, b, left, right)


@pytest.mark.parametrize("seed", [1, 7])
def test_voronoi(seed):
    sb = S.voronoi_slope_blocks(SURF, 0.0, spacing=1.5, seed=seed, min_distance=0.7, joints=[PLANE],
                                cracks=[VCRACK, FOLDED])
    assert sb.pattern == "voronoi" and sb.slope_area == S.region_area(SURF, 0.0)
    slope = _check_tiling(sb)
    assert 60 < len(slope) < 200
    for line in (PLANE, VCRACK, FOLDED):
        _check_follows(slope, line)
    assert sb.cracks == [VCRACK, FOLDED]
    kinds = [b.kind for b in sb.blocks if b.fixed]
    assert kinds == ["foundation", "wall", "wall"]


def test_voronoi_polygon_and_layers():
    poly = [(0, 0), (30, 0), (30, 6), (18, 6), (10, 14), (0, 14)]
    top = [(0, 3), (30, 5)]
    sb = S.voronoi_slope_blocks(polygon=poly, n=80, seed=3, layers=[(top, "weak"), (None, "top")])
    slope = _check_tiling(sb)
    _check_follows(slope, top)
    for b in slope:
        c = S.polygon_centroid(b.vertices)
        below = c[1] < 3 + c[0] * 2 / 30
        assert b.layer == (0 if below else 1)


def test_triangles():
    """triangle_slope_blocks (the blocks of plastic soil): the same region, cuts and fixed blocks as the Voronoi
    builder, in triangles (cut along the joints and cracks, where a cut crosses one: then convex polygons)."""
    sb = S.triangle_slope_blocks(SURF, 0.0, spacing=1.5, joints=[PLANE], cracks=[VCRACK, FOLDED])
    assert sb.pattern == "triangles" and sb.slope_area == S.region_area(SURF, 0.0)
    slope = _check_tiling(sb)
    assert sum(1 for b in slope if len(b.vertices) == 3) > 0.8 * len(slope)
    assert max(math.dist(b.vertices[i - 1], b.vertices[i]) for b in slope for i in range(len(b.vertices))) <= 1.5 * (1 + 1e-9)
    for line in (PLANE, VCRACK, FOLDED):
        _check_follows(slope, line)
    assert [b.kind for b in sb.blocks if b.fixed] == ["foundation", "wall", "wall"]
    poly = [(0, 0), (30, 0), (30, 6), (18, 6), (10, 14), (0, 14)]
    sb = S.triangle_slope_blocks(polygon=poly, spacing=2.0, layers=[([(0, 3), (30, 5)], "weak"), (None, "top")])
    _check_follows(_check_tiling(sb), [(0, 3), (30, 5)])
    other = S.triangle_slope_blocks(SURF, 0.0, spacing=1.5, joints=[PLANE], cracks=[VCRACK, FOLDED], seed=3)
    assert [b.vertices for b in other.blocks] != [b.vertices for b in sb.blocks]  # another mesh of the same slope
    _check_tiling(other)  # (a cut passing close to a moved vertex may leave a sliver, merged by the builder's policy)
    with pytest.raises(ValueError, match="triangle_slope_blocks: give spacing"):
        S.triangle_slope_blocks(SURF, 0.0)
    with pytest.raises(ValueError, match="triangle_slope_blocks: give exactly one of surface"):
        S.triangle_slope_blocks(SURF, 0.0, spacing=1.0, polygon=poly)


def test_columns_stepped_base():
    sb = S.column_blocks(SURF, STEPS, 1.0, block_h=3.0, cracks=[FOLDED])
    slope = _check_tiling(sb)
    # closed form: area under the ground minus the steps
    assert sb.slope_area == pytest.approx(S.region_area(SURF, 0.0) - 4 * 1 - 14 * 2)
    _check_follows(slope, FOLDED)
    tall = [b for b in slope if max(v[0] for v in b.vertices) - min(v[0] for v in b.vertices) <= 1 + 1e-12]
    assert len(tall) > 0.8 * len(slope)  # narrow columns (the crack cuts a few)
    for b in slope:  # every column stands on the step below it
        x = S.polygon_centroid(b.vertices)[0]
        assert min(v[1] for v in b.vertices) >= (0 if x < 6 else 1 if x < 10 else 2) - 1e-12
    fixed = [b for b in sb.blocks if b.fixed]
    assert sum(b.kind == "foundation" for b in fixed) == 3 + 2 and sum(b.kind == "wall" for b in fixed) == 2


# Goodman & Bray's geometry: flat-topped columns, the ground stepping up by a riser at each column's side
STEPPED_GROUND = [(0, 3), (2, 3), (2, 9.5), (4, 9.5), (4, 12), (6, 12)]
STEPPED_BASE = [(0, 0), (2, 0), (2, 0.5), (4, 0.5), (4, 1), (6, 1)]


def test_columns_stepped_ground():
    """column_blocks on a ground with risers (repeated x): every column a rectangle with a flat top at its own
    height, the riser a face of the taller column and open to the sky beside the lower one."""
    sb = S.column_blocks(STEPPED_GROUND, STEPPED_BASE, 2.0, wall=0.0)
    slope = _check_tiling(sb)
    assert sb.slope_area == pytest.approx(2 * 3 + 2 * 9 + 2 * 11, rel=1e-15)
    rects = sorted((min(v[0] for v in b.vertices), min(v[1] for v in b.vertices), max(v[0] for v in b.vertices),
                    max(v[1] for v in b.vertices), len(b.vertices)) for b in slope)
    assert rects == [(0, 0, 2, 3, 4), (2, 0.5, 4, 9.5, 4), (4, 1, 6, 12, 4)]
    level = S.column_blocks([(0, 3), (2, 3), (2, 3), (4, 3.5)], 0.0, 2.0)  # a riser of no height: none
    assert [len(b.vertices) for b in level.blocks if b.kind == "slope"] == [4, 4]
    for ground, match in (([(0, 3), (0, 4), (2, 4), (6, 12)], "riser at an end"),
                          ([(0, 3), (2, 3), (2, 5), (2, 9.5), (6, 12)], "more than one riser at x = 2"),
                          ([(0, 3), (2, 3), (1, 4), (6, 12)], "non-decreasingly")):
        with pytest.raises(ValueError, match=match):
            S.column_blocks(ground, 0.0, 2.0)
    with pytest.raises(ValueError, match="x must be strictly increasing"):  # (risers are the columns' only)
        S.brick_blocks(STEPPED_GROUND, 0.0, 2.0, 1.0)


def test_bricks_any_crack_and_layers():
    sb = S.brick_blocks(SURF, 0.0, 2.0, 1.0, joints=[PLANE], cracks=[VCRACK, FOLDED], layers=LAYERS)
    slope = _check_tiling(sb)
    for line in (PLANE, VCRACK, FOLDED, LAYERS[0][0], LAYERS[1][0]):
        _check_follows(slope, line)
    assert {b.layer for b in slope} == {0, 1, 2}
    for b in slope:
        x, y = S.polygon_centroid(b.vertices)
        assert b.layer == (0 if y < S._interp_y(LAYERS[0][0], x) else 1 if y < S._interp_y(LAYERS[1][0], x) else 2)


def test_cut_keeps_shared_points_exact():
    # two squares sharing an edge, cut by one inclined segment: identical crossing point on the edge
    sq = [[(0, 0), (1, 0), (1, 1), (0, 1)], [(1, 0), (2, 0), (2, 1), (1, 1)]]
    pieces = S.cut_polygons(sq, [[(0.1, 0.13), (1.9, 0.77)]])
    assert len(pieces) == 4
    on_edge = {v for p in pieces for v in p if v[0] == 1 and 0 < v[1] < 1}
    assert len(on_edge) == 1
    assert sum(S.polygon_area(p) for p in pieces) == pytest.approx(2.0, rel=1e-14)
    # a segment that stops short of a block does not cut it
    assert len(S.cut_polygons(sq, [[(0.2, 0.5), (0.8, 0.5)]])) == 3
