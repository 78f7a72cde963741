"""Brick builder: the blocks tile the slope (area) and the blocks on either side of a joint share
their edges exactly (every interior edge is covered, with the same coordinates, by edges of
neighbours)."""
import math

import pytest

from conftest import load_slope

S = load_slope()
SURF = [(0, 2), (6, 2), (14, 12), (24, 12)]
PLANE = [(6, 2), (17, 2 + 11 * math.tan(math.radians(35)))]


def _cases():
    yield dict(surface=SURF, base=0.0, brick_w=2.0, brick_h=1.0)
    yield dict(surface=SURF, base=0.0, brick_w=2.0, brick_h=1.0, joints=[PLANE], crack=(17.0, PLANE[1][1]))
    yield dict(surface=[(0, 1.3), (3.7, 1.3), (9.1, 7.9), (15, 8.4)], base=-0.5, brick_w=1.3, brick_h=0.7,
               joints=[[(3.7, 1.3), (12, 6.1)]], crack=(12.0, 6.1))


def _on_boundary(a, b, sb):
    x0, xn = sb.surface[0][0], sb.surface[-1][0]
    if a[1] == b[1] == sb.base or a[0] == b[0] == x0 or a[0] == b[0] == xn:
        return True
    for p, q in zip(sb.surface[:-1], sb.surface[1:]):  # on the ground polyline
        for r in (a, b):
            cr = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
            if abs(cr) > 1e-9 or not (min(p[0], q[0]) - 1e-12 <= r[0] <= max(p[0], q[0]) + 1e-12):
                break
        else:
            return True
    return False


def _overlap(a, b, c, d):
    """Length of overlap of segment cd with ab if collinear (exactly, up to 1e-12), else 0."""
    ux, uy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(ux, uy)
    for r in (c, d):
        if abs(ux * (r[1] - a[1]) - uy * (r[0] - a[0])) > 1e-12 * L:
            return 0.0
    t = sorted(((r[0] - a[0]) * ux + (r[1] - a[1]) * uy) / L for r in (c, d))
    return max(0.0, min(L, t[1]) - max(0.0, t[0]))


@pytest.mark.parametrize("kw", list(_cases()))
def test_area_and_shared_edges(kw):
    sb = S.brick_blocks(**kw)
    slope = [b for b in sb.blocks if b.kind == "slope"]
    area = sum(b.area for b in slope)
    assert area + sb.dropped_area == pytest.approx(S.region_area(kw["surface"], kw["base"]), rel=1e-12)
    assert sb.dropped_area < 1e-3 * area
    for b in slope:
        assert b.area > 0 and S.polygon_area(b.vertices) > 0  # counter-clockwise
        n = len(b.vertices)
        for i in range(n):  # convex
            p, q, r = b.vertices[i - 1], b.vertices[i], b.vertices[(i + 1) % n]
            assert (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]) > 0
    if sb.dropped_area > 0:
        return  # a dropped sliver leaves an uncovered edge
    edges = [(b.vertices[i], b.vertices[(i + 1) % len(b.vertices)], k)
             for k, b in enumerate(slope) for i in range(len(b.vertices))]
    for a, b, k in edges:
        if _on_boundary(a, b, sb):
            continue
        covered = sum(_overlap(a, b, d, c) for c, d, j in edges if j != k)
        assert covered == pytest.approx(math.dist(a, b), rel=1e-9), (a, b)


def test_crack_is_a_joint():
    xc, yc = 17.0, PLANE[1][1]
    sb = S.brick_blocks(SURF, 0.0, 2.0, 1.0, joints=[PLANE], crack=(xc, yc))
    on = [b for b in sb.blocks if b.kind == "slope" and any(v[0] == xc for v in b.vertices)
          and min(v[1] for v in b.vertices) >= yc - 1e-12]
    assert on, "blocks above the crack tip must have an edge on x = xc"


def test_bad_input():
    with pytest.raises(ValueError):
        S.brick_blocks([(0, 1), (0, 2)], 0.0, 1, 1)
    with pytest.raises(ValueError):
        S.brick_blocks(SURF, 5.0, 1, 1)
