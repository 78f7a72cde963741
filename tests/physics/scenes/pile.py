"""A small pile: 36 blocks (brick rows, slightly rotated quadrilaterals from a seeded generator) falling
into a fixed box under gravity, frictional (φ = 30°), contact damping ξ = 0.1, dt = 1e-4.
Returns every block's x, y, rotation angle and velocity after `steps` steps.
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys, random
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, cos, sin, atan2
from _common import params, emit
from yade_rbsm import polygon2d

p = params()
rng = random.Random(12345)
mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=radians(30))
O.materials.append(mat)
O.bodies.append(polygon2d([(-0.5, -0.5), (4.5, -0.5), (4.5, 0), (-0.5, 0)], mat, fixed=True))
O.bodies.append(polygon2d([(-0.5, 0), (0, 0), (0, 6), (-0.5, 6)], mat, fixed=True))
O.bodies.append(polygon2d([(4, 0), (4.5, 0), (4.5, 6), (4, 6)], mat, fixed=True))
ids = []
for row in range(6):
    for col in range(6):
        cx = 0.4 + col * 0.62 + (0.15 if row % 2 else 0) + rng.uniform(-0.03, 0.03)
        cy = 0.35 + row * 0.5
        a = rng.uniform(-0.15, 0.15)
        pts = [(-0.27, -0.2), (0.27, -0.2 + rng.uniform(-0.03, 0.03)), (0.25, 0.2), (-0.26, 0.19)]
        ids.append(O.bodies.append(polygon2d([(cx + x * cos(a) - y * sin(a), cy + x * sin(a) + y * cos(a)) for x, y in pts], mat)))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0))], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=0.1)]),
             NewtonIntegrator(gravity=(0, -9.81, 0), damping=0)]
O.dt = p.get("dt", 1e-4)
O.run(p.get("steps", 4000), True)
out = []
for i in ids:
    s = O.bodies[i].state
    out.append([s.pos[0], s.pos[1], 2 * atan2(s.ori[2], s.ori[3]), s.vel[0], s.vel[1]])
emit({"bodies": out, "threads": O.numThreads, "n_inter": sum(1 for i in O.interactions if i.isReal),
      "ymin": min(b[1] for b in out)})
