# A new user's toppling slope: 17 columns 2 m wide on a stepped base rising 1 m a column, joints dipping
# 76.5 deg into the slope (gravity tilted by 13.5 deg), frictional (c = 0), E = 1 GPa; settled, then reduced.
#   yade-rbsm -n -x stepped_columns.py 35 8000   phi 35 deg: the columns topple 3-4 m while settling, and
#                                                strength reduction must refuse that state (REFUSED <message>)
#   yade-rbsm -n -x stepped_columns.py 50 8000   phi 50 deg: the soft columns settle slowly; with max_steps
#                                                8000 the failed end only did not converge (WARNING lines)
# Prints SETTLED <converged> <steps> <ratio> rotation <largest rotation [rad]>, then REFUSED <message> or the
# result, WARNING <text> for each of its warnings and RESULT <FS> <number of warnings>.
import math
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

phi, max_steps = math.radians(float(sys.argv[1])), int(sys.argv[2])
patience = int(sys.argv[3]) if len(sys.argv) > 3 else 4
rho, g, al = 2600.0, 9.81, math.radians(13.5)
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
try:
    r = strength_reduction(start=1.0, grow=1.2, rtol=0.01, density_scaling=True, max_steps=max_steps, patience=patience, check=200,
                           d_fail=0.1, verbose=False)
except ValueError as e:
    print("REFUSED %s" % e)
    sys.exit(0)
print(r)
for w in r.warnings:
    print("WARNING " + w)
print("RESULT %.5f %d" % (r.fs, len(r.warnings)))
