# yade script (run by test_contact_fs.py): a block on a fixed block, plane joint at psi = 20 deg,
# phi = 30 deg, c = 0; after a damped gravity stage prints N, T, FS and the hand values (per metre of the
# blocks' thickness, argv[1], default 1 m) and ContactFS's repr. argv[2] = "kink": the base block reaches past the
# joint's lower end, and the slip polyline comes up steeply to that end from below the base's centroid.
import math, os, sys
from yade import O, wrapper
import yade_rbsm as yr
sys.path.insert(0, os.getcwd())  # the tests run these scripts in their own directory
from plane_blocks import bonded_gravity_stage, plane_frame  # noqa: E402
from yade_rbsm import safety
psi, phi = math.radians(20), math.radians(30)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=0, tensileStrength=0)
O.materials.append(mat)
rot = plane_frame(psi)
c, s = math.cos(psi), math.sin(psi)  # for the hand values
kink = len(sys.argv) > 2 and sys.argv[2] == "kink"
start = -5 if kink else -1
base = [rot(start, -1), rot(3, -1), rot(3, 0), rot(start, 0)]
top = [rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)]
t = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
O.bodies.append([yr.polygon2d(base, mat, fixed=True, thickness=t), yr.polygon2d(top, mat, thickness=t)])
ok, n, r = bonded_gravity_stage()
if kink:  # steeply up from below the base's centroid, then the joint's line
    res = safety.contact_fs([(-2, -10), rot(0, 0), rot(3, 0)])
else:
    res = safety.contact_fs([rot(-1, 0), rot(3, 0)])
W = O.bodies[1].state.mass * 9.81 / 1e3 / t  # kN/m
print("RESULT %r %d %.6e %.9g %.9g %.9g %.9g %.9g %.9g %d" % (ok, n, r, res.normal, res.shear, res.fs,
      W * c, W * s, math.tan(phi) / math.tan(psi), res.n_joints))
print("REPR", repr(res))
