"""Bad input of the slope helpers (yade_rbsm.slope, pure Python; issue 6): each case raises
ValueError whose message names the problem. Tried: empty surface / joint / crack / layer lists
entries, NaN and inf coordinates, non-increasing surface x, ground below the base, non-positive or
NaN block sizes, a crack or joint polyline that misses the slope, a slope polygon that is not
simple (bow tie, touching edges), a repeated vertex, a zero-area polygon, Voronoi with both or
neither of surface and polygon, malformed layers (not pairs, None top not last, top not spanning
the slope, no material), a stepped base that does not span the slope or rises above the ground.
(Bad input of the factor-of-safety helpers, which need YADE, is in test_circle_slip.py.)"""
import math

import pytest

from conftest import load_slope

S = load_slope()
SURF = [(0, 2), (6, 2), (14, 12), (24, 12)]
NAN = float("nan")

CASES = [
    ("brick surface empty", lambda: S.brick_blocks([], 0.0, 1, 1), "empty"),
    ("brick surface NaN", lambda: S.brick_blocks([(0, 2), (NAN, 3)], 0.0, 1, 1), "NaN"),
    ("brick surface inf", lambda: S.brick_blocks([(0, 2), (5, math.inf)], 0.0, 1, 1), "NaN or inf"),
    ("brick surface order", lambda: S.brick_blocks([(0, 1), (0, 2)], 0.0, 1, 1), "increasing"),
    ("brick base above ground", lambda: S.brick_blocks(SURF, 5.0, 1, 1), "above the base"),
    ("brick base NaN", lambda: S.brick_blocks(SURF, NAN, 1, 1), "base"),
    ("brick width 0", lambda: S.brick_blocks(SURF, 0.0, 0, 1), "brick_w"),
    ("brick height NaN", lambda: S.brick_blocks(SURF, 0.0, 1, NAN), "brick_h"),
    ("crack empty", lambda: S.brick_blocks(SURF, 0.0, 1, 1, cracks=[[]]), "cracks[0]"),
    ("crack one point", lambda: S.brick_blocks(SURF, 0.0, 1, 1, cracks=[[(3, 1)]]), "at least 2"),
    ("crack NaN", lambda: S.brick_blocks(SURF, 0.0, 1, 1, cracks=[[(3, 1), (NAN, 2)]]), "NaN"),
    ("crack misses", lambda: S.brick_blocks(SURF, 0.0, 1, 1, cracks=[[(30, 1), (40, 2)]]), "misses the slope"),
    ("joint misses", lambda: S.column_blocks(SURF, 0.0, 1, joints=[[(1, 20), (5, 30)]]), "misses the slope"),
    ("layers not pairs", lambda: S.brick_blocks(SURF, 0.0, 1, 1, layers=[3]), "pair"),
    ("layers None not last", lambda: S.brick_blocks(SURF, 0.0, 1, 1, layers=[(None, "a"), ([(0, 1), (24, 1)], "b")]),
     "only the last"),
    ("layer top short", lambda: S.brick_blocks(SURF, 0.0, 1, 1, layers=[([(0, 1), (10, 1)], "a"), (None, "b")]),
     "span the slope"),
    ("layer no material", lambda: S.brick_blocks(SURF, 0.0, 1, 1, layers=[(None, None)]), "no material"),
    ("layer top NaN", lambda: S.brick_blocks(SURF, 0.0, 1, 1, layers=[([(0, NAN), (24, 1)], "a")]), "NaN"),
    ("columns width NaN", lambda: S.column_blocks(SURF, 0.0, NAN), "width"),
    ("columns base short", lambda: S.column_blocks(SURF, [(0, 0), (10, 0)], 1.0), "must run from"),
    ("columns base above ground", lambda: S.column_blocks(SURF, [(0, 0), (6, 0), (6, 3), (24, 3)], 1.0), "below the ground"),
    ("voronoi no region", lambda: S.voronoi_slope_blocks(n=10), "exactly one of surface"),
    ("voronoi both", lambda: S.voronoi_slope_blocks(SURF, 0.0, polygon=[(0, 0), (1, 0), (0, 1)], n=10), "exactly one"),
    ("polygon bow tie", lambda: S.voronoi_slope_blocks(polygon=[(0, 0), (4, 4), (4, 0), (0, 4)], n=10), "not simple"),
    ("polygon touching", lambda: S.voronoi_slope_blocks(polygon=[(0, 0), (4, 0), (4, 4), (2, 0.0), (0, 4)], n=10),
     "not simple"),
    ("polygon repeated vertex", lambda: S.check_polygon([(0, 0), (1, 0), (1, 0), (0, 1)]), "repeated"),
    ("polygon zero area", lambda: S.check_polygon([(0, 0), (1, 1), (2, 2)]), "zero area"),
    ("polygon empty", lambda: S.check_polygon([]), "empty"),
    ("polygon NaN", lambda: S.voronoi_slope_blocks(polygon=[(0, 0), (1, NAN), (0, 1)], n=10), "NaN"),
    ("voronoi spacing NaN", lambda: S.voronoi_slope_blocks(SURF, 0.0, spacing=NAN), "spacing"),
]


@pytest.mark.parametrize("label,fn,word", CASES, ids=[c[0] for c in CASES])
def test_value_error(label, fn, word):
    with pytest.raises(ValueError) as e:
        fn()
    assert word in str(e.value), str(e.value)
