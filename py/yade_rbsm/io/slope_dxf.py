"""A slope drawing (DXF) read as an outline and joint traces, for :func:`yade_rbsm.slope.jointset_blocks`
(``slope.jointset_blocks_dxf`` does both in one call). Pure Python with ezdxf; no YADE.

The drawing: one closed polyline on the outline layer (any simple polygon, non-convex included), and
joint traces on other layers: LINEs and open or closed LWPOLYLINE/POLYLINEs, one layer per joint set
or family of mapped joints. The drawing's units are honoured as :mod:`.dxf` says ($INSUNITS or
``units=``). Refused, naming the file, the entity's handle and layer: no outline or more than one, an
open, self-intersecting or bulged outline, a bulged trace, a trace of a single point. Entities of other
kinds (text, hatches, dimensions) and layers not asked for are reported in a warning, and so is a drawing without
units (read in metres) whose outline is kilometres across (drawn in millimetres? ``units='mm'``).

Material layers (*material_layers*): a layer that holds the top of one rock unit, one open polyline
across the outline (the boundary between it and the unit above); read as ``materials`` {layer: polyline},
not as joint traces.
"""
import warnings
from dataclasses import dataclass, field
from typing import Dict, List, Tuple

from .dxf_units import read_drawing, warn_if_unitless_and_huge
from .polylines import block_outline

__all__ = ["SlopeDrawing", "read_slope_dxf"]


@dataclass
class SlopeDrawing:
    outline: List[Tuple[float, float]]  # counter-clockwise, metres
    traces: Dict[str, List[List[Tuple[float, float]]]] = field(default_factory=dict)  # layer -> polylines, metres
    scale: float = 1.0  # metres per drawing unit
    materials: Dict[str, List[Tuple[float, float]]] = field(default_factory=dict)  # layer -> the top of its unit

    def __repr__(self):
        return "SlopeDrawing(outline of %d vertices, traces: %s%s; %g m per drawing unit)" % (
            len(self.outline), ", ".join("%s %d" % (k, len(v)) for k, v in self.traces.items()) or "none",
            "; material tops: %s" % ", ".join(self.materials) if self.materials else "", self.scale)


def _points(e, where):
    from ezdxf.math import Vec3
    kind = e.dxftype()
    if kind == "LINE":
        return [(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)], False
    if kind == "LWPOLYLINE":
        pts = list(e.get_points("xyb"))
        if any(b != 0 for _, _, b in pts):
            raise ValueError("%s: arc segment (bulge): straight segments only" % where)
        ocs, z = e.ocs(), e.dxf.elevation
        return [(p.x, p.y) for p in (ocs.to_wcs(Vec3(x, y, z)) for x, y, _ in pts)], e.closed
    if kind == "POLYLINE" and (e.is_2d_polyline or e.is_3d_polyline):
        if any(v.dxf.bulge != 0 for v in e.vertices):
            raise ValueError("%s: arc segment (bulge): straight segments only" % where)
        pts = list(e.points())
        xy = [e.ocs().to_wcs(p) for p in pts] if e.is_2d_polyline else pts
        return [(p.x, p.y) for p in xy], e.is_closed
    return None, None


def read_slope_dxf(filename, outline_layer="OUTLINE", trace_layers=None, units=None, material_layers=()):
    """The outline and the traces of the DXF *filename* (module docstring): a :class:`SlopeDrawing`.
    *trace_layers*: the layers to read traces from (default: every layer but the outline's and the
    *material_layers* that has lines); *material_layers*: layers each holding the top of a rock unit (one
    open polyline); layer names match case-insensitively."""
    doc, scale = read_drawing(filename, units)
    wanted = None if trace_layers is None else {l.lower(): l for l in trace_layers}
    tops_wanted = {l.lower(): l for l in material_layers}
    both = [l for l in tops_wanted if wanted is not None and l in wanted]
    if both:
        raise ValueError("read_slope_dxf: the layers %s are asked for as joint traces and as material tops" % both)
    outlines, traces, skipped, other_layers, tops = [], {}, {}, set(), {}
    for e in doc.modelspace():
        layer = e.dxf.layer
        where = "%s: %s #%s on layer %r" % (filename, e.dxftype(), e.dxf.handle, layer)
        pts, closed = _points(e, where)
        if pts is None:
            skipped[e.dxftype()] = skipped.get(e.dxftype(), 0) + 1
            continue
        pts = [(x * scale, y * scale) for x, y in pts]
        if layer.lower() == outline_layer.lower():
            outlines.append((where, pts, closed))
            continue
        if layer.lower() in tops_wanted:
            if closed:
                raise ValueError("%s: a material layer holds the top of its unit, an open polyline across the "
                                 "outline (this one is closed)" % where)
            tops.setdefault(layer, []).append((where, pts))
            continue
        if wanted is not None and layer.lower() not in wanted:
            other_layers.add(layer)
            continue
        if closed and pts[0] != pts[-1]:
            pts = pts + [pts[0]]
        if len(set(pts)) < 2:
            raise ValueError("%s: a trace of a single point" % where)
        traces.setdefault(layer, []).append(pts)  # the drawing's spelling of the layer
    if not outlines:
        raise ValueError("%s: no closed polyline on the outline layer %r (layers: %s)" % (
            filename, outline_layer, ", ".join(sorted(l.dxf.name for l in doc.layers))))
    if len(outlines) > 1:
        raise ValueError("%s: %d polylines on the outline layer %r (%s): the outline is one closed polyline" % (
            filename, len(outlines), outline_layer, "; ".join(w for w, _, _ in outlines)))
    where, pts, closed = outlines[0]
    outline, _ = block_outline(pts, closed, where)
    warn_if_unitless_and_huge(doc, units, filename, outline, "read_slope_dxf")
    if wanted is not None:
        have = {l.lower() for l in traces}
        missing = [l for k, l in wanted.items() if k not in have]
        if missing:
            raise ValueError("%s: no trace on the layers %s" % (filename, ", ".join(map(repr, missing))))
    for key, layer in tops_wanted.items():
        found = [v for k, v in tops.items() if k.lower() == key]
        if not found:
            raise ValueError("%s: no polyline on the material layer %r (the top of its unit)" % (filename, layer))
        if len(found[0]) > 1:
            raise ValueError("%s: %d polylines on the material layer %r (%s): the top of a unit is one polyline" % (
                filename, len(found[0]), layer, "; ".join(w for w, _ in found[0])))
    if skipped or other_layers:
        warnings.warn("read_slope_dxf: %s: skipped %s" % (filename, "; ".join(
            (["%d %s" % (n, k) for k, n in sorted(skipped.items())] if skipped else [])
            + (["the layers %s (not in trace_layers)" % ", ".join(sorted(other_layers))] if other_layers else []))))
    return SlopeDrawing(outline, traces, scale, {k: v[0][1] for k, v in tops.items()})
