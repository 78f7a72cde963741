# A new user's planar slide (trial 14a): a 60 deg face, 12 m high, a bedding set dipping 30 deg that
# daylights 3 m up the face (c 20 kPa, phi 30 deg, ductile), a vertical tension-crack set from the bedding to
# the crest at x = 22 m (c 0, phi 20 deg), bricks of strong rock (E 200 MPa, c 5 MPa, phi 45 deg); the sets
# given after settling. Hoek & Bray, dry tension crack: FS = (c L + W cos(psi) tan(phi)) / (W sin(psi)).
#   yade-rbsm -n -x joint_set_plane.py [BRICK_W BRICK_H]
# The wedge settles 1.2 cm down its bedding: the crack joint at the bedding's end then reaches past the
# crack polyline's end; it was not found, kept the rock's 5 MPa and glued the heel (FS 2.01).
import json
import math
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

bw, bh = (float(sys.argv[1]), float(sys.argv[2])) if len(sys.argv) > 2 else (1.5, 1.0)
psi, beta, rho, g = math.radians(30), math.radians(60), 2600.0, 9.81
xt, H = 10.0, 12.0
xcrest = xt + H / math.tan(beta)
xd, yd, xc = xt + 3 / math.tan(beta), 3.0, 22.0
yc = yd + (xc - xd) * math.tan(psi)
bedding, crack = [(xd, yd), (xc, yc)], [(xc, yc), (xc, H)]
cb, phib = 20e3, math.radians(30)
wedge = [(xd, yd), (xc, yc), (xc, H), (xcrest, H)]
W = rho * g * 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1]))
L = (xc - xd) / math.cos(psi)
closed = (cb * L + W * math.cos(psi) * math.tan(phib)) / (W * math.sin(psi))
rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
                       tensileStrength=2e6, ductile=True)
O.materials.append(rock)
sb = sl.brick_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, bw, bh, joints=[bedding, crack])
sl.build_scene(sb, rock)
O.engines = yr.engines(enlarge=0.01)
sl.bond_and_break(sb)
bonded = {(I.id1, I.id2) for I in sl.joints_on([bedding]) + sl.joints_on([crack])}
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
sl.set_joint_strength([bedding], cb, phib, ductile=True)
sl.set_joint_strength([crack], 0.0, math.radians(20), ductile=True)
missed = sorted(k for k in bonded if O.interactions.has(*k) and O.interactions[k].isReal
                and O.interactions[k].phys.cohesion == rock.cohesion)
r = strength_reduction(start=1.0, grow=1.2, rtol=0.005, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
                       verbose=False)
print("RESULT " + json.dumps(dict(fs=r.fs, lo=r.lo, hi=r.hi, closed=closed, missed=missed, bonded=len(bonded))))
