"""Landslide of a block slope with a tension crack (seed paper, section 3: Table 1, Table 2, Fig. 5-6).

    build/yade-rbsm -n -x scripts/landslide_slope.py [--pattern voronoi] [--strength-reduction] [--mpi 3]

A 10 m slope of staggered bricks (or Voronoi blocks, or columns), a joint plane at 35 deg from the toe to
a tension crack, Table 1's material, in the stages of slope.SlopeModel: bond; gravity (friction held at
tan(phi) = 5); Table 2 and limit equilibrium; the surface of slipping joints; optionally slope.fos, water
and an earthquake; the undamped slide. Every FS in one table; PNGs, VTK, plots and a report in --out.
"""
import argparse, ast, math, os, sys
from yade import O
import yade_rbsm as yr
from yade_rbsm import earthquake as eq, mpi as rmpi, safety, slope as sl


def kv(text):  # KEY=VALUE of --engines and --fos
    key, value = text.split("=", 1)
    return key, ast.literal_eval(value)


SEED_TABLE2 = [("seed paper: RBSM", 217.0, 271.0, 0.72), ("seed paper: Fellenius", 231.0, 253.0, 0.63)]
ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
opt = ap.add_argument
opt("--density-units", choices=["kgf", "si"], default="kgf")
opt("--out", default="out/landslide")
opt("--pattern", choices=["bricks", "voronoi", "columns"], default="bricks")
opt("--brick", type=float, nargs=2, default=(2.0, 1.0), metavar=("W", "H"))
opt("--size", type=float, help="Voronoi spacing or column width [m] (default sqrt(W H) or W/2 of --brick)")
opt("--seed", type=int, default=1, help="seed of the Voronoi sites")
opt("--height", type=float, default=10.0, help="slope height [m]")
opt("--small", action="store_true", help="a 4 m slope, for smoke tests")
opt("--tol", type=float, default=1e-3, help="unbalanced-force ratio that ends the gravity stage")
opt("--max-settle", type=int, default=20000, help="steps of the gravity stage at most")
opt("--probe-steps", type=int, default=300, help="steps of the probe for the surface of slipping joints (0: none)")
opt("--no-search", action="store_true", help="skip the critical-circle search")
opt("--strength-reduction", action="store_true", help="also the FS by strength reduction (slope.fos)")
opt("--fos", type=kv, nargs="*", default=[], metavar="KEY=VALUE", help="slope.fos arguments, e.g. rtol=0.05 max_steps=2000")
opt("--time", type=float, default=3.0, help="simulated time of the dynamic stage [s]")
opt("--engines", type=kv, nargs="*", default=[], metavar="KEY=VALUE",
    help="yade_rbsm.engines arguments, e.g. impact_safety=0.8 update_tolerance=1e-4 sorted_loop=True")
opt("--vtk-every", type=float, default=0.1, help="VTK snapshot period of the dynamic stage [s]")
opt("--plot-every", type=int, default=150, help="yade.plot recording period [steps]")
opt("--water", type=float, metavar="ZW", help="water in the joints: a phreatic line from the toe to ZW m up the crack")
opt("--earthquake", nargs="?", const="synthetic", metavar="CSV", help="shake the dynamic stage: a record (t [s], a [g]) or the shipped one")
opt("--mpi", type=int, nargs="?", const=0, metavar="N", help="distributed with yade.mpy, N ranks (0: mpiexec's)")
args = ap.parse_args(sys.argv[1:])

mp = rmpi.start(args.mpi) if args.mpi is not None else None
master = mp is None or mp.rank == 0
if mp is not None and (args.probe_steps or args.strength_reduction):
    print("--mpi: the probe (--probe-steps) and the strength reduction are serial stages: skipped")
    args.probe_steps, args.strength_reduction = 0, False
yr.quiet_yade_warnings()  # (YADE warns each time a joint separates)
s = 0.4 if args.small else args.height / 10.0
toe, crest, xcrack, y0, top = 6 * s, 14 * s, 17 * s, 2 * s, 12 * s
surface = [(0.0, y0), (toe, y0), (crest, top), (24 * s, top)]
psi, phi = math.radians(35.0), math.radians(30.0)
ycrack = y0 + (xcrack - toe) * math.tan(psi)
plane, crack = [(toe, y0), (xcrack, ycrack)], [(xcrack, ycrack), (xcrack, top)]
slip = plane + [(xcrack + 1e-3, top + 1.0)]  # the plane, then up the crack
rho = 245.0 * 9.80665 if args.density_units == "kgf" else 245.0
print("density: 245 %s -> %.1f kg/m3" % ("kgf.s2/m4 (gravitational units)" if args.density_units == "kgf" else "kg/m3 (SI as printed)", rho))
rock = O.materials[O.materials.append(RbsmMat(young=200e6, poisson=0.2, density=rho, frictionAngle=phi, cohesion=0.0,
                                               tensileStrength=0.0, planeStrain=True, label="rock"))]
W, H = args.brick
size = args.size or (math.sqrt(W * H) * (s if args.small else 1.0) if args.pattern == "voronoi" else W / 2)
cut = dict(foundation=1.0, wall=1.0, joints=[plane])
if args.pattern == "voronoi":  # CGAL's Voronoi cells, cut along the plane and the crack
    blocks = sl.voronoi_slope_blocks(surface, 0.0, spacing=size, seed=args.seed, min_distance=0.5 * size, cracks=[crack], **cut)
elif args.pattern == "columns":  # full height, cut along the plane and the crack
    blocks = sl.column_blocks(surface, 0.0, size, cracks=[crack], **cut)
else:  # staggered rows
    blocks = sl.brick_blocks(surface, 0.0, W, H, crack=(xcrack, ycrack), **cut)
print(blocks)
model = sl.SlopeModel(blocks, rock)
f = model.build(distribute=mp is not None, bond_dt=1e-6, damping=0.7, enlarge=min(W, H) * 1e-2, **dict(args.engines)).figures
print("time step: critical %.3e s (seed paper: 0.003 s); running with dt = %.3e s; joints: %d bonded, %d on the crack broken"
      % (f["critical_dt"], f["dt"], f["joints"], f["broken"]))
if mp is None:  # the displacement of blocks at the wedge's toe, middle and crest, and behind it
    model.watch(blocks.nearest([(7 * s, y0 + s / 2), (11 * s, y0 + 5.5 * s), (15.5 * s, top - s / 2), (20 * s, top - s / 2)]), args.plot_every)
print("gravity stage:", model.settle(tol=args.tol, max_steps=args.max_settle, density_scaling=False, hold_friction=5.0))
rmpi.merge()  # (yade.mpy: rank 0 holds every block and joint for the factors of safety)
if master:
    fs = model.contact_fs(plane)  # the crack's joints (open, c = 0) carry no force
    circle = safety.circle_through((toe, y0), (xcrack, top), (2 * toe - xcrack, top))  # tangent at the toe, through the crack
    search = None if args.no_search else dict(x_range=(toe - 6 * s, crest + 6 * s), y_range=(y0 + 4 * s, y0 + 30 * s), nx=16, ny=16, refine=2)
    lem = model.limit_equilibrium(polyline=slip, circle=circle, toe=(toe, y0), search=search)
    print(safety.table2(fs, lem["Fellenius, slip polyline"]))
    thrust = [I.phys.normalForce / 1e3 for I in sl.joints_on([crack])]
    print("crack: %d joints in contact carry a normal force of %.1f kN/m (thrust of the crest mass, absent from Fellenius); %s"
          % (len(thrust), sum(thrust), fs))
    for k, v in lem.items():
        print("  %-28s %s" % (k + ":", v))
    found = model.probe(args.probe_steps) if args.probe_steps else None
    if found is not None:
        print(found.surface)
        print(safety.table2(found.contact, found.fellenius if not isinstance(found.fellenius, str) else None,
                            title="Table 2 (surface of slipping joints found by the program)", reference=SEED_TABLE2))
    if args.strength_reduction:
        r = model.fos(**dict(dict(rtol=0.01, tol=1e-3, d_fail=0.1, probe=False, circle=False, verbose=True), **dict(args.fos)))
        print("  %s\n  %s" % (r.strength_reduction, r.strength_reduction.criterion))
if args.water:  # u = gamma_w depth in the joints below the line; equilibrium again with the friction held, as before
    model.set_water([(toe, y0), (xcrack, ycrack + args.water)], "all", settle=dict(hold_friction=5.0, density_scaling=False, tol=args.tol))
if args.earthquake:  # along +x, into the slope (the face looks to -x): its positive half throws the wedge out
    model.set_earthquake(eq.Record.synthetic() if args.earthquake == "synthetic" else eq.Record.from_csv(args.earthquake))
model.run(args.time, chunks=3, snapshots=os.path.join(args.out, "landslide"), slip=slip, vtk=os.path.join(args.out, "vtk"),
          vtk_every=args.vtk_every, period=args.plot_every)
if mp is None:
    print("plot %s, data %s" % model.save_plot(os.path.join(args.out, "landslide_plot"), "landslide slope: gravity, then dynamic stage"))
if master:
    print("snapshots in %s; VTK series %s (open in ParaView)" % (args.out, ", ".join(model.stages[-1].figures["vtk"])))
    model.report(os.path.join(args.out, "report.md"))
    model.to_json(os.path.join(args.out, "summary.json"), blocks=True)  # the stages' figures, each block's displacement
    beta = math.atan2(top - y0, crest - toe)
    print(model.fs_table([("RBSM strength reduction", None, "not run (--strength-reduction; serial: not with --mpi)")] * (not args.strength_reduction) + [
        ("closed form: planar wedge tan(phi)/tan(psi)", math.tan(phi) / math.tan(psi), "psi = 35 deg, no crack thrust"),
        ("closed form: infinite slope tan(phi)/tan(beta)", math.tan(phi) / math.tan(beta), "face beta = %.1f deg" % math.degrees(beta)),
        ("seed paper: RBSM", 0.72, "Table 2"), ("seed paper: Fellenius", 0.63, "Table 2")]))
    print("wall time %.1f s (the stages)" % sum(st.wall for st in model.stages))
