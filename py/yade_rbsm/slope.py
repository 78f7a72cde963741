"""Slope of RBSM blocks: the block patterns (pure Python; the polygon toolbox they use is
geometry.py) and, re-exported from slope_scene.py, the scene set-up and run control (YADE).

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


def _sibling(name):
    """The package's module *name*; when this file is loaded as a plain file (tests without YADE),
    the file *name*.py beside it."""
    import importlib
    if __package__:
        return importlib.import_module("." + name, __package__)
    import importlib.util
    import os
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name + ".py")
    spec = importlib.util.spec_from_file_location("rbsm_" + name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# the polygon toolbox lives in geometry.py; its public names stay importable from here
_geometry = _sibling("geometry")
(polygon_area, region_area, polygon_centroid, cut_polygons, check_polygon, Line, segment_at, clip, split_by_line,
 clean, points, monotone, interp_y, point_segment_distance) = (
    _geometry.polygon_area, _geometry.region_area, _geometry.polygon_centroid, _geometry.cut_polygons,
    _geometry.check_polygon, _geometry.Line, _geometry.segment_at, _geometry.clip, _geometry.split_by_line,
    _geometry.clean, _geometry.points,
    _geometry.monotone, _geometry.interp_y, _geometry.point_segment_distance)
_interp_y = interp_y  # the name safety.py and tests used

__all__ = ["Block", "SlopeBlocks", "JointSet", "Trace", "jointset_blocks", "jointset_blocks_dxf", "fos", "FosResult", "SlopeModel", "brick_blocks", "column_blocks", "voronoi_slope_blocks", "triangle_slope_blocks", "slope_polygon",
           "cut_polygons", "polygon_area", "region_area", "check_polygon", "build_scene", "bond_and_break",
           "break_crack", "joints_on", "joints_of", "set_water", "set_seismic", "break_joints", "set_joint_strength", "give_joint_sets", "joint_sets", "apply_joint_sets",
           "unbalanced_ratio", "settle"]


@dataclass
class Block:
    vertices: List[Tuple[float, float]]  # world, counter-clockwise
    area: float
    fixed: bool = False
    kind: str = "slope"  # slope | foundation | wall
    row: int = -1
    id: int = -1  # body id once in the scene
    layer: int = -1  # index in SlopeBlocks.layers (-1: no layers given)


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
    cracks: List[Sequence[Tuple[float, float]]] = field(default_factory=list)  # broken after bonding
    layers: list = field(default_factory=list)  # [(top polyline or None, material)] from the bottom up
    polygon: List[Tuple[float, float]] = field(default_factory=list)  # the slope region, CCW
    pattern: str = "bricks"

    @property
    def free(self):
        return [b for b in self.blocks if not b.fixed]

    def nearest(self, points):
        """The ids of the free blocks whose centroids are nearest to each of *points* (x, y), once built."""
        cs = [(polygon_centroid(b.vertices), b.id) for b in self.free]
        return [min(cs, key=lambda c: math.hypot(c[0][0] - x, c[0][1] - y))[1] for x, y in points]

    def __repr__(self):
        nfree = len(self.free)
        return "SlopeBlocks(%s: %d free blocks, %d fixed; area %.3f m2 (closed form %.3f, slivers dropped %.2e))" % (
            self.pattern, nfree, len(self.blocks) - nfree, sum(b.area for b in self.free), self.slope_area, self.dropped_area)


def brick_blocks(surface, base, brick_w, brick_h, joints=(), crack=None, foundation=1.0, wall=1.0,
                 min_area=None, stagger=0.5, cracks=(), layers=(), sets=(), traces=()):
    """Cut the slope under the ground polyline *surface* (strictly increasing x) and above *base*
    into bricks (see the module docstring). *joints*: polylines along which the blocks are cut too
    (pre-existing joints, e.g. a slip plane; bonded). *cracks*: polylines along which the blocks are
    cut and whose joints :func:`bond_and_break` breaks after bonding (cracks with strictly increasing
    x are cut exactly like *joints*, others, e.g. vertical or folded ones, by :func:`cut_polygons`).
    *crack*: ``(xc, yc)`` vertical crack from the ground down to ``yc``. *layers*: ``[(top polyline,
    material), ...]`` from the bottom up, the last top may be None (the ground): the blocks are cut
    along the tops and each takes the layer containing its centroid (``Block.layer``). *sets*, *traces*:
    JointSets and Traces that cut the bricks and carry their strength (joint_sets.cut_by_joint_sets, as
    every builder takes them). Returns a :class:`SlopeBlocks`; the slope blocks come first, then the
    foundation and the walls (fixed)."""
    surf, base, joints, cracks, layers, foundation, wall = _common_args(surface, base, joints, cracks, layers,
                                                                      foundation, wall, "brick_blocks")
    brick_w = _number("brick_blocks: brick_w", brick_w)
    brick_h = _number("brick_blocks: brick_h", brick_h)
    if crack is not None:
        crack = points("brick_blocks: crack", [crack], 1)[0]
    def mono(l):
        return all(b[0] > a[0] for a, b in zip(l[:-1], l[1:]))
    generic = [c for c in cracks if not mono(c)] + [j for j in joints if not mono(j)]
    cut_tops = [t for t, _ in layers if t is not None]
    all_cracks, given_joints = cracks, joints
    joints = [j for j in joints if mono(j)] + [c for c in cracks if mono(c)] + cut_tops
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
            g = segment_at(surf, xa, xb)
            if max(g.y(xa), g.y(xb)) <= ya + eps:
                continue
            rect = [(xa, ya), (xb, ya), (xb, yb), (xa, yb)]
            piece = clip(rect, g, True, eps)
            if not piece:
                continue
            pieces = [piece]
            for j in joints:
                ln = segment_at(j, xa, xb)
                if ln is None:
                    continue
                pieces = split_by_line(pieces, ln, eps)
            for p in pieces:
                a = polygon_area(p)
                if a < min_area:
                    dropped += a
                    continue
                blocks.append(Block(p, a, False, "slope", r))
    if generic:  # the rows are lost: the cut pieces are no bricks of one row
        blocks, dropped = _finish([b.vertices for b in blocks], generic, min_area, (), eps, dropped)
    if layers:
        _assign_layers(blocks, layers)
    slope_area = region_area(surf, base)
    blocks += _fixed_blocks(surf, base, foundation, wall)
    return _with_sets(SlopeBlocks(blocks, surf, float(base), slope_area, dropped, crack, given_joints, cracks=all_cracks,
                                  layers=layers, polygon=slope_polygon(surf, base), pattern="bricks"), sets, traces, "brick_blocks")


def column_blocks(surface, base, width, block_h=None, joints=(), cracks=(), layers=(), foundation=1.0, wall=1.0,
                  min_area=None, sets=(), traces=()):
    """Columns for toppling: the slope under the ground polyline *surface* (increasing x; a repeated x is a
    riser, a vertical step of the ground between two columns' flat tops, as in Goodman & Bray's geometry:
    :func:`yade_rbsm.toppling.columns` reads such columns back for the limit-equilibrium comparison)
    cut by vertical joints every *width* from the left end (and at every kink of the ground and of
    the base) and, if *block_h* is given, by horizontal cross joints at ``min(base) + k·block_h``
    (aligned from column to column). *base*: a number (flat base) or a stepped base polyline from the
    left to the right end of the slope, x non-decreasing (a repeated x is a vertical riser), below
    the ground; each column stands on its own step when the steps are *width* wide. The fixed
    foundation follows the base (one block per base segment, ``foundation`` m below its lowest point)
    and the walls stand on it at both ends. *joints*, *cracks*, *layers*, *sets*, *traces*: as in
    :func:`brick_blocks` (cut with :func:`cut_polygons`)."""
    who = "column_blocks"
    surf = _with_risers("%s: surface" % who, surface)
    x0, xn = surf[0][0], surf[-1][0]
    if isinstance(base, (int, float)) and not isinstance(base, bool):
        b0 = _number("%s: base" % who, base, positive=False)
        basel = [(x0, b0), (xn, b0)]
    else:
        basel = monotone("%s: base polyline" % who, base, strict=False)
        if basel[0][0] != x0 or basel[-1][0] != xn:
            raise ValueError("%s: the base polyline must run from x = %g to x = %g (the ends of the surface)"
                             % (who, x0, xn))
    ymin = min(y for _, y in basel)
    surf, _, joints, cracks, layers, foundation, wall = _common_args(surf, ymin - 1e-9 * (1 + abs(ymin)), joints,
                                                                     cracks, layers, foundation, wall, who, risers=True)
    width = _number("%s: width" % who, width)
    if block_h is not None:
        block_h = _number("%s: block_h" % who, block_h)
    for (xa, ya), (xb, yb) in zip(basel[:-1], basel[1:]):
        for x, y in ((xa, ya), (xb, yb)):
            g = interp_y(surf, x)
            if y > g or (y == g and x not in (x0, xn)):  # on the ground only at an end: firm base at toe level
                raise ValueError("%s: the base must be below the ground (at x = %g)" % (who, x))
    bsegs = [(a, b) for a, b in zip(basel[:-1], basel[1:]) if b[0] > a[0]]
    ytop = max(y for _, y in surf)
    scale = max(xn - x0, ytop - ymin)
    eps = 1e-12 * scale
    if min_area is None:
        min_area = 1e-3 * width * (block_h or width)
    xs = set(x for x, _ in surf) | set(x for x, _ in basel)
    k = 1
    while x0 + k * width < xn - eps:
        xs.add(x0 + k * width)
        k += 1
    xs = sorted(xs)
    pieces = []
    for xa, xb in zip(xs[:-1], xs[1:]):
        g = segment_at(surf, xa, xb)
        bl = [Line(a, b) for a, b in bsegs if a[0] <= 0.5 * (xa + xb) <= b[0]][0]
        quad = clean([(xa, bl.y(xa)), (xb, bl.y(xb)), (xb, g.y(xb)), (xa, g.y(xa))], eps)
        if not quad:
            continue
        col = [quad]
        if block_h is not None:
            levels = []
            y = ymin + block_h
            while y < ytop - eps:
                levels.append(y)
                y += block_h
            for y in levels:
                col = split_by_line(col, Line((xa, y), (xb, y)), eps)
        pieces += col
    cuts = joints + cracks + [t for t, _ in layers if t is not None]
    blocks, dropped = _finish(pieces, cuts, min_area, layers)
    region = [(x0, basel[0][1])] + basel[1:] + list(reversed(surf))
    region = [p for i, p in enumerate(region) if p != region[i - 1]]
    slope_area = polygon_area(region)
    if foundation > 0:
        yf = ymin - foundation
        for a, b in bsegs:
            f = clean([(a[0], yf), (b[0], yf), b, a], eps)
            blocks.append(Block(f, polygon_area(f), True, "foundation"))
        if wall > 0:
            for x, xw in ((x0 - wall, x0), (xn, xn + wall)):
                yb = basel[0][1] if xw == x0 else basel[-1][1]
                f = [(x, yf), (xw, yf), (xw, yb), (x, yb)]
                blocks.append(Block(f, polygon_area(f), True, "foundation"))
    if wall > 0:
        for w in ([(x0 - wall, basel[0][1]), (x0, basel[0][1]), (x0, surf[0][1]), (x0 - wall, surf[0][1])],
                  [(xn, basel[-1][1]), (xn + wall, basel[-1][1]), (xn + wall, surf[-1][1]), (xn, surf[-1][1])]):
            if w[2][1] > w[1][1]:  # no wall where the ground lies on the base
                blocks.append(Block(w, polygon_area(w), True, "wall"))
    return _with_sets(SlopeBlocks(blocks, surf, ymin, slope_area, dropped, None, joints, cracks=cracks, layers=layers,
                                  polygon=region, pattern="columns"), sets, traces, "column_blocks")


def voronoi_slope_blocks(surface=None, base=0.0, n=None, spacing=None, seed=0, min_distance=0.0, sites=None,
                         polygon=None, joints=(), cracks=(), layers=(), foundation=1.0, wall=1.0, min_area=None,
                         sets=(), traces=()):
    """Random Voronoi blocks (CGAL, :func:`yade_rbsm.voronoi.voronoi_blocks`) tiling the slope under
    the ground polyline *surface* above *base* (or the simple polygon *polygon*), then cut along
    *joints*, *cracks* and the layer tops with :func:`cut_polygons`; *n* / *spacing* / *sites*,
    *seed*, *min_distance*: as in voronoi_blocks. *layers*, *sets*, *traces*: as in :func:`brick_blocks`. The fixed
    foundation and walls as for bricks (with *polygon*: only a foundation under its lowest point,
    spanning its width)."""
    who = "voronoi_slope_blocks"
    region = _Region(surface, base, polygon, joints, cracks, layers, foundation, wall, who)
    vor = _sibling("voronoi")
    t = vor.voronoi_tessellation(region.poly, n=n, spacing=spacing, seed=seed, min_distance=min_distance, sites=sites)
    return region.blocks([list(b) for b in t.blocks], min_area, t.dropped_area, "voronoi", sets, traces)


def triangle_slope_blocks(surface=None, base=0.0, spacing=None, polygon=None, joints=(), cracks=(), layers=(),
                          foundation=1.0, wall=1.0, min_area=None, sets=(), traces=(), seed=None):
    """Triangles tiling the slope under the ground polyline *surface* above *base* (or the simple polygon
    *polygon*), no edge longer than *spacing* and no angle below about 20.7 deg (CGAL's Delaunay refinement,
    :func:`yade_rbsm.voronoi.triangle_blocks`), then cut along *joints*, *cracks* and the layer tops; the other
    arguments as :func:`voronoi_slope_blocks`. The blocks for a plastic deformable soil
    (``RbsmMat(deformable=True, plastic=True)``): its shear band runs through triangles, where Voronoi cells of
    six edges lock (Griffiths & Lane's slope, Bishop 1.382: strength reduction 1.409 on 1 m triangles, 1.712 on
    1 m Voronoi cells; docs/manual/guide/deformable.md). *seed*: None, the mesh CGAL makes; an integer, that mesh
    with its interior vertices moved at random (:func:`yade_rbsm.voronoi.jitter_mesh`): meshes of one spacing
    whose results scatter as a user's would."""
    who = "triangle_slope_blocks"
    if spacing is None:
        raise ValueError("%s: give spacing, the longest edge of a triangle [m]" % who)
    region = _Region(surface, base, polygon, joints, cracks, layers, foundation, wall, who)
    triangles = _sibling("voronoi").triangle_blocks(region.poly, spacing, seed=seed)
    return region.blocks(triangles, min_area, 0.0, "triangles", sets, traces)


class _Region:
    """The slope region a tessellating builder fills (voronoi_slope_blocks, triangle_slope_blocks): from the
    ground *surface* above *base* or from a *polygon*, with its cuts, layers and fixed blocks."""

    def __init__(self, surface, base, polygon, joints, cracks, layers, foundation, wall, who):
        if (surface is None) == (polygon is None):
            raise ValueError("%s: give exactly one of surface (with base) and polygon" % who)
        self.from_polygon = polygon is not None
        if polygon is not None:
            poly = check_polygon(polygon, "%s: slope polygon" % who)
            if polygon_area(poly) < 0:
                poly = list(reversed(poly))
            xs, ys = [p[0] for p in poly], [p[1] for p in poly]
            surf = [(min(xs), max(ys)), (max(xs), max(ys))]
            base = min(ys)
            joints = [points("%s: joints[%d]" % (who, k), j, 2) for k, j in enumerate(joints)]
            cracks = [points("%s: cracks[%d]" % (who, k), j, 2) for k, j in enumerate(cracks)]
            layers = _check_layers(layers, min(xs), max(xs)) if layers else []
            slope_area = polygon_area(poly)
        else:
            surf, base, joints, cracks, layers, foundation, wall = _common_args(surface, base, joints, cracks, layers,
                                                                              foundation, wall, who)
            poly = slope_polygon(surf, base)
            slope_area = region_area(surf, base)
        self.who, self.poly, self.surf, self.base, self.slope_area = who, poly, surf, base, slope_area
        self.joints, self.cracks, self.layers, self.foundation, self.wall = joints, cracks, layers, foundation, wall

    def blocks(self, pieces, min_area, dropped, pattern, sets, traces):
        """The SlopeBlocks of *pieces* (the tessellation of self.poly, *dropped*: the area it left out) cut along
        the joints, cracks and layer tops, slivers below *min_area* (default 1e-6 of the mean) dropped, with the
        fixed foundation and walls, then cut by the joint *sets* and *traces*."""
        if min_area is None:
            min_area = 1e-6 * self.slope_area / max(1, len(pieces))
        blocks, dropped = _finish(pieces, self.joints + self.cracks + [tp for tp, _ in self.layers if tp is not None],
                                  min_area, self.layers, dropped=dropped)
        if self.from_polygon:
            if self.foundation > 0:
                xs = [p[0] for p in self.poly]
                w = self.wall
                f = [(min(xs) - w, self.base - self.foundation), (max(xs) + w, self.base - self.foundation),
                     (max(xs) + w, self.base), (min(xs) - w, self.base)]
                blocks.append(Block(f, polygon_area(f), True, "foundation"))
        else:
            blocks += _fixed_blocks(self.surf, self.base, self.foundation, self.wall)
        return _with_sets(SlopeBlocks(blocks, self.surf, self.base, self.slope_area, dropped, None, self.joints,
                                      cracks=self.cracks, layers=self.layers, polygon=self.poly, pattern=pattern),
                          sets, traces, self.who)


def _with_sets(sb, sets, traces, who):
    """*sb* cut by the JointSets and Traces (joint_sets.cut_by_joint_sets), or as it is without them."""
    if not sets and not traces:
        return sb
    from . import joint_sets
    return joint_sets.cut_by_joint_sets(sb, sets, traces, who=who)


# ---------------------------------------------------------------------------------------------
# input checks
# ---------------------------------------------------------------------------------------------
def _number(name, v, positive=True, allow_zero=False):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise ValueError("%s must be a finite number, got %r" % (name, v))
    if positive and (v < 0 or (v == 0 and not allow_zero)):
        raise ValueError("%s must be %s 0, got %r" % (name, ">=" if allow_zero else ">", v))
    return float(v)


def _check_layers(layers, x0, xn):
    """[(top polyline or None, material)] from the bottom up; only the last top may be None (the
    ground)."""
    out = []
    for k, item in enumerate(layers):
        try:
            top, mat = item
        except (TypeError, ValueError):
            raise ValueError("layers[%d] must be a (top polyline, material) pair" % k) from None
        if top is None:
            if k != len(layers) - 1:
                raise ValueError("layers[%d]: only the last (top) layer may have no top polyline" % k)
        else:
            top = monotone("layers[%d] top polyline" % k, top)
            if top[0][0] > x0 or top[-1][0] < xn:
                raise ValueError("layers[%d] top polyline must span the slope, x in [%g, %g]" % (k, x0, xn))
        if mat is None:
            raise ValueError("layers[%d]: no material" % k)
        out.append((top, mat))
    return out


def _layer_of(layers, c):
    for k, (top, _) in enumerate(layers):
        if top is None or c[1] < interp_y(top, c[0]):
            return k
    return len(layers) - 1


def _assign_layers(blocks, layers):
    for b in blocks:
        if b.kind == "slope":
            b.layer = _layer_of(layers, polygon_centroid(b.vertices))


def _finish(blocks_v, extra_cuts, min_area, layers, eps=None, dropped=0.0):
    """Cut slope block vertex lists along *extra_cuts* (:func:`cut_polygons`, *eps*), drop slivers
    (their area added to *dropped*); returns (Blocks, dropped)."""
    pieces = cut_polygons(blocks_v, extra_cuts, eps) if extra_cuts else blocks_v
    out = []
    for p in pieces:
        a = polygon_area(p)
        if a < min_area:
            dropped += a
            continue
        out.append(Block(p, a, False, "slope"))
    if layers:
        _assign_layers(out, layers)
    return out, dropped


def _check_ground_above(surf, base, who):
    """The ground is above the base, except that it may lie on it at either end: a firm base at toe
    level (a toe flat on the base, as in Griffiths & Lane's D = 1 slopes)."""
    lo, hi = _on_base_ends(surf, base)
    if any(y < base for _, y in surf) or any(y <= base for _, y in surf[lo + 1:hi]) or hi - lo < 1:
        raise ValueError("%s: the ground must be above the base everywhere (it may lie on the base only "
                         "at either end, a firm base at toe level)" % who)


def _on_base_ends(surf, base):
    """Indices (lo, hi): surf[lo] is the last point of the leading run on the base (0 if none) and
    surf[hi] the first of the trailing run (len - 1 if none)."""
    lo, hi = 0, len(surf) - 1
    while lo + 1 < len(surf) and surf[lo][1] <= base and surf[lo + 1][1] <= base:
        lo += 1
    while hi - 1 >= 0 and surf[hi][1] <= base and surf[hi - 1][1] <= base:
        hi -= 1
    return lo, hi


def slope_polygon(surface, base):
    """The slope region (CCW polygon) under the ground polyline *surface* and above y = *base*; the
    parts of the ground lying on the base (a toe at base level) are left out."""
    surf = monotone("surface", surface)
    lo, hi = _on_base_ends(surf, float(base))
    part = surf[lo:hi + 1]
    poly = [(part[0][0], float(base)), (part[-1][0], float(base))] + list(reversed(part))
    return [p for k, p in enumerate(poly) if p != poly[k - 1]]


def _fixed_blocks(surf, base, foundation, wall):
    x0, xn = surf[0][0], surf[-1][0]
    out = []
    if foundation > 0:
        f = [(x0 - wall, base - foundation), (xn + wall, base - foundation), (xn + wall, base), (x0 - wall, base)]
        out.append(Block(f, polygon_area(f), True, "foundation"))
    if wall > 0:
        for w in ([(x0 - wall, base), (x0, base), (x0, surf[0][1]), (x0 - wall, surf[0][1])],
                  [(xn, base), (xn + wall, base), (xn + wall, surf[-1][1]), (xn, surf[-1][1])]):
            if w[2][1] > base:  # no wall where the ground lies on the base
                out.append(Block(w, polygon_area(w), True, "wall"))
    return out


def _common_args(surface, base, joints, cracks, layers, foundation, wall, who, risers=False):
    surf = _with_risers("%s: surface" % who, surface) if risers else monotone("%s: surface" % who, surface)
    base = _number("%s: base" % who, base, positive=False)
    _check_ground_above(surf, base, who)
    joints = [points("%s: joints[%d]" % (who, k), j, 2) for k, j in enumerate(joints)]
    cracks = [points("%s: cracks[%d]" % (who, k), j, 2) for k, j in enumerate(cracks)]
    layers = _check_layers(layers, surf[0][0], surf[-1][0]) if layers else []
    foundation = _number("%s: foundation" % who, foundation, allow_zero=True)
    wall = _number("%s: wall" % who, wall, allow_zero=True)
    for k, c in enumerate(joints + cracks):
        if not _meets_region(c, surf, base):
            raise ValueError("%s: %s misses the slope" % (who, ("joints[%d]" % k) if k < len(joints)
                                                           else ("cracks[%d]" % (k - len(joints)))))
    return surf, base, joints, cracks, layers, foundation, wall


def _with_risers(name, surface):
    """A ground polyline with x non-decreasing whose repeated x are single risers (a vertical step between two
    columns' flat tops), none at an end; ValueError naming *name* otherwise."""
    surf = monotone(name, surface, strict=False)
    surf = [p for k, p in enumerate(surf) if k == 0 or p != surf[k - 1]]  # (a riser of no height is none)
    if len(surf) < 2:
        raise ValueError("%s: one point" % name)
    if surf[1][0] == surf[0][0] or surf[-2][0] == surf[-1][0]:
        raise ValueError("%s: a riser at an end (x = %g): the ground must start and end with a segment along x"
                         % (name, surf[0][0] if surf[1][0] == surf[0][0] else surf[-1][0]))
    for a, b, c in zip(surf[:-2], surf[1:-1], surf[2:]):
        if a[0] == b[0] == c[0]:
            raise ValueError("%s: more than one riser at x = %g (give it as one vertical segment)" % (name, a[0]))
    return surf


def _meets_region(line, surf, base):
    """Some point of the polyline lies inside the slope region (sampled along its segments)."""
    for a, b in zip(line[:-1], line[1:]):
        for k in range(65):
            t = k / 64.0
            x, y = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
            if surf[0][0] < x < surf[-1][0] and base < y < interp_y(surf, x):
                return True
    return False


# the scene part (needs YADE) lives in slope_scene.py; its names stay importable from here
_scene = _sibling("slope_scene")
(build_scene, break_crack, joints_on, joints_of, set_water, set_seismic, break_joints, set_joint_strength, give_joint_sets, joint_sets,
 apply_joint_sets, bond_and_break, unbalanced_ratio, settle) = (
    _scene.build_scene, _scene.break_crack, _scene.joints_on, _scene.joints_of, _scene.set_water, _scene.set_seismic,
    _scene.break_joints,
    _scene.set_joint_strength,
    _scene.give_joint_sets,
    _scene.joint_sets, _scene.apply_joint_sets, _scene.bond_and_break, _scene.unbalanced_ratio, _scene.settle)


def __getattr__(name):
    """The joint-set builder (joint_sets.py: JointSet, Trace, jointset_blocks), loaded when first used."""
    if name == "set_earthquake":  # earthquake.py: a ground-acceleration record in the model's base frame
        from .earthquake import apply
        return apply
    if name in ("JointSet", "Trace", "jointset_blocks", "jointset_blocks_dxf", "cut_by_joint_sets"):
        from . import joint_sets
        return getattr(joint_sets, name)
    if name in ("fos", "FosResult"):
        from . import fos
        return getattr(fos, name)
    if name in ("SlopeModel", "Stage"):
        from . import model
        return getattr(model, name)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))
