"""Blocks from the closed polylines of a DXF drawing (``import_dxf``) and back (``export_dxf``), with
ezdxf (Debian's python3-ezdxf).

Every LWPOLYLINE and POLYLINE of the model space is one block: its vertices in the world x-y plane
(z dropped), its layer mapped to a material. Rock engineers draw joint patterns in CAD, where the
drawing direction carries no meaning: clockwise polylines are reversed (not refused). Refused, with
an error naming the file, the entity's handle and layer: open polylines, arc segments (bulges),
fewer than 3 distinct vertices, self-intersecting or non-convex outlines, layers without a
material. Other entities (lines, text, hatches ...) are skipped with a warning that counts them.

Units: the drawing's ``$INSUNITS`` scales it to metres (0, unitless, is taken as metres, with a warning when
the drawing is more than 5 km across: drawn in millimetres?; a unit that is no length for a slope, e.g.
parsecs, is refused naming it), or ``units=`` says them ("mm", "cm", "dm",
"m", "km", "in", "ft", "yd"). Thickness: a polyline's DXF thickness (group 39, in the drawing's units) is
the block's thickness; ``export_dxf`` writes it, and ``$INSUNITS = 6`` (metres), so a round trip keeps
the mass. The materials are not in the drawing, only their labels (the layers): give them on import.
"""
import warnings

from yade import wrapper

from ..blocks import polygon2d
from ..omega import is_fixed
from .dxf_units import _ezdxf, drawing_scale, read_drawing, warn_if_unitless_and_huge  # noqa: F401 (drawing_scale: part of this module's API)
from .polylines import block_outline

__all__ = ["import_dxf", "export_dxf", "drawing_scale"]

def _rings(msp, filename):
    """(handle, layer, [(x, y)...] in world coordinates, closed flag) of every polyline; counts the rest."""
    from ezdxf.math import Vec3
    skipped = {}
    for e in msp:
        kind = e.dxftype()
        where = "%s: %s #%s on layer %r" % (filename, kind, e.dxf.handle, e.dxf.layer)
        if kind == "LWPOLYLINE":
            pts = list(e.get_points("xyb"))
            if any(b != 0 for _, _, b in pts):
                raise ValueError("%s: arc segment (bulge): blocks are polygons, straight edges only" % where)
            ocs, z = e.ocs(), e.dxf.elevation
            xy = [ocs.to_wcs(Vec3(x, y, z)) for x, y, _ in pts]
            yield where, e.dxf.layer, [(p.x, p.y) for p in xy], e.closed, e.dxf.get("thickness", 0.0)
        elif kind == "POLYLINE":
            if not (e.is_2d_polyline or e.is_3d_polyline):
                raise ValueError("%s: a polygon mesh or polyface is not a block outline" % where)
            if any(v.dxf.bulge != 0 for v in e.vertices):
                raise ValueError("%s: arc segment (bulge): blocks are polygons, straight edges only" % where)
            pts = list(e.points())  # OCS for a 2D polyline, WCS for a 3D one
            xy = [e.ocs().to_wcs(p) for p in pts] if e.is_2d_polyline else pts
            yield where, e.dxf.layer, [(p.x, p.y) for p in xy], e.is_closed, e.dxf.get("thickness", 0.0)
        else:
            skipped[kind] = skipped.get(kind, 0) + 1
    if skipped:
        warnings.warn("import_dxf: %s: skipped %s (only LWPOLYLINE and POLYLINE make blocks)" % (
            filename, ", ".join("%d %s" % (n, k) for k, n in sorted(skipped.items()))))


def _material(layer, materials, O, where):
    if isinstance(materials, wrapper.Material):
        return materials
    for key, m in materials.items():  # DXF layer names are case-insensitive
        if key.lower() == layer.lower():
            return O.materials[m] if isinstance(m, (int, str)) else m
    raise ValueError("%s: layer %r has no material (materials= maps: %s)" % (where, layer, ", ".join(map(repr, materials)) or "nothing"))


def import_dxf(filename, materials, fixed_layers=(), thickness=None, O=None, units=None):
    """Reads the DXF file *filename* and returns one :yref:`Polygon2D` body per closed polyline of
    its model space, in drawing order (``O.bodies.append(import_dxf("joints.dxf", {"rock": rock}))``).

    *materials*: dict layer name -> RbsmMat (or its id/label in O.materials), or one RbsmMat for
    every layer; *fixed_layers*: names of the layers whose blocks are fixed (foundation, walls);
    *thickness*: out-of-plane thickness of the blocks [m] where a polyline has none (default 1; a
    polyline's own DXF thickness wins, as export_dxf writes it); *units*: the drawing's length unit
    (default: its $INSUNITS, module docstring). Clockwise polylines are reversed; the problems listed
    in the module docstring raise ValueError naming file, entity handle and layer."""
    if O is None:
        from yade import O
    doc, scale = read_drawing(filename, units)
    fixed = {l.lower() for l in fixed_layers}
    bodies, drawn = [], []
    for where, layer, pts, closed, drawn_thickness in _rings(doc.modelspace(), filename):
        drawn += pts
        ring, _ = block_outline([(x * scale, y * scale) for x, y in pts], closed, where)
        mat = _material(layer, materials, O, where)
        t = drawn_thickness * scale if drawn_thickness > 0 else (1.0 if thickness is None else thickness)
        try:
            bodies.append(polygon2d(ring, mat, thickness=t, fixed=layer.lower() in fixed))
        except ValueError as e:
            raise ValueError("%s: %s" % (where, e)) from None
    warn_if_unitless_and_huge(doc, units, filename, drawn, "import_dxf")
    return bodies


def export_dxf(filename, bodies=None, O=None):
    """Writes the :yref:`Polygon2D` bodies (all, or those in *bodies*) as closed LWPOLYLINEs in the
    world frame to the DXF file *filename*: layer = the material's label (``mat<id>`` without one),
    fixed blocks on ``<label>_fixed``, so that ``import_dxf(f, {...}, fixed_layers=[...])`` reads
    them back; each block's thickness as the polyline's DXF thickness, the drawing in metres
    ($INSUNITS = 6). Returns the number of blocks written."""
    if O is None:
        from yade import O
    ezdxf = _ezdxf()
    if bodies is None:
        bodies = [b for b in O.bodies if b is not None]
    else:
        bodies = [O.bodies[b] if isinstance(b, int) else b for b in bodies]
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 6
    msp = doc.modelspace()
    n = 0
    for b in bodies:
        if not isinstance(b.shape, wrapper.Polygon2D):
            continue
        label = b.material.label or "mat%d" % b.material.id
        layer = label + ("_fixed" if is_fixed(b) else "")
        if layer not in doc.layers:
            doc.layers.add(layer)
        pts = [(v[0], v[1]) for v in b.shape.worldVertices(b.state.pos, b.state.ori)]
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": layer, "thickness": b.shape.thickness})
        n += 1
    doc.saveas(filename)
    return n
