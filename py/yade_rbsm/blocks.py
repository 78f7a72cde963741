"""Building RBSM blocks (Polygon2D bodies) from world-frame polygons."""
import math

from yade import wrapper

from .geometry import polygon_properties, signed_area as _signed_area

__all__ = ["polygon_properties", "polygon2d"]


def _describe(pts, most=4):
    """Short text naming a polygon by its first vertices, for error messages."""
    shown = ", ".join("(%.12g, %.12g)" % p for p in pts[:most])  # (map coordinates: 1 mm apart at 4e6 m)
    return "[" + shown + (", ... %d vertices" % len(pts) if len(pts) > most else "") + "]"


def polygon2d(vertices, material, thickness=1.0, fixed=False, color=None, wire=False):
    """A YADE Body for an RBSM block.

    *vertices*: convex polygon in world coordinates (x, y) [m], counter-clockwise.
    *material*: an :yref:`RbsmMat` (or the id/label of one in O.materials).
    *thickness*: out-of-plane thickness [m]; 1 gives masses and forces per metre of width.
    *fixed*: a fixed block (foundation, wall): all degrees of freedom blocked.

    The body is placed at the centroid with the vertices centred on it; mass = density·area·thickness,
    polar inertia = density·thickness·J. Motion is planar: z translation and x, y rotations are
    blocked ('zXY'). A non-convex, clockwise or degenerate polygon, a material that is not an
    RbsmMat, or a non-positive density or thickness raises ValueError naming the problem.
    """
    mat = material
    if isinstance(mat, (int, str)) and not isinstance(mat, bool):
        from yade import O
        try:
            mat = O.materials[mat]  # YADE looks up an index or a label
        except (IndexError, KeyError, ValueError, RuntimeError):
            raise ValueError("polygon2d: no material %r in O.materials" % (mat,)) from None
    if not isinstance(mat, wrapper.RbsmMat):
        raise ValueError("polygon2d: material must be an RbsmMat, got %s" % type(mat).__name__)
    if not (isinstance(thickness, (int, float)) and math.isfinite(thickness) and thickness > 0):
        raise ValueError("polygon2d: thickness must be a finite number > 0, got %r" % (thickness,))
    if not (math.isfinite(mat.density) and mat.density > 0):
        raise ValueError("polygon2d: material density must be > 0, got %r" % mat.density)
    try:
        pts = [(float(x), float(y)) for x, y in vertices]
    except (TypeError, ValueError):
        raise ValueError("polygon2d: vertices must be a sequence of (x, y) pairs")
    if len(pts) < 3:
        raise ValueError("polygon2d: a polygon needs at least 3 vertices, got %d" % len(pts))
    if not all(math.isfinite(c) for p in pts for c in p):
        raise ValueError("polygon2d: vertices contain NaN or inf")
    try:
        if _signed_area(pts) == 0:
            # a bow-tie has zero area too: Polygon2D calls it self-intersecting, which says more
            ox, oy = pts[0]
            try:
                wrapper.Polygon2D(vertices=[(x - ox, y - oy) for x, y in pts])
            except ValueError as e:
                if "self-intersecting" in str(e):
                    raise
        area, (cx, cy), j = polygon_properties(pts)
        local = [(x - cx, y - cy) for x, y in pts]
        ox, oy = pts[0]
        extent = max(max(abs(x - ox), abs(y - oy)) for x, y in pts)
        if max(abs(ox), abs(oy)) > 1e4 * extent:
            # far from the origin (map coordinates: a 1 mm block at 4e6 m) x - cx has the round-off of x,
            # 1e-9 m, which moved the block's centroid off its body's origin: the offsets to the first
            # vertex (exact) less the centroid's offset instead. (Not everywhere: near the origin the blocks
            # of existing scenes keep their vertices to the bit, and their bonds, which depend on them.)
            offsets = [(x - ox, y - oy) for x, y in pts]
            area, (rx, ry), j = polygon_properties(offsets)
            local = [(x - rx, y - ry) for x, y in offsets]
            cx, cy = ox + rx, oy + ry
        # Polygon2D checks convexity, orientation and degeneracy and names the problem (ValueError).
        shape = wrapper.Polygon2D(vertices=local, thickness=thickness, wire=wire)
    except ValueError as e:
        # name the block by its world vertices: the body has no id before it is appended
        raise ValueError("polygon2d(%s): %s" % (_describe(pts), e)) from None
    _warn_short_edges(pts)
    _warn_far_from_origin(pts, cx, cy, math.sqrt(area))
    if color is not None:
        shape.color = color
    b = wrapper.Body()
    if mat.deformable:
        b.state = mat.newAssocState()  # a DeformableState: the block's strain (rigid blocks keep YADE's State)
    b.shape = shape
    b.material = mat
    b.state.pos = (cx, cy, 0)
    b.state.refPos = b.state.pos  # displacements (Monitor, VtkSeries, snapshots, qt view) count from here
    mass = mat.density * shape.area * thickness
    inertia = mat.density * thickness * shape.polarMoment
    b.state.mass = mass
    # Rotation about x and y is blocked; equal components keep NewtonIntegrator on its spherical
    # (leapfrog) rotation update, which is exact for rotation about a fixed axis.
    b.state.inertia = (inertia, inertia, inertia)
    b.state.blockedDOFs = "xyzXYZ" if fixed else "zXY"
    return b


def _warn_far_from_origin(pts, cx, cy, size, fraction=1e-6):
    """A warning for a block so far from the origin that double precision resolves its position to more than
    *fraction* of its size: its motion is rounded (blocks at 1e10-2.4e12 m, resolved to 2e-5-2.5e-3 of their size,
    moved 2.4-44 % of their size otherwise than the same scene at the origin, one lost its rotation: issue 34's
    closing pass). UTM coordinates keep 1e-9 m: below the fraction for blocks above 1 mm."""
    import warnings
    resolution = math.ulp(max(abs(cx), abs(cy)))
    if resolution > fraction * size:
        warnings.warn("polygon2d(%s): at (%.6g, %.6g) m from the origin double precision resolves a position to %.3g m, "
                      "%.2g of the block's size (%.3g m): its motion would be rounded; move the model near the origin "
                      "(subtract a reference point from its coordinates)" % (_describe(pts), cx, cy, resolution,
                                                                             resolution / size, size), stacklevel=3)


def _warn_short_edges(pts, fraction=0.02):
    """A warning for a polygon whose edges are all shorter than *fraction* of its diameter (a 10 000-gon standing
    for a disc): a joint acts along one pair of edges, so such a block carries load on a few millimetres of
    spring and sinks into what it rests on (issue 34, item 8: 41 % of its diameter into a base)."""
    import warnings
    n = len(pts)
    longest = max(math.hypot(pts[(k + 1) % n][0] - pts[k][0], pts[(k + 1) % n][1] - pts[k][1]) for k in range(n))
    diameter = max(math.hypot(p[0] - q[0], p[1] - q[1]) for p in pts[:: max(1, n // 64)] for q in pts)
    if longest < fraction * diameter:
        warnings.warn("polygon2d(%s): its longest edge, %.3g m, is %.2g %% of its size (%.3g m): an RBSM joint acts "
                      "along one pair of edges, so this block would rest on a %.3g m spring and sink into what it "
                      "meets; model it with fewer, longer edges (a disc: a sphere, or a polygon of at most %d sides)"
                      % (_describe(pts), longest, 100 * longest / diameter, diameter, longest, int(math.pi / fraction)),
                      stacklevel=3)
