# Blocks in open water (issue 40): slope.set_water(..., open_water=True) puts the still water's pressure on the blocks'
# whole boundary below the water table (OpenWaterPressure), not only in their joints.
#   yade-rbsm -n -x submerged_block.py float           -> RESULT {"draft", "closed"}: a 2 x 1 m block of 500 kg/m3
#     floats at the draft rho/rho_w x 1 m (Archimedes)
#   yade-rbsm -n -x submerged_block.py plane open|joints -> RESULT {"fs", "closed", ...}: a 2 x 1 m block on a plane at
#     psi = 35 deg (c 5 kPa, phi 30 deg), submerged to half its height (a level water table through its centroid):
#     strength reduction against (c L + (W - B) cos psi tan phi) / ((W - B) sin psi), B = gamma_w A / 2 (open water);
#     "joints": the water in the base joint only (UDEC's joint water), for comparison
import json
import math
import os
import sys

from yade import O, Vector3, wrapper

import yade_rbsm as yr
from yade_rbsm import slope

sys.path.insert(0, os.getcwd())
mode = sys.argv[1]
gw = 9810.0
if mode == "float":
    mat = wrapper.RbsmMat(young=1e8, poisson=0.2, density=500.0)
    O.materials.append(mat)
    O.bodies.append(yr.polygon2d([(0, 0), (2, 0), (2, 1), (0, 1)], mat))
    O.engines = yr.engines(damping=0.3, set_dt=False)  # (a lone block: no joint sets the step)
    O.dt = 1e-3  # the heave's period is 1.4 s
    slope.set_water([(-10, 0.0), (10, 0.0)], joints="all", open_water=True)
    O.trackEnergy = True
    yr.advance(20000)
    b = O.bodies[0]
    bottom = min(v[1] for v in b.shape.worldVertices(b.state.pos, b.state.ori))
    # then undamped heave from 0.1 m below: the water's work and gravity's balance the kinetic energy
    yr.omega.newton(O).damping = 0
    b.state.pos = b.state.pos - Vector3(0, 0.1, 0)
    b.state.vel = (0, 0, 0)
    O.trackEnergy = True
    yr.advance(1)
    total0, peak, drift = sum(O.energy[k] for k in O.energy.keys()), 0.0, 0.0
    for k in range(3000):
        yr.advance(1)
        peak = max(peak, O.energy["kinetic"])
        drift = max(drift, abs(sum(O.energy[k] for k in O.energy.keys()) - total0))
    engines = [type(e).__name__ for e in O.engines]
    try:
        slope.set_water([(-10, 0.0), (10, 0.0)], joints="all", open_water="yes")
        refused = None
    except ValueError as e:
        refused = str(e)
    slope.set_water(None)
    print("RESULT " + json.dumps(dict(draft=-bottom, heave_peak=peak, heave_drift=drift, refused=refused,
                                      after_none=[type(e).__name__ for e in O.engines], law_open=yr.omega.engine("law", O).openWater, closed=500.0 / 1000.0 * 1.0, speed=b.state.vel.norm(), time=O.time,
                                      engines=engines)))
    sys.exit(0)

from plane_blocks import bonded_gravity_stage, plane_frame  # noqa: E402
from yade_rbsm.strength_reduction import strength_reduction  # noqa: E402
psi, phi, c, rho = math.radians(35), math.radians(30), 5000.0, 2000.0
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=rho, frictionAngle=phi, cohesion=c, tensileStrength=c, ductile=True)
O.materials.append(mat)
rot = plane_frame(psi)
O.bodies.append([yr.polygon2d([rot(-1, -1), rot(3, -1), rot(3, 0), rot(-1, 0)], mat, fixed=True),
                 yr.polygon2d([rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)], mat)])
ok, n, r = bonded_gravity_stage()
yc = O.bodies[1].state.pos[1]  # the water table through the block's centroid: half of it under water
slope.set_water([(-10, yc), (10, yc)], joints="all", open_water=(sys.argv[2] == "open"))
slope.settle(tol=1e-6, max_steps=20000, check=100)
res = strength_reduction(start=1.0, grow=1.2, rtol=0.002, tol=1e-5, d_fail=2e-3, max_steps=3000, check=100, damping=0.7)
W, B, L = rho * 9.81 * 2.0, gw * 1.0, 2.0
closed = (c * L + (W - B) * math.cos(psi) * math.tan(phi)) / ((W - B) * math.sin(psi))
dry = (c * L + W * math.cos(psi) * math.tan(phi)) / (W * math.sin(psi))
print("RESULT " + json.dumps(dict(fs=res.fs, closed=closed, dry=dry, warnings=list(res.warnings), settled=bool(ok))))
