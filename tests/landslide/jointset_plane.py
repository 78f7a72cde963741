# Hoek & Bray's plane failure built by the joint-set cutter (issue 36): the slope of joint_set_plane.py
# (a 60 deg face 12 m high, a bedding dipping 30 deg that daylights 3 m up the face, c 20 kPa, phi 30 deg,
# a vertical tension crack at x = 22 m, c 0, phi 20 deg) as an outline and two traces that carry their
# strength; the rock is one block cut only where the outline is non-convex (welds), no set_joint_strength.
#   yade-rbsm -n -x jointset_plane.py [ZW [KH]]
# KH > 0: a pseudo-static horizontal acceleration kh g out of the face (slope.set_seismic), dry: Hoek & Bray's
# FS = (c A + W (cos psi - kh sin psi) tan phi) / (W (sin psi + kh cos psi)).
# ZW [m] > 0: water in the tension crack to ZW above its base and along the bedding down to the daylight point
# (slope.set_water; Hoek & Bray's U = gw zw A / 2 on the plane and V = gw zw^2 / 2 in the crack).
import json
import math
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

psi, beta, rho, g = math.radians(30), math.radians(60), 2600.0, 9.81
xt, H = 10.0, 12.0
xcrest = xt + H / math.tan(beta)
xd, yd, xc = xt + 3 / math.tan(beta), 3.0, 22.0
yc = yd + (xc - xd) * math.tan(psi)
cb, phib = 20e3, math.radians(30)
wedge = [(xd, yd), (xc, yc), (xc, H), (xcrest, H)]
W = rho * g * 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1]))
L = (xc - xd) / math.cos(psi)
zw, gw = (float(sys.argv[1]) if len(sys.argv) > 1 else 0.0), 9810.0
kh = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
U, V = 0.5 * gw * zw * L, 0.5 * gw * zw ** 2
def hoek_bray(U, V):
    return ((cb * L + (W * (math.cos(psi) - kh * math.sin(psi)) - U - V * math.sin(psi)) * math.tan(phib))
            / (W * (math.sin(psi) + kh * math.cos(psi)) + V * math.cos(psi)))


closed, closed_no_crack_water = hoek_bray(U, V), hoek_bray(U, 0.0)
rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
                       tensileStrength=2e6, ductile=True)
O.materials.append(rock)
bedding = sl.Trace([(xd, yd), (xc, yc)], cohesion=cb, friction_angle=30, tensile_strength=0, ductile=True, name="bedding")
crack = sl.Trace([(xc, yc), (xc, H)], friction_angle=20, ductile=True, name="tension crack")
sb = sl.jointset_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, traces=[bedding, crack])
from yade_rbsm.joint_sets import report
print(report(sb))
sl.build_scene(sb, rock)
O.engines = yr.engines(enlarge=0.01)
sl.bond_and_break(sb, give_sets=False)  # an elastic equilibrium first, then the joints' strength (UDEC's practice)
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
given = sl.give_joint_sets(sb)
wet = sl.set_water([(xd, yd), (xc, yc + zw)], joints="sets") if zw > 0 else 0
if zw > 0:
    sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
if kh > 0:
    sl.set_seismic(kh, towards=-1)  # the face looks to -x (the toe is on the left)
    sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
water = {n: sum(I.phys.waterForce for I in sl.joints_of(n)) for n in ("bedding", "tension crack")}
seismic_errors = []
for bad in (dict(kh=1.5), dict(kh=0.1, towards=0), dict(kh=float("nan"))):
    try:
        sl.set_seismic(**bad)
    except ValueError as e:
        seismic_errors.append(str(e))
water_errors = []
for bad in (dict(phreatic=[(5, 1), (2, 3)]), dict(phreatic=[(0, 1), (9, 2)], joints=["fault"]),
            dict(phreatic=[(0, 1), (9, 2)], unit_weight=-1)):
    try:
        sl.set_water(**bad)
    except ValueError as e:
        water_errors.append(str(e))
on = {n: [(I.phys.cohesion, I.phys.tanPhi) for I in sl.joints_on([t.points])] for n, t in (("bedding", bedding), ("crack", crack))}
by_name = {n: [(I.phys.cohesion, I.phys.tanPhi) for I in sl.joints_of(n)] for n in ("bedding", "tension crack")}
try:
    sl.joints_of("fault")
except ValueError as e:
    unknown = str(e)
r = strength_reduction(start=1.0, grow=1.2, rtol=0.005, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
                       verbose=False)
wet_by_name = sl.set_water([(xd, yd), (xc, yc + max(zw, 1.0))], joints="bedding")  # one set, by its name (after)
print("RESULT " + json.dumps(dict(fs=r.fs, lo=r.lo, hi=r.hi, closed=closed, blocks=len(sb.free), welds=len(sb.welds), given=given, wet=wet, wet_by_name=wet_by_name, seismic_errors=seismic_errors, water_errors=water_errors, water=water, U=U, V=V, closed_u=closed_no_crack_water, by_name=by_name, unknown=unknown,
                                  on=on, tan_rock=math.tan(rock.frictionAngle))))
