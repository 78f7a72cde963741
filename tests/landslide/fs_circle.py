# yade script (run by test_circle_slip.py): two blocks (2 m and 1.5 m long, 1 m high) side by side on
# a fixed block along a plane joint inclined at psi = 20 deg; phi = 30 deg, c = 5 kPa (bonded);
# damped gravity stage; FS along a circle of radius 100 m tangent to the plane at the middle of the
# contact; prints it with the hand values; then the bad-input checks (ValueError expected).
import math, os, sys
from yade import O, wrapper
import yade_rbsm as yr
sys.path.insert(0, os.getcwd())  # the tests run these scripts in their own directory
from plane_blocks import bonded_gravity_stage, plane_frame  # noqa: E402
from yade_rbsm import safety
psi, phi, coh = math.radians(20), math.radians(30), 5e3
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=coh, tensileStrength=coh)
O.materials.append(mat)
rot = plane_frame(psi)
c, s = math.cos(psi), math.sin(psi)  # for the hand values
O.bodies.append([yr.polygon2d([rot(-1, -1), rot(5, -1), rot(5, 0), rot(-1, 0)], mat, fixed=True),
                 yr.polygon2d([rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)], mat),
                 yr.polygon2d([rot(2, 0), rot(3.5, 0), rot(3.5, 1), rot(2, 1)], mat)])
ok, n, r = bonded_gravity_stage()
R = 100.0
mid = rot(1.75, 0)
centre = (mid[0] - s * R, mid[1] + c * R)  # along the plane's normal, above it
res = safety.contact_fs_circle((centre[0], centre[1], R), band=0.1)
W = sum(O.bodies[i].state.mass for i in (1, 2)) * 9.81
L = 3.5
print("RESULT %r %d %.6e %.9g %.9g %.9g %.9g %.9g %.9g %d %.9g" % (
    ok, n, r, res.normal, res.shear, res.fs, W * c / 1e3, W * s / 1e3,
    (coh * L + W * c * math.tan(phi)) / (W * s), res.n_joints, res.length))
# the same along the plane as a polyline (contact_fs) for comparison
pl = safety.contact_fs([rot(-1, 0), rot(5, 0)])
print("POLY %.9g %.9g %.9g" % (pl.normal, pl.shear, pl.fs))


def bad(label, fn):
    try:
        fn()
    except ValueError as e:
        print("BAD %s ValueError: %s" % (label, e))
    else:
        print("BAD %s no error" % label)


bad("circle-misses", lambda: safety.contact_fs_circle((50, 50, 3)))
bad("circle-nan", lambda: safety.contact_fs_circle((float("nan"), 0, 3)))
bad("circle-radius", lambda: safety.contact_fs_circle((0, 0, -1)))
bad("circle-band", lambda: safety.contact_fs_circle((0, 0, 3), band=0))
bad("polyline-misses", lambda: safety.contact_fs([(30, 30), (40, 31)]))
bad("polyline-empty", lambda: safety.contact_fs([]))
bad("polyline-nan", lambda: safety.contact_fs([(0, 0), (float("nan"), 1)]))
bad("polyline-order", lambda: safety.contact_fs([(1, 0), (0, 1)]))
bad("slip-none", lambda: safety.slip_surface_fs())  # nothing slips in equilibrium
