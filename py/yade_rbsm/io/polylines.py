"""Checks that turn a drawn closed polyline into a block outline (pure Python, no YADE): closure,
repeated vertices, self-intersection, orientation. Used by the DXF importer."""

from ..geometry import signed_area as _relative_area

__all__ = ["block_outline", "signed_area", "self_intersection"]


def signed_area(pts):
    """Shoelace area, > 0 for a counter-clockwise ring, relative to its first vertex (geometry.signed_area):
    from world coordinates a 1 m block at (1e12, 1e12) lost every digit and its sign."""
    return _relative_area(pts)


def _orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _on_segment(a, b, p):
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def _segments_meet(a, b, c, d):
    """Whether the closed segments ab and cd have a point in common (exact for exact inputs)."""
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    if ((o1 > 0 and o2 < 0) or (o1 < 0 and o2 > 0)) and ((o3 > 0 and o4 < 0) or (o3 < 0 and o4 > 0)):
        return True
    return ((o1 == 0 and _on_segment(a, b, c)) or (o2 == 0 and _on_segment(a, b, d))
            or (o3 == 0 and _on_segment(c, d, a)) or (o4 == 0 and _on_segment(c, d, b)))


def self_intersection(pts):
    """(i, j) of the first pair of non-adjacent edges (edge i: vertex i -> i+1) that meet, else None.
    O(n²): drawn blocks have few vertices."""
    n = len(pts)
    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # adjacent through the closing vertex
            if _segments_meet(a, b, pts[j], pts[(j + 1) % n]):
                return i, j
    return None


def block_outline(pts, closed, where):
    """Counter-clockwise vertex list of the ring *pts* (x, y) drawn as a polyline; *closed*: the
    polyline's closed flag. A last vertex equal to the first closes it too; exact consecutive
    repeats are dropped; a clockwise ring is reversed (drawing direction carries no meaning in CAD).
    Raises ValueError starting with *where* for an open polyline, fewer than 3 distinct vertices, a
    self-intersecting ring or zero area. Returns (vertices, reversed)."""
    pts = [(float(x), float(y)) for x, y in pts]
    if len(pts) >= 2 and pts[0] == pts[-1]:
        pts.pop()
        closed = True
    if not closed:
        raise ValueError("%s: open polyline (a block needs a closed one: set its closed flag or end it at its first vertex)" % where)
    ring = [p for i, p in enumerate(pts) if p != pts[i - 1]] if len(pts) > 1 else pts
    if len(ring) < 3:
        raise ValueError("%s: fewer than 3 distinct vertices" % where)
    hit = self_intersection(ring)
    if hit:
        i, j = hit
        raise ValueError("%s: self-intersecting polyline: edge %d (%g, %g)-(%g, %g) meets edge %d (%g, %g)-(%g, %g)" % (
            where, i, *ring[i], *ring[(i + 1) % len(ring)], j, *ring[j], *ring[(j + 1) % len(ring)]))
    area = signed_area(ring)
    if area == 0:
        raise ValueError("%s: zero area" % where)
    if area < 0:
        return ring[::-1], True
    return ring, False
