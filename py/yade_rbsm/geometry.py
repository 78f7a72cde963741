"""Plane geometry of points, polylines and polygons, in pure Python (no YADE, no package imports):
the one home of the shoelace sums, point-segment distances, polyline checks and the convex cuts
that blocks.py, slope.py and safety.py share.

Points are ``(x, y)`` pairs; polygons lists of points (counter-clockwise unless said otherwise);
polylines lists of points, usually with strictly increasing x (ground, joints, slip surfaces).
The sums run in a fixed order, vertex by vertex, so results are the same to the last bit on every
call (block areas and cuts feed the scene). Input checks raise ValueError naming the argument.

slope.py is also loaded as a plain file (tests without YADE) and then loads this one beside it:
keep this module free of relative imports.
"""
import math

__all__ = ["polygon_area", "signed_area", "polygon_properties", "polygon_centroid", "z_order", "region_area",
           "point_segment_distance", "point_polyline_distance", "height_above", "interp_y", "Line", "segment_at",
           "clip", "split_by_line", "clean", "split_convex", "cut_polygons", "segments_intersect", "circle_through",
           "points", "monotone", "check_polyline", "check_polygon"]


# ---------------------------------------------------------------------------------------------
# areas and moments (shoelace)
# ---------------------------------------------------------------------------------------------
def _shoelace(poly, ox=0.0, oy=0.0, second=False):
    """The shoelace sums of a polygon, coordinates taken relative to (ox, oy): with the edge cross
    products c = x0·y1 - x1·y0, ``(Σc, Σc(x0+x1), Σc(y0+y1), Σc(x0²+x0x1+x1²+y0²+y0y1+y1²))`` (the
    last one only with *second*, else 0): twice the signed area, six times the first moments, twelve
    times the polar second moment about (ox, oy)."""
    n = len(poly)
    a2 = sx = sy = j = 0.0
    for i in range(n):
        x0, y0 = poly[i][0] - ox, poly[i][1] - oy
        x1, y1 = poly[(i + 1) % n][0] - ox, poly[(i + 1) % n][1] - oy
        c = x0 * y1 - x1 * y0
        a2 += c
        sx += c * (x0 + x1)
        sy += c * (y0 + y1)
        if second:
            j += c * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
    return a2, sx, sy, j


def polygon_area(poly):
    """Signed area (> 0 counter-clockwise), from the world coordinates as given."""
    return 0.5 * _shoelace(poly)[0]


def signed_area(vertices):
    """Signed area (> 0 counter-clockwise), coordinates relative to the first vertex (small
    round-off far from the origin)."""
    ox, oy = vertices[0]
    return 0.5 * _shoelace(vertices, ox, oy)[0]


def polygon_properties(vertices):
    """Area, centroid and polar second moment J about the centroid of a polygon given
    counter-clockwise (shoelace formulas; J = ∫(x²+y²)dA, m⁴). Coordinates relative to the
    first vertex keep round-off small far from the origin."""
    ox, oy = vertices[0]
    a2, cx, cy, j = _shoelace(vertices, ox, oy, second=True)
    area = a2 / 2.0
    if area == 0:
        raise ValueError("degenerate polygon (zero area)")
    cx, cy = cx / (6 * area), cy / (6 * area)
    j = j / 12.0 - area * (cx * cx + cy * cy)
    return area, (cx + ox, cy + oy), j


def polygon_centroid(poly):
    """Centroid of a polygon (coordinates relative to the first vertex)."""
    ox, oy = poly[0]
    a2, cx, cy, _ = _shoelace(poly, ox, oy)
    return cx / (3 * a2) + ox, cy / (3 * a2) + oy


def _spread_bits(v):
    """The 16 low bits of v moved to the even bit positions (0, 2, 4, ...)."""
    v &= 0xFFFF
    v = (v | (v << 8)) & 0x00FF00FF
    v = (v | (v << 4)) & 0x0F0F0F0F
    v = (v | (v << 2)) & 0x33333333
    return (v | (v << 1)) & 0x55555555


def z_order(points):
    """Indices of *points* sorted along a Z-order (Morton) curve over their bounding square, 2^16 cells a
    side: points near each other in the plane get near places in the order (ties keep their order)."""
    if not points:
        return []
    x0, y0 = min(p[0] for p in points), min(p[1] for p in points)
    span = max(max(p[0] for p in points) - x0, max(p[1] for p in points) - y0)
    scale = 65535.0 / span if span > 0 else 0.0

    def key(p):
        return _spread_bits(int((p[0] - x0) * scale)) | (_spread_bits(int((p[1] - y0) * scale)) << 1)
    keys = [key(p) for p in points]
    return sorted(range(len(points)), key=keys.__getitem__)


def region_area(surface, base):
    """Closed form: area between the ground polyline and y = base (trapezoids)."""
    return sum(0.5 * ((ya - base) + (yb - base)) * (xb - xa)
               for (xa, ya), (xb, yb) in zip(surface[:-1], surface[1:]))


# ---------------------------------------------------------------------------------------------
# distances and sides
# ---------------------------------------------------------------------------------------------
def point_segment_distance(p, a, b):
    """Distance from p to the segment a-b (a point if a == b)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def point_polyline_distance(p, poly):
    """Distance from p to the polyline (inf for fewer than 2 points)."""
    best = float("inf")
    for a, b in zip(poly[:-1], poly[1:]):
        best = min(best, point_segment_distance(p, a, b))
    return best


def height_above(p, poly):
    """> 0 if p is above the polyline (x increasing): vertical offset, constant extrapolation
    beyond its ends."""
    xs = [q[0] for q in poly]
    x = min(max(p[0], xs[0]), xs[-1])
    for (xa, ya), (xb, yb) in zip(poly[:-1], poly[1:]):
        if xa <= x <= xb:
            y = ya if xb == xa else ya + (x - xa) * (yb - ya) / (xb - xa)
            return p[1] - y
    return 0.0


def _lerp(u, ua, va, ub, vb):
    """v at u on the straight line through (ua, va) and (ub, vb), exact at those two points."""
    if u == ua:
        return va
    if u == ub:
        return vb
    return va + (u - ua) * (vb - va) / (ub - ua)


class Line:
    """One straight segment of a polyline, with exact evaluation at its end vertices."""

    def __init__(self, a, b):
        self.a, self.b = (float(a[0]), float(a[1])), (float(b[0]), float(b[1]))

    def y(self, x):
        (xa, ya), (xb, yb) = self.a, self.b
        return _lerp(x, xa, ya, xb, yb)

    def x(self, y):
        (xa, ya), (xb, yb) = self.a, self.b
        return _lerp(y, ya, xa, yb, xb)

    def side(self, p):
        """> 0 above the line, < 0 below."""
        return p[1] - self.y(p[0])

    def cross(self, p, q):
        if p[0] == q[0]:
            return (p[0], self.y(p[0]))
        if p[1] == q[1]:
            return (self.x(p[1]), p[1])
        dp, dq = self.side(p), self.side(q)
        t = dp / (dp - dq)
        return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))


def segment_at(poly, xa, xb):
    """The segment (a :class:`Line`) of *poly* containing the strip [xa, xb] (the strip never
    straddles a kink); None if none does."""
    xm = 0.5 * (xa + xb)
    for a, b in zip(poly[:-1], poly[1:]):
        if a[0] <= xm <= b[0]:
            return Line(a, b)
    return None


def interp_y(poly, x):
    """y of the polyline (strictly increasing x) at x, constant beyond its ends."""
    if x <= poly[0][0]:
        return poly[0][1]
    if x >= poly[-1][0]:
        return poly[-1][1]
    for a, b in zip(poly[:-1], poly[1:]):
        if a[0] <= x <= b[0]:
            return Line(a, b).y(x)
    return poly[-1][1]


def segments_intersect(p, q, r, s):
    """Closed segments pq and rs intersect (touching counts)."""
    def orient(a, b, c):
        v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return (v > 0) - (v < 0)

    def on(a, b, c):
        return min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1])
    o1, o2, o3, o4 = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
    if o1 != o2 and o3 != o4:
        return True
    return ((o1 == 0 and on(p, q, r)) or (o2 == 0 and on(p, q, s)) or (o3 == 0 and on(r, s, p))
            or (o4 == 0 and on(r, s, q)))


def circle_through(a, b, c):
    """(xc, yc, R) of the circle through three points."""
    (ax, ay), (bx, by), (cx, cy) = a, b, c
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if d == 0:
        raise ValueError("circle_through: collinear points")
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


# ---------------------------------------------------------------------------------------------
# cutting convex polygons
# ---------------------------------------------------------------------------------------------
def clean(poly, eps):
    """Drops repeated vertices (closer than eps) and collinear ones (turn below eps per unit length);
    [] if fewer than 3 remain."""
    res = []
    for p in poly:
        if not res or (abs(p[0] - res[-1][0]) > eps or abs(p[1] - res[-1][1]) > eps):
            res.append(p)
    while len(res) > 1 and abs(res[0][0] - res[-1][0]) <= eps and abs(res[0][1] - res[-1][1]) <= eps:
        res.pop()
    changed = True
    while changed and len(res) >= 3:
        changed = False
        for i in range(len(res)):
            a, b, c = res[i - 1], res[i], res[(i + 1) % len(res)]
            cr = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            L = math.hypot(c[0] - a[0], c[1] - a[1])
            if abs(cr) <= eps * max(L, eps):
                del res[i]
                changed = True
                break
    return res if len(res) >= 3 else []


def clip(poly, line, keep_below, eps):
    """The part of the convex polygon above (or, *keep_below*, below) the :class:`Line`, cleaned
    (:func:`clean`); [] if nothing is left."""
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        sp, sq = line.side(p), line.side(q)
        if keep_below:
            sp, sq = -sp, -sq
        pin = sp >= -eps
        if pin:
            out.append(p)
        if (sp > eps and sq < -eps) or (sp < -eps and sq > eps):
            out.append(line.cross(p, q))
    # repeated and collinear vertices dropped as for every other cut
    return clean(out, eps)


def split_by_line(polys, line, eps):
    """Each convex polygon cut along the :class:`Line` into its parts below and above it (in that
    order; empty parts dropped)."""
    out = []
    for p in polys:
        for below in (True, False):
            q = clip(p, line, below, eps)
            if q:
                out.append(q)
    return out


def split_convex(poly, a, b, eps):
    """Split the convex CCW polygon *poly* by the line through the segment a-b if the *segment*
    reaches into its interior; returns [left, right] or None. The crossing point on an edge is
    computed from the edge's end points in lexicographic order, so two blocks sharing the edge get
    bit-identical points."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)

    def side(p):
        return (dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / L

    s = [side(p) for p in poly]
    if max(s) <= eps or min(s) >= -eps:
        return None
    n = len(poly)
    left, right, ts = [], [], []
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        sp, sq = s[i], s[(i + 1) % n]
        if sp >= -eps:
            left.append(p)
        if sp <= eps:
            right.append(p)
        if abs(sp) <= eps:
            ts.append(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (L * L))
        if (sp > eps and sq < -eps) or (sp < -eps and sq > eps):
            (u, su), (v, sv) = sorted([(p, sp), (q, sq)])
            t = su / (su - sv)
            x = (u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1]))
            left.append(x)
            right.append(x)
            ts.append(((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / (L * L))
    if not ts or max(ts) <= eps / L or min(ts) >= 1 - eps / L:
        return None  # the line crosses the block, the segment does not reach it
    return [q for q in (clean(left, eps), clean(right, eps)) if q]


def cut_polygons(polys, polylines, eps=None):
    """Cut convex CCW polygons along polylines (any direction, any number of vertices): every
    polygon that a segment of a polyline reaches into is split in two by the segment's line (the
    cut runs across the whole block, so a block containing a kink or an end of the polyline is cut
    a little beyond it: the extension is an ordinary joint). Pieces stay convex and CCW; blocks on
    either side of a cut share its end points exactly. Returns the list of pieces."""
    polys = [list(p) for p in polys]
    if not polys:
        return []
    if eps is None:
        xs = [p[0] for q in polys for p in q]
        ys = [p[1] for q in polys for p in q]
        eps = 1e-12 * max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    for line in polylines:
        for a, b in zip(line[:-1], line[1:]):
            if a == b:
                continue
            out = []
            for p in polys:
                r = split_convex(p, a, b, eps)
                out.extend(r if r else [p])
            polys = out
    return polys


# ---------------------------------------------------------------------------------------------
# input checks
# ---------------------------------------------------------------------------------------------
def points(name, seq, at_least=1):
    """List of finite (x, y) float pairs; ValueError naming *name* otherwise."""
    if seq is None:
        raise ValueError("%s: none given" % name)
    try:
        pts = [(float(x), float(y)) for x, y in seq]
    except (TypeError, ValueError):
        raise ValueError("%s must be a sequence of (x, y) pairs, got %r" % (name, seq)) from None
    if len(pts) < at_least:
        raise ValueError("%s needs at least %d points, got %d%s" % (name, at_least, len(pts),
                                                                    " (empty list)" if not pts else ""))
    if not all(math.isfinite(c) for p in pts for c in p):
        raise ValueError("%s contains NaN or inf" % name)
    return pts


def monotone(name, seq, strict=True):
    """A polyline of at least 2 finite points with increasing x (strictly, or with *strict* False
    non-decreasing); ValueError naming *name* and the first bad x otherwise."""
    pts = points(name, seq, 2)
    bad = [a for a, b in zip(pts[:-1], pts[1:]) if (b[0] <= a[0] if strict else b[0] < a[0])]
    if bad:
        raise ValueError("%s: x must be %s increasing (at x = %g)" % (name, "strictly" if strict else "non-decreasingly",
                                                                        bad[0][0]))
    return pts


def check_polyline(surface, name="slip surface"):
    """The polyline as float pairs: at least 2 finite points with strictly increasing x."""
    return monotone(name, surface)


def check_polygon(poly, name="slope polygon"):
    """The vertices of a simple polygon (either orientation) as float pairs; ValueError naming the
    problem: fewer than 3 vertices, NaN/inf, a repeated vertex, zero area, edges that cross or touch
    (not simple)."""
    pts = points(name, poly, 3)
    if len(set(pts)) != len(pts):
        raise ValueError("%s: repeated vertex" % name)
    n = len(pts)
    for i in range(n):
        for j in range(i + 1, n):
            if j == i + 1 or (i == 0 and j == n - 1):
                continue  # adjacent edges share a vertex
            if segments_intersect(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]):
                raise ValueError("%s is not simple: edge %d (%g, %g)-(%g, %g) meets edge %d" % (
                    name, i, pts[i][0], pts[i][1], pts[(i + 1) % n][0], pts[(i + 1) % n][1], j))
    if polygon_area(pts) == 0:
        raise ValueError("%s has zero area" % name)
    return pts
