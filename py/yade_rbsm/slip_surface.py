"""The surface of slipping joints: found from the joints that slip now or during a probe run
(:func:`slipping_surface`, :func:`probe_slipping_surface`: the slipping joints linked into
connected sets, the largest one followed by a shortest path), and its factor of safety from the
contact forces and by Fellenius (:func:`slip_surface_fs`); see :mod:`yade_rbsm.safety`'s docstring.
Import these from ``yade_rbsm.safety``."""
import math
from dataclasses import dataclass
from typing import NamedTuple

from . import omega
from .checks import count, number
from .contact_safety import contact_fs
from .geometry import interp_y, point_polyline_distance
from .le_bridge import le_slope

__all__ = ["SlipSurface", "SlipSurfaceFS", "slipping_surface", "probe_slipping_surface", "slip_surface_fs"]


def _median_joint_length(O):
    """Median length of the scene's joints of non-zero length (the upper one of an even count)."""
    la = sorted(I.geom.length for I in omega.joints(O) if I.geom.length > 0)
    return la[len(la) // 2]


@dataclass
class SlipSurface:
    polyline: list  # [(x, y), ...], increasing x
    joints: list  # (id1, id2) of the joints that slipped (the surface is drawn through them)
    length: float  # m, sum of their contact lengths

    def __str__(self):
        return "slipping surface: %d slipping joints, %.2f m, polyline %s" % (
            len(self.joints), self.length, " ".join("(%.2f, %.2f)" % p for p in self.polyline))

    def __repr__(self):
        (x0, y0), (x1, y1) = self.polyline[0], self.polyline[-1]
        return "SlipSurface(%d slipping joints, %.3g m, from (%.3g, %.3g) to (%.3g, %.3g))" % (
            len(self.joints), self.length, x0, y0, x1, y1)


class SlipSurfaceFS(NamedTuple):
    """What :func:`slip_surface_fs` returns; unpacks as (surface, contact, fellenius) like the tuple it was."""
    surface: SlipSurface
    contact: object  # contact_safety.ContactFS
    fellenius: object  # limit_equilibrium.Result, the reason it failed (str), or None

    def __repr__(self):
        fel = self.fellenius
        fel = ("Fellenius FS %.3f" % fel.fs) if hasattr(fel, "fs") else ("Fellenius: %s" % fel if fel else "no Fellenius")
        return "SlipSurfaceFS(contact forces FS %.3f from the %d joints on the surface, %s; %r)" % (
            self.contact.fs, self.contact.n_joints, fel, self.surface)

    def note(self):
        """The two counts a table row needs: the joints whose forces were read (every joint on the surface,
        slipping or not) and the joints that slipped and drew it."""
        return "%d joints on the surface (%d slipped and drew it)" % (self.contact.n_joints, len(self.surface.joints))


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


def probe_slipping_surface(steps=500, damping=0.0, check=20, O=None, min_share=0.1, **kw):
    """Run *steps* steps from the current state (NewtonIntegrator damping *damping*, PyRunners
    off), reading every *check* steps the energy each joint has dissipated by slip since the start,
    find the surface of the joints that dissipated at least *min_share* x the most any joint did
    (:func:`slipping_surface` with them, keywords *kw*), then restore the state (O.saveTmp /
    O.loadTmp): the surface of a failing slope read from its first motion, to evaluate the contact
    forces of the equilibrium state along it. Returns a SlipSurface or None.

    Why dissipation and not "slipped at some check": an undamped probe of a failing slope is chaotic,
    and about 190 joints of the landslide example slip now and then, most of them by chatter that
    round-off (OpenMP's summation order at -j2) switches on and off; eleven joints dissipate 94 % of
    the energy, in the same order at -j1 and -j2 (docs/benchmarks.md)."""
    steps = count("probe_slipping_surface", "steps", steps, 0)
    check = count("probe_slipping_surface", "check", check)
    damping = number("probe_slipping_surface", "damping", damping, 0, 1, high_open=True)
    min_share = number("probe_slipping_surface", "min_share", min_share, 0, 1, low_open=True)
    if O is None:
        from yade import O
    from .scene import advance
    mark = "rbsm_slip_probe"
    O.saveTmp(mark)
    try:
        omega.switch_off_pyrunners(O)
        omega.newton(O).damping = damping
        try:  # the first motion at the gravity stage's step (restored with the state): *steps*, the same time
            ts = omega.engine("timeStepper", O)
            ts.impactSafety = ts.safetyFactor
        except LookupError:
            pass
        start = {(I.id1, I.id2): I.phys.plasticDissipation for I in omega.joints(O)}
        dissipated = {}  # joint -> the most it has dissipated since the start (a joint may be lost later)
        done = 0
        while done < steps:
            k = min(check, steps - done)
            advance(int(k))
            done += k
            for I in omega.joints(O):
                key = (I.id1, I.id2)
                d = I.phys.plasticDissipation - start.get(key, 0.0)
                if d > dissipated.get(key, 0.0):
                    dissipated[key] = d
        if not dissipated:
            return None
        least = min_share * max(dissipated.values())
        return slipping_surface(O=O, joints={j for j, d in dissipated.items() if d >= least}, **kw)
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
    """FS along the surface of slipping joints: returns a :class:`SlipSurfaceFS` (surface, contact:
    ContactFS, fellenius: Result or str or None), which unpacks as that tuple. *surface*: a SlipSurface (default: :func:`slipping_surface` now);
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
    return SlipSurfaceFS(ss, fs, fel)
