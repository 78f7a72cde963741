"""A block U (1 x 1 m) on a broken crack over fixed block L2, touching fixed block L1 only at a corner
(L1's edge 'overlap' short of U's): every contact bonded at once (setCohesionNow), the crack broken, then
gravity tilted 30 deg towards L1 with phi = 20 deg on every joint (c 1 MPa, sigma_t 1 MPa, brittle or
ductile). U slides over L1's top edge, so the corner joint grows from 'overlap' towards 1 m.
params: ductile (bool), overlap [m], seconds. Returns the slide, the corner joint's bonded length,
length and shear force at the end."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import math
from _common import params, emit
import yade_rbsm as yr
from yade_rbsm import omega
from yade_rbsm import polygon2d

p = params()
ov = p.get("overlap", 2e-6)
mat = RbsmMat(young=1e9, poisson=0.25, density=2600, frictionAngle=math.radians(20), cohesion=1e6,
              tensileStrength=1e6, ductile=p.get("ductile", True))
O.materials.append(mat)
L1 = O.bodies.append(polygon2d([(-3, -1), (1 + ov, -1), (1 + ov, 0), (-3, 0)], mat, fixed=True))
L2 = O.bodies.append(polygon2d([(1 + ov, -1), (2, -1), (2, 0), (1 + ov, 0)], mat, fixed=True))
U = O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], mat))
al = math.radians(30)
O.engines = yr.engines(gravity=(-9.81 * math.sin(al), -9.81 * math.cos(al), 0), damping=0.7, set_dt=True, enlarge=0.01)
O.dt = 1e-6
omega.ip2(O).setCohesionNow = True
O.step()
O.interactions[L2, U].phys.breakJoint()  # the crack under U
bonded0 = O.interactions[L1, U].phys.bondedLength
x0 = O.bodies[U].state.pos[0]
yr.advance(int(p.get("seconds", 2.0) / O.dt))
I = O.interactions[L1, U]
emit(dict(slide=x0 - O.bodies[U].state.pos[0], bonded0=bonded0, bonded=I.phys.bondedLength if I.isReal else None,
          length=I.geom.length if I.isReal else None, shear=I.phys.shearForce if I.isReal else None,
          intact=list(I.phys.intactPoints) if I.isReal else None, dt=O.dt))
