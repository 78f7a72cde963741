"""Factor of safety from the RBSM contact forces along a given slip polyline (:func:`contact_fs`) or
circle (:func:`contact_fs_circle`); the rules are in :mod:`yade_rbsm.safety`'s docstring. Import
these from ``yade_rbsm.safety``."""
import math
from dataclasses import dataclass

from . import omega
from .geometry import check_polyline, point_polyline_distance, point_segment_distance

__all__ = ["ContactFS", "contact_fs", "contact_fs_circle"]


@dataclass
class ContactFS:
    fs: float
    normal: float  # kN/m (per metre of the blocks' thickness, as limit equilibrium's slices)
    shear: float  # kN/m (driving, positive downslope)
    resisting: float  # kN/m
    n_joints: int
    length: float  # m of slip surface covered by joints
    ids: list  # (id1, id2) of the joints used

    def row(self, label="Present method (RBSM)"):
        return (label, self.shear, self.normal, self.fs)

    def __repr__(self):
        return "ContactFS(fs=%.4g, shear %.4g kN/m, normal %.4g kN/m, resisting %.4g kN/m, %d joints over %.3g m)" % (
            self.fs, self.shear, self.normal, self.resisting, self.n_joints, self.length)


def contact_fs(surface, tol=None, O=None, allow_empty=False):
    """FS along the slip polyline *surface* ``[(x, y), ...]`` (strictly increasing x) from the
    current contact forces; see the module docstring. *tol* defaults to 1e-3 × the polyline's
    extent (blocks move by the elastic settlement, mm, before the forces are read). ValueError if
    no joint lies on it (the surface misses the slope) unless *allow_empty*."""
    if O is None:
        from yade import O
    poly = check_polyline(surface)
    if tol is not None and not (math.isfinite(tol) and tol > 0):
        raise ValueError("contact_fs: tol must be a finite number > 0, got %r" % (tol,))
    if tol is None:
        size = max(poly[-1][0] - poly[0][0], max(p[1] for p in poly) - min(p[1] for p in poly))
        tol = 1e-3 * size
    direction = 1.0 if poly[-1][1] < poly[0][1] else -1.0  # sliding towards +x or -x
    N = T = R = L = 0.0
    used = []
    for I in omega.joints(O):
        g = I.geom
        p0, p1 = (g.p0[0], g.p0[1]), (g.p1[0], g.p1[1])
        if point_polyline_distance(p0, poly) > tol or point_polyline_distance(p1, poly) > tol:
            continue
        c1, c2 = O.bodies[I.id1].state.pos, O.bodies[I.id2].state.pos
        s1, s2 = _above_joint(c1, p0, p1, poly), _above_joint(c2, p0, p1, poly)
        if s1 * s2 >= 0:
            continue
        upper_is_2 = s2 > 0
        t = (g.tangent[0], g.tangent[1])
        d = t if t[0] * direction > 0 else (-t[0], -t[1])
        t_, n_, r_ = _joint_terms(I, upper_is_2, d)
        T += t_
        N += n_
        R += r_
        L += g.length
        used.append((I.id1, I.id2))
    if not used and not allow_empty:
        raise ValueError("contact_fs: no joint lies on the slip surface %s within tol = %g m with its blocks on "
                         "opposite sides: it misses the slope, or crosses blocks (the blocks' stresses read any "
                         "surface: SlopeModel.stress_fs, limit_equilibrium.stress_polyline)" % (_short(poly), tol))
    fs = R / abs(T) if T != 0 else float("inf")
    return ContactFS(fs, N / 1e3, T / 1e3, R / 1e3, len(used), L, used)


def _above_joint(c, p0, p1, poly):
    """> 0 if the centroid c is above the polyline's segment that a joint p0-p1 lies on, extended as a line: the
    side of that segment, not the polyline's height at c's x, which past a kink is another segment's. (Not the
    joint's own line: a short joint across the surface is near it only by its shortness.)"""
    m = (0.5 * (p0[0] + p1[0]), 0.5 * (p0[1] + p1[1]))
    a, b = min(zip(poly[:-1], poly[1:]), key=lambda s: point_segment_distance(m, s[0], s[1]))
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _short(poly, most=3):
    return "[" + ", ".join("(%g, %g)" % p for p in poly[:most]) + (", ...]" if len(poly) > most else "]")


def _check_circle(circle):
    try:
        xc, yc, R = (float(v) for v in circle)
    except (TypeError, ValueError):
        raise ValueError("circle must be (xc, yc, R), got %r" % (circle,)) from None
    if not all(math.isfinite(v) for v in (xc, yc, R)):
        raise ValueError("circle (xc, yc, R) contains NaN or inf")
    if R <= 0:
        raise ValueError("circle radius R must be > 0, got %g" % R)
    return xc, yc, R


def _joint_terms(I, upper_is_2, d):
    """(T, N, R) of one joint per metre of its thickness: driving shear on the upper block along d, normal,
    strength (a slope built 2 m thick carries twice the force of the same slope per metre)."""
    g, ph = I.geom, I.phys
    t = (g.tangent[0], g.tangent[1])
    sgn = 1.0 if upper_is_2 else -1.0
    f_on_upper = (sgn * ph.shearForce * t[0], sgn * ph.shearForce * t[1])
    T = -(f_on_upper[0] * d[0] + f_on_upper[1] * d[1])
    w = list(g.weights)
    R = sum(ph.cohesion * wk * g.length * g.thickness for wk, ok in zip(w, list(ph.intactPoints)) if ok)
    R += ph.normalForce * ph.tanPhi
    return T / g.thickness, ph.normalForce / g.thickness, R / g.thickness


def contact_fs_circle(circle, band=None, O=None):
    """FS along the circle ``(xc, yc, R)`` from the current contact forces (module docstring);
    *band* (m) defaults to 2 % of R. ValueError if no joint lies within the band (the circle misses
    the slope)."""
    if O is None:
        from yade import O
    xc, yc, Rc = _check_circle(circle)
    band = 0.02 * Rc if band is None else band
    if not (isinstance(band, (int, float)) and math.isfinite(band) and band > 0):
        raise ValueError("contact_fs_circle: band must be a finite number > 0, got %r" % (band,))
    sel = []
    for I in omega.joints(O):
        g = I.geom
        mx, my = 0.5 * (g.p0[0] + g.p1[0]), 0.5 * (g.p0[1] + g.p1[1])
        if abs(math.hypot(mx - xc, my - yc) - Rc) > band:
            continue
        c1, c2 = O.bodies[I.id1].state.pos, O.bodies[I.id2].state.pos
        in1 = math.hypot(c1[0] - xc, c1[1] - yc) < Rc
        in2 = math.hypot(c2[0] - xc, c2[1] - yc) < Rc
        if in1 == in2:
            continue
        sel.append((I, in2, (mx, my)))
    if not sel:
        raise ValueError("contact_fs_circle: the circle (%g, %g, R = %g) misses the slope: no joint within the "
                         "band %g m with its blocks on opposite sides" % (xc, yc, Rc, band))
    # rotation sense of the sliding mass: moment of the weights of the free blocks inside
    moment = 0.0
    for b in omega.free_bodies(O):
        p = b.state.pos
        if math.hypot(p[0] - xc, p[1] - yc) < Rc:
            moment += b.state.mass * (p[0] - xc)
    cw = moment >= 0
    N = T = R = L = 0.0
    used = []
    for I, upper_is_2, (mx, my) in sel:
        rx, ry = (mx - xc), (my - yc)
        r = math.hypot(rx, ry)
        d = (ry / r, -rx / r) if cw else (-ry / r, rx / r)  # z x r is CCW
        t_, n_, r_ = _joint_terms(I, upper_is_2, d)
        T += t_
        N += n_
        R += r_
        L += I.geom.length
        used.append((I.id1, I.id2))
    fs = R / abs(T) if T != 0 else float("inf")
    return ContactFS(fs, N / 1e3, T / 1e3, R / 1e3, len(used), L, used)
