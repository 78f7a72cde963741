# Factor of safety of a homogeneous c'-phi' slope cut into Voronoi blocks, against limit equilibrium
# (issue 21, docs/slope_factor_of_safety.md). A slope H = 10 m on a firm base at toe level:
#   --slope gl   Griffiths & Lane (1999) example 1: 2:1 face, c' = 10 kPa, phi' = 20 deg (charts: FS 1.380)
#   --slope 45   45 deg face, c' = 10 kPa, phi' = 40 deg
# Joints: --mode raw (the soil's c', phi', brittle: Kawai's joints), ductile (the soil's, ductile),
# calibrated (yade_rbsm.calibration: the joint strength that gives the assembly c', phi' at its biaxial
# peak, times --k; strength reduction of the assembly's strength), joints (ductile joints of strength
# --cj [Pa], --tanphij, divided by F), or table (--table T.json: the joints that give the assembly c'/F,
# tan phi'/F in a table of simple-shear fits, scripts/simple_shear_table.py, interpolated as Calibration
# does), or stress (the soil's, ductile: no strength reduction; Kulhawy's stress-based FS of the settled
# slope's block stresses, critical circle at least --min-depth spacings deep, Bishop's among the
# candidates). Prints the Bishop and Spencer FS of the critical circle, the RBSM FS with its bracket, and
# RESULT <json>.
#   --slope 20   20 deg face, c' = 5 kPa (c'/gamma H = 0.025), phi' = 20 deg
#   --slope 30   30 deg face, c' = 20 kPa (0.1), phi' = 25 deg
#
#   build/yade-rbsm -n -x scripts/slope_fs_study.py --slope 45 --mode calibrated --spacing 1 --seed 1
#   build/yade-rbsm -j1 -n -x scripts/slope_fs_study.py --slope 45 --mode joints --cj 12999 --tanphij 0.2267
#   build/yade-rbsm -j1 -n -x scripts/slope_fs_study.py --slope 30 --mode stress --spacing 0.5 --seed 2
#   build/yade-rbsm -j1 -n -x scripts/slope_fs_study.py --slope gl --mode plastic --cells crossed --spacing 1
import argparse
import json
import math
import os
import sys
import time

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import limit_equilibrium as le
from yade_rbsm import slope as sl
from yade_rbsm.calibration import calibrate
from yade_rbsm.safety import stress_field
from yade_rbsm.strength_reduction import strength_reduction

# (under yade -x, __file__ is yade's own script: the scripts folder from the package's place)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(yr.__file__)))), "scripts"))
from reference_slopes import GAMMA, H, SLOPES, UNDRAINED, case, face_length, ground, plastic_soil, search, soil as soil_of  # noqa: E402
ap = argparse.ArgumentParser()
ap.add_argument("--slope", choices=sorted(SLOPES) + sorted(UNDRAINED), default="gl")
ap.add_argument("--mode", choices=["raw", "ductile", "calibrated", "joints", "table", "stress", "plastic"], default="raw")
ap.add_argument("--cells", choices=["voronoi", "triangles", "crossed"], default="voronoi", help="--mode plastic: the blocks")
ap.add_argument("--penalty", type=float, default=10.0, help="--mode plastic: RbsmMat.penalty of the welded joints")
ap.add_argument("--young", type=float, default=100e6, help="E of the blocks [Pa]")
ap.add_argument("--poisson", type=float, default=0.3, help="Poisson's ratio of the blocks")
ap.add_argument("--brittle", action="store_true", help="--mode stress: brittle joints (Kawai's), as in --mode raw")
ap.add_argument("--min-depth", type=float, default=2.0, help="--mode stress: least depth of a circle, in spacings")
ap.add_argument("--k", type=float, default=1.0, help="--mode calibrated: factor on the calibrated joint strengths")
ap.add_argument("--cj", type=float, help="joint cohesion [Pa] (--mode joints; --mode table: if the soil is outside it)")
ap.add_argument("--tanphij", type=float, help="joint tan phi (--mode joints; --mode table: as --cj)")
ap.add_argument("--table", default="", help="--mode table: JSON rows of simple-shear fits (tan_phi_j, c_j, c_<key>, "
                "phi_<key> [deg]) of a grid of joints")
ap.add_argument("--table-key", default="large", help="--mode table: which fit, 'peak' or 'large'")
ap.add_argument("--start", type=float, default=1.4, help="first trial F")
ap.add_argument("--grow", type=float, default=1.2, help="trial F growth until a failure")
ap.add_argument("--spacing", type=float, default=1.0, help="Voronoi spacing [m]")
ap.add_argument("--seed", type=int, default=1, help="Voronoi sites' seed")
ap.add_argument("--mesh-seed", type=int, default=None, help="--cells triangles: the mesh's interior vertices moved at "
                "random by this seed (default: CGAL's mesh as made)")
ap.add_argument("--png", default="", help="path prefix of the mechanism drawings")
ap.add_argument("--cache", default=None, help="calibration cache directory")
ap.add_argument("--no-density-scaling", action="store_true", help="settle and reduce at the dynamic step")
ap.add_argument("--d-fail", type=float, default=0.1, help="strength reduction's runaway displacement [m]")
ap.add_argument("--max-steps", type=int, default=8000, help="steps of a trial (x 3 without density scaling)")
args = ap.parse_args(sys.argv[1:])

gamma = GAMMA * 1e3  # N/m3 (the RBSM's SI units)
young, poisson = args.young, args.poisson
_, c_kpa, phi_deg, _ = case(args.slope)
c, phi = c_kpa * 1e3, math.radians(phi_deg)
tension = c / math.tan(phi) if phi > 0 else 10 * c  # the apex; undrained: no cut-off the slope reaches
surface = ground(args.slope)
t0 = time.time()

soil = soil_of(args.slope)
SEARCH = search(args.slope)
crit = le.critical_circle(soil, **SEARCH)
spencer = le.spencer_circle(soil, crit.circle)
print("limit equilibrium: Bishop %.3f, Spencer %.3f on %s" % (crit.fs, spencer.fs, crit.circle))


class ScaledCalibration:
    """k x the joint strengths of a calibration (what Calibration.joint_strength gives, scaled)."""

    def __init__(self, cal, k):
        self.cal, self.k = cal, k

    def joint_strength(self, cohesion, tan_phi):
        cj, tj = self.cal.joint_strength(cohesion, tan_phi)
        return self.k * cj, self.k * tj


cal = None
cj, tj = c, math.tan(phi)
if args.mode == "calibrated":
    cal = calibrate(c, phi, young, poisson, gamma * H, density=gamma / 9.81, cache=args.cache)
    if args.k != 1:
        cal = ScaledCalibration(cal, args.k)
    cj, tj = cal.joint_strength(c, math.tan(phi))
    print("calibrated joints (k = %g): c_j = %.4g Pa, phi_j = %.2f deg" % (args.k, cj, math.degrees(math.atan(tj))))
elif args.mode == "table":
    from yade_rbsm.calibration import Calibration
    rows = [dict(tan_phi_j=r["tan_phi_j"], c_j=r["c_j"], c_macro=r["c_" + args.table_key],
                 phi_macro=r["phi_" + args.table_key]) for r in json.load(open(args.table))]
    cal = Calibration(dict(cohesion=c), [r for r in rows if r["c_macro"] >= 0])
    print("simple-shear table %s (%s): %d of %d rows" % (args.table, args.table_key, len(cal.rows), len(rows)))
    try:
        cj, tj = cal.joint_strength(c, math.tan(phi))
    except ValueError as e:  # the soil itself outside the table: the gravity stage with --cj, --tanphij
        if args.cj is None or args.tanphij is None:
            raise
        print("the soil is outside the table (%s); gravity stage with --cj, --tanphij" % e)
        cj, tj = args.cj, args.tanphij
elif args.mode == "joints":
    if args.cj is None or args.tanphij is None:
        ap.error("--mode joints needs --cj and --tanphij")
    cj, tj = args.cj, args.tanphij
    print("joints: c_j = %.5g Pa, tan phi_j = %.5f (phi_j = %.2f deg)" % (cj, tj, math.degrees(math.atan(tj))))


def crossed_slope_blocks(name, spacing):
    """The slope region (base, face, crest, right end: a quadrilateral) in rows of *spacing* whose quads follow the
    face, each quad cut along both diagonals into four triangles: the mesh on which constant-strain elements do
    not lock in plastic flow (Nagtegaal et al. 1974)."""
    from yade_rbsm.geometry import polygon_area
    x_end, L = surface[-1][0], face_length(name)
    ny, nx = max(1, round(H / spacing)), max(1, round((x_end - 12) / spacing))

    def node(i, j):
        xf = 12 + L * j / ny  # the face at this row
        return (xf + (x_end - xf) * i / nx, H * j / ny)
    blocks = []
    for j in range(ny):
        for i in range(nx):
            q = [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
            m = (sum(p[0] for p in q) / 4, sum(p[1] for p in q) / 4)
            for k in range(4):
                tri = [q[k], q[(k + 1) % 4], m]
                blocks.append(sl.Block(tri, polygon_area(tri)))
    area = sum(b.area for b in blocks)
    return sl.SlopeBlocks(blocks + sl._fixed_blocks(surface, 0.0, 1.0, 1.0), surface, 0.0, area, 0.0, pattern="crossed")


if args.mode == "plastic":  # the soil's strength in the blocks; the welded joints between them are the continuum's
    mat = plastic_soil(args.slope, penalty=args.penalty, young=young, poisson=poisson)
else:
    mat = wrapper.RbsmMat(young=young, poisson=poisson, density=gamma / 9.81, frictionAngle=math.atan(tj), cohesion=cj,
                          tensileStrength=tension, ductile=args.mode != "raw" and not args.brittle)
O.materials.append(mat)
if args.cells != "voronoi" and args.mode != "plastic":
    ap.error("--cells %s is for --mode plastic" % args.cells)
if args.cells == "crossed":
    sb = crossed_slope_blocks(args.slope, args.spacing)
elif args.cells == "triangles":
    sb = sl.triangle_slope_blocks(surface, 0.0, spacing=args.spacing, seed=args.mesh_seed)
else:
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=args.spacing, seed=args.seed, min_distance=0.5 * args.spacing)
sl.build_scene(sb, mat)
O.engines = yr.engines(set_dt=True, enlarge=0.01)
O.dt = 1e-6
nj, _ = sl.bond_and_break(sb)
ds = not args.no_density_scaling
ok, steps, ratio = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=ds)
broken = sum(1 for I in O.interactions if I.isReal and I.phys.nIntact < len(I.phys.intactPoints))
print("%d blocks, %d joints; gravity stage %s after %d steps, %d joints broken" % (len(sb.free), nj,
      "converged" if ok else "NOT converged", steps, broken))
if args.mode == "stress":
    t1 = time.time()
    field = stress_field()
    r = le.critical_circle(soil, method="stress", stress=field, min_depth=args.min_depth * args.spacing,
                           candidates=[crit.circle], **SEARCH)  # (Bishop's circle too: the grid alone missed it)
    on_bishop = le.stress_circle(soil, crit.circle, field)
    wall = time.time() - t0
    print("stress-based FS %.4f on %s (%.1f s search); on Bishop's circle %.4f; Bishop %.4f; %.0f s wall"
          % (r.fs, r.circle, time.time() - t1, on_bishop.fs, crit.fs, wall))
    print("RESULT " + json.dumps(dict(slope=args.slope, mode=args.mode, spacing=args.spacing, seed=args.seed,
                                      blocks=len(sb.free), fs=r.fs, on_bishop_circle=on_bishop.fs, bishop=crit.fs,
                                      spencer=spencer.fs, circle=[r.circle.xc, r.circle.yc, r.circle.R],
                                      min_depth=args.min_depth * args.spacing, young=young, poisson=poisson,
                                      brittle=args.brittle, broken=broken, joints=nj, wall=wall,
                                      settle_steps=steps)))
    sys.exit(0)
# unscaled, the step is about 3 x shorter: the same simulated time per trial takes 3 x the steps
r = strength_reduction(start=args.start, grow=args.grow, rtol=0.02, density_scaling=ds,
                       max_steps=args.max_steps if ds else 3 * args.max_steps, check=200, d_fail=args.d_fail,
                       calibration=cal, soil=(c, phi) if cal else None, png=args.png or None,
                       png_line=crit.circle.polyline() if args.png else None)
wall = time.time() - t0
print("%s; %.0f s wall" % (r, wall))
print("RESULT " + json.dumps(dict(slope=args.slope, mode=args.mode, cells=args.cells, k=args.k, cj=cj, tanphij=tj, spacing=args.spacing,
                                  seed=args.seed,
                                  blocks=len(sb.free), fs=r.fs, lo=r.lo, hi=r.hi, bishop=crit.fs, spencer=spencer.fs,
                                  broken=broken, joints=nj, wall=wall, density_scaling=ds, settle_steps=steps,
                                  sr_steps=sum(t.steps for t in r.trials))))
