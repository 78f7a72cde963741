# Issue 21: does cutting each Voronoi cell into rigid triangles (a fan from its centroid, as UDEC's Trigon
# pattern cuts cells, but with rigid blocks) lower the interlocking of the assembly? The plugin's biaxial test
# (calibration.biaxial_test: 8 x 16 cells, rough platens, sigma3 on the sides) on the cells and on their
# triangles; prints the peak and the mobilised friction angle asin((s1 - s3) / (s1 + s3)).
#
#   build/yade-rbsm -j1 -n -x scripts/trigon_biaxial_study.py [--tanphij 0.00873] [--sigma3 30e3] [--seed 1]
import argparse
import math
import sys

import yade_rbsm.calibration as calibration
import yade_rbsm.voronoi as voronoi

ap = argparse.ArgumentParser()
ap.add_argument("--tanphij", type=float, default=math.tan(math.radians(0.5)))
ap.add_argument("--sigma3", type=float, default=30e3)
ap.add_argument("--seed", type=int, default=1)
args = ap.parse_args(sys.argv[1:])

cells = voronoi.voronoi_tessellation


def fan(poly):
    """The triangles joining a convex CCW polygon's centroid to each of its edges."""
    a = cx = cy = 0.0
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        w = x0 * y1 - x1 * y0
        a, cx, cy = a + w, cx + (x0 + x1) * w, cy + (y0 + y1) * w
    c = (cx / (3 * a), cy / (3 * a))
    return [[c, tuple(p), tuple(q)] for p, q in zip(poly, poly[1:] + poly[:1])]


def triangles(*a, **k):
    t = cells(*a, **k)
    return t._replace(blocks=[tri for b in t.blocks for tri in fan(b)])


for name, tess in (("Voronoi cells", cells), ("their centroid triangles", triangles)):
    voronoi.voronoi_tessellation = tess  # (biaxial_test imports it from the module at each call)
    r = calibration.biaxial_test(args.sigma3, 0.0, args.tanphij, 100e6, 0.3, seed=args.seed)
    phi = math.degrees(math.asin((r.peak - args.sigma3) / (r.peak + args.sigma3)))
    print("%-26s %4d blocks: peak sigma1 %8.1f kPa at %.2f %% strain, mobilised phi %.1f deg (joints %.1f deg)"
          % (name, r.blocks, r.peak / 1e3, 100 * r.strain_at_peak, phi, math.degrees(math.atan(args.tanphij))))
voronoi.voronoi_tessellation = cells
