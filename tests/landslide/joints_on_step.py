# A free block (id 0) on a fixed one (id 1), soft (E = 10 MPa: the first step moves the free block
# 2.7 mm, far more than joints_on's default tolerance, 4e-6 m): the joint under it is bonded in one
# step and must then be found on the polyline along the interface, both right after that step (the
# geometry is that of the step's start, the blocks have moved since) and after settling (where the joint's
# overlap is 2 mm).
#   yade-rbsm -n -x joints_on_step.py     prints RESULT <found after the bond step> <broken> <found settled>
import math

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import omega
from yade_rbsm import slope as sl
from yade_rbsm.blocks import polygon2d

mat = wrapper.RbsmMat(young=1e7, poisson=0.25, density=2600, frictionAngle=math.radians(40), cohesion=5e6,
                      tensileStrength=2e6)
O.materials.append(mat)
O.bodies.append([polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], mat), polygon2d([(0, -1), (4, -1), (4, 0), (0, 0)], mat,
                                                                                fixed=True)])
O.engines = yr.engines(set_dt=True, enlarge=0.01)
O.dt = 1e-6
omega.ip2(O).setCohesionNow = True
O.step()
line = [[(0, 0), (4, 0)]]
moved = (O.bodies[0].state.pos - O.bodies[0].state.refPos).norm()
found = len(sl.joints_on(line))
O.saveTmp("bonded")
broken = sl.break_joints(line)
O.loadTmp("bonded")
sl.settle(tol=1e-5, max_steps=20000, check=200)
I = O.interactions[0, 1]
print("RESULT %d %d %d %.3e %.3e %d" % (found, broken, len(sl.joints_on(line)), moved, I.geom.d0, I.geom.refBody))
