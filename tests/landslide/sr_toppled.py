# Columns on a stepped base that topple while settling (a new user's scene: 2 m columns, joints dipping
# 76.5 deg into the slope as gravity tilted by 13.5 deg, phi 35 deg, E = 1 GPa): strength reduction of
# that collapsed state must be refused, not reduced. Prints the settled state's largest rotation and
# REFUSED <message> or RESULT <FS>.
#   yade-rbsm -n -x sr_toppled.py [reference_rotation | none]
import math
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

limit = sys.argv[1] if len(sys.argv) > 1 else "default"
rho, g, al, phi = 2600.0, 9.81, math.radians(13.5), math.radians(35.0)
xn, b, a = 34.0, 2.0, 1.0
surface = [(0, 3), (4, 3), (12, 17), (xn, 17)]
n = int(round(xn / b))
base = [(0.0, 0.0)]
for i in range(n):
    base += [(b * (i + 1), a * i)] + ([(b * (i + 1), a * (i + 1))] if i < n - 1 else [])
mat = wrapper.RbsmMat(young=1e9, poisson=0.25, density=rho, frictionAngle=phi, cohesion=0.0, tensileStrength=0.0)
O.materials.append(mat)
sb = sl.column_blocks(surface, base, b, wall=0.0)
sl.build_scene(sb, mat)
O.engines = yr.engines(gravity=(-g * math.sin(al), -g * math.cos(al), 0), set_dt=True, enlarge=0.01)
O.dt = 1e-6
sl.bond_and_break(sb)
ok, steps, ratio = sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
rot = max(abs((O.bodies[k.id].state.refOri.conjugate() * O.bodies[k.id].state.ori).toAxisAngle()[1]) for k in sb.free)
print("SETTLED %s %d %.3g rotation %.4f" % (ok, steps, ratio, rot))
kw = {} if limit == "default" else dict(reference_rotation=None if limit == "none" else float(limit))
try:
    r = strength_reduction(start=1.0, grow=1.2, rtol=0.02, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
                           verbose=False, **kw)
    print("RESULT %.4f" % r.fs)
except ValueError as e:
    print("REFUSED %s" % e)
