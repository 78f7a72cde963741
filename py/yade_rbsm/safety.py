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

:func:`contact_fs_circle` does the same along a circle ``(xc, yc, R)``: the joints whose contact
segment midpoint lies within ``band`` of the circle (``|dist - R| <= band``) and whose blocks are
on opposite sides (centroid inside / outside); the sliding block is the one inside; the driving
direction ``d`` at a joint is the circle's tangent in the sense of the rotation of the sliding mass
(clockwise if the weights of the blocks inside the circle have their centroid right of the centre,
i.e. ``Σ m (x - xc) > 0``, as in Fellenius' driving moment).

:func:`slipping_surface` finds the surface of slipping joints: the real joints with at least
``min_slipping`` slipping integration points (``phys.nSlipping``) are linked when their contact
segments share an end (within *tol*); the largest connected set (by length) is the surface,
returned as a polyline: the shortest path (by length) through its joints and the gaps between
them from its end point of least x to its end point of greatest x (x made strictly increasing), with
the joints along that path.
Joints are linked when their contact segments come within *tol* of each other (default half the
median length of the scene's joints: a sliding block's contact may cover only part of its edge); point contacts
(length < 1 % of the median) are left out.
:func:`slip_surface_fs` evaluates :func:`contact_fs` along it and, given the ground polyline and
the material, Fellenius along it (the ends of the polyline that lie below the ground are extended
to the ground along their end segments, or vertically like a tension crack if the end segment
does not rise to the ground, for the slices).

Bad input (an empty or NaN polyline, a polyline or circle that meets no joint of the scene: "misses
the slope", a non-positive band) raises ValueError naming the problem.
"""
import math
from dataclasses import dataclass

from .checks import count, number
from . import omega
from .geometry import check_polyline, circle_through, height_above as _side, interp_y, point_polyline_distance

__all__ = ["ContactFS", "contact_fs", "contact_fs_circle", "SlipSurface", "slipping_surface", "slip_surface_fs",
           "point_polyline_distance", "table2", "le_slope", "circle_through", "limit_equilibrium_summary",
           "fs_table", "check_polyline", "probe_slipping_surface"]


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
        s1, s2 = _side((c1[0], c1[1]), poly), _side((c2[0], c2[1]), poly)
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
        raise ValueError("contact_fs: the slip surface %s misses the slope: no joint lies on it within tol = %g m "
                         "with its blocks on opposite sides" % (_short(poly), tol))
    fs = R / abs(T) if T != 0 else float("inf")
    return ContactFS(fs, N / 1e3, T / 1e3, R / 1e3, len(used), L, used)


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
    """(T, N, R) of one joint: driving shear on the upper block along d, normal, strength."""
    g, ph = I.geom, I.phys
    t = (g.tangent[0], g.tangent[1])
    sgn = 1.0 if upper_is_2 else -1.0
    f_on_upper = (sgn * ph.shearForce * t[0], sgn * ph.shearForce * t[1])
    T = -(f_on_upper[0] * d[0] + f_on_upper[1] * d[1])
    w = list(g.weights)
    R = sum(ph.cohesion * wk * g.length * g.thickness for wk, ok in zip(w, list(ph.intactPoints)) if ok)
    R += ph.normalForce * ph.tanPhi
    return T, ph.normalForce, R


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


def _median_joint_length(O):
    """Median length of the scene's joints of non-zero length (the upper one of an even count)."""
    la = sorted(I.geom.length for I in omega.joints(O) if I.geom.length > 0)
    return la[len(la) // 2]


@dataclass
class SlipSurface:
    polyline: list  # [(x, y), ...], increasing x
    joints: list  # (id1, id2)
    length: float  # m, sum of the contact lengths

    def __str__(self):
        return "slipping surface: %d joints, %.2f m, polyline %s" % (
            len(self.joints), self.length, " ".join("(%.2f, %.2f)" % p for p in self.polyline))


def _segments_distance(a, b):
    """Distance between the segments a = (p, q, ...) and b, which do not cross (joints)."""
    return min(point_polyline_distance(a[0], [b[0], b[1]]), point_polyline_distance(a[1], [b[0], b[1]]),
               point_polyline_distance(b[0], [a[0], a[1]]), point_polyline_distance(b[1], [a[0], a[1]]))


def _largest_linked_set(segs, tol):
    """Indices (increasing) of the largest set, by total length ``seg[3]``, of segments linked by
    coming within *tol* of each other (connected components, scipy.sparse.csgraph); on a tie the
    set with the least index."""
    import numpy as np
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    n = len(segs)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n) if _segments_distance(segs[i], segs[j]) <= tol]
    ij = np.array(pairs, dtype=int).reshape(-1, 2)
    _, labels = connected_components(coo_matrix((np.ones(len(ij)), (ij[:, 0], ij[:, 1])), shape=(n, n)), directed=False)
    groups = {}
    for k in range(n):
        groups.setdefault(labels[k], []).append(k)
    return max(groups.values(), key=lambda g: sum(segs[k][3] for k in g))


def _shortest_path(adj, src, dst):
    """Dijkstra from *src* to *dst* over ``adj = {node: [(node, length), ...]}``: the nodes of the
    path, [dst] alone if dst is not reached."""
    import heapq
    dist, prev, heap = {src: 0.0}, {}, [(0.0, src)]
    while heap:
        d, a = heapq.heappop(heap)
        if a == dst or d > dist.get(a, float("inf")):
            if a == dst:
                break
            continue
        for b, w in adj[a]:
            if d + w < dist.get(b, float("inf")):
                dist[b], prev[b] = d + w, a
                heapq.heappush(heap, (d + w, b))
    path = [dst]
    while path[-1] != src and path[-1] in prev:
        path.append(prev[path[-1]])
    path.reverse()
    return path


def slipping_surface(O=None, tol=None, min_slipping=1, joints=None):
    """The surface of slipping joints of the current state (module docstring); None if no joint
    slips. *joints*: a set of (id1, id2) to use instead of the joints slipping now (e.g. those that
    slipped at some time of a run, :func:`probe_slipping_surface`)."""
    if O is None:
        from yade import O
    segs = []
    for I in omega.joints(O):
        if (I.phys.nSlipping < min_slipping) if joints is None else ((I.id1, I.id2) not in joints):
            continue
        g = I.geom
        segs.append(((g.p0[0], g.p0[1]), (g.p1[0], g.p1[1]), (I.id1, I.id2), g.length))
    if not segs:
        return None
    L = sorted(s[3] for s in segs)
    med = L[len(L) // 2]
    segs = [sg for sg in segs if sg[3] > 0.01 * med]  # corner (point) contacts are no part of a surface
    if not segs:
        return None
    if tol is None:  # half the median length of all joints of the scene
        tol = 0.5 * _median_joint_length(O)
    best = _largest_linked_set(segs, tol)
    # the surface through the set: shortest path (by length) over the joints and the gaps (<= tol)
    # between their ends, from the end point of least x to the end point of greatest x
    nodes = [p for k in best for p in segs[k][:2]]
    adj = {i: [] for i in range(len(nodes))}
    for m, k in enumerate(best):
        adj[2 * m].append((2 * m + 1, segs[k][3]))
        adj[2 * m + 1].append((2 * m, segs[k][3]))
    for a in range(len(nodes)):
        for b in range(a + 1, len(nodes)):
            if a // 2 != b // 2:
                d = math.hypot(nodes[a][0] - nodes[b][0], nodes[a][1] - nodes[b][1])
                if d <= tol:
                    adj[a].append((b, d))
                    adj[b].append((a, d))
    src = min(range(len(nodes)), key=lambda i: (nodes[i][0], nodes[i][1]))
    dst = max(range(len(nodes)), key=lambda i: (nodes[i][0], nodes[i][1]))
    path = _shortest_path(adj, src, dst)
    on_path = {best[i // 2] for i in path}
    best = [k for k in best if k in on_path]
    dx = 1e-6 * max(1.0, max(abs(c) for i in path for c in nodes[i]))
    poly = []
    for i in path:  # strictly increasing x (a vertical run is spread by a tiny dx; back steps dropped)
        x, y = nodes[i]
        if poly and math.hypot(x - poly[-1][0], y - poly[-1][1]) <= tol * 1e-3:
            continue
        if poly and x <= poly[-1][0]:
            if poly[-1][0] - x > tol:
                continue
            x = poly[-1][0] + dx
        poly.append((x, y))
    return SlipSurface(poly, [segs[k][2] for k in best], sum(segs[k][3] for k in best))


def probe_slipping_surface(steps=500, damping=0.0, check=20, O=None, **kw):
    """Run *steps* steps from the current state (NewtonIntegrator damping *damping*, PyRunners
    off), collecting every *check* steps the joints that slip (a sliding joint sticks now and
    then), find the surface of the joints that slipped (:func:`slipping_surface` with them,
    keywords *kw*), then restore the state (O.saveTmp / O.loadTmp): the surface of a failing slope
    read from its first motion, to evaluate the contact forces of the equilibrium state along it.
    Returns a SlipSurface or None."""
    steps = count("probe_slipping_surface", "steps", steps, 0)
    check = count("probe_slipping_surface", "check", check)
    damping = number("probe_slipping_surface", "damping", damping, 0, 1, high_open=True)
    if O is None:
        from yade import O
    from .scene import advance
    mark = "rbsm_slip_probe"
    O.saveTmp(mark)
    try:
        omega.switch_off_pyrunners(O)
        omega.newton(O).damping = damping
        seen = set()
        done = 0
        while done < steps:
            k = min(check, steps - done)
            advance(int(k))
            done += k
            seen.update((I.id1, I.id2) for I in omega.joints(O) if I.phys.nSlipping > 0)
        return slipping_surface(O=O, joints=seen, **kw)
    finally:
        O.loadTmp(mark)


def _extend_to_ground(poly, ground):
    """Extend the ends of *poly* that lie below the ground polyline along their end segments up to
    the ground (a plane is continued as a plane), or vertically if the end segment does not rise
    towards the ground within the slope's extent."""
    out = list(poly)
    x0, xn = ground[0][0], ground[-1][0]
    for end in (0, -1):
        p = out[end]
        q = out[1] if end == 0 else out[-2]
        if p[1] >= interp_y(ground, p[0]):
            continue
        dx, dy = p[0] - q[0], p[1] - q[1]
        hit = None
        if dx != 0:
            def below(m):
                return p[1] + m * dy < interp_y(ground, p[0] + m * dx)
            lo, hi = 0.0, 1.0
            while below(hi) and x0 < p[0] + hi * dx < xn and hi < 1e6:
                hi *= 2
            if not below(hi):
                for _ in range(60):
                    m = 0.5 * (lo + hi)
                    if below(m):
                        lo = m
                    else:
                        hi = m
                hit = (p[0] + hi * dx, p[1] + hi * dy)
        if hit is None:
            e = 1e-6 * max(1.0, abs(p[0]))
            hit = (p[0] - e if end == 0 else p[0] + e, max(y for _, y in ground) + 1.0)
        if end == 0:
            out.insert(0, hit)
        else:
            out.append(hit)
    return out


def slip_surface_fs(surface=None, ground=None, material=None, g=9.81, n=50, O=None, tol=None, slope=None):
    """FS along the surface of slipping joints: returns ``(SlipSurface, ContactFS, Fellenius
    Result or str or None)``. *surface*: a SlipSurface (default: :func:`slipping_surface` now);
    with *ground* (ground polyline) and *material* (RbsmMat), also Fellenius along it (ends below
    the ground extended to it, module docstring), or along the limit_equilibrium.Slope *slope*
    (its ground and layers: e.g. the strength of the joints rather than of the blocks). *tol*: as in :func:`contact_fs`, default 0.1 x
    the median joint length. ValueError if no joint slips."""
    g = number("slip_surface_fs", "g", g, 0, low_open=True)
    n = count("slip_surface_fs", "n", n)
    if O is None:
        from yade import O
    ss = surface if surface is not None else slipping_surface(O=O)
    if ss is None:
        raise ValueError("slip_surface_fs: no joint slips: there is no slipping surface")
    if len(ss.polyline) < 2:
        raise ValueError("slip_surface_fs: the slipping surface is a single point")
    if tol is None:  # the blocks have moved a little along the surface since it was found
        tol = 0.1 * _median_joint_length(O)
    fs = contact_fs(ss.polyline, O=O, tol=tol)
    fel = None
    if slope is None and ground is not None and material is not None:
        slope = le_slope(ground, material, g=g)
    if slope is not None:
        from . import limit_equilibrium as le
        try:
            fel = le.fellenius_polyline(slope, _extend_to_ground(ss.polyline, [tuple(p) for p in slope.surface]), n)
        except ValueError as e:
            fel = str(e)
    return ss, fs, fel


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
    c, g = number("le_slope", "c", c, 0), number("le_slope", "g", g, 0, low_open=True)
    phi = number("le_slope", "phi", phi, 0, math.pi / 2, high_open=True)
    density = number("le_slope", "density", density, 0, low_open=True)
    return le.Slope([(float(x), float(y)) for x, y in surface],
                    le.Layer(c=c / 1e3, phi=math.degrees(phi), gamma=density * g / 1e3, name="blocks"))


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
