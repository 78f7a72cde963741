"""Random Voronoi blocks for a slope: the slope polygon cut into convex blocks by a Voronoi
tessellation of random sites, clipped to the slope.

The geometry is CGAL's, in the compiled module ``yade_rbsm_tessellation``
(``pkg/rbsm/tessellation/VoronoiClip.hpp`` says how): exact Delaunay/Voronoi, exact clipping to the
slope, a convex partition of the pieces that a non-convex slope makes non-convex, then one
rounding to double per exact vertex. Blocks on either side of a joint therefore share the joint's
two end vertices bit for bit, and every block is accepted by ``Polygon2D`` (convex,
counter-clockwise, no repeated or collinear vertices)::

    from yade_rbsm.voronoi import voronoi_blocks
    from yade_rbsm import polygon2d
    slope = [(0, 0), (60, 0), (60, 10), (35, 10), (20, 25), (0, 25)]   # base, toe, face, crest
    for v in voronoi_blocks(slope, spacing=2.5, seed=1, min_distance=1.2):
        O.bodies.append(polygon2d(v, rock))

This module itself does not import yade: it is usable (and tested) from plain python3.
"""
import collections
import math
import os
import sys

__all__ = ["voronoi_blocks", "voronoi_tessellation", "random_sites", "VoronoiTessellation"]


def _load_module():
    try:
        import yade_rbsm_tessellation as m
        return m
    except ImportError:
        pass
    # Not on sys.path (plain python3 outside the launcher): look in the build directories.
    here = os.path.dirname(os.path.abspath(__file__))
    source = os.path.normpath(os.path.join(here, "..", ".."))
    candidates = []
    if os.environ.get("RBSM_BUILD_DIR"):
        candidates.append(os.path.join(os.environ["RBSM_BUILD_DIR"], "python"))
    candidates.append(os.path.join(source, "build", "python"))
    for d in candidates:
        if os.path.exists(os.path.join(d, "yade_rbsm_tessellation.so")):
            sys.path.append(d)
            import yade_rbsm_tessellation as m
            return m
    raise ImportError("yade_rbsm.voronoi needs the compiled module yade_rbsm_tessellation (CGAL): build the project "
                      "(cmake --build build) and run through build/yade-rbsm, or set RBSM_BUILD_DIR; looked in %s" % candidates)


_tess = _load_module()

VoronoiTessellation = collections.namedtuple("VoronoiTessellation", "blocks sites site cells split dropped dropped_area")
VoronoiTessellation.__doc__ = """Result of voronoi_tessellation:
blocks: convex counter-clockwise polygons [(x, y), ...] in world coordinates;
sites: the Voronoi sites used; site[i]: index in sites of the cell block i comes from;
cells: number of Voronoi cells that meet the slope; split: clipped cells cut into several convex blocks
(a non-convex slope); dropped, dropped_area: slivers left out (area < min_area), see voronoi_tessellation."""


def _points(name, seq, at_least=0):
    try:
        pts = [(float(x), float(y)) for x, y in seq]
    except (TypeError, ValueError):
        raise ValueError("%s must be a sequence of (x, y) pairs" % name)
    if len(pts) < at_least:
        raise ValueError("%s needs at least %d vertices, got %d" % (name, at_least, len(pts)))
    return pts


def _slope(slope):
    pts = _points("slope polygon", slope, 3)
    problem = _tess.region_problem(pts)
    if problem:
        raise ValueError("slope polygon: " + problem.replace("the region ", "", 1))
    return pts


def _is_count(n):
    return isinstance(n, int) and not isinstance(n, bool) or type(n).__name__ in ("int64", "int32", "uint64", "uint32")


def random_sites(slope, n, seed=0, min_distance=0.0):
    """n points uniformly distributed strictly inside the slope polygon, from std::mt19937_64(seed)
    (same seed, same points, on any machine). min_distance > 0: no two points closer than that
    (dart throwing; RuntimeError if n points do not fit)."""
    pts = _slope(slope)
    if not _is_count(n) or n <= 0:
        raise ValueError("the number of sites n must be an integer > 0, got %r" % (n,))
    if not _is_count(seed) or not 0 <= seed < 2 ** 64:
        raise ValueError("seed must be an integer in [0, 2**64), got %r" % (seed,))
    if not (isinstance(min_distance, (int, float)) and math.isfinite(min_distance) and min_distance >= 0):
        raise ValueError("min_distance must be a finite number >= 0, got %r" % (min_distance,))
    return _tess.random_sites(pts, int(n), int(seed), float(min_distance), 0)


def voronoi_tessellation(slope, n=None, spacing=None, seed=0, min_distance=0.0, sites=None, min_area=None):
    """The slope polygon cut into convex Voronoi blocks (see the module's docstring); returns a
    VoronoiTessellation (blocks, sites, site, cells, split, dropped, dropped_area).

    slope: the polygon [(x, y), ...] (m), simple, either orientation (a clockwise one is reversed;
        the blocks are always counter-clockwise); collinear vertices are allowed.

    Exactly one of:

    - n: number of random sites, uniform inside the slope;
    - spacing: typical block size (m): n = round(slope area / spacing²), at least 1;
    - sites: the sites [(x, y), ...] themselves (they may lie outside the slope).

    seed: integer seed of the random sites (std::mt19937_64): the same seed gives the same blocks.

    min_distance: random sites at least this far apart (m; 0: plain uniform sites). About half the
        spacing gives blocks of more even size (fewer small blocks that shorten the time step).

    min_area: pieces of smaller area (m²) are dropped, leaving a hole reported in dropped and
        dropped_area; default 1e-9 × the mean cell area (slope area / number of sites), which drops
        only the slivers that rounding to double could make degenerate.

    ValueError names a bad argument (slope with fewer than 3 vertices, NaN, repeated vertex, not
    simple, zero area; n, spacing, seed, min_distance, min_area out of range); RuntimeError if
    min_distance leaves no room for n sites.
    """
    pts = _slope(slope)
    area = abs(_tess.signed_area(pts))
    given = [k for k, v in (("n", n), ("spacing", spacing), ("sites", sites)) if v is not None]
    if len(given) != 1:
        raise ValueError("give exactly one of n, spacing, sites (got %s)" % (", ".join(given) or "none"))
    if spacing is not None:
        if isinstance(spacing, bool) or not (isinstance(spacing, (int, float)) and math.isfinite(spacing) and spacing > 0):
            raise ValueError("spacing must be a finite number > 0, got %r" % (spacing,))
        n = max(1, int(round(area / spacing ** 2)))
    if sites is not None:
        site_pts = _points("sites", sites, 1)
        if not all(math.isfinite(c) for p in site_pts for c in p):
            raise ValueError("sites contain NaN or inf")
    else:
        site_pts = random_sites(pts, n, seed, min_distance)
    if min_area is None:
        min_area = 1e-9 * area / len(site_pts)
    if not (isinstance(min_area, (int, float)) and math.isfinite(min_area) and min_area >= 0):
        raise ValueError("min_area must be a finite number >= 0, got %r" % (min_area,))
    r = _tess.voronoi_clip(pts, site_pts, float(min_area))
    blocks = [list(b) for b in r["blocks"]]
    return VoronoiTessellation(blocks, site_pts, list(r["site"]), r["cells"], r["split"], r["dropped"], r["dropped_area"])


def triangle_blocks(slope, spacing, seed=None):
    """Triangles [[(x, y), ...], ...] (counter-clockwise) tiling the slope polygon, none with an edge longer than
    *spacing* nor an angle below about 20.7 deg: CGAL's constrained Delaunay refinement. The blocks for plastic
    deformable soil (RbsmMat.plastic): a band runs through triangles, where Voronoi cells lock. The mesh is
    deterministic; with a *seed* (an integer >= 0) its interior vertices move at random (:func:`jitter_mesh`), so
    that seeds give the scatter of a result over meshes of one spacing, as Voronoi seeds do."""
    pts = _slope(slope)
    if isinstance(spacing, bool) or not (isinstance(spacing, (int, float)) and math.isfinite(spacing) and spacing > 0):
        raise ValueError("triangle_blocks: spacing must be a length > 0 (got %r)" % (spacing,))
    tris = [list(t) for t in _tess.triangle_mesh(pts, float(spacing))]
    if seed is None:
        return tris
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ValueError("triangle_blocks: seed must be an integer >= 0 or None (got %r)" % (seed,))
    return jitter_mesh(tris, seed, spacing)


def jitter_mesh(tris, seed, spacing, amount=0.2, min_angle=15.0, max_edge=1.25):
    """The triangles *tris* (shared vertices bit for bit) with every vertex off the outline (a vertex all of whose
    edges two triangles share) moved once, in a fixed order, by a random vector (numpy's generator of *seed*) up
    to *amount* x its shortest edge; a move that would leave one of its triangles with an angle below *min_angle*
    deg or an edge longer than *max_edge* x *spacing* is halved, up to three times, then not made."""
    import numpy as np
    rng = np.random.default_rng(seed)
    tris = [[tuple(v) for v in t] for t in tris]
    edges = collections.Counter(frozenset((t[k], t[(k + 1) % 3])) for t in tris for k in range(3))
    outline = {v for e, n in edges.items() if n == 1 for v in e}
    at = collections.defaultdict(list)
    for i, t in enumerate(tris):
        for v in t:
            at[v].append(i)

    def fits(t):
        for k in range(3):
            a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
            u, w = (b[0] - a[0], b[1] - a[1]), (c[0] - a[0], c[1] - a[1])
            lu, lw = math.hypot(*u), math.hypot(*w)
            if lu > max_edge * spacing or u[0] * w[1] - u[1] * w[0] <= math.sin(math.radians(min_angle)) * lu * lw:
                return False
        return True
    for v in sorted(at):
        if v in outline:
            continue
        r = amount * min(math.dist(v, u) for i in at[v] for u in tris[i] if u != v)
        angle, rho = rng.uniform(0.0, 2 * math.pi), r * math.sqrt(rng.uniform())
        for _ in range(4):
            w = (v[0] + rho * math.cos(angle), v[1] + rho * math.sin(angle))
            moved = [[w if u == v else u for u in tris[i]] for i in at[v]]
            if all(fits(t) for t in moved):
                for i, t in zip(at[v], moved):
                    tris[i] = t
                at[w] = at.pop(v)
                break
            rho *= 0.5
    return [list(t) for t in tris]


def voronoi_blocks(slope, n=None, spacing=None, seed=0, min_distance=0.0, sites=None, min_area=None):
    """Convex counter-clockwise blocks [[(x, y), ...], ...] tiling the slope polygon: the blocks of
    voronoi_tessellation (same arguments), ready for yade_rbsm.polygon2d."""
    return voronoi_tessellation(slope, n=n, spacing=spacing, seed=seed, min_distance=min_distance, sites=sites, min_area=min_area).blocks
