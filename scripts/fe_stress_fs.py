# Issue 21: the stress-based FS (Kulhawy) of a slope's linear-elastic finite-element stress field, to set
# beside the same method on the settled RBSM blocks' stresses (scripts/slope_fs_study.py --mode stress):
# whatever the two share is the stress method's own difference from limit equilibrium, not the blocks'.
# Plane strain, gravity switched on at once, base fixed, far side fixed (as the RBSM slope's bonded
# foundation and wall); GetFEM (Debian's python3-getfem), P2 triangles, the stress at each triangle's
# centroid as the field (yade_rbsm.le_bridge.StressField). No YADE:
#
#   /usr/bin/python3 scripts/fe_stress_fs.py [--slope 45|gl|20|30] [--h 0.25] [--poisson 0.3]
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "py"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from yade_rbsm import limit_equilibrium as le  # noqa: E402
from yade_rbsm.le_bridge import StressField  # noqa: E402
from reference_slopes import GAMMA, H, SLOPES, face_length, search, soil as soil_of  # noqa: E402


def mesh_of(poly, h):
    """Triangles of the convex polygon *poly* with nodes about *h* apart (a grid inside, its edges divided)."""
    from scipy.spatial import Delaunay
    from matplotlib.path import Path
    P = np.asarray(poly, dtype=float)
    outline = Path(P)
    pts = [P[i] + t * (P[(i + 1) % len(P)] - P[i]) for i in range(len(P))
           for t in np.linspace(0, 1, max(2, int(np.ceil(np.linalg.norm(P[(i + 1) % len(P)] - P[i]) / h))) + 1)[:-1]]
    x0, y0 = P.min(axis=0)
    x1, y1 = P.max(axis=0)
    gx, gy = np.meshgrid(np.arange(x0 + h / 2, x1, h), np.arange(y0 + h / 2, y1, h))
    grid = np.column_stack([gx.ravel(), gy.ravel()])
    inside = outline.contains_points(grid, radius=-0.3 * h) & outline.contains_points(grid)
    pts = np.vstack([np.array(pts), grid[inside]])
    tri = Delaunay(pts).simplices
    keep = outline.contains_points(pts[tri].mean(axis=1))
    return pts, tri[keep]


def fe_stress(poly, h, young, poisson, gamma):
    """(centroids, stresses [kPa, compression positive]) of the linear-elastic plane-strain slope."""
    import getfem as gf
    gf.util_trace_level(0)  # (its assembly traces)
    gf.util_warning_level(0)
    pts, tri = mesh_of(poly, h)
    m = gf.Mesh("pt2D", pts.T, tri.T)
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, 4)
    faces = m.outer_faces()
    normal = m.normal_of_faces(faces)
    BASE, SIDE = 1, 2
    m.set_region(BASE, faces[:, normal[1] < -0.99])  # the base (y = 0)
    m.set_region(SIDE, faces[:, normal[0] > 0.99])  # the far side (the face looks to -x)
    lam = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
    mu = young / (2 * (1 + poisson))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    md.add_initialized_data("f", [0.0, -gamma])
    md.add_source_term_brick(mim, "u", "f")
    md.add_Dirichlet_condition_with_multipliers(mim, "u", mfu, BASE)
    md.add_Dirichlet_condition_with_multipliers(mim, "u", mfu, SIDE)
    md.solve()
    c = pts[tri].mean(axis=1)
    s = md.interpolation("lambda*Trace(Grad_u)*Id(2)+2*mu*Sym(Grad_u)", c.T, m)
    s = np.asarray(s).reshape(-1, 2, 2)  # a 2 x 2 tensor per point
    return c, np.column_stack([-s[:, 0, 0], -s[:, 1, 1], -0.5 * (s[:, 0, 1] + s[:, 1, 0])])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--slope", choices=sorted(SLOPES), default="45")
    ap.add_argument("--h", type=float, default=0.25, help="element size [m]")
    ap.add_argument("--poisson", type=float, default=0.3)
    ap.add_argument("--min-depth", type=float, default=1.0, help="least depth of a circle [m]")
    a = ap.parse_args()
    L, gamma = face_length(a.slope), GAMMA
    soil = soil_of(a.slope)
    grid = search(a.slope)
    bishop = le.critical_circle(soil, **grid)
    pts, sig = fe_stress([(12, 0), (12 + L, H), (32 + L, H), (32 + L, 0)], a.h, 100e3, a.poisson, gamma)  # kPa units
    field = StressField(pts, sig, reach=a.h)
    deep = field(22.0 + L, 0.5)  # under the crest, 9.5 m deep: about gamma z vertically
    print("FE check: syy %.1f kPa, sxx %.1f kPa at 9.5 m under the crest (gamma z = %.1f)" % (deep[1], deep[0], gamma * 9.5))
    kul = le.critical_circle(soil, method="stress", stress=field, min_depth=a.min_depth, candidates=[bishop.circle],
                             **grid)
    on_b = le.stress_circle(soil, bishop.circle, field)
    print("slope %s, FE h = %g m (%d triangles), nu %g: stress FS %.4f on %s; on Bishop's circle %.4f; Bishop %.4f "
          "(stress/Bishop %+.1f %%)" % (a.slope, a.h, len(pts), a.poisson, kul.fs, kul.circle, on_b.fs, bishop.fs,
                                       100 * (kul.fs / bishop.fs - 1)))


if __name__ == "__main__":
    main()
