"""The joint-set cutter (issue 36): slope.JointSet and slope.jointset_blocks (py/yade_rbsm/joint_sets.py,
the CGAL cutter pkg/rbsm/tessellation/TraceCut.cpp). Plain python3, no YADE.

Checked on every cut (check_cut): the blocks tile the outline (sum of areas = the outline's area, exact
fractions, rel. 1e-9; no overlap: CGAL's exact union area equals the sum), each is accepted by
Polygon2D's own check (convex, counter-clockwise, no repeated or collinear vertex), none is below the
sliver limit unless reported as kept, and every piece of boundary two blocks share lies on a set's or a
trace's line or on a weld of the outline's decomposition: there is no other joint (the old way, cutting a
non-convex outline at toe level first, left a joint through the whole model).
"""
import math
import os
import random
import re
import sys
import warnings
from fractions import Fraction

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
sys.path.insert(0, os.path.join(SOURCE, "py"))
from yade_rbsm import slope  # noqa: E402
from yade_rbsm import joint_sets as J  # noqa: E402
from yade_rbsm.voronoi import _tess  # noqa: E402

# the issue's slope: a 20 m 2:1 rock slope (toe flat, face, crest flat) on a base 10 m below the toe
SURFACE = [(-10, 0), (10, 0), (20, 20), (40, 20)]
SET_A = dict(dip=-20, spacing=3, friction_angle=30)  # dips 20 deg towards +x (this face looks to -x: into it)
SET_B = dict(dip=110, spacing=4, origin=(1, 0), friction_angle=35, cohesion=1e4)  # = -70: 70 deg towards +x
BENCH = [(0, 0), (40, 0), (40, 20), (28, 20), (24, 12), (18, 12), (14, 4), (0, 4)]  # a bench: two reflex corners
OVERHANG = [(0, 0), (30, 0), (30, 14), (18, 14), (12, 10), (16, 6), (10, 2), (0, 2)]  # the face leans out


def exact_area(poly):
    s = Fraction(0)
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        s += Fraction(x0) * Fraction(y1) - Fraction(x1) * Fraction(y0)
    return abs(s) / 2


def _on(p, a, b, tol):
    ex, ey = b[0] - a[0], b[1] - a[1]
    L = math.hypot(ex, ey)
    cross = (ex * (p[1] - a[1]) - ey * (p[0] - a[0])) / L
    t = (ex * (p[0] - a[0]) + ey * (p[1] - a[1])) / (L * L)
    return abs(cross) <= tol and -tol / L <= t <= 1 + tol / L


def shared_pieces(blocks, tol):
    """(edge of a block, overlap length) for every edge that an edge of another block overlaps along a length."""
    edges = [(i, (v[k], v[(k + 1) % len(v)])) for i, v in enumerate(blocks) for k in range(len(v))]
    out = []
    for i, (a, b) in edges:
        L = math.hypot(b[0] - a[0], b[1] - a[1])
        u = ((b[0] - a[0]) / L, (b[1] - a[1]) / L)
        for j, (c, d) in edges:
            if j == i or any(abs(u[0] * (p[1] - a[1]) - u[1] * (p[0] - a[0])) > tol for p in (c, d)):
                continue  # the same block, or not on the line of a-b
            tc, td = sorted(u[0] * (p[0] - a[0]) + u[1] * (p[1] - a[1]) for p in (c, d))
            if min(L, td) - max(0.0, tc) > tol:
                out.append(((a, b), min(L, td) - max(0.0, tc)))
    return out


def check_cut(sb, region, sets=(), traces=()):
    free = [b.vertices for b in sb.free]
    assert free
    total = sum(exact_area(v) for v in free)
    assert abs(float(total - exact_area(region))) <= 1e-9 * float(exact_area(region))
    assert _tess.union_area(free) == pytest.approx(float(total), rel=1e-12)
    for v in free:
        assert _tess.polygon_problem(v) == "", v
    small = [b.area for b in sb.free if b.area < sb.slivers["min_area"]]
    assert len(small) == len(sb.slivers["kept"]), (small, sb.slivers)
    scale = max(abs(c) for p in region for c in p)
    tol = 1e-9 * max(1.0, scale)
    lines = [s for js in sets for s in J.set_traces(js, _bbox(region))] + [s for t in traces for s in zip(t[:-1], t[1:])]
    lines += [tuple(w) for w in sb.welds]
    def on_lines(p):
        return any(_on(p, a, b, 1e-6 * scale) for a, b in lines)
    # (both ends and the middle: a corner that rounding put on the line of its neighbours went, and the edge
    # then spans two joints that cross at a hair's angle)
    stray = [e for e, _ in shared_pieces(free, tol)
             if not (on_lines(e[0]) and on_lines(e[1]) and on_lines((0.5 * (e[0][0] + e[1][0]), 0.5 * (e[0][1] + e[1][1]))))]
    assert stray == [], "joints on no set, trace or weld: %s" % stray[:5]
    return sb


def _bbox(region):
    xs, ys = [p[0] for p in region], [p[1] for p in region]
    return (min(xs), min(ys), max(xs), max(ys))


def test_the_issue_slope_is_one_call():
    A, B = slope.JointSet(**SET_A), slope.JointSet(**SET_B)
    sb = slope.jointset_blocks(SURFACE, base=-10, sets=[A, B])
    region = slope.slope_polygon(SURFACE, -10)
    check_cut(sb, region, [A, B])
    assert sb.pattern == "joint sets" and sb.dropped_area == 0 and len(sb.free) > 50
    names = [sc.name for sc in sb.joint_sets]
    assert names == ["set A", "set B"]
    for sc in sb.joint_sets:  # persistent sets: every metre of trace inside the outline is a joint but slivers'
        assert sc.length == pytest.approx(sc.given, rel=0.01) and sc.length <= sc.given + 1e-9
    # the default sliver limit, 1 % of the smallest spacing squared: the two below it were merged
    assert sb.slivers["min_area"] == pytest.approx(0.09) and len(sb.slivers["merged"]) >= 1
    assert min(b.area for b in sb.free) >= 0.09
    assert "set A" in J.report(sb) and "merged into a neighbour" in J.report(sb)


def test_same_blocks_on_every_call():
    a = slope.jointset_blocks(SURFACE, -10, sets=[slope.JointSet(**SET_A), slope.JointSet(**SET_B)])
    b = slope.jointset_blocks(SURFACE, -10, sets=[slope.JointSet(**SET_A), slope.JointSet(**SET_B)])
    assert [x.vertices for x in a.blocks] == [x.vertices for x in b.blocks]


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("outline", ["slope", "bench", "overhang"])
def test_random_sets_on_non_convex_outlines(seed, outline):
    rng = random.Random(seed)
    sets = []
    for k in range(rng.choice((1, 2, 3))):
        persistent = rng.random() < 0.5
        sp = rng.uniform(1.5, 5.0)
        sets.append(slope.JointSet(dip=rng.uniform(-90, 90), spacing=sp, origin=(rng.uniform(0, 10), rng.uniform(0, 10)),
                                   trace=None if persistent else rng.uniform(2, 12), gap=0 if persistent else rng.uniform(0.5, 3),
                                   dip_spread=rng.choice((0, 5)), spacing_spread=rng.choice((0, 0.3)), seed=seed))
    if outline == "slope":
        region = slope.slope_polygon(SURFACE, -10)
        sb = slope.jointset_blocks(SURFACE, -10, sets=sets)
    else:
        region = BENCH if outline == "bench" else OVERHANG
        sb = slope.jointset_blocks(outline=region, sets=sets)
    check_cut(sb, region, sets)
    for sc in sb.joint_sets:
        assert sc.length <= sc.given + 1e-6


def test_a_non_convex_outline_gets_welds_not_a_joint_through_the_model():
    """The bench alone: a few blocks joined by welds between its corners; before, the user split it at toe level
    by hand, a joint through the whole model."""
    sb = check_cut(slope.jointset_blocks(outline=BENCH), BENCH)
    assert len(sb.free) >= 2 and len(sb.welds) == len(sb.free) - 1 and sb.joint_sets == []
    for (a, b) in sb.welds:  # between corners of the outline
        assert a in BENCH and b in BENCH


def test_a_trace_that_ends_in_rock_is_no_joint():
    """UDEC's rule: a trace that does not cut a block apart goes; one that does stays, with its strength."""
    box = [(0, 0), (10, 0), (10, 10), (0, 10)]
    half = slope.Trace([(-1, 5), (6, 5)], friction_angle=25)
    full = slope.Trace([(5, -1), (5, 11)], friction_angle=25, name="fault")
    sb = slope.jointset_blocks(outline=box, traces=[half], foundation=0)
    assert len(sb.free) == 1 and sb.joint_sets[0].length == 0 and sb.joint_sets[0].given == pytest.approx(6)
    sb = check_cut(slope.jointset_blocks(outline=box, traces=[half, full], foundation=0), box, traces=[half.points, full.points])
    assert len(sb.free) == 3
    assert sb.joint_sets[0].length == pytest.approx(5) and sb.joint_sets[1].length == pytest.approx(10)
    assert sb.joint_sets[1].name == "fault"


def test_a_trace_that_daylights_on_the_face_by_round_off_still_cuts():
    """A bedding from a point computed on the face (off it by round-off) to a crack: the exact cutter took its
    end for one inside rock and dropped the wedge."""
    xt, H, beta, psi = 10.0, 12.0, math.radians(60), math.radians(30)
    xd, yd, xc = xt + 3 / math.tan(beta), 3.0, 22.0
    yc = yd + (xc - xd) * math.tan(psi)
    surface = [(0, 0), (xt, 0), (xt + H / math.tan(beta), H), (35, H)]
    sb = slope.jointset_blocks(surface, -4.0, traces=[[(xd, yd), (xc, yc)], [(xc, yc), (xc, H)]])
    check_cut(sb, slope.slope_polygon(surface, -4.0), traces=[[(xd, yd), (xc, yc)], [(xc, yc), (xc, H)]])
    assert [round(sc.length, 9) for sc in sb.joint_sets] == [round(sc.given, 9) for sc in sb.joint_sets]
    assert sb.joint_sets[0].length == pytest.approx((xc - xd) / math.cos(psi))


def test_slivers_are_merged_and_reported():
    box = [(0, 0), (10, 0), (10, 10), (0, 10)]
    t1, t2 = [(-1, 4.0), (11, 4.0)], [(-1, 4.02), (11, 4.1)]  # 0.027-0.093 m apart over the box: a sliver of 0.6 m2
    sb = check_cut(slope.jointset_blocks(outline=box, traces=[t1, t2], min_area=1.0, foundation=0), box, traces=[t1, t2])
    assert len(sb.free) == 2 and len(sb.slivers["merged"]) == 1 and sb.slivers["merged_area"] == pytest.approx(0.6, rel=1e-6)
    sb = check_cut(slope.jointset_blocks(outline=box, traces=[t1, t2], min_area=0.5, foundation=0), box, traces=[t1, t2])
    assert len(sb.free) == 3 and not sb.slivers["merged"]


def test_far_from_the_origin():
    off = 1e6
    region = [(x + off, y + off) for x, y in BENCH]
    sets = [slope.JointSet(dip=-30, spacing=2.5, origin=(off, off)), slope.JointSet(dip=80, spacing=3, origin=(off, off))]
    check_cut(slope.jointset_blocks(outline=region, sets=sets), region, sets)


@pytest.mark.parametrize("kw, message", [
    (dict(dip=10, spacing=0), "spacing"),
    (dict(dip=float("nan"), spacing=1), "dip"),
    (dict(dip=10, spacing=1, gap=1), "gap"),
    (dict(dip=10, spacing=1, friction_angle=95), "friction_angle"),
    (dict(dip=10, spacing=1, origin=5), "origin"),
    (dict(dip=10, spacing=1, ductile="no"), "ductile"),
])
def test_bad_joint_sets_are_named(kw, message):
    with pytest.raises(ValueError, match=message):
        slope.JointSet(**kw)


def test_bad_calls_are_named():
    with pytest.raises(ValueError, match="sets\\[0\\] is not a JointSet"):
        slope.jointset_blocks(SURFACE, -10, sets=[(10, 3)])
    with pytest.raises(ValueError, match="not both"):
        slope.jointset_blocks(SURFACE, -10, outline=BENCH)
    with pytest.raises(ValueError, match="base"):
        slope.jointset_blocks(SURFACE)


def _slope_drawing(path, insunits=4, k=1000.0):
    """The issue's drawing, in millimetres: the outline of the 20 m 2:1 slope and the traces of its two sets
    (set A dipping 20 deg out of the face every 3 m, set B 70 deg into it every 4 m) drawn as LINEs past the
    outline, on layers SET_A and SET_B; a TEXT besides."""
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = insunits
    msp = doc.modelspace()
    region = slope.slope_polygon(SURFACE, -10)
    msp.add_lwpolyline([(x * k, y * k) for x, y in region], close=True, dxfattribs={"layer": "OUTLINE"})
    for layer, js in (("SET_A", slope.JointSet(**SET_A)), ("SET_B", slope.JointSet(**SET_B))):
        for a, b in J.set_traces(js, _bbox(region)):
            msp.add_line((a[0] * k, a[1] * k), (b[0] * k, b[1] * k), dxfattribs={"layer": layer})
    msp.add_text("two joint sets")
    doc.saveas(path)
    return region


def test_the_issue_slope_is_one_call_from_a_drawing_in_millimetres(tmp_path):
    region = _slope_drawing(str(tmp_path / "slope.dxf"))
    with pytest.warns(UserWarning, match="1 TEXT"):
        sb = slope.jointset_blocks_dxf(str(tmp_path / "slope.dxf"), layers={"SET_A": dict(friction_angle=30),
                                                                           "set_b": dict(friction_angle=35, cohesion=1e4)})
    check_cut(sb, region, [slope.JointSet(**SET_A), slope.JointSet(**SET_B)])
    assert sb.slope_area == pytest.approx(1000.0)  # m2, not mm2
    ref = slope.jointset_blocks(outline=region, sets=[slope.JointSet(**SET_A), slope.JointSet(**SET_B)])
    assert len(sb.free) == len(ref.free)
    assert [sc.name for sc in sb.joint_sets] == ["SET_A", "SET_B"]
    assert [sc.source.friction_angle for sc in sb.joint_sets] == [30, 35] and sb.joint_sets[1].source.cohesion == 1e4
    for sc, r in zip(sb.joint_sets, ref.joint_sets):
        assert sc.length == pytest.approx(r.length, rel=1e-9)


def test_a_unitless_drawing_kilometres_across_is_named(tmp_path):
    """A drawing in millimetres saved without units ($INSUNITS 0) is read in metres (as documented): a 20 m slope
    becomes 20 km. The reader says so and names the way out (before, it said nothing); units='mm' reads it
    right, without the warning; the same slope drawn in metres without units gets none."""
    _slope_drawing(str(tmp_path / "mm.dxf"), insunits=0)
    with pytest.warns(UserWarning, match="no units .* units='mm'"):
        sb = slope.jointset_blocks_dxf(str(tmp_path / "mm.dxf"), layers={"SET_A": None, "SET_B": None})
    assert sb.slope_area == pytest.approx(1000.0 * 1e6)
    for units, k in (("mm", 1000.0), (None, 1.0)):
        _slope_drawing(str(tmp_path / "x.dxf"), insunits=0, k=k)
        with warnings.catch_warnings(record=True) as seen:
            warnings.simplefilter("always")
            sb = slope.jointset_blocks_dxf(str(tmp_path / "x.dxf"), layers={"SET_A": None, "SET_B": None}, units=units)
        assert not [w for w in seen if "no units" in str(w.message)], units
        assert sb.slope_area == pytest.approx(1000.0)


def _units_drawing(path, top, extra=None):
    """The issue's slope drawing (metres) with SET_A's traces and the top of a shale unit on layer SHALE_TOP."""
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    region = slope.slope_polygon(SURFACE, -10)
    msp.add_lwpolyline(region, close=True, dxfattribs={"layer": "OUTLINE"})
    for a, b in J.set_traces(slope.JointSet(**SET_A), _bbox(region)):
        msp.add_line(a, b, dxfattribs={"layer": "SET_A"})
    if top is not None:
        msp.add_lwpolyline(top, dxfattribs={"layer": "SHALE_TOP"})
    if extra:
        extra(msp)
    doc.saveas(path)
    return region


def test_material_units_from_a_drawing(tmp_path):
    """Issue 36, "DXF in: ... material layers -> blocks": a layer holding the top of a rock unit (shale under
    sandstone) drawn right to left across the outline. The blocks are cut along it (bonded rock, as
    jointset_blocks' layers), each lies wholly on one side and takes its unit (Block.layer, sb.layers' material);
    the layer is no joint trace. On 3b4a483 there was no way to give units from a drawing (materials= unknown)."""
    top = [(45.0, -2.0), (12.0, -6.0), (-15.0, -4.0)]  # right to left, across x -10..40
    region = _units_drawing(str(tmp_path / "units.dxf"), top)
    shale, sandstone = object(), object()  # (the builder only carries them)
    sb = slope.jointset_blocks_dxf(str(tmp_path / "units.dxf"), layers={"SET_A": dict(friction_angle=30)},
                                   materials=[("SHALE_TOP", shale), (None, sandstone)])
    check_cut(sb, region, [slope.JointSet(**SET_A)], [top[::-1]])
    assert [sc.name for sc in sb.joint_sets] == ["SET_A"]
    line = top[::-1]
    from yade_rbsm.geometry import interp_y
    below = [b for b in sb.free if b.layer == 0]
    above = [b for b in sb.free if b.layer == 1]
    assert below and above and len(below) + len(above) == len(sb.free)
    for b in below:
        assert all(y <= interp_y(line, x) + 1e-9 for x, y in b.vertices)
    for b in above:
        assert all(y >= interp_y(line, x) - 1e-9 for x, y in b.vertices)
    assert sb.layers[0][1] is shale and sb.layers[1][1] is sandstone
    shale_area = sum(b.area for b in below)
    ref = slope.jointset_blocks(outline=region, sets=[slope.JointSet(**SET_A)], layers=[(line, shale), (None, sandstone)])
    assert shale_area == pytest.approx(sum(b.area for b in ref.free if b.layer == 0), rel=1e-12)


@pytest.mark.parametrize("case, message", [
    ("missing", "no polyline on the material layer 'SHALE_TOP'"),
    ("two", "2 polylines on the material layer 'SHALE_TOP'"),
    ("closed", "open polyline across the outline (this one is closed)"),
    ("short", "must run across the outline"),
    ("last", "the last of materials is the unit that reaches the ground"),
    ("above", "does not cross the outline: it runs wholly above or below it"),
    ("below", "does not cross the outline: it runs wholly above or below it"),
    ("pair", "must be a (layer name or None, material) pair"),
])
def test_bad_material_units_are_refused_by_name(tmp_path, case, message):
    top = [(-15.0, -4.0), (45.0, -3.0)]
    if case == "missing":
        top = None
    elif case == "short":
        top = [(0.0, -4.0), (45.0, -3.0)]
    elif case in ("above", "below"):  # across the outline's x range, but over or under it (a new user's drawing)
        top = [(-15.0, 30.0), (45.0, 31.0)] if case == "above" else [(-15.0, -13.0), (45.0, -12.0)]
    extra = None
    if case == "two":
        extra = lambda msp: msp.add_lwpolyline([(-15, -8), (45, -8)], dxfattribs={"layer": "SHALE_TOP"})
    if case == "closed":
        top, extra = None, lambda msp: msp.add_lwpolyline([(-15, -8), (45, -8), (45, -9)], close=True, dxfattribs={"layer": "SHALE_TOP"})
    _units_drawing(str(tmp_path / "bad.dxf"), top, extra)
    units = {"last": [(None, 1), ("SHALE_TOP", 2)], "pair": [("SHALE_TOP",), (None, 2)]}.get(case, [("SHALE_TOP", 1), (None, 2)])
    with pytest.raises(ValueError, match=re.escape(message)):
        slope.jointset_blocks_dxf(str(tmp_path / "bad.dxf"), materials=units)


@pytest.mark.parametrize("bad, message", [
    ("open", "open polyline"), ("two", "2 polylines on the outline layer"), ("none", "no closed polyline on the outline"),
    ("bulge", "bulge"), ("units", "INSUNITS = 19"), ("crossing", "self-intersecting"),
])
def test_bad_slope_drawings_are_refused_by_name(tmp_path, bad, message):
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 19 if bad == "units" else 6
    msp = doc.modelspace()
    box = [(0, 0), (10, 0), (10, 5), (0, 5)]
    if bad != "none":
        pts = [(0, 0), (10, 5), (10, 0), (0, 5)] if bad == "crossing" else box
        msp.add_lwpolyline(pts, close=bad != "open", dxfattribs={"layer": "OUTLINE"})
    if bad == "two":
        msp.add_lwpolyline([(20, 0), (21, 0), (21, 1)], close=True, dxfattribs={"layer": "OUTLINE"})
    msp.add_lwpolyline([(-1, 2, 0.5), (11, 3, 0)] if bad == "bulge" else [(-1, 2), (11, 3)], format="xyb", dxfattribs={"layer": "J1"})
    doc.saveas(str(tmp_path / "bad.dxf"))
    with pytest.raises(ValueError, match=message) as e:
        slope.jointset_blocks_dxf(str(tmp_path / "bad.dxf"))
    assert "bad.dxf" in str(e.value)


@pytest.mark.parametrize("builder", ["bricks", "columns", "voronoi"])
def test_every_builder_takes_joint_sets_and_traces(builder):
    """Issue 36: the builders share one way in for joint sets: bricks, columns and Voronoi blocks cut by a
    persistent set and a fault trace that carry their strength (joint_sets.cut_by_joint_sets): the blocks
    still tile the slope, convex; the set's and the fault's joints are all there and on their lines."""
    A = slope.JointSet(dip=-20, spacing=3, friction_angle=30)
    fault = slope.Trace([(5, -12), (30, 25)], friction_angle=20, name="fault")
    kw = dict(sets=[A], traces=[fault])
    sb = {"bricks": lambda: slope.brick_blocks(SURFACE, -10, 4, 2, **kw),
          "columns": lambda: slope.column_blocks(SURFACE, -10, 3, **kw),
          "voronoi": lambda: slope.voronoi_slope_blocks(SURFACE, -10, spacing=3, seed=1, **kw)}[builder]()
    region = slope.slope_polygon(SURFACE, -10)
    free = [b.vertices for b in sb.free]
    total = sum(exact_area(v) for v in free) + Fraction(sb.dropped_area)
    assert abs(float(total - exact_area(region))) <= 1e-9 * float(exact_area(region))
    assert _tess.union_area(free) == pytest.approx(float(sum(exact_area(v) for v in free)), rel=1e-12)
    for v in free:
        assert _tess.polygon_problem(v) == "", v
    assert [sc.name for sc in sb.joint_sets] == ["set A", "fault"] and sb.pattern == builder
    lines = {"set A": J.set_traces(A, _bbox(region)), "fault": [tuple(fault.points)]}
    for sc in sb.joint_sets:  # persistent: all of it is joint (but slivers merged away), and on its own lines
        assert sc.length == pytest.approx(sc.given, rel=0.01) and sc.length > 10, sc
        for a, b in sc.segments:
            assert any(_on(a, p, q, 1e-6) and _on(b, p, q, 1e-6) for p, q in lines[sc.name]), (sc.name, a, b)
    assert all(list(e) in sb.joints or [e[0], e[1]] in sb.joints for sc in sb.joint_sets for e in sc.segments)


def test_an_island_of_joints_is_joined_by_welds_not_dropped():
    """A closed triangle of joints inside rock, touching nothing: on c194afc the cutter removed it (its joints
    lost); now it is a block, joined to the rest by two horizontal welds from its extreme corners."""
    box = [(0, 0), (10, 0), (10, 10), (0, 10)]
    tri = [(3, 3), (7, 3), (5, 7)]
    traces = [slope.Trace([tri[0], tri[1], tri[2], tri[0]], friction_angle=30, name="lens")]
    sb = check_cut(slope.jointset_blocks(outline=box, traces=traces, foundation=0), box, traces=[tri + [tri[0]]])
    assert any(sorted(b.vertices) == sorted(tri) for b in sb.free)
    lens = sb.joint_sets[0]
    perimeter = sum(math.dist(a, b) for a, b in zip(tri, tri[1:] + tri[:1]))
    assert lens.length == pytest.approx(perimeter) and lens.given == pytest.approx(perimeter)
    assert ((3.0, 3.0), (0.0, 3.0)) in sb.welds and ((7.0, 3.0), (10.0, 3.0)) in sb.welds


def test_a_long_thin_strip_is_a_sliver_too():
    """Issue 36: a sliver may be long: two joints 5 cm apart across a 10 m box make a 0.5 m2 strip, above the
    area limit but 5 cm wide (a block that sets the time step of the whole model). The mean width 2 A / P
    limit (min_width, default 2 % of the smallest spacing) merges it; without it, it stays."""
    box = [(0, 0), (10, 0), (10, 10), (0, 10)]
    t1, t2 = [(-1, 4.0), (11, 4.0)], [(-1, 4.05), (11, 4.05)]
    kw = dict(outline=box, traces=[t1, t2], min_area=0.1, foundation=0)
    strip = check_cut(slope.jointset_blocks(min_width=0.0, **kw), box, traces=[t1, t2])
    assert len(strip.free) == 3 and min(b.area for b in strip.free) == pytest.approx(0.5)
    merged = check_cut(slope.jointset_blocks(min_width=0.1, **kw), box, traces=[t1, t2])
    assert len(merged.free) == 2 and merged.slivers["merged_area"] == pytest.approx(0.5)
    assert "0.1 m wide" in J.report(merged)


@pytest.mark.parametrize("dip", [0, 180, -180, 90, -90, 270])
def test_level_and_upright_sets_on_a_level_ground(dip):
    """A new user's trial: dip 180 (the same set as 0) stopped with 'a block is degenerate after rounding'
    (sin 180 deg is 1.2e-16 in floating point: joints a hair off the level crest). Every multiple of 90 is now
    exact; 0 and 180 give the same blocks."""
    bench = [(0, 30), (30, 30), (36.99, 15), (46.99, 15), (53.99, 0), (83.99, 0)]
    region = slope.slope_polygon(bench, -8)
    js = slope.JointSet(dip=dip, spacing=4)
    sb = check_cut(slope.jointset_blocks(bench, base=-8, sets=[js]), region, [js])
    same = slope.jointset_blocks(bench, base=-8, sets=[slope.JointSet(dip=dip % 180, spacing=4)])
    assert sorted(map(sorted, (b.vertices for b in sb.free))) == sorted(map(sorted, (b.vertices for b in same.free)))


def test_radians_given_for_degrees_are_warned_about():
    with pytest.warns(UserWarning, match="dip -0.610865 is in degrees here"):
        slope.JointSet(dip=-math.radians(35), spacing=3)
    with pytest.warns(UserWarning, match="friction_angle 0.558505 is in degrees"):
        slope.Trace([(0, 0), (1, 1)], friction_angle=math.radians(32))
