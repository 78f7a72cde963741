"""Landslide of a block slope with a tension crack (seed paper, section 3: Table 1, Table 2, Fig. 5-6).

Run headless:  build/yade-rbsm -n -x scripts/landslide_slope.py [options]

Geometry (the seed's figure geometry is not available; chosen here, all in metres):
  * ground: toe flat at y = 2 for x in [0, 6], face up to the crest y = 12 at x = 14 (10 m high,
    51.3 deg), crest flat to x = 24; base of the blocks y = 0; fixed foundation (1 m) and side walls;
  * bricks 2 m x 1 m with staggered vertical joints (cut at the kinks so every block is convex);
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
  4. dynamic stage: damping 0, joint friction back to phi = 30 deg: the wedge slides off.
"""
import argparse
import math
import os
import sys
import time

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl, safety, snapshots
from yade_rbsm import limit_equilibrium as le

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("--density-units", choices=["kgf", "si"], default="kgf")
ap.add_argument("--out", default="out/landslide")
ap.add_argument("--brick", type=float, nargs=2, default=(2.0, 1.0), metavar=("W", "H"))
ap.add_argument("--height", type=float, default=10.0, help="slope height [m]")
ap.add_argument("--tol", type=float, default=1e-3, help="unbalanced-force ratio of the gravity stage")
ap.add_argument("--max-settle", type=int, default=20000, help="max steps of the gravity stage")
ap.add_argument("--time", type=float, default=3.0, help="simulated time of the dynamic stage [s]")
ap.add_argument("--dt", type=float, default=None, help="time step [s] (default: 0.8 x critical)")
ap.add_argument("--small", action="store_true", help="tiny slope for smoke tests")
args = ap.parse_args(sys.argv[1:])

t_wall = time.time()
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

sb = sl.brick_blocks(surface, 0.0, args.brick[0], args.brick[1], joints=[plane], crack=(xcrack, ycrack),
                     foundation=1.0, wall=1.0)
sl.build_scene(sb, mat)
print("slope: %d free blocks, %d fixed; area %.3f m2 (closed form %.3f, slivers dropped %.2e)"
      % (len(sb.free), len(sb.blocks) - len(sb.free), sum(b.area for b in sb.free), sb.slope_area, sb.dropped_area))
print("joint plane psi = 35 deg from the toe (%.2f, %.2f) to the crack at x = %.2f (down to y = %.2f)"
      % (toe, y0, xcrack, ycrack))

bmin = min(args.brick) * 1e-2
O.engines = yr.engines(gravity=(0, -9.81, 0), damping=0.7, set_dt=False, enlarge=bmin)
O.dt = 1e-6  # bonding step
nj, nbroken = sl.bond_and_break(sb)
dtc = yr.critical_time_step()
ts = [e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0]
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
fs = safety.contact_fs(plane)  # the crack joints (open, c = 0) carry no force: plane only
g = 9.81
slope_le = le.Slope(surface, le.Layer(c=0.0, phi=30.0, gamma=rho245 * g / 1e3))
fel = le.fellenius_polyline(slope_le, slip, n=50)
print(safety.table2(fs, fel))
crack = [I for I in O.interactions if I.isReal and abs(I.geom.p0[0] - xcrack) < 1e-2 * scale
         and abs(I.geom.p1[0] - xcrack) < 1e-2 * scale and I.geom.p0[1] > ycrack - 1e-2]
print("crack: %d joints in contact carry a normal force of %.1f kN/m (thrust of the crest mass, "
      "absent from Fellenius)" % (len(crack), sum(I.phys.normalForce for I in crack) / 1e3))
print("(RBSM: %d joints on the slip polyline, %.2f m of it; planar wedge closed form tan(phi)/tan(psi) = %.3f)"
      % (fs.n_joints, fs.length, math.tan(phi) / math.tan(psi)))
snapshots.snapshot(os.path.join(args.out, "landslide_0_before.png"), "after gravity stage, t = 0", O=O, slip=slip)

# --- dynamic stage ---------------------------------------------------------------------------
O.engines[-1].damping = 0.0
nsteps = int(args.time / O.dt)  # O.dt may change a little (time stepper)
nchunks = 3
mobile = [b.id for b in sb.free]
t_dyn0 = O.time
t0 = time.time()
for k in range(nchunks):
    while O.time - t_dyn0 < args.time * (k + 1) / nchunks * (1 - 1e-9):
        O.run(max(1, min(200, nsteps // nchunks)), True)
    dmax = max((O.bodies[i].state.pos - O.bodies[i].state.refPos).norm() for i in mobile)
    nslip = sum(1 for I in O.interactions if I.isReal and I.phys.nSlipping > 0)
    nopen = sum(1 for I in O.interactions if I.isReal and I.phys.nOpen > 0)
    print("  dynamic stage: t = %.3f s  max displacement %.3f m  slipping joints %d  open joints %d  (%.1f s wall)"
          % (O.time - t_dyn0, dmax, nslip, nopen, time.time() - t0))
    name = "landslide_%d_%s.png" % (k + 1, "during" if k < nchunks - 1 else "after")
    snapshots.snapshot(os.path.join(args.out, name), "dynamic stage, t = %.2f s" % (O.time - t_dyn0), O=O, slip=slip)
print("snapshots in %s" % args.out)
print("wall time %.1f s" % (time.time() - t_wall))
