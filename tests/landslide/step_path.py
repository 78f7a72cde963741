# A step path in a 65 deg rock face 20 m high: bedding dipping 30 deg out of the face, offset at cross joints
# every 4 m (step_net.Net), cut through Voronoi blocks of strong rock (c 5 MPa); the joint sets get c 20 kPa,
# phi 35 deg, ductile, after settling (slope.set_joint_strength). Strength reduction against the least
# rigid-block limit equilibrium over the step paths. A new user's trial found two bugs with this scene (a
# corner bond growing with its contact, joints found through the wrong block).
#   yade-rbsm -n -x step_path.py seed     prints RESULT <json>
import json
import math
import os
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

sys.path.insert(0, os.getcwd())  # run from tests/landslide
from step_net import Net, best  # noqa: E402

seed = int(sys.argv[1])
rho, g, H, beta = 2600.0, 9.81, 20.0, math.radians(65)
y0, xt = 4.0, 10.0
surface = [(0, y0), (xt, y0), (xt + H / math.tan(beta), y0 + H), (45.0, y0 + H)]
net = Net(surface, 4.0, 3.46, 30.0)
polylines = net.polylines()
c, phi = 20e3, math.radians(35)
rows, npaths = best(net, c, phi, rho * g, 1)
rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=rho, frictionAngle=phi, cohesion=5e6, tensileStrength=2e6)
O.materials.append(rock)
sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=2.0, seed=seed, min_distance=1.0, joints=polylines)
sl.build_scene(sb, rock)
O.engines = yr.engines(set_dt=True, enlarge=0.01)
O.dt = 1e-6
sl.bond_and_break(sb)
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
n_set = sl.set_joint_strength(polylines, c, phi, tensile_strength=0.0, ductile=True)
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
r = strength_reduction(start=1.3, grow=1.2, rtol=0.01, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
                       verbose=False)
print(r)
print("RESULT " + json.dumps(dict(fs=r.fs, lo=r.lo, hi=r.hi, le=rows[0][0], paths=npaths, n_set=n_set,
                                  mechanism=r.mechanism, warnings=r.warnings, blocks=len(sb.free))))
