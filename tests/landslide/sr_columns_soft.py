# A new user's toppling slope: 17 columns 2 m wide on a stepped base, joints dipping 76.5 deg into the slope
# (gravity tilted by 13.5 deg), phi 50 deg, E = 1 GPa: the soft, tall columns settle slowly, and with
# max_steps 8000 the failed end of the bracket is a trial that only did not converge (nothing ran away).
# Prints RESULT <fs> <number of warnings> and the warnings.
#   yade-rbsm -n -x sr_columns_soft.py max_steps
import math
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

max_steps = int(sys.argv[1])
rho, g, al, phi = 2600.0, 9.81, math.radians(13.5), math.radians(50.0)
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
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
r = strength_reduction(start=1.0, grow=1.2, rtol=0.01, density_scaling=True, max_steps=max_steps, check=200,
                       d_fail=0.1, verbose=False)
print(r)
for w in r.warnings:
    print("WARNING " + w)
print("RESULT %.5f %d" % (r.fs, len(r.warnings)))
