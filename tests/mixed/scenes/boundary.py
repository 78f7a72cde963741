"""A block on an incline whose ground is a fixed Polygon2D, a YADE Wall or a YADE Facet (issue 17), as
tests/physics/scenes/incline.py: block L x H = 4 x 0.5 m, density 2000, E = 1e8, nu = 0.2, contact damping
0.3, dt = 1e-5, gravity tilted by psi from the start, `steps` steps.
params: ground ('block', 'wall', 'facet'), groundMat ('rbsm' or 'frict'), psi, phi (deg), steps,
engines ('explicit' or 'mixed': mixed_engines()). Returns the least-squares acceleration of the block's x
velocity over the second half, its displacement, the joint's classes, kn and the force on the ground."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, sin, cos
from yade import utils
from _common import params, emit, lsq_slope, pair_balance
from yade_rbsm import polygon2d, mixed_engines

p = params()
psi, phi, g = radians(p.get("psi", 35)), radians(p.get("phi", 30)), 9.81
L, H, ground = 4.0, 0.5, p.get("ground", "block")
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=phi)
base = rock if p.get("groundMat", "rbsm") == "rbsm" else FrictMat(young=1e8, poisson=0.2, density=2000, frictionAngle=phi)
O.materials.append([rock, base])
if ground == "block":
    O.bodies.append(polygon2d([(-50, -1), (50, -1), (50, 0), (-50, 0)], rock, fixed=True))
elif ground == "wall":
    O.bodies.append(utils.wall((0, 0, 0), axis=1, material=base))
else:  # a vertical triangle in the plane y = 0 whose trace in z = 0 runs from x = -40 to 40
    O.bodies.append(utils.facet([(-60, 0, -1), (60, 0, -1), (0, 0, 2)], material=base))
b = O.bodies[O.bodies.append(polygon2d([(0, 0), (L, 0), (L, H), (0, H)], rock))]
grav = (g * sin(psi), -g * cos(psi), 0)
if p.get("engines", "explicit") == "mixed":
    O.engines = mixed_engines(gravity=grav, contact_damping=0.3)
    O.engines[3].dead = True  # the time stepper: the same dt as the other runs
else:
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(), Ig2_Polygon2D_Wall_RbsmGeom(), Ig2_Polygon2D_Facet_RbsmGeom()],
                                 [Ip2_RbsmMat_RbsmMat_RbsmPhys(), Ip2_RbsmMat_FrictMat_FrictPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=0.3)]),
                 NewtonIntegrator(gravity=grav, damping=0)]
O.dt = 1e-5
x0 = b.state.pos[0]
n = p.get("steps", 20000)
ts, vs = [], []
for k in range(n):
    x1, x2 = Vector3(O.bodies[0].state.pos), Vector3(b.state.pos)  # where the law of this step applies the forces
    O.step()
    if k >= n // 2 and k % 10 == 0:
        ts.append(O.time)
        vs.append(b.state.vel[0])
i = O.interactions[b.id, 0] if O.interactions.has(0, b.id) else None
emit({"a": lsq_slope(ts, vs), "disp": b.state.pos[0] - x0, "geom": type(i.geom).__name__ if i else None,
      "phys": type(i.phys).__name__ if i else None, "kn": i.phys.kn if i else None, "length": i.geom.length if i else None,
      "balance": pair_balance(O, 0, b.id, x1, x2), "weight": b.state.mass * g, "y": b.state.pos[1]})
