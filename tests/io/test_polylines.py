"""Block outlines from drawn polylines (yade_rbsm.io.polylines, no YADE): closure, repeats,
orientation, self-intersection."""
import pytest

from yade_rbsm.io.polylines import block_outline, self_intersection, signed_area

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]


def test_counter_clockwise_ring_is_kept():
    assert block_outline(SQUARE, True, "w") == (SQUARE, False)


def test_clockwise_ring_is_reversed():
    ring, rev = block_outline(SQUARE[::-1], True, "w")
    assert rev and signed_area(ring) == 1 and ring == SQUARE[::-1][::-1]


def test_closing_vertex_and_repeats():
    assert block_outline(SQUARE + [SQUARE[0]], False, "w")[0] == SQUARE
    assert block_outline([(0, 0), (1, 0), (1, 0), (1, 1), (0, 1)], True, "w")[0] == SQUARE


@pytest.mark.parametrize("pts,closed,message", [
    (SQUARE, False, "w: open polyline"),
    ([(0, 0), (1, 1), (1, 0), (0, 1)], True, "w: self-intersecting polyline: edge 0"),
    ([(0, 0), (1, 0), (0, 0)], True, "w: fewer than 3 distinct vertices"),
    ([(0, 0), (1, 0), (2, 0)], True, "w: zero area"),
])
def test_refused(pts, closed, message):
    with pytest.raises(ValueError) as e:
        block_outline(pts, closed, "w")
    assert str(e.value).startswith(message), str(e.value)


def test_self_intersection_touching_vertex():
    # vertex 3 lies on edge 0: a pinched outline
    assert self_intersection([(0, 0), (2, 0), (2, 2), (1, 0), (0, 2)]) == (0, 2)
    assert self_intersection(SQUARE) is None


@pytest.mark.parametrize("far", [1e6, 1e9, 1e12, 1e15])
def test_far_from_the_origin(far):
    """Issue 34, item 14: a valid 1 m block at (1e12, 1e12) was refused as "clockwise": its area, summed from
    world coordinates, lost every digit to cancellation and came out with the wrong sign, so the ring was
    reversed. The area is taken relative to the first vertex (geometry.signed_area)."""
    ccw = [(far, far), (far + 1, far), (far + 1, far + 1), (far, far + 1)]
    ring, reversed_ = block_outline(ccw, True, "block")
    assert not reversed_ and ring == ccw
    ring, reversed_ = block_outline(ccw[::-1], True, "block")
    assert reversed_ and ring == ccw[::-1][::-1]
    assert signed_area(ccw) == pytest.approx(1.0, rel=1e-12)
