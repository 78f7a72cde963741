"""An upper block bonded on a fixed one across a face with a small misfit: its bottom edge is tilted so
that one end touches and the other is 'gap' above (imported geometry, not snapped). Every contact is
bonded at the first step (setCohesionNow); gravity closes the face elastically. params: gap [m], steps.
Returns the joint's bonded length, length, intact points and whether it ever slipped."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import math
from _common import params, emit
import yade_rbsm as yr
from yade_rbsm import polygon2d, omega

p = params()
gap = p.get("gap", 1e-9)
mat = RbsmMat(young=1e8, poisson=0.25, density=2600, frictionAngle=math.radians(30), cohesion=1e5,
              tensileStrength=1e5)
O.materials.append(mat)
lower = O.bodies.append(polygon2d([(0, -1), (1, -1), (1, 0), (0, 0)], mat, fixed=True))
upper = O.bodies.append(polygon2d([(0, 0), (1, gap), (1, 1), (0, 1)], mat))
O.engines = yr.engines(gravity=(0, -9.81, 0), damping=0.7, set_dt=True)
O.dt = 1e-6
omega.ip2(O).setCohesionNow = True
O.step()
b0 = O.interactions[lower, upper].phys.bondedLength
yr.advance(p.get("steps", 2000))
I = O.interactions[lower, upper]
emit(dict(bonded0=b0, bonded=I.phys.bondedLength, length=I.geom.length, intact=I.phys.nIntact,
          slipped=I.phys.plasticDissipation > 0))
