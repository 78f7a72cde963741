# yade script (run by test_strength_reduction.py): a 2 m x 1 m block on a fixed block along a plane
# joint inclined at psi (argv[1], deg), phi = 30 deg, c = 0; damped gravity stage, then the factor of
# safety by strength reduction; prints it with the closed form tan(phi)/tan(psi).
import math, sys
from yade import O, wrapper, Vector3
import yade_rbsm as yr
from yade_rbsm import slope
from yade_rbsm.strength_reduction import strength_reduction
psi, phi = math.radians(float(sys.argv[1])), math.radians(30)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=0, tensileStrength=0)
O.materials.append(mat)
c, s = math.cos(psi), math.sin(psi)
rot = lambda x, y: (x * c - y * s, x * s + y * c)
O.bodies.append([yr.polygon2d([rot(-1, -1), rot(3, -1), rot(3, 0), rot(-1, 0)], mat, fixed=True),
                 yr.polygon2d([rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)], mat)])
O.engines = yr.engines(damping=0.7, set_dt=False, enlarge=0.01)
O.dt = 1e-6
O.engines[2].physDispatcher.functors[0].setCohesionNow = True
O.step()
O.dt = 0.8 * yr.critical_time_step() * (1 - 1e-9)
ok, n, r = slope.settle(tol=1e-6, max_steps=20000, check=100)
pos0 = Vector3(O.bodies[1].state.pos)
res = strength_reduction(start=1.0, grow=1.5, rtol=0.005, tol=1e-4, d_fail=2e-3, max_steps=1500, check=100,
                         damping=0.7, verbose=True)
print(res)
print("RESULT %r %.9g %.9g %.9g %.9g %d %.3e %.9g" % (ok, res.fs, res.lo, res.hi, math.tan(phi) / math.tan(psi),
      len(res.trials), (O.bodies[1].state.pos - pos0).norm(), O.interactions[0, 1].phys.tanPhi))
