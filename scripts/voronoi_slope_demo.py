# Voronoi slope demo: a slope cut into random convex Voronoi blocks (CGAL, yade_rbsm.voronoi) on a
# fixed foundation, a few hundred steps under gravity, then a PNG of the blocks coloured by
# displacement (out/voronoi_slope/voronoi_slope.png; another directory with RBSM_OUT=...).
#
#   build/yade-rbsm -n -x scripts/voronoi_slope_demo.py
import math
import os

from yade_rbsm import polygon2d, engines, omega
from yade_rbsm.snapshots import snapshot
from yade_rbsm.voronoi import voronoi_tessellation

steps = int(os.environ.get("RBSM_STEPS", "400"))
out = os.environ.get("RBSM_OUT", os.path.join("out", "voronoi_slope"))

# base, toe, face, crest (m): 60 m wide, toe at 10 m, crest at 25 m
slope = [(0, 0), (60, 0), (60, 10), (35, 10), (20, 25), (0, 25)]
t = voronoi_tessellation(slope, spacing=2.5, seed=1, min_distance=1.25)
areas = [abs(sum(b[i][0] * b[(i + 1) % len(b)][1] - b[(i + 1) % len(b)][0] * b[i][1] for i in range(len(b)))) / 2 for b in t.blocks]
print("Voronoi slope: %d sites, %d blocks (%d cells cut into convex pieces, %d slivers dropped); block area %.3g..%.3g m2, total %.6f m2"
      % (len(t.sites), len(t.blocks), t.split, t.dropped, min(areas), max(areas), sum(areas)))

rock = RbsmMat(young=200e6, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=20e3, tensileStrength=10e3, label="rock")
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -3), (65, -3), (65, 0), (-5, 0)], rock, fixed=True, color=(0.5, 0.5, 0.5)))  # foundation
ids = O.bodies.append([polygon2d(v, rock) for v in t.blocks])
for b in O.bodies:
    b.state.refPos = b.state.pos  # displacements from here
O.engines = engines(gravity=(0, -9.81, 0), damping=0.3)  # no contact damping: known instability at the stepper dt (tests/robustness, bug 1)
# the joints made at the first step are bonded (cohesion and tensile strength); later ones are frictional
omega.ip2().setCohesionNow = True
O.run(steps, True)

joints = sum(1 for i in O.interactions if i.isReal)
umax = max((O.bodies[i].state.pos - O.bodies[i].state.refPos).norm() for i in ids)
assert all(math.isfinite(O.bodies[i].state.pos[k]) for i in ids for k in range(3)), "non-finite position"
print("%d steps, dt = %.3e s (t = %.3f s): %d joints, largest displacement %.3e m" % (O.iter, O.dt, O.time, joints, umax))
os.makedirs(out, exist_ok=True)
png = snapshot(os.path.join(out, "voronoi_slope.png"), title="Voronoi slope, t = %.2f s" % O.time)
print("snapshot:", png)
