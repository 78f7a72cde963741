"""Two bonded 1 m blocks without gravity, vibrating (kinetic energy 1.6e-5 J); at step 149, between two
full estimates of RbsmTimeStepper (interval 100), a script makes the system 10 x faster: params
{"change": "mass"} (both blocks' mass and inertia x 0.01, velocities x 10: the same kinetic energy) or
"kn" (the joint's kn, ks x 100 at about zero force: no energy added). The scheme conserves energy
(bonded, linear, undamped): emits the kinetic energy before and its largest value after, and whether
the bond held (a new user's trial 14b: mass x 0.1 -> 64.7 J, kn x 100 -> 1071 J, the bond torn)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite  # noqa: E402
from yade_rbsm import polygon2d, engines, advance, omega  # noqa: E402

change = params()["change"]
save = params().get("save", False)  # O.save and O.load right after the change (before the next step)
m = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=0.6, cohesion=1e6, tensileStrength=1e6)
O.materials.append(m)
a = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], m))
b = O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], m))
O.engines = engines(gravity=(0, 0, 0))
omega.ip2(O).setCohesionNow = True
advance(1)
omega.ip2(O).setCohesionNow = False
O.bodies[b].state.vel = (1e-4, 0, 0)


def kinetic():
    return sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm()
               + 0.5 * O.bodies[i].state.inertia[2] * O.bodies[i].state.angVel[2] ** 2 for i in (a, b))


advance(149 - O.iter)
out = {"before": kinetic(), "dt_before": O.dt}
if change == "mass":
    for i in (a, b):
        s = O.bodies[i].state
        s.mass *= 0.01
        s.inertia = s.inertia * 0.01
        s.vel = s.vel * 10
elif change == "kn":
    I = O.interactions[a, b]
    I.phys.kn *= 100
    I.phys.ks *= 100
if save:
    O.save("/tmp/stale_step_%d.yade.gz" % os.getpid())
    O.load("/tmp/stale_step_%d.yade.gz" % os.getpid())
    os.remove("/tmp/stale_step_%d.yade.gz" % os.getpid())
peak = 0.0
for k in range(60):
    advance(1)
    peak = max(peak, kinetic())
out.update(x=O.bodies[b].state.pos[0], peak=peak, dt_after=O.dt, intact=O.interactions[a, b].phys.nIntact if O.interactions.has(a, b) else 0,
           finite=all_finite(O))
emit(out)
