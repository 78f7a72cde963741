"""Factor of safety from the RBSM contact forces along a slip surface (seed paper, Table 2).

:func:`contact_fs` selects the real RBSM joints whose contact segment (``geom.p0``–``geom.p1``)
lies on a slip polyline (both ends within *tol* of it) and whose two blocks are on opposite sides
of it (centroids above / below). For each such joint, with the block *above* the surface taken as
the sliding one:

* normal force ``N_j = phys.normalForce`` (> 0 compression);
* the shear force the lower block exerts on the upper one is ``±phys.shearForce·t`` (``+`` if the
  upper block is body 2: the law's shear force is the force on body 2 along the tangent); the
  driving shear is its opposite projected on the downslope direction ``d`` (unit tangent of the
  joint pointing the way the polyline descends), ``T_j = -(F_shear on upper)·d``;
* strength ``c_j·ℓ_j·thickness`` over the intact points (``phys.cohesion``, tributary
  ``w_k·ℓ``) plus ``N_j·tanφ_j`` (``phys.tanPhi``).

``FS = Σ(c ℓ t + N tanφ) / |Σ T|``. Forces are returned in kN (per metre of thickness for
thickness 1), ready to print next to :func:`limit_equilibrium.fellenius_polyline`.
"""
import math
from dataclasses import dataclass

__all__ = ["ContactFS", "contact_fs", "point_polyline_distance", "table2", "le_slope", "circle_through",
           "limit_equilibrium_summary", "fs_table"]


def point_polyline_distance(p, poly):
    best = float("inf")
    for (xa, ya), (xb, yb) in zip(poly[:-1], poly[1:]):
        dx, dy = xb - xa, yb - ya
        L2 = dx * dx + dy * dy
        t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - xa) * dx + (p[1] - ya) * dy) / L2))
        best = min(best, math.hypot(p[0] - xa - t * dx, p[1] - ya - t * dy))
    return best


def _side(p, poly):
    """> 0 if p is above the polyline (vertical offset, constant extrapolation beyond its ends)."""
    xs = [q[0] for q in poly]
    x = min(max(p[0], xs[0]), xs[-1])
    for (xa, ya), (xb, yb) in zip(poly[:-1], poly[1:]):
        if xa <= x <= xb:
            y = ya if xb == xa else ya + (x - xa) * (yb - ya) / (xb - xa)
            return p[1] - y
    return 0.0


@dataclass
class ContactFS:
    fs: float
    normal: float  # kN
    shear: float  # kN (driving, positive downslope)
    resisting: float  # kN
    n_joints: int
    length: float  # m of slip surface covered by joints
    ids: list  # (id1, id2) of the joints used

    def row(self, label="Present method (RBSM)"):
        return (label, self.shear, self.normal, self.fs)


def contact_fs(surface, tol=None, O=None):
    """FS along the slip polyline *surface* ``[(x, y), ...]`` (strictly increasing x) from the
    current contact forces; see the module docstring. *tol* defaults to 1e-3 × the polyline's
    extent (blocks move by the elastic settlement, mm, before the forces are read)."""
    if O is None:
        from yade import O
    poly = [(float(x), float(y)) for x, y in surface]
    if tol is None:
        size = max(poly[-1][0] - poly[0][0], max(p[1] for p in poly) - min(p[1] for p in poly))
        tol = 1e-3 * size
    direction = 1.0 if poly[-1][1] < poly[0][1] else -1.0  # sliding towards +x or -x
    N = T = R = L = 0.0
    used = []
    for I in O.interactions:
        if not I.isReal or type(I.phys).__name__ != "RbsmPhys":
            continue
        g, ph = I.geom, I.phys
        p0, p1 = (g.p0[0], g.p0[1]), (g.p1[0], g.p1[1])
        if point_polyline_distance(p0, poly) > tol or point_polyline_distance(p1, poly) > tol:
            continue
        c1, c2 = O.bodies[I.id1].state.pos, O.bodies[I.id2].state.pos
        s1, s2 = _side((c1[0], c1[1]), poly), _side((c2[0], c2[1]), poly)
        if s1 * s2 >= 0:
            continue
        upper_is_2 = s2 > 0
        t = (g.tangent[0], g.tangent[1])
        d = t if t[0] * direction > 0 else (-t[0], -t[1])
        sgn = 1.0 if upper_is_2 else -1.0
        f_on_upper = (sgn * ph.shearForce * t[0], sgn * ph.shearForce * t[1])
        T += -(f_on_upper[0] * d[0] + f_on_upper[1] * d[1])
        N += ph.normalForce
        intact = list(ph.intactPoints)
        w = list(g.weights)
        R += sum(ph.cohesion * wk * g.length * g.thickness for wk, ok in zip(w, intact) if ok)
        R += ph.normalForce * ph.tanPhi
        L += g.length
        used.append((I.id1, I.id2))
    fs = R / abs(T) if T != 0 else float("inf")
    return ContactFS(fs, N / 1e3, T / 1e3, R / 1e3, len(used), L, used)


def table2(rbsm, fellenius=None, title="Table 2 - factor of safety along the slip surface"):
    """Table 2 of the seed paper: RBSM (a :class:`ContactFS`) next to Fellenius (a
    limit_equilibrium.Result), plus the seed's own figures for reference."""
    from .limit_equilibrium import results_table
    rows = [rbsm.row()]
    if fellenius is not None:
        rows.append(("Limit equilibrium (Fellenius)", fellenius.shear, fellenius.normal, fellenius.fs))
    rows += [("seed paper: RBSM", 217.0, 271.0, 0.72), ("seed paper: Fellenius", 231.0, 253.0, 0.63)]
    return results_table(rows, title)


# ---------------------------------------------------------------------------------------------
# limit equilibrium on the block slope's geometry and material
# ---------------------------------------------------------------------------------------------
def le_slope(surface, material=None, c=None, phi=None, density=None, g=9.81):
    """A :class:`limit_equilibrium.Slope` with the ground polyline of a block slope (e.g.
    ``SlopeBlocks.surface``) and one layer with the block material: ``gamma = density·g`` [kN/m³],
    ``c`` [kPa] and ``phi`` [deg] of the joints. Either an RbsmMat (*material*: ``density``,
    ``cohesion`` [Pa], ``frictionAngle`` [rad]) or the values (*c* [Pa], *phi* [rad], *density*
    [kg/m³]); explicit values win."""
    from . import limit_equilibrium as le
    if material is not None:
        c = material.cohesion if c is None else c
        phi = material.frictionAngle if phi is None else phi
        density = material.density if density is None else density
    if c is None or phi is None or density is None:
        raise ValueError("le_slope: give a material or c, phi and density")
    return le.Slope([(float(x), float(y)) for x, y in surface],
                    le.Layer(c=c / 1e3, phi=math.degrees(phi), gamma=density * g / 1e3, name="blocks"))


def circle_through(a, b, c):
    """(xc, yc, R) of the circle through three points."""
    (ax, ay), (bx, by), (cx, cy) = a, b, c
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if d == 0:
        raise ValueError("circle_through: collinear points")
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


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
