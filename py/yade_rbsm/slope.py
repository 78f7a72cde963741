"""Slope of RBSM blocks: geometry (pure Python) and scene set-up (YADE).

Geometry
--------
The slope region is ``{(x, y): x0 <= x <= xn, base <= y <= g(x)}`` with ``g`` the ground-surface
polyline (strictly increasing x), e.g. toe flat, face, crest flat. :func:`brick_blocks` cuts it into
a regular brick pattern:

* rows of height ``brick_h`` from ``base`` upwards; in row j the vertical joints are at
  ``x0 + (i + offset_j)·brick_w`` with ``offset_j = 0`` for even rows and ``0.5`` (staggered) for odd
  rows;
* every brick is also split at the x of every kink of the ground polyline, of every *joint*
  polyline (e.g. a pre-existing inclined slip plane) and at the crack abscissa, so that within one
  piece each of those polylines is a single straight segment and every piece stays convex;
* a piece is clipped to the region below the ground (half-plane of the ground segment) and split in
  two by every joint polyline crossing it (above / below);
* the crack ``(xc, yc)`` is a vertical joint at ``x = xc`` from the ground down to the row boundary
  at or below ``yc`` (rows whose top is above ``yc`` are split at ``xc``); its joints are broken
  after bonding (:func:`break_crack`);
* slivers: pieces of area below ``min_area`` (default ``1e-3·brick_w·brick_h``) are dropped; their
  total area is reported as ``dropped_area`` so that ``Σ area + dropped_area`` equals the slope area.

Intersections of a polyline with vertical piece boundaries and with horizontal row lines are
computed from the polyline *segment* (not from the piece), so the two blocks on either side of a
joint get bit-identical coordinates; along horizontal row lines the staggered bricks meet in
T-junctions (the edges overlap partially, which RBSM's edge-to-edge contact handles).

A fixed foundation block spans ``[x0 - wall, xn + wall] × [base - foundation, base]``; two fixed
walls ``[x0 - wall, x0]`` and ``[xn, xn + wall]`` (up to the ground at the ends) give the usual
roller-like lateral boundaries of a slope model.
"""
import math
from dataclasses import dataclass, field
from typing import List, Optional, Sequence, Tuple

__all__ = ["Block", "SlopeBlocks", "brick_blocks", "polygon_area", "region_area",
           "build_scene", "bond_and_break", "break_crack", "unbalanced_ratio", "settle"]


def polygon_area(poly):
    a = 0.0
    n = len(poly)
    for i in range(n):
        x0, y0 = poly[i]
        x1, y1 = poly[(i + 1) % n]
        a += x0 * y1 - x1 * y0
    return 0.5 * a


def region_area(surface, base):
    """Closed form: area between the ground polyline and y = base (trapezoids)."""
    return sum(0.5 * ((ya - base) + (yb - base)) * (xb - xa)
               for (xa, ya), (xb, yb) in zip(surface[:-1], surface[1:]))


class _Line:
    """One straight segment of a polyline, with exact evaluation at its end vertices."""

    def __init__(self, a, b):
        self.a, self.b = (float(a[0]), float(a[1])), (float(b[0]), float(b[1]))

    def y(self, x):
        (xa, ya), (xb, yb) = self.a, self.b
        if x == xa:
            return ya
        if x == xb:
            return yb
        return ya + (x - xa) * (yb - ya) / (xb - xa)

    def x(self, y):
        (xa, ya), (xb, yb) = self.a, self.b
        if y == ya:
            return xa
        if y == yb:
            return xb
        return xa + (y - ya) * (xb - xa) / (yb - ya)

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


def _segment_at(poly, xa, xb):
    """The segment of *poly* containing the strip [xa, xb] (the strip never straddles a kink)."""
    xm = 0.5 * (xa + xb)
    for a, b in zip(poly[:-1], poly[1:]):
        if a[0] <= xm <= b[0]:
            return _Line(a, b)
    return None


def _clip(poly, line, keep_below, eps):
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        sp, sq = line.side(p), line.side(q)
        if keep_below:
            sp, sq = -sp, -sq
        pin, qin = sp >= -eps, sq >= -eps
        if pin:
            out.append(p)
        if (sp > eps and sq < -eps) or (sp < -eps and sq > eps):
            out.append(line.cross(p, q))
    # snap points lying on the line onto it? no: keep, then drop duplicates
    res = []
    for p in out:
        if not res or (abs(p[0] - res[-1][0]) > eps or abs(p[1] - res[-1][1]) > eps):
            res.append(p)
    while len(res) > 1 and abs(res[0][0] - res[-1][0]) <= eps and abs(res[0][1] - res[-1][1]) <= eps:
        res.pop()
    # drop collinear vertices
    changed = True
    while changed and len(res) >= 3:
        changed = False
        for i in range(len(res)):
            a, b, c = res[i - 1], res[i], res[(i + 1) % len(res)]
            cr = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            if abs(cr) <= eps * eps * 10:
                del res[i]
                changed = True
                break
    return res if len(res) >= 3 else []


@dataclass
class Block:
    vertices: List[Tuple[float, float]]  # world, counter-clockwise
    area: float
    fixed: bool = False
    kind: str = "slope"  # slope | foundation | wall
    row: int = -1
    id: int = -1  # body id once in the scene


@dataclass
class SlopeBlocks:
    blocks: List[Block]
    surface: List[Tuple[float, float]]
    base: float
    slope_area: float
    dropped_area: float
    crack: Optional[Tuple[float, float]] = None
    joints: List[Sequence[Tuple[float, float]]] = field(default_factory=list)
    ids: List[int] = field(default_factory=list)

    @property
    def free(self):
        return [b for b in self.blocks if not b.fixed]


def brick_blocks(surface, base, brick_w, brick_h, joints=(), crack=None, foundation=1.0, wall=1.0,
                 min_area=None, stagger=0.5):
    """Cut the slope under the ground polyline *surface* (strictly increasing x) and above *base*
    into bricks (see the module docstring). *joints*: polylines (strictly increasing x) along which
    the blocks are cut too (pre-existing joints, e.g. a slip plane). *crack*: ``(xc, yc)`` vertical
    crack from the ground down to ``yc``. Returns a :class:`SlopeBlocks`; the slope blocks come
    first, then the foundation and the walls (fixed)."""
    surf = [(float(x), float(y)) for x, y in surface]
    if any(b[0] <= a[0] for a, b in zip(surf[:-1], surf[1:])):
        raise ValueError("brick_blocks: surface x must be strictly increasing")
    if any(y <= base for _, y in surf):
        raise ValueError("brick_blocks: the ground must be above the base everywhere")
    if brick_w <= 0 or brick_h <= 0:
        raise ValueError("brick_blocks: brick sizes must be > 0")
    joints = [[(float(x), float(y)) for x, y in j] for j in joints]
    x0, xn = surf[0][0], surf[-1][0]
    ytop = max(y for _, y in surf)
    scale = max(xn - x0, ytop - base)
    eps = 1e-12 * scale
    if min_area is None:
        min_area = 1e-3 * brick_w * brick_h
    kinks = set(x for x, _ in surf)
    for j in joints:
        kinks.update(x for x, _ in j if x0 < x < xn)
    blocks, dropped = [], 0.0
    nrows = int(math.ceil((ytop - base) / brick_h - 1e-9))
    for r in range(nrows):
        ya, yb = base + r * brick_h, min(base + (r + 1) * brick_h, ytop)
        xs = set(kinks)
        off = (stagger if r % 2 else 0.0) * brick_w
        k = 0
        while True:
            x = x0 + off + k * brick_w
            if x >= xn - eps:
                break
            if x > x0 + eps:
                xs.add(x)
            k += 1
        if crack is not None and yb > crack[1] + eps and x0 < crack[0] < xn:
            xs.add(float(crack[0]))
        xs = sorted(x for x in xs if x0 <= x <= xn)
        for xa, xb in zip(xs[:-1], xs[1:]):
            g = _segment_at(surf, xa, xb)
            if max(g.y(xa), g.y(xb)) <= ya + eps:
                continue
            rect = [(xa, ya), (xb, ya), (xb, yb), (xa, yb)]
            piece = _clip(rect, g, True, eps)
            if not piece:
                continue
            pieces = [piece]
            for j in joints:
                ln = _segment_at(j, xa, xb)
                if ln is None:
                    continue
                new = []
                for p in pieces:
                    for below in (True, False):
                        q = _clip(p, ln, below, eps)
                        if q:
                            new.append(q)
                pieces = new
            for p in pieces:
                a = polygon_area(p)
                if a < min_area:
                    dropped += a
                    continue
                blocks.append(Block(p, a, False, "slope", r))
    slope_area = region_area(surf, base)
    if foundation > 0:
        f = [(x0 - wall, base - foundation), (xn + wall, base - foundation), (xn + wall, base), (x0 - wall, base)]
        blocks.append(Block(f, polygon_area(f), True, "foundation"))
    if wall > 0:
        for w in ([(x0 - wall, base), (x0, base), (x0, surf[0][1]), (x0 - wall, surf[0][1])],
                  [(xn, base), (xn + wall, base), (xn + wall, surf[-1][1]), (xn, surf[-1][1])]):
            blocks.append(Block(w, polygon_area(w), True, "wall"))
    return SlopeBlocks(blocks, surf, float(base), slope_area, dropped, crack, joints)


# ---------------------------------------------------------------------------------------------
# scene (needs YADE)
# ---------------------------------------------------------------------------------------------
def build_scene(sb, material, thickness=1.0):
    """Append the blocks of *sb* to O.bodies (slope blocks free, foundation and walls fixed); sets
    ``Block.id`` and ``sb.ids`` and each body's refPos (for displacements). Returns the ids."""
    from yade import O
    from .blocks import polygon2d
    bodies = [polygon2d(b.vertices, material, thickness=thickness, fixed=b.fixed) for b in sb.blocks]
    ids = O.bodies.append(bodies)
    for b, i in zip(sb.blocks, ids):
        b.id = i
        O.bodies[i].state.refPos = O.bodies[i].state.pos
    sb.ids = list(ids)
    return sb.ids


def break_crack(sb, tol=None):
    """Break (RbsmPhys.breakJoint) every joint lying on the crack line x = xc above yc. Returns the
    number of joints broken."""
    from yade import O
    if sb.crack is None:
        return 0
    xc, yc = sb.crack
    tol = tol if tol is not None else 1e-6 * max(1.0, abs(xc))
    n = 0
    for I in O.interactions:
        if not I.isReal:
            continue
        p0, p1 = I.geom.p0, I.geom.p1
        if abs(p0[0] - xc) <= tol and abs(p1[0] - xc) <= tol and 0.5 * (p0[1] + p1[1]) > yc:
            I.phys.breakJoint()
            n += 1
    return n


def bond_and_break(sb):
    """Bond every initial joint (ip2.setCohesionNow for the first step), take that step, then break
    the crack joints. Returns (number of joints, number broken)."""
    from yade import O
    ip2 = [f for e in O.engines if hasattr(e, "physDispatcher") for f in e.physDispatcher.functors][0]
    ip2.setCohesionNow = True
    O.step()
    nj = sum(1 for I in O.interactions if I.isReal)
    return nj, break_crack(sb)


def unbalanced_ratio(ids=None, gravity=None):
    """Unbalanced-force ratio = mean over free blocks of |contact force + m·g| divided by the mean
    of |m·g| (computed from O.forces.f, the masses and NewtonIntegrator's gravity). 0 at static
    equilibrium, about 1 for blocks in free fall."""
    from yade import O
    if gravity is None:
        newton = [e for e in O.engines if type(e).__name__ == "NewtonIntegrator"][0]
        gravity = newton.gravity
    gx, gy = gravity[0], gravity[1]
    g = math.hypot(gx, gy)
    num = den = 0.0
    n = 0
    for b in O.bodies:
        if b is None or (ids is not None and b.id not in ids) or b.state.blockedDOFs == "xyzXYZ":
            continue
        f = O.forces.f(b.id)
        m = b.state.mass
        num += math.hypot(f[0] + m * gx, f[1] + m * gy)
        den += m * g
        n += 1
    return num / den if den > 0 else 0.0


def settle(tol=1e-3, max_steps=50000, check=100, damping=0.7, progress=None):
    """Initial (gravity) stage: run with NewtonIntegrator damping *damping* until the unbalanced-force
    ratio (:func:`unbalanced_ratio`) is below *tol*, checked every *check* steps, or *max_steps*.
    Restores the previous damping. Returns (converged, steps, ratio)."""
    from yade import O
    newton = [e for e in O.engines if type(e).__name__ == "NewtonIntegrator"][0]
    old = newton.damping
    newton.damping = damping
    steps, ratio = 0, float("inf")
    try:
        while steps < max_steps:
            O.run(check, True)
            steps += check
            ratio = unbalanced_ratio()
            if progress:
                progress(steps, ratio)
            if ratio < tol:
                return True, steps, ratio
        return False, steps, ratio
    finally:
        newton.damping = old
