# yade script (run by test_contact_fs.py): a block on a fixed block, plane joint at psi = 20 deg,
# phi = 30 deg, c = 0; after a damped gravity stage prints N, T, FS and the hand values.
import math, sys
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import safety, slope
psi, phi = math.radians(20), math.radians(30)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=0, tensileStrength=0)
O.materials.append(mat)
c, s = math.cos(psi), math.sin(psi)
rot = lambda x, y: (x * c - y * s, x * s + y * c)
base = [rot(-1, -1), rot(3, -1), rot(3, 0), rot(-1, 0)]
top = [rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)]
O.bodies.append([yr.polygon2d(base, mat, fixed=True), yr.polygon2d(top, mat)])
O.engines = yr.engines(damping=0.7, set_dt=False, enlarge=0.01)
O.dt = 1e-6
O.engines[2].physDispatcher.functors[0].setCohesionNow = True
O.step()
O.dt = 0.8 * yr.critical_time_step() * (1 - 1e-9)
ok, n, r = slope.settle(tol=1e-6, max_steps=20000, check=100)
res = safety.contact_fs([rot(-1, 0), rot(3, 0)])
W = O.bodies[1].state.mass * 9.81 / 1e3
print("RESULT %r %d %.6e %.9g %.9g %.9g %.9g %.9g %.9g %d" % (ok, n, r, res.normal, res.shear, res.fs,
      W * c, W * s, math.tan(phi) / math.tan(psi), res.n_joints))
