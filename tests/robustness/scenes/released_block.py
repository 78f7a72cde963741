"""A 2 cm block fixed on a free 2 m x 1 m block (bonded, on a fixed base, gravity), released by the script
(blockedDOFs "zXY") at step 10, between two full estimates of RbsmTimeStepper (interval 100). Emits O.dt
before and at the step after the release, the stable step then (a full estimate), and whether the next 60
steps ran (a report stops the run: its message) with the bond intact."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import emit, all_finite  # noqa: E402
from yade_rbsm import polygon2d, engines, advance, time_stepper, omega  # noqa: E402

m = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=1e6, tensileStrength=1e6)
O.materials.append(m)
O.bodies.append(polygon2d([(-2, -1), (2, -1), (2, 0), (-2, 0)], m, fixed=True))
O.bodies.append(polygon2d([(-1, 0), (1, 0), (1, 1), (-1, 1)], m))
s = O.bodies[O.bodies.append(polygon2d([(0, 1), (0.02, 1), (0.02, 1.02), (0, 1.02)], m, fixed=True))]
O.engines = engines(gravity=(0, -9.81, 0))
omega.ip2(O).setCohesionNow = True
O.dt = 1e-6
advance(10)
before = O.dt
s.state.blockedDOFs = "zXY"
advance(1)
out = {"dt_before": before, "dt_after": O.dt, "limit": time_stepper().stableDt}
stopped = ""
try:
    advance(60)
except RuntimeError as e:
    stopped = str(e)
I = O.interactions[1, 2] if O.interactions.has(1, 2) else None
out.update(stopped=stopped, intact=I.phys.nIntact if I is not None and I.isReal else 0, finite=all_finite(O), iter=O.iter)
emit(out)
