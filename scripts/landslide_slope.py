"""Landslide of a block slope with a tension crack (seed paper, section 3: Table 1, Table 2, Fig. 5-6).

Run headless:  build/yade-rbsm -n -x scripts/landslide_slope.py [options]

Geometry (the seed's figure geometry is not available; chosen here, all in metres):
  * ground: toe flat at y = 2 for x in [0, 6], face up to the crest y = 12 at x = 14 (10 m high,
    51.3 deg), crest flat to x = 24; base of the blocks y = 0; fixed foundation (1 m) and side walls;
  * bricks 2 m x 1 m with staggered vertical joints (cut at the kinks so every block is convex);
    --pattern voronoi: random Voronoi blocks (CGAL, --spacing, --seed) cut along the joint plane and
    the crack; --pattern columns: full-height columns (--column-width) cut along them;
  * a pre-existing joint plane from the toe (6, 2) rising at psi = 35 deg to the crack, and a
    tension crack behind the crest at x = 17 from the ground down to that plane (joints broken);
    the slip polyline used for the factor of safety is the plane + the crack.
Material (Table 1): E = 200 MPa, nu = 0.2, phi = 30 deg, c = 0, tensile strength 0, density 245
in kgf.s2/m4 (= 2403 kg/m3, default) or in kg/m3 (--density-units si); plane strain.

Stages:
  1. bond the joints (setCohesionNow), break the crack joints;
  2. gravity stage: NewtonIntegrator damping 0.7, joint friction raised to tan(phi) = 5 (so that the
     slope, unstable with phi = 30 deg, can reach its initial stress state), until the
     unbalanced-force ratio (mean |resultant force on free blocks| / mean |m g|) < --tol;
  3. Table 2: RBSM factor of safety from the contact forces along the slip polyline with the real
     phi = 30 deg, next to Fellenius along the same polyline (gamma = rho g);
  4. limit equilibrium on the same slope (ground polyline, gamma = rho g, c, phi of the joints):
     Fellenius along the slip polyline; Fellenius and Bishop for the circle tangent to the toe flat
     at the toe and through the top of the crack; critical toe circle (grid search, Fellenius and
     Bishop);
  4b. the surface of slipping joints found by the program: an undamped --probe-steps probe with the
     real phi from the state after stage 2 (restored afterwards) collects the joints that slip; their
     largest connected set is the surface (a polyline); contact-force FS (state after stage 2) and
     Fellenius along it (its ends continued to the ground), printed like Table 2;
  5. optional (--strength-reduction): FS by strength reduction from the state of stage 2 (tan(phi)
     and c divided by F, damped stage; failure = a block displaced by more than --sr-dfail, or the
     unbalanced-force ratio not below --sr-tol within --sr-steps steps; bracket and bisect);
  6. dynamic stage: damping 0, joint friction back to phi = 30 deg: the wedge slides off.
All factors of safety are printed in one table at the end.

Distributed (--mpi, YADE's yade.mpy): `mpiexec -n 3 build/yade-rbsm -n -x scripts/landslide_slope.py --mpi`,
or `build/yade-rbsm -n -x scripts/landslide_slope.py --mpi 3` (spawns 2 workers). The free blocks are cut
into vertical slices, one per worker (yade_rbsm.mpi.decompose_by_x; the fixed blocks stay on rank 0);
the gravity stage and the dynamic stage run distributed (one time step for all ranks), the scene is
merged on rank 0 after the gravity stage and after each third of the dynamic stage, and rank 0 does
all the post-processing (factors of safety, snapshots, VTK at those merges) and prints alone. The
probe (4b), strength reduction (5) and the yade.plot series are serial stages, skipped with --mpi.
--summary FILE writes the figures the tests compare (factors of safety, displacements) as JSON.

Outputs in --out: PNG snapshots (landslide_*.png, Fig. 5-6 style); VTK time series of the blocks and
contacts (vtk/landslide_blocks.pvd, vtk/landslide_contacts.pvd: open them in ParaView), written
every --vtk-every s of the dynamic stage; yade.plot series recorded by a PyRunner during the gravity
and dynamic stages (displacement of monitored blocks, kinetic energy, unbalanced-force ratio, numbers
of slipping and open joints) saved as landslide_plot.png and landslide_plot.txt; a progress line
every --progress s of wall time.
"""
import argparse
import math
import os
import sys
import time

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import omega, slope as sl, safety, snapshots, vtkexport
from yade_rbsm.monitor import Monitor
from yade_rbsm.strength_reduction import strength_reduction

# the seed paper's own figures (Table 2: driving shear T and normal force N along the slip surface,
# kN/m, and FS), printed next to this run's for comparison
SEED_TABLE2 = [("seed paper: RBSM", 217.0, 271.0, 0.72), ("seed paper: Fellenius", 231.0, 253.0, 0.63)]

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("--density-units", choices=["kgf", "si"], default="kgf")
ap.add_argument("--out", default="out/landslide")
ap.add_argument("--pattern", choices=["bricks", "voronoi", "columns"], default="bricks",
                help="blocks: staggered bricks (default), random Voronoi blocks (CGAL) or columns")
ap.add_argument("--brick", type=float, nargs=2, default=(2.0, 1.0), metavar=("W", "H"))
ap.add_argument("--spacing", type=float, default=None, help="Voronoi block size [m] (default sqrt(W H) of --brick)")
ap.add_argument("--seed", type=int, default=1, help="seed of the Voronoi sites")
ap.add_argument("--column-width", type=float, default=None, help="column width [m] (default W/2 of --brick)")
ap.add_argument("--probe-steps", type=int, default=300,
                help="steps of the undamped probe that finds the surface of slipping joints (0: skip)")
ap.add_argument("--height", type=float, default=10.0, help="slope height [m]")
ap.add_argument("--tol", type=float, default=1e-3, help="unbalanced-force ratio of the gravity stage")
ap.add_argument("--max-settle", type=int, default=20000, help="max steps of the gravity stage")
ap.add_argument("--time", type=float, default=3.0, help="simulated time of the dynamic stage [s]")
ap.add_argument("--dt", type=float, default=None, help="time step [s] (default: 0.8 x critical)")
ap.add_argument("--impact-safety", type=float, default=None,
                help="RbsmTimeStepper.impactSafety of the undamped stage (default 0.25; 0.8: the stable step alone, as "
                     "before issue 14: 3.2x fewer steps, impacts less accurate)")
ap.add_argument("--update-tolerance", type=float, default=0.0,
                help="Ig2 updateTolerance: frozen contact kinematics between exact updates (default 0: exact geometry)")
ap.add_argument("--small", action="store_true", help="tiny slope for smoke tests")
ap.add_argument("--strength-reduction", action="store_true", help="also the FS by strength reduction")
ap.add_argument("--sr-rtol", type=float, default=0.01, help="relative width of the final FS bracket")
ap.add_argument("--sr-tol", type=float, default=1e-3, help="unbalanced-force ratio of a stable trial")
ap.add_argument("--sr-steps", type=int, default=4000, help="max steps of a strength-reduction trial")
ap.add_argument("--sr-dfail", type=float, default=0.1, help="runaway displacement of a trial [m]")
ap.add_argument("--vtk-every", type=float, default=0.1, help="VTK snapshot period in the dynamic stage [s]")
ap.add_argument("--plot-every", type=int, default=150,
                help="yade.plot recording period [steps] (150: every 11 ms of the dynamic stage, as 50 did before the impact step of RbsmTimeStepper.impactSafety)")
ap.add_argument("--progress", type=float, default=10.0, help="progress line period [s of wall time]")
ap.add_argument("--no-search", action="store_true", help="skip the critical-circle search")
ap.add_argument("--mpi", type=int, nargs="?", const=0, default=None, metavar="N",
                help="run distributed with yade.mpy: N ranks (spawned; under mpiexec its ranks)")
ap.add_argument("--sorted-loop", action="store_true",
                help="sum each block's joint forces in id order (InteractionLoop.loopOnSortedInteractions): the "
                     "same numbers bit for bit serially (-j1) and with --mpi (slower)")
ap.add_argument("--summary", default=None, help="write the factors of safety and displacements as JSON")
ap.add_argument("--yade-warnings", action="store_true",
                help="keep YADE's InteractionLoop/InsertionSortCollider warnings (one per joint that separates)")
args = ap.parse_args(sys.argv[1:])

t_wall = time.time()
mp, master = None, True
if args.mpi is not None:
    # 3 ranks on 2 cores: waiting ranks yield the CPU instead of spinning (mpiexec --oversubscribe sets it)
    os.environ.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    from yade import mpy as mp
    import yade_rbsm.mpi as rmpi
    if mp.numThreads is None or mp.numThreads < 2:  # not under mpiexec, not a spawned worker
        if args.mpi < 2:
            sys.exit("landslide_slope.py: --mpi N needs N >= 2 ranks (or start it with mpiexec -n N ... --mpi)")
        mp.initialize(args.mpi)
    elif args.mpi not in (0, mp.numThreads):
        sys.exit("landslide_slope.py: --mpi %d but %d MPI ranks" % (args.mpi, mp.numThreads))
    master = mp.rank == 0
    if not master:  # the workers compute; rank 0 prints (errors still show: yade.mpy sends stderr to the terminal)
        sys.stdout = open(os.devnull, "w")
    if args.probe_steps > 0 or args.strength_reduction:
        print("--mpi: the probe (--probe-steps) and the strength reduction are serial stages: skipped")
        args.probe_steps, args.strength_reduction = 0, False
if not args.yade_warnings:
    # YADE warns "IGeomFunctor returned false on existing interaction!" each time a joint separates
    # (thousands of lines in a landslide) and about verletDist without spheres: errors only.
    from yade import log
    log.setLevel("InteractionLoop", log.ERROR)
    log.setLevel("InsertionSortCollider", log.ERROR)
H = args.height
scale = H / 10.0
if args.small:
    scale, args.brick = 0.4, (2.0, 1.0)
toe, crestx, xend = 6 * scale, 14 * scale, 24 * scale
y0 = 2 * scale
surface = [(0.0, y0), (toe, y0), (crestx, y0 + 10 * scale), (xend, y0 + 10 * scale)]
psi = math.radians(35.0)
xcrack = 17 * scale
ycrack = y0 + (xcrack - toe) * math.tan(psi)
plane = [(toe, y0), (xcrack, ycrack)]
slip = plane + [(xcrack + 1e-3, surface[-1][1] + 1.0)]  # plane, then up the crack (x increasing)

rho245 = 245.0 * 9.80665 if args.density_units == "kgf" else 245.0
print("density: 245 %s -> %.1f kg/m3" % ("kgf.s2/m4 (gravitational units)" if args.density_units == "kgf" else "kg/m3 (SI as printed)", rho245))
phi = math.radians(30.0)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=rho245, frictionAngle=phi, cohesion=0.0,
                      tensileStrength=0.0, planeStrain=True, label="rock")
O.materials.append(mat)

crack_line = [(xcrack, ycrack), (xcrack, surface[-1][1])]
if args.pattern == "voronoi":
    spacing = args.spacing or math.sqrt(args.brick[0] * args.brick[1]) * (scale if args.small else 1.0)
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=spacing, seed=args.seed, min_distance=0.5 * spacing,
                                 joints=[plane], cracks=[crack_line], foundation=1.0, wall=1.0)
    print("pattern: Voronoi blocks (CGAL), spacing %.2f m, seed %d, cut along the joint plane and the crack"
          % (spacing, args.seed))
elif args.pattern == "columns":
    cw = args.column_width or 0.5 * args.brick[0]
    sb = sl.column_blocks(surface, 0.0, cw, joints=[plane], cracks=[crack_line], foundation=1.0, wall=1.0)
    print("pattern: columns %.2f m wide (full height), cut along the joint plane and the crack" % cw)
else:
    sb = sl.brick_blocks(surface, 0.0, args.brick[0], args.brick[1], joints=[plane], crack=(xcrack, ycrack),
                         foundation=1.0, wall=1.0)
    print("pattern: bricks %g m x %g m, staggered" % tuple(args.brick))
sl.build_scene(sb, mat)
print("slope: %d free blocks, %d fixed; area %.3f m2 (closed form %.3f, slivers dropped %.2e)"
      % (len(sb.free), len(sb.blocks) - len(sb.free), sum(b.area for b in sb.free), sb.slope_area, sb.dropped_area))
print("joint plane psi = 35 deg from the toe (%.2f, %.2f) to the crack at x = %.2f (down to y = %.2f)"
      % (toe, y0, xcrack, ycrack))

bmin = min(args.brick) * 1e-2
O.engines = yr.engines(gravity=(0, -9.81, 0), damping=0.7, set_dt=False, enlarge=bmin, update_tolerance=args.update_tolerance,
                       mpi=mp is not None, sorted_loop=args.sorted_loop)
O.dt = 1e-6  # bonding step


# monitored blocks: the free blocks nearest to the wedge's toe, middle and crest, and one behind it
def nearest(x, y):
    return min(sb.free, key=lambda b: (O.bodies[b.id].state.pos[0] - x) ** 2 + (O.bodies[b.id].state.pos[1] - y) ** 2).id


def watched():
    return [nearest(7 * scale, y0 + 0.5 * scale), nearest(11 * scale, y0 + 5.5 * scale),
            nearest(15.5 * scale, y0 + 9.5 * scale), nearest(20 * scale, y0 + 9.5 * scale)]


if mp is not None:
    watch = watched()  # on the whole scene, before the split
    slices = rmpi.decompose_by_x()
    print("yade.mpy: %d ranks; free blocks cut into %d vertical slices (centroids x in %s), fixed blocks on rank 0"
          % (mp.numThreads, len(slices), ", ".join("[%.2f, %.2f]" % r for r in slices)))
    # split before the joints are made: yade.mpy would make the joints across its borders anew, unbonded
    rmpi.distribute()
nj, nbroken = sl.bond_and_break(sb)
dtc = yr.critical_time_step()
ts = omega.engine("timeStepper")
if args.impact_safety is not None:
    ts.impactSafety = args.impact_safety
if args.dt:
    O.dt = args.dt  # the time stepper refuses it if it exceeds its stable limit
else:
    O.dt = 0.8 * dtc * (1 - 1e-9)
    ts.setDt = True  # keeps O.dt = 0.8 x critical as the joints change
print("time step: critical %.3e s (seed paper: 0.003 s); running with dt = %.3e s (%s)"
      % (dtc, O.dt, "given" if args.dt else "0.8 x critical, the stable step: the seed's 0.003 s would exceed it"
         if dtc < 0.003 / 0.8 else "0.8 x critical"))
print("joints: %d bonded, %d on the crack broken" % (nj, nbroken))
os.makedirs(args.out, exist_ok=True)

mon = None
if mp is None:
    watch = watched()
    print("monitored blocks (yade.plot d_<id>): %s" % ", ".join("%d at (%.1f, %.1f)" % (i, O.bodies[i].state.pos[0],
          O.bodies[i].state.pos[1]) for i in watch))
    mon = Monitor(ids=watch, period=args.plot_every, progress=args.progress)  # PyRunner in O.engines

# --- gravity stage ---------------------------------------------------------------------------
tan_settle = 5.0
for I in O.interactions:
    if I.isReal:
        I.phys.tanPhi = tan_settle
t0 = time.time()
ok, steps, ratio = sl.settle(tol=args.tol, max_steps=args.max_settle, check=200, damping=0.7,
                             progress=lambda s, r: print("  gravity stage: step %6d  unbalanced ratio %.2e" % (s, r)) if s % 2000 == 0 else None)
print("gravity stage: %s after %d steps (ratio %.2e < %.0e), %.1f s wall"
      % ("converged" if ok else "NOT converged", steps, ratio, args.tol, time.time() - t0))
for I in O.interactions:
    if I.isReal:
        I.phys.tanPhi = math.tan(phi)
for b in O.bodies:
    b.state.refPos = b.state.pos  # displacements of the dynamic stage
    b.state.refOri = b.state.ori
if mp is not None:
    rmpi.merge()  # rank 0 now holds every block and joint
fs = lem = found = None
if master:  # post-processing: rank 0 holds the merged scene
    fs = safety.contact_fs(plane)  # the crack joints (open, c = 0) carry no force: plane only
    g = 9.81
    slope_le = safety.le_slope(sb.surface, mat, g=g)  # ground polyline of the blocks; gamma = rho g, c, phi of the material
    # circle tangent to the toe flat at the toe and through the top of the crack (centre above the toe)
    circle = safety.circle_through((toe, y0), (xcrack, surface[-1][1]), (2 * toe - xcrack, surface[-1][1]))
    t0 = time.time()
    search = None if args.no_search else dict(x_range=(toe - 6 * scale, crestx + 6 * scale), y_range=(y0 + 4 * scale, y0 + 30 * scale),
                                              nx=16, ny=16, refine=2)
    lem = safety.limit_equilibrium_summary(slope_le, circle=circle, polyline=slip, toe=(toe, y0), search=search, n=50)
    fel = lem["Fellenius, slip polyline"]
    print(safety.table2(fs, fel))
    crack = [I for I in O.interactions if I.isReal and abs(I.geom.p0[0] - xcrack) < 1e-2 * scale
             and abs(I.geom.p1[0] - xcrack) < 1e-2 * scale and I.geom.p0[1] > ycrack - 1e-2]
    print("crack: %d joints in contact carry a normal force of %.1f kN/m (thrust of the crest mass, "
          "absent from Fellenius)" % (len(crack), sum(I.phys.normalForce for I in crack) / 1e3))
    print("(RBSM: %d joints on the slip polyline, %.2f m of it; planar wedge closed form tan(phi)/tan(psi) = %.3f)"
          % (fs.n_joints, fs.length, math.tan(phi) / math.tan(psi)))
    print("limit equilibrium on the same slope (gamma = %.2f kN/m3, c = 0, phi = 30 deg; %.1f s wall):"
          % (slope_le.layers[0].gamma, time.time() - t0))
    for k, v in lem.items():
        print("  %-28s %s" % (k + ":", v))

    # --- surface of slipping joints found by the program ------------------------------------------
    found = None
    if args.probe_steps > 0:
        t0 = time.time()
        ss = safety.probe_slipping_surface(steps=args.probe_steps, damping=0.0)
        if ss is None:
            print("surface of slipping joints: no joint slipped in a %d-step probe" % args.probe_steps)
        else:
            try:
                found = safety.slip_surface_fs(ss, slope=slope_le)  # contact forces of the state after the gravity stage
            except ValueError as e:
                print("surface of slipping joints: %s" % e)
            else:
                print("%s (found in an undamped %d-step probe from the state after the gravity stage, state restored; "
                      "%.1f s wall)" % (ss, args.probe_steps, time.time() - t0))
                fel_found = found[2] if not isinstance(found[2], str) else None
                print(safety.table2(found[1], fel_found, title="Table 2 (surface of slipping joints found by the program)",
                                   reference=SEED_TABLE2))
                if isinstance(found[2], str):
                    print("  Fellenius along it failed: %s" % found[2])
    snapshots.snapshot(os.path.join(args.out, "landslide_0_before.png"), "after gravity stage, t = 0", O=O, slip=slip)

# --- strength reduction (optional) -------------------------------------------------------------
sr = None
if args.strength_reduction:
    t0 = time.time()
    print("strength reduction from the state after the gravity stage (phi = 30 deg, c = 0):")
    sr = strength_reduction(start=1.0, grow=1.25, rtol=args.sr_rtol, tol=args.sr_tol, d_fail=args.sr_dfail,
                            max_steps=args.sr_steps, check=100, damping=0.7)
    print("  %s\n  %s; %.1f s wall" % (sr, sr.criterion, time.time() - t0))

# --- dynamic stage ---------------------------------------------------------------------------
if mon:
    mon.mark(" dynamic stage")
vtk_series = vtkexport.VtkSeries(os.path.join(args.out, "vtk"), "landslide")
if master:
    vtk_series.write()  # t = 0 of the dynamic stage
if mp is None:
    vtk_runner = wrapper.PyRunner(command="vtk_series.write()", virtPeriod=args.vtk_every, label="vtkRunner")
    vtk_runner.virtLast = O.time
    O.engines = O.engines + [vtk_runner]
# (--mpi: a PyRunner would write each rank's part of the scene; VTK is written at the merges instead)
newton = [e for e in O.engines if type(e).__name__ == "NewtonIntegrator"][0]
newton.damping = 0.0
nsteps = int(args.time / O.dt)  # O.dt may change a little (time stepper)
if mon:
    mon.target(time=args.time)  # by simulated time: the stepper changes O.dt on the way
nchunks = 3
mobile = [b.id for b in sb.free]
t_dyn0 = O.time
t0 = time.time()
balance0 = None  # O.energy at the end of the first chunk: the balance of the dynamic stage is checked from there
if mp is None:
    O.trackEnergy = True  # (the forces and the motion are the same with it)
for k in range(nchunks):
    while O.time - t_dyn0 < args.time * (k + 1) / nchunks * (1 - 1e-9):  # O.time: the same on every rank
        if mp is None:
            yr.advance(max(1, min(200, nsteps // nchunks)))
            if balance0 is None:
                balance0 = (O.energy.total(), O.energy["gravWork"])
        else:
            rmpi.run(max(1, min(200, nsteps // nchunks)))
    if mp is not None:
        rmpi.merge()
    if not master:
        continue
    dmax = max((O.bodies[i].state.pos - O.bodies[i].state.refPos).norm() for i in mobile)
    nslip = sum(1 for I in O.interactions if I.isReal and I.phys.nSlipping > 0)
    nopen = sum(1 for I in O.interactions if I.isReal and I.phys.nOpen > 0)
    print("  dynamic stage: t = %.3f s  max displacement %.3f m  slipping joints %d  open joints %d  (%.1f s wall)"
          % (O.time - t_dyn0, dmax, nslip, nopen, time.time() - t0))
    name = "landslide_%d_%s.png" % (k + 1, "during" if k < nchunks - 1 else "after")
    snapshots.snapshot(os.path.join(args.out, name), "dynamic stage, t = %.2f s" % (O.time - t_dyn0), O=O, slip=slip)
    if mp is not None:
        vtk_series.write()
if balance0 is not None:
    grav = balance0[1] - O.energy["gravWork"]
    print("  energy balance of the dynamic stage (O.energy, J/m): %s; off by %.3g %% of the work of gravity"
          % (", ".join("%s %.4g" % kv for kv in sorted(O.energy.items())), 100 * (O.energy.total() - balance0[0]) / grav))
if master and vtk_series.entries["blocks"][-1][0] < O.time:
    vtk_series.write()  # the last state
png = txt = "not recorded (--mpi)"
if mon:
    png, txt = mon.save(os.path.join(args.out, "landslide_plot"), "landslide slope: gravity stage, then dynamic stage")
print("snapshots in %s; VTK series %s (%d snapshots, open in ParaView); plot %s, data %s"
      % (args.out, ", ".join(sorted(vtk_series.pvd.values())), len(vtk_series.entries["blocks"]), png, txt))
if mp is not None:
    states = rmpi.rank_states()  # collective
    print("yade.mpy: ranks at t = %s s after %s steps" % (", ".join("%.9g" % t for t, i, dt in states),
                                                         ", ".join(str(i) for t, i, dt in states)))
if args.summary and master:
    import json
    with open(args.summary, "w") as f:
        json.dump({"ranks": mp.numThreads if mp else 1, "settle_steps": steps, "settle_ratio": ratio,
                   "fs_contact": fs.fs, "fs_shear": fs.shear, "fs_normal": fs.normal, "fs_joints": fs.n_joints,
                   "dynamic_time": O.time - t_dyn0, "iter": O.iter, "dt": O.dt,
                   "displacement": {str(i): list(O.bodies[i].state.pos - O.bodies[i].state.refPos)[:2] for i in mobile},
                   "rotation": {str(i): O.bodies[i].state.ori.toAxisAngle()[1] * O.bodies[i].state.ori.toAxisAngle()[0][2]
                                for i in mobile}}, f, indent=1)

# --- all factors of safety (rank 0) -------------------------------------------------------
if master:
    def _fs(v):
        return v.fs if hasattr(v, "fs") else None

    def _note(v, extra=""):
        if isinstance(v, str):
            return "failed: " + v
        if hasattr(v, "circle"):  # SearchResult
            return "%s; %d of %d toe circles valid" % (v.circle, v.n_valid, v.n_tried)
        return "T = %.1f kN/m, N = %.1f kN/m%s" % (v.shear, v.normal, extra)

    beta = math.atan2(surface[2][1] - surface[1][1], surface[2][0] - surface[1][0])
    rows = [("RBSM contact forces, slip polyline", fs.fs, "T = %.1f kN/m, N = %.1f kN/m, %d joints (Table 2)"
             % (fs.shear, fs.normal, fs.n_joints))]
    if found is not None:
        rows.append(("RBSM contact forces, found surface", found[1].fs, "T = %.1f kN/m, N = %.1f kN/m, %d joints"
                     % (found[1].shear, found[1].normal, found[1].n_joints)))
        rows.append(("Fellenius, found surface", found[2] if isinstance(found[2], str) else found[2].fs,
                     found[2] if isinstance(found[2], str) else "T = %.1f kN/m, N = %.1f kN/m" % (found[2].shear, found[2].normal)))
    if sr is not None:
        rows.append(("RBSM strength reduction", sr.fs, "bracket [%.3f stable, %.3f failed], %d trials"
                     % (sr.lo, sr.hi, len(sr.trials))))
    else:
        rows.append(("RBSM strength reduction", None, "not run (--strength-reduction)"))
    for k, v in lem.items():
        rows.append((k, _fs(v), _note(v, ", " + str(v.surface) if k.endswith(", circle") and not isinstance(v, str) else "")))
    rows += [("closed form: planar wedge tan(phi)/tan(psi)", math.tan(phi) / math.tan(psi), "psi = 35 deg, no crack thrust"),
             ("closed form: infinite slope tan(phi)/tan(beta)", math.tan(phi) / math.tan(beta),
              "face beta = %.1f deg (shallowest mechanism)" % math.degrees(beta)),
             ("seed paper: RBSM", 0.72, "Table 2"), ("seed paper: Fellenius", 0.63, "Table 2")]
    print(safety.fs_table(rows))
    print("wall time %.1f s" % (time.time() - t_wall))
