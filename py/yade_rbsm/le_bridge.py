"""Limit equilibrium (:mod:`yade_rbsm.limit_equilibrium`) on a block slope: its ground and material
as a limit_equilibrium.Slope (:func:`le_slope`), the methods on one slope (:func:`limit_equilibrium_summary`)
and the tables that print them next to the RBSM factors of safety (:func:`table2`, :func:`fs_table`),
and the blocks' stresses as a field for limit_equilibrium's stress-based method (:func:`stress_field`).
Import these from ``yade_rbsm.safety``."""
import math

from .checks import number

__all__ = ["table2", "le_slope", "limit_equilibrium_summary", "fs_table", "stress_field", "StressField"]


def table2(rbsm, fellenius=None, title="Table 2 - factor of safety along the slip surface", reference=()):
    """A table like Table 2 of the seed paper: RBSM (a :class:`ContactFS`) next to Fellenius (a
    limit_equilibrium.Result), then the rows *reference* ``(label, T, N, FS)`` given for comparison
    (scripts/landslide_slope.py passes the seed paper's own figures)."""
    from .limit_equilibrium import results_table
    rows = [rbsm.row()]
    if fellenius is not None:
        rows.append(("Limit equilibrium (Fellenius)", fellenius.shear, fellenius.normal, fellenius.fs))
    rows += list(reference)
    return results_table(rows, title)


def le_slope(surface, material=None, c=None, phi=None, density=None, g=9.81, kh=0.0, kv=0.0):
    """A :class:`limit_equilibrium.Slope` with the ground polyline of a block slope (e.g.
    ``SlopeBlocks.surface``) and one layer with the block material: ``gamma = density·g`` [kN/m³],
    ``c`` [kPa] and ``phi`` [deg] of the joints. Either an RbsmMat (*material*: ``density``,
    ``cohesion`` [Pa], ``frictionAngle`` [rad]) or the values (*c* [Pa], *phi* [rad], *density*
    [kg/m³]); explicit values win. *kh*, *kv*: the pseudo-static load (:class:`limit_equilibrium.Slope`)."""
    from . import limit_equilibrium as le
    if material is not None:
        c = material.cohesion if c is None else c
        phi = material.frictionAngle if phi is None else phi
        density = material.density if density is None else density
    if c is None or phi is None or density is None:
        raise ValueError("le_slope: give a material or c, phi and density")
    c, g = number("le_slope", "c", c, 0), number("le_slope", "g", g, 0, low_open=True)
    phi = number("le_slope", "phi", phi, 0, math.pi / 2, high_open=True)
    density = number("le_slope", "density", density, 0, low_open=True)
    return le.Slope([(float(x), float(y)) for x, y in surface],
                    le.Layer(c=c / 1e3, phi=math.degrees(phi), gamma=density * g / 1e3, name="blocks"), kh=kh, kv=kv)


def limit_equilibrium_summary(slope, circle=None, polyline=None, toe=None, search=None, n=50):
    """Fellenius and Bishop on *circle* ``(xc, yc, R)``, Fellenius on *polyline*, and the
    critical-circle search (Fellenius and Bishop) through *toe* over the centre grid *search* =
    ``dict(x_range=..., y_range=..., nx=.., ny=.., refine=..)``. Returns ``{label: Result or
    SearchResult}`` (a method that fails on this geometry, e.g. Bishop's m_alpha limit, is reported
    as its ValueError message, a str)."""
    from . import limit_equilibrium as le
    out = {}

    def _try(label, fn, *a, **k):
        try:
            out[label] = fn(*a, **k)
        except ValueError as e:
            out[label] = str(e)

    if polyline is not None:
        _try("Fellenius, slip polyline", le.fellenius_polyline, slope, polyline, n)
    if circle is not None:
        _try("Fellenius, circle", le.fellenius_circle, slope, le.Circle(*circle), n)
        _try("Bishop, circle", le.bishop_circle, slope, le.Circle(*circle), n)
    if search is not None and toe is not None:
        for meth in ("fellenius", "bishop"):
            _try("%s, critical circle" % meth.capitalize(), le.critical_circle, slope, through=toe,
                 method=meth, n=n, **search)
    return out


def fs_table(rows, title="Factor of safety - all methods"):
    """Rows ``(method, FS, note)``; FS may be None (not computed) or a str (failed)."""
    w = max([len(r[0]) for r in rows] + [20])
    lines = [title, "%-*s %8s  %s" % (w, "method", "FS", "note"), "-" * (w + 40)]
    for lab, fs, note in rows:
        f = "%8.3f" % fs if isinstance(fs, (int, float)) and fs is not None else "%8s" % "-"
        lines.append("%-*s %s  %s" % (w, lab, f, note))
    return "\n".join(lines)


class StressField:
    """The stress of a block slope as a field for :func:`limit_equilibrium.stress_circle`: called with
    x, y [m] (numbers or arrays of one shape) it returns (sxx, syy, sxy) [kPa, compression positive] of
    that shape, linear between the blocks' centroids (Delaunay triangles of them) and the nearest
    block's outside their hull; NaN at a point farther than *reach* [m] from every centroid (beyond the
    blocks: the stress method then says the surface leaves the field) and at a non-finite point.
    ``points`` [m] and ``values`` [kPa] are the centroids and their stresses."""

    def __init__(self, points, values, reach=None):
        from scipy.interpolate import LinearNDInterpolator
        from scipy.spatial import QhullError, cKDTree
        import numpy as np
        self.points, self.values = np.asarray(points, dtype=float), np.asarray(values, dtype=float)
        if self.points.ndim != 2 or self.points.shape[1] != 2 or self.values.shape != (len(self.points), 3):
            raise ValueError("StressField: points must be (n, 2) and values (n, 3); got %s and %s"
                             % (self.points.shape, self.values.shape))
        if len(self.points) < 3:
            raise ValueError("StressField: at least 3 blocks are needed (got %d)" % len(self.points))
        self.reach = None if reach is None else number("StressField", "reach", reach, 0, low_open=True)
        try:
            self._linear = LinearNDInterpolator(self.points, self.values)
        except QhullError:
            raise ValueError("StressField: the %d centroids are on one line (a single row of blocks?): no field "
                             "between them" % len(self.points)) from None
        self._tree = cKDTree(self.points)

    def __call__(self, x, y):
        import numpy as np
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        p = np.column_stack([x.ravel(), y.ravel()])
        s = np.full((len(p), 3), np.nan)
        ok = np.all(np.isfinite(p), axis=1)
        if ok.any():
            d, k = self._tree.query(p[ok])
            v = self._linear(p[ok])
            out = np.isnan(v[:, 0])
            v[out] = self.values[k[out]]
            if self.reach is not None:
                v[d > self.reach] = np.nan
            s[ok] = v
        return s.T.reshape((3,) + x.shape)


def stress_field(O=None, ids=None):
    """A :class:`StressField` of the blocks *ids* (default: every Polygon2D block that is not fixed) in
    their present state: each block's average stress (:func:`yade_rbsm.measure.block_stresses`, Love-Weber
    from its joint forces) at its centroid, up to the largest block's reach (centroid to farthest vertex)
    beyond the centroids. For Kulhawy's stress-based factor of safety of a settled
    slope: ``limit_equilibrium.critical_circle(soil, ..., method="stress", stress=stress_field(),
    min_depth=2 * block_size)``. The stresses are the joints': in a dry slope the effective ones."""
    from . import measure, omega
    from .checks import body_ids
    want = None if ids is None else body_ids("stress_field", ids)
    if O is None:
        from yade import O
    S = measure.block_stresses(O)
    pts, vals, reach = [], [], 0.0
    for b in O.bodies:
        if b is None or b.id not in S or (want is None and omega.is_fixed(b)) or (want is not None and b.id not in want):
            continue
        s = S[b.id]
        pts.append((b.state.pos[0], b.state.pos[1]))
        vals.append((-s[0][0] / 1e3, -s[1][1] / 1e3, -0.5 * (s[0][1] + s[1][0]) / 1e3))
        reach = max([reach] + [math.hypot(v[0] - pts[-1][0], v[1] - pts[-1][1])
                               for v in b.shape.worldVertices(b.state.pos, b.state.ori)])
    if want is not None and len(pts) < len(want):
        raise ValueError("stress_field: ids %s are not Polygon2D blocks" % sorted(want - set(int(b.id) for b in O.bodies if b is not None and b.id in S))[:10])
    if not pts:
        raise ValueError("stress_field: ids is empty" if want is not None else
                         "stress_field: no Polygon2D block in the scene that is not fixed (give ids= to take fixed ones)")
    return StressField(pts, vals, reach=reach)
