"""Two blocks in contact created in either id order: a square and a rotated triangle whose vertex is
pressed into the square's top edge, with relative sliding and spinning velocities, no gravity.
params: case 'edge' or 'vertex', order 'AB' (square first) or 'BA'; steps. Returns, per block (keyed 'square', 'triangle'), the
force and torque of the last step and the final position.
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians
from _common import params, emit
from yade_rbsm import polygon2d

p = params()
mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=radians(30))
O.materials.append(mat)
sq = lambda: polygon2d([(0, 0), (2, 0), (2, 1), (0, 1)], mat)
TRI = {"vertex": [(0.7, 0.9995), (1.6, 1.5), (0.5, 1.7)],          # a vertex pressed into the top edge
       "edge": [(0.5, 0.9998), (1.5, 0.9996), (1.2, 1.8)]}          # a slightly tilted edge on the top edge
tri = lambda: polygon2d(TRI[p.get("case", "edge")], mat)
if p.get("order", "AB") == "AB":
    S, T = O.bodies.append(sq()), O.bodies.append(tri())
else:
    T, S = O.bodies.append(tri()), O.bodies.append(sq())
O.bodies[S].state.vel = (0.02, 0.0, 0)
O.bodies[T].state.vel = (-0.05, -0.03, 0)
O.bodies[T].state.angVel = (0, 0, 0.2)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0))], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
             NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
O.dt = 1e-5
hist = []                     # normal force of the joint at each step
for k in range(p.get("steps", 20)):
    O.step()
    I = [i for i in O.interactions if i.isReal]
    hist.append([I[0].phys.normalForce, I[0].geom.separation] if I else None)
O.engines = O.engines[:3]     # one more step without moving: forces of the current configuration
O.step()
res = {"history": hist, "n_inter": sum(1 for i in O.interactions if i.isReal)}
for name, i in (("square", S), ("triangle", T)):
    f, t, s = O.forces.f(i), O.forces.t(i), O.bodies[i].state
    res[name] = {"f": [f[0], f[1], f[2]], "t": [t[0], t[1], t[2]], "pos": [s.pos[0], s.pos[1]], "id": i}
i = [i for i in O.interactions if i.isReal]
res["normalForce"] = i[0].phys.normalForce if i else None
emit(res)
