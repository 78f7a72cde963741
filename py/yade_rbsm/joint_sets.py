"""Joint sets and the cutter that turns a slope outline and its joints into blocks (UDEC's ``jset``).

A :class:`JointSet` is data: the geometry of parallel joints (dip, spacing, origin, persistence as
trace length and gap, an optional random spread) and their strength and stiffness.
:func:`jointset_blocks` cuts any simple outline (the region under a ground polyline, or a polygon of
your own, non-convex included: a bench, an overhang) by the sets' traces and by given traces, with
CGAL in exact arithmetic (``pkg/rbsm/tessellation/TraceCut.hpp``):

* a trace that does not separate two blocks (the end of a non-persistent joint, inside rock) is
  removed, as UDEC does: a joint is a joint only where it cuts a block apart; the length kept of
  each set is reported;
* the faces the traces leave are cut into convex blocks by diagonals between their corners where the
  outline is non-convex; these cuts are *welds* (no joint of the rock mass: they are bonded with the
  rock's strength, and reported as such), never a joint through the whole model;
* slivers (area below ``min_area``) are merged into a neighbour: across their longest inner edge
  whose removal leaves a convex block; the count, the places and the area are reported; a sliver that
  no neighbour takes convexly stays a block, reported;
* every vertex is an exact point rounded once, so blocks on either side of a joint share it bit for bit.

The result is a :class:`yade_rbsm.slope.SlopeBlocks` like the other builders' (``blocks``,
``slope_area``, ``dropped_area`` = 0: the blocks tile the outline), with ``joint_sets`` (what each
set kept) and ``welds``; :func:`yade_rbsm.slope.bond_and_break` gives every set its strength, so
that ``set_joint_strength`` is not needed, and the sets stay with the scene (``O.tags``) for
strength reduction and contacts made later along them.

Pure Python apart from the compiled cutter; it imports without YADE.
"""
import math
import random
import warnings
from dataclasses import dataclass, field
from typing import List, Optional, Sequence, Tuple

from .checks import count, number

__all__ = ["JointStrength", "JointSet", "Trace", "SetCut", "jointset_blocks", "jointset_blocks_dxf", "cut_by_joint_sets",
           "set_traces", "report"]


@dataclass(kw_only=True)
class JointStrength:
    """The strength and stiffness a joint set or a trace gives its joints (keywords only): *cohesion* [Pa],
    *friction_angle* [deg] (None: the rock's, ``RbsmMat.frictionAngle``), *tensile_strength* [Pa], *kn*,
    *ks* [Pa/m] (None: the blocks' Kawai springs), *ductile* (None: the blocks', ``RbsmMat.ductile``, False by
    default: brittle, a point loses its cohesion when it first slips, Kawai's joint; True keeps it while it slips,
    the perfectly plastic joint of limit equilibrium), and *name* for the reports. A joint is a discontinuity: by
    default no cohesion and no tensile strength."""
    cohesion: float = 0.0
    friction_angle: Optional[float] = None
    tensile_strength: float = 0.0
    kn: Optional[float] = None
    ks: Optional[float] = None
    ductile: Optional[bool] = None
    name: Optional[str] = None

    def __repr__(self):
        # its own fields first (geometry), then the strength; defaults left out
        from dataclasses import MISSING, fields
        own = [f for f in fields(self) if f.name not in _STRENGTH_FIELDS] + [f for f in fields(self) if f.name in _STRENGTH_FIELDS]
        shown = [(f.name, getattr(self, f.name)) for f in own
                 if f.default is MISSING or getattr(self, f.name) != f.default]
        return "%s(%s)" % (type(self).__name__, ", ".join("%s=%r" % kv for kv in shown))

    def _check_strength(self, who):
        self.cohesion = number(who, "cohesion", self.cohesion, 0)
        if self.friction_angle is not None:
            self.friction_angle = number(who, "friction_angle (degrees)", self.friction_angle, 0, 90, high_open=True)
            if 0 < self.friction_angle < 1.5:  # (YADE's own angles are radians)
                warnings.warn("%s: friction_angle %g is in degrees here; %g rad would be %.1f deg" % (
                    who, self.friction_angle, self.friction_angle, math.degrees(self.friction_angle)), stacklevel=3)
        self.tensile_strength = number(who, "tensile_strength", self.tensile_strength, 0)
        for key in ("kn", "ks"):
            if getattr(self, key) is not None:
                setattr(self, key, number(who, key, getattr(self, key), 0, low_open=True))
        if self.ductile is not None and not isinstance(self.ductile, bool):
            raise ValueError("%s: ductile must be True, False or None (the blocks'), got %r" % (who, self.ductile))


_STRENGTH_FIELDS = ("cohesion", "friction_angle", "tensile_strength", "kn", "ks", "ductile", "name")


@dataclass(repr=False)
class JointSet(JointStrength):
    """A set of parallel joints, as UDEC's ``jset``.

    Geometry: *dip* [deg] counter-clockwise from +x (a set dipping 20 deg towards +x, out of a face
    that looks to +x, has dip = -20; 0 and 180 are the same set); *spacing* [m] normal to the joints;
    *origin* a point on one joint of the set; *trace* [m] the length of each joint along its line and
    *gap* [m] the rock bridge between two joints of one line (*trace* None: fully persistent);
    *dip_spread* [deg] and *spacing_spread* (a fraction of the spacing) the standard deviations of a
    random spread drawn from *seed* (normal, the spacing kept above a tenth of its mean).

    Strength and stiffness of the joints: the keywords of :class:`JointStrength`; *name* addresses the
    set in reports (default ``set A``, ``set B``, ...)."""
    dip: float
    spacing: float
    origin: Tuple[float, float] = (0.0, 0.0)
    trace: Optional[float] = None
    gap: float = 0.0
    dip_spread: float = 0.0
    spacing_spread: float = 0.0
    seed: int = 0

    def __post_init__(self):
        who = "JointSet"
        self.dip = number(who, "dip", self.dip, -360, 360)
        if 0 < abs(self.dip) < 1.6:  # (YADE's own angles are radians)
            warnings.warn("%s: dip %g is in degrees here; %g rad would be %.1f deg" % (
                who, self.dip, self.dip, math.degrees(self.dip)), stacklevel=3)
        self.spacing = number(who, "spacing", self.spacing, 0, low_open=True)
        try:
            ox, oy = self.origin
        except (TypeError, ValueError):
            raise ValueError("%s: origin must be a point (x, y) (got %r)" % (who, self.origin)) from None
        self.origin = (number(who, "origin x", ox), number(who, "origin y", oy))
        if self.trace is not None:
            self.trace = number(who, "trace", self.trace, 0, low_open=True)
        self.gap = number(who, "gap", self.gap, 0)
        if self.gap > 0 and self.trace is None:
            raise ValueError("%s: a gap (%g m) needs a trace length: trace=None is a fully persistent set" % (who, self.gap))
        self.dip_spread = number(who, "dip_spread", self.dip_spread, 0, 45)
        self.spacing_spread = number(who, "spacing_spread", self.spacing_spread, 0, 1)
        self.seed = count(who, "seed", self.seed, 0)
        self._check_strength(who)


@dataclass(repr=False)
class Trace(JointStrength):
    """One given joint trace (a fault, a mapped joint): a polyline *points* with the strength fields
    of :class:`JointSet` (a trace given as a bare polyline takes the defaults: no cohesion, no
    tensile strength, the rock's friction)."""
    points: Sequence[Tuple[float, float]]

    def __post_init__(self):
        from .geometry import points
        self.points = points("Trace: points", self.points, 2)
        self._check_strength("Trace")


@dataclass
class SetCut:
    """What one set or trace became in the blocks: *segments* the block edges on it (an edge of the
    block on either side), *length* [m] the length of joint it makes, *given* [m] the length of its
    traces inside the outline (less is kept where a trace ends inside rock)."""
    source: object  # the JointSet or Trace
    name: str
    segments: List[Tuple[Tuple[float, float], Tuple[float, float]]] = field(default_factory=list)
    length: float = 0.0
    given: float = 0.0
    traces: List[Tuple[Tuple[float, float], Tuple[float, float]]] = field(default_factory=list)  # those that kept a joint

    def __repr__(self):
        return "SetCut(%r: %.4g m of joint, %.4g m of trace given inside the outline)" % (self.name, self.length, self.given)


def _line_angle(dip):
    """The dip [deg] as the angle of its line in (-90, 90] (a line dipping 180 is the one dipping 0)."""
    d = math.fmod(dip, 180.0)
    return d - 180.0 if d > 90.0 else d + 180.0 if d <= -90.0 else d


def _direction(deg):
    """(cos, sin) of *deg*, exact where it is a multiple of 90 (sin 180 is 1.2e-16 in floating point, and a
    joint 1e-16 off the horizontal makes slivers of a horizontal ground)."""
    if deg % 90.0 == 0.0:
        k = int(round(deg / 90.0)) % 4
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][k]
    a = math.radians(deg)
    return (math.cos(a), math.sin(a))


def set_traces(js, bbox):
    """The traces of the JointSet *js* over the box ``(xmin, ymin, xmax, ymax)``: a list of segments
    ((x0, y0), (x1, y1)), reaching past the box."""
    xmin, ymin, xmax, ymax = bbox
    rng = random.Random(js.seed)
    diag = math.hypot(xmax - xmin, ymax - ymin)
    cx, cy = 0.5 * (xmin + xmax), 0.5 * (ymin + ymax)
    a = math.radians(_line_angle(js.dip))
    d = _direction(_line_angle(js.dip))
    nrm = (-d[1], d[0])
    corners = [(xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax)]
    off = [(p[0] - js.origin[0]) * nrm[0] + (p[1] - js.origin[1]) * nrm[1] for p in corners]
    lo, hi = min(off) - 0.5 * diag * math.sin(math.radians(3 * js.dip_spread)), max(off) + 0.5 * diag * math.sin(math.radians(3 * js.dip_spread))

    def step():
        if js.spacing_spread == 0:
            return js.spacing
        return js.spacing * max(0.1, rng.gauss(1.0, js.spacing_spread))
    offsets = [0.0]
    while offsets[-1] < hi:
        offsets.append(offsets[-1] + step())
    below = [0.0]
    while below[-1] > lo:
        below.append(below[-1] - step())
    out = []
    for s in sorted(set(below[1:] + offsets)):
        if s < lo - js.spacing or s > hi + js.spacing:
            continue
        u = _direction(_line_angle(js.dip) + (rng.gauss(0.0, js.dip_spread) if js.dip_spread else 0.0))
        p = (js.origin[0] + s * nrm[0], js.origin[1] + s * nrm[1])  # on this joint's line
        # the line's parameter range over the box: around the box centre's projection, +- the diagonal
        t0 = (cx - p[0]) * u[0] + (cy - p[1]) * u[1]
        ta, tb = t0 - diag, t0 + diag
        if js.trace is None:
            out.append(((p[0] + ta * u[0], p[1] + ta * u[1]), (p[0] + tb * u[0], p[1] + tb * u[1])))
            continue
        period = js.trace + js.gap
        k = math.floor(ta / period)  # traces start at the line's foot of the origin, every trace + gap
        while k * period < tb:
            t = k * period
            out.append(((p[0] + t * u[0], p[1] + t * u[1]), (p[0] + (t + js.trace) * u[0], p[1] + (t + js.trace) * u[1])))
            k += 1
    return out


def _inside_length(seg, poly):
    """Length of the segment inside the simple polygon *poly*."""
    (x0, y0), (x1, y1) = seg
    ts = {0.0, 1.0}
    n = len(poly)
    for i in range(n):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % n]
        den = (x1 - x0) * (by - ay) - (y1 - y0) * (bx - ax)
        if den == 0:
            continue
        t = ((ax - x0) * (by - ay) - (ay - y0) * (bx - ax)) / den
        u = ((ax - x0) * (y1 - y0) - (ay - y0) * (x1 - x0)) / den
        if 0 < t < 1 and 0 <= u <= 1:
            ts.add(t)
    ts = sorted(ts)
    L = math.hypot(x1 - x0, y1 - y0)
    return sum((tb - ta) * L for ta, tb in zip(ts[:-1], ts[1:])
               if point_in_polygon((x0 + 0.5 * (ta + tb) * (x1 - x0), y0 + 0.5 * (ta + tb) * (y1 - y0)), poly))


def point_in_polygon(p, poly):
    """*p* strictly inside the simple polygon *poly* (crossing number)."""
    x, y = p
    inside = False
    n = len(poly)
    for i in range(n):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % n]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


def _on(seg, trace, tol):
    """The block edge *seg* lies on the trace segment (both ends within *tol*)."""
    from .geometry import point_segment_distance
    return all(point_segment_distance(p, trace[0], trace[1]) <= tol for p in seg)


def _overlap(seg, trace, tol):
    """The part of the block edge *seg* that lies on the trace segment (on its line within *tol*), as a
    segment of positive length, else None: a block's edge may run past a joint's end along a weld."""
    (ax, ay), (bx, by) = trace
    L = math.hypot(bx - ax, by - ay)
    ux, uy = (bx - ax) / L, (by - ay) / L
    if any(abs(ux * (p[1] - ay) - uy * (p[0] - ax)) > tol for p in seg):
        return None
    t0, t1 = ((p[0] - ax) * ux + (p[1] - ay) * uy for p in seg)
    lo, hi = max(min(t0, t1), 0.0), min(max(t0, t1), L)
    if hi - lo <= tol:
        return None
    if (lo, hi) == (min(t0, t1), max(t0, t1)):
        return tuple(seg)  # the whole edge (its own coordinates, bit for bit)
    return ((ax + lo * ux, ay + lo * uy), (ax + hi * ux, ay + hi * uy))


def jointset_blocks(surface=None, base=None, sets=(), traces=(), min_area=None, outline=None, layers=(),
                    foundation=1.0, wall=1.0, min_width=None):
    """Blocks of the slope under the ground polyline *surface* above *base* (or inside the simple polygon
    *outline*, any shape) cut by the JointSets *sets* and the *traces* (polylines or :class:`Trace`),
    see the module docstring. *min_area* [m2] and *min_width* [m]: the sliver limits, by area and by
    mean width 2 A / P (defaults: 1 % of the square of the smallest set spacing, or 1e-4 of the outline's
    area without sets; 2 % of the smallest spacing, or none without sets). *layers*, *foundation*,
    *wall*: as for :func:`yade_rbsm.slope.brick_blocks` (with *outline*: a foundation under its lowest
    point). Returns a SlopeBlocks (pattern "joint sets") with ``joint_sets`` (a :class:`SetCut` per set
    and trace, in the order given), ``welds`` (the outline decomposition's cuts) and ``slivers``
    (dict: merged places and area, kept places and area)."""
    from . import slope as S
    from .geometry import polygon_area
    who = "jointset_blocks"
    if (surface is None) == (outline is None):
        raise ValueError("%s: give the ground polyline surface (with base) or the polygon outline, not both" % who)
    sets, traces = _checked(sets, traces, who)
    if outline is not None:
        if base is not None:
            raise ValueError("%s: base goes with surface; an outline is the whole region" % who)
        region = S.check_polygon(outline, "%s: outline" % who)
        if polygon_area(region) < 0:
            region = list(reversed(region))
        xs, ys = [p[0] for p in region], [p[1] for p in region]
        surf, base_y = [(min(xs), max(ys)), (max(xs), max(ys))], min(ys)
        layers = S._check_layers(layers, min(xs), max(xs)) if layers else []
    else:
        if base is None:
            raise ValueError("%s: give base (the y of the firm base) with surface" % who)
        surf, base_y, _, _, layers, foundation, wall = S._common_args(surface, base, (), (), layers, foundation, wall, who)
        region = S.slope_polygon(surf, base_y)
    xs, ys = [p[0] for p in region], [p[1] for p in region]
    area = polygon_area(region)
    if min_area is None:
        min_area = 0.01 * min(js.spacing for js in sets) ** 2 if sets else 1e-4 * area
    min_area = number(who, "min_area", min_area, 0)
    min_width = _min_width(min_width, sets, who)
    tops = [s for t, _ in layers if t is not None for s in zip(t[:-1], t[1:])]  # layer tops: bonded rock
    vertex_lists, cuts, welds, slivers = _cut([region], region, sets, traces, tops, min_area, min_width)
    blocks = [S.Block(list(v), polygon_area(v), False, "slope") for v in vertex_lists]
    if layers:
        S._assign_layers(blocks, layers)
    if outline is not None:
        fixed = []
        if foundation > 0:
            f = [(min(xs) - wall, base_y - foundation), (max(xs) + wall, base_y - foundation), (max(xs) + wall, base_y),
                 (min(xs) - wall, base_y)]
            fixed.append(S.Block(f, polygon_area(f), True, "foundation"))
    else:
        fixed = S._fixed_blocks(surf, base_y, foundation, wall)
    sb = S.SlopeBlocks(blocks + fixed, surf, base_y, area, 0.0, None,
                       [[a, b] for sc in cuts for a, b in sc.segments], layers=layers, polygon=region,
                       pattern="joint sets")
    sb.joint_sets, sb.welds, sb.slivers = cuts, welds, slivers
    return sb


def _bbox_of(pts):
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _min_width(min_width, sets, who):
    if min_width is None:
        return 0.02 * min(js.spacing for js in sets) if sets else 0.0
    return number(who, "min_width", min_width, 0)


def _cut(pieces, region, sets, traces, extra, min_area, min_width=0.0):
    """The convex blocks of *pieces* (simple polygons inside *region*) cut by the JointSets *sets*, the
    Traces *traces* and the segments *extra* (untagged cuts: layer tops), each piece with the CGAL cutter;
    returns (vertex lists, SetCuts merged by name, welds, slivers dict)."""
    from .voronoi import _tess
    bbox = _bbox_of(region)
    names = [js.name or "set %s" % chr(ord("A") + k) for k, js in enumerate(sets)]
    names += [t.name or "traces[%d]" % k for k, t in enumerate(traces)]
    source_segs = [set_traces(js, bbox) for js in sets]
    source_segs += [list(zip(t.points[:-1], t.points[1:])) for t in traces]
    # a trace end meant to lie on the outline or on another trace (a bedding that daylights on the face)
    # is off it by round-off, and the exact cutter would take it for an end inside rock: every trace
    # reaches 1e-9 x the model's size past its ends (the overshoot dangles, and goes)
    # (a polyline's inner vertices and a closed polyline's ends meet exactly: they are not moved)
    reach = 1e-9 * max(bbox[2] - bbox[0], bbox[3] - bbox[1])
    cut_segs = [_extended(sg, reach) for segs in source_segs[:len(sets)] for sg in segs]
    for t in traces:
        pts, closed = t.points, tuple(t.points[0]) == tuple(t.points[-1])
        n = len(pts) - 1
        cut_segs += [_extended((pts[i], pts[i + 1]), reach, start=i == 0 and not closed, end=i == n - 1 and not closed)
                     for i in range(n)]
    cut_segs += [tuple(sg) for sg in extra]
    seg_boxes = [_bbox_of(sg) for sg in cut_segs]
    blocks, welds = [], []
    slivers = dict(min_area=min_area, min_width=min_width, merged=[], merged_area=0.0, kept=[], kept_area=0.0)
    for piece in pieces:
        x0, y0, x1, y1 = _bbox_of(piece)
        near = [sg for sg, (a0, b0, a1, b1) in zip(cut_segs, seg_boxes) if a0 <= x1 and a1 >= x0 and b0 <= y1 and b1 >= y0]
        if not near and len(pieces) > 1:  # (a convex piece no trace reaches: itself)
            blocks.append([tuple(p) for p in piece])
            continue
        r = _tess.cut_by_traces(piece, near, min_area, min_width)
        blocks += [list(v) for v in r["blocks"]]
        welds += [tuple(map(tuple, w)) for w in r["welds"]]
        slivers["merged"] += [tuple(p) for p in r["merged"]]
        slivers["merged_area"] += r["merged_area"]
        slivers["kept"] += [tuple(p) for p in r["kept_slivers"]]
        slivers["kept_area"] += r["kept_area"]
    # tag each block edge shared by two blocks by the set or trace it lies on (the first that has it)
    scale = max(1.0, max(abs(c) for p in region for c in p))
    tol = 1e-9 * scale
    cuts = [SetCut(src, nm) for src, nm in zip(list(sets) + list(traces), names)]
    faces = [[] for _ in cuts]  # every block edge on the set (its part on it), from both sides of each joint
    kept = [set() for _ in cuts]  # indices of the set's traces that carry an edge
    for v in blocks:
        for i in range(len(v)):
            e = (v[i], v[(i + 1) % len(v)])
            for k, segs in enumerate(source_segs):
                hit = next(((j, o) for j, sg in enumerate(segs) for o in [_overlap(e, sg, tol)] if o), None)
                if hit is not None:
                    faces[k].append(hit[1])
                    if not _on_outline(hit[1], region, tol):
                        kept[k].add(hit[0])
                    break
    for k, (sc, segs, f) in enumerate(zip(cuts, source_segs, faces)):
        # an edge on the outline is no joint (a set's line along the outline): blocks on both sides only
        f = [e for e in f if not _on_outline(e, region, tol)]
        sc.segments = list({tuple(sorted(e)): e for e in f}.values())
        sc.length = 0.5 * sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in f)  # each joint seen from both sides
        sc.given = sum(_inside_length(sg, region) for sg in segs)
        sc.traces = [segs[j] for j in sorted(kept[k])]
    merged = {}
    for sc in cuts:  # the traces of one name (a drawing's layer) are one family
        m = merged.setdefault(sc.name, SetCut(sc.source, sc.name))
        m.segments += sc.segments
        m.traces += sc.traces
        m.length += sc.length
        m.given += sc.given
    return blocks, list(merged.values()), welds, slivers


def _checked(sets, traces, who):
    sets = list(sets)
    for k, js in enumerate(sets):
        if not isinstance(js, JointSet):
            raise ValueError("%s: sets[%d] is not a JointSet (got %r)" % (who, k, js))
    from .geometry import points
    return sets, [t if isinstance(t, Trace) else Trace(points("%s: traces[%d]" % (who, k), t, 2)) for k, t in enumerate(traces)]


def cut_by_joint_sets(sb, sets=(), traces=(), min_area=None, who="cut_by_joint_sets", min_width=None):
    """The free blocks of the SlopeBlocks *sb* (any builder's: bricks, columns, Voronoi) cut by the
    JointSets *sets* and the *traces*, which carry their strength as in :func:`jointset_blocks`: the
    builders' way in for joint sets (their ``sets=`` and ``traces=``). A trace that ends inside a block
    cuts nothing of it (UDEC's rule); slivers below *min_area* (default: the builder's smallest block
    x 1e-3, or 1 % of the smallest set spacing squared, the smaller) or thinner than *min_width* (default
    0: the pattern makes the shapes; a merge takes a piece of joint away) are merged into the rest of the
    block they were cut from. Returns *sb* with its free blocks replaced, ``joint_sets``, ``welds`` and
    ``slivers`` set, and the sets' joints added to ``sb.joints`` (found again after bonding)."""
    from . import slope as S
    from .geometry import polygon_area
    sets, traces = _checked(sets, traces, who)
    if not sets and not traces:
        return sb
    free = [b for b in sb.blocks if not b.fixed]
    fixed = [b for b in sb.blocks if b.fixed]
    if min_area is None:
        cands = [1e-3 * min(b.area for b in free)] + ([0.01 * min(js.spacing for js in sets) ** 2] if sets else [])
        min_area = min(cands)
    min_area = number(who, "min_area", min_area, 0)
    min_width = _min_width(0.0 if min_width is None else min_width, sets, who)
    vertex_lists, cuts, welds, slivers = _cut([b.vertices for b in free], sb.polygon, sets, traces, (), min_area, min_width)
    blocks = [S.Block(list(v), polygon_area(v), False, "slope") for v in vertex_lists]
    if sb.layers:
        S._assign_layers(blocks, sb.layers)
    sb.blocks = blocks + fixed
    sb.joint_sets, sb.welds, sb.slivers = cuts, welds, slivers
    sb.joints = list(sb.joints) + [[a, b] for sc in cuts for a, b in sc.segments]
    return sb


def jointset_blocks_dxf(filename, layers=None, outline_layer="OUTLINE", sets=(), units=None, materials=(), **kw):
    """:func:`jointset_blocks` of a slope drawing: the closed polyline on *outline_layer* is the outline,
    the lines and polylines of the *layers* are joint traces (:func:`yade_rbsm.io.read_slope_dxf`; the
    drawing's units honoured, or *units*). *layers*: {layer: strength} with the keywords of :class:`Trace`
    (``dict(friction_angle=30, cohesion=1e4)``, or None for its defaults); default every layer with
    lines, at Trace's defaults. The traces of a layer are one family named after it in the report and in
    ``joint_sets``. *materials*: the rock units from the bottom up, ``[(layer, RbsmMat), ..., (None,
    RbsmMat)]``: each named layer holds the top of its unit, one open polyline across the outline (bonded
    rock: the blocks are cut along it, as jointset_blocks' *layers*), the last unit reaches the ground.
    *sets*: JointSets generated over the outline besides; *kw*: jointset_blocks'."""
    from .io.slope_dxf import read_slope_dxf
    units_given = list(materials)
    for k, item in enumerate(units_given):
        if not (isinstance(item, (tuple, list)) and len(item) == 2 and (item[0] is None or isinstance(item[0], str))):
            raise ValueError("jointset_blocks_dxf: materials[%d] must be a (layer name or None, material) pair, got %r"
                             % (k, item))
    d = read_slope_dxf(filename, outline_layer=outline_layer, trace_layers=None if layers is None else list(layers),
                       units=units, material_layers=[l for l, _ in units_given if l is not None])
    if units_given:
        xs = [p[0] for p in d.outline]
        tops = {}
        for layer, top in d.materials.items():
            top = top if top[0][0] < top[-1][0] else top[::-1]  # (drawn either way)
            if any(b[0] <= a[0] for a, b in zip(top[:-1], top[1:])) or top[0][0] > min(xs) or top[-1][0] < max(xs):
                raise ValueError("jointset_blocks_dxf: %s: the top of the unit on layer %r must run across the outline "
                                 "(x from %g to %g), each vertex further along x; it runs from %g to %g" % (
                                     filename, layer, min(xs), max(xs), top[0][0], top[-1][0]))
            if not _enters(top, d.outline):  # (above or below the whole outline: every block would be one unit)
                raise ValueError("jointset_blocks_dxf: %s: the top of the unit on layer %r does not cross the outline: "
                                 "it runs wholly above or below it" % (filename, layer))
            tops[layer.lower()] = top
        if units_given[-1][0] is not None:
            raise ValueError("jointset_blocks_dxf: the last of materials is the unit that reaches the ground: "
                             "(None, material), got layer %r" % units_given[-1][0])
        kw["layers"] = [(None if l is None else tops[l.lower()], m) for l, m in units_given]
    strength = {k.lower(): (v or {}) for k, v in (layers or {}).items()}
    traces = []
    for layer, polylines in d.traces.items():
        opts = dict(strength.get(layer.lower(), {}))
        if "name" in opts or "points" in opts:
            raise ValueError("jointset_blocks_dxf: layers[%r]: the name is the layer's and the points the drawing's" % layer)
        traces += [Trace(p, name=layer, **opts) for p in polylines]
    return jointset_blocks(outline=d.outline, sets=sets, traces=traces, **kw)


def _enters(polyline, region):
    """Whether *polyline* passes inside the polygon *region*."""
    return any(_inside_length(seg, region) > 0 for seg in zip(polyline[:-1], polyline[1:]))


def _extended(seg, d, start=True, end=True):
    """The segment reaching *d* past its start and end (where asked)."""
    (x0, y0), (x1, y1) = seg
    L = math.hypot(x1 - x0, y1 - y0)
    ux, uy = (x1 - x0) / L * d, (y1 - y0) / L * d
    return ((x0 - ux, y0 - uy) if start else (x0, y0), (x1 + ux, y1 + uy) if end else (x1, y1))


def _on_outline(e, region, tol):
    n = len(region)
    return any(_on(e, (region[i], region[(i + 1) % n]), tol) for i in range(n))


def report(sb):
    """The lines a user reads about a joint-set cut: blocks, each set's joints, welds, slivers."""
    out = ["%d blocks tile %.4g m2 (%d fixed blocks besides)" % (len(sb.free), sb.slope_area, len(sb.blocks) - len(sb.free))]
    for sc in sb.joint_sets:
        src = sc.source
        phi = "rock's" if src.friction_angle is None else "%g deg" % src.friction_angle
        out.append("  %s: %.4g m of joint kept of %.4g m of trace inside the outline (c %g Pa, phi %s, sigma_t %g Pa)"
                   % (sc.name, sc.length, sc.given, src.cohesion, phi, src.tensile_strength))
    if sb.welds:
        out.append("  welds (cuts of the non-convex outline, bonded with the rock's strength): %d, %.3g m"
                   % (len(sb.welds), sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in sb.welds)))
    s = sb.slivers
    if s["merged"] or s["kept"]:
        out.append("  slivers (below %.3g m2 or %.3g m wide): %d merged into a neighbour (%.3g m2, at %s)%s" % (
            s["min_area"], s.get("min_width", 0.0), len(s["merged"]), s["merged_area"], ", ".join("(%.2f, %.2f)" % p for p in s["merged"][:5]),
            "" if not s["kept"] else "; %d kept, no convex union (%.3g m2, at %s)" % (
                len(s["kept"]), s["kept_area"], ", ".join("(%.2f, %.2f)" % p for p in s["kept"][:5]))))
    return "\n".join(out)
