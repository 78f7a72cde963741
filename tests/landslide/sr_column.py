# A column 2 m wide and 7 m tall bonded to a fixed base, gravity tilted by alpha = 20 deg: h/b = 3.5 >
# cot(alpha) = 2.75, so only the bond's tension holds it; friction 60 deg (sliding would need F =
# tan 60 / tan 20 = 4.76). Strength reduction with the tensile strength reduced too finds where the
# bond lets go, and the failed end must be reported as toppling (the F itself depends on how finely
# the joint samples its tension: 0.85 for the edge fibre of a continuous joint, 1.96 at the upslope
# Gauss point of a 2-point joint; not asserted).
#   yade-rbsm -n -x sr_column.py     prints RESULT <fs> <lo> <hi> <mechanism> <rocking>
import math

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.blocks import polygon2d
from yade_rbsm.strength_reduction import strength_reduction

al, b, h = math.radians(20), 2.0, 7.0
mat = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2600, frictionAngle=math.radians(60), cohesion=600e3,
                      tensileStrength=400e3)
O.materials.append(mat)
O.bodies.append(polygon2d([(-5, -1), (10, -1), (10, 0), (-5, 0)], mat, fixed=True))
O.bodies.append(polygon2d([(0, 0), (b, 0), (b, h), (0, h)], mat))
O.engines = yr.engines(gravity=(-9.81 * math.sin(al), -9.81 * math.cos(al), 0), set_dt=True, enlarge=0.01)
O.dt = 1e-6
sl.bond_and_break(sl.SlopeBlocks([], [(0, 0), (1, 1)], 0, 0, 0))
ok, steps, ratio = sl.settle(tol=1e-5, max_steps=20000, check=200)
r = strength_reduction(start=1.0, grow=1.5, rtol=0.01, tol=1e-5, max_steps=20000, check=200, d_fail=0.05,
                       reduce_tensile=True, verbose=True)
print(r)
t = [t for t in r.trials if t.F == r.hi][0]
print("RESULT %.6g %.6g %.6g %s %.4f" % (r.fs, r.lo, r.hi, r.mechanism.replace(" ", "_"), t.rocking))
