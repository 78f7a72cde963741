"""A staggered wall of nx x ny bricks (0.4 x 0.2 m) on a fixed base, frictional (φ = 30°), settled under
gravity with Cundall damping 0.4 in NewtonIntegrator (a quasi-static stage) for `steps` steps.
params: ut (Ig2 updateTolerance), nx, ny, steps, dt, phi (deg), bonded (all joints intact and strong).
Returns the vertical reaction of the base, the total weight, YADE's unbalanced-force ratio, the share of
contact-steps on frozen kinematics and every joint's normal force, keyed "id1-id2"."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians
from _common import params, emit, FrozenShare
from yade_rbsm import polygon2d
from yade import utils

p = params()
nx, ny, BW, BH = p.get("nx", 8), p.get("ny", 6), 0.4, 0.2
bonded = p.get("bonded", False)  # intact joints (c = σt = 1 GPa): a linear elastic structure with one equilibrium
mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=radians(p.get("phi", 30)), cohesion=1e9 if bonded else 0,
              tensileStrength=1e9 if bonded else 0)
O.materials.append(mat)
base = O.bodies.append(polygon2d([(-1, -0.5), (nx * BW + 1, -0.5), (nx * BW + 1, 0), (-1, 0)], mat, fixed=True))
for row in range(ny):
    off = 0.5 * BW if row % 2 else 0.0
    for col in range(nx if row % 2 == 0 else nx - 1):
        x0, y0 = off + col * BW, row * BH
        O.bodies.append(polygon2d([(x0, y0), (x0 + BW, y0), (x0 + BW, y0 + BH), (x0, y0 + BH)], mat))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0))], [Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=bonded)],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=0.1)]),
             NewtonIntegrator(gravity=(0, -9.81, 0), damping=0.4)]
O.dt = p.get("dt", 1e-5)
fz = FrozenShare()
for k in range(p.get("steps", 6000)):
    O.step()
    if k % 10 == 0:
        fz.sample(O)
weight = sum(b.state.mass for b in O.bodies if b.id != base) * 9.81
emit({"reaction": O.forces.f(base)[1], "weight": weight, "unbalanced": utils.unbalancedForce(),
      "frozen_share": fz.share(), "fn": {"%d-%d" % (i.id1, i.id2): i.phys.normalForce for i in O.interactions if i.isReal}})
