"""A block resting on a YADE Wall under mixed_engines() (setDt, no spheres), the wall fixed by utils.wall or
left with some degrees of freedom free and no mass (utils.wall gives it none): params wallDofs (None: as
utils.wall leaves it; else the wall's state.blockedDOFs), steps. Returns O.dt, the time stepper's criticalDt
and criticalBody, the block's vertical displacement and whether the state stayed finite."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade import utils  # noqa: E402
from _common import params, emit  # noqa: E402
from yade_rbsm import polygon2d, mixed_engines  # noqa: E402

p = params()
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(rock)
w = utils.wall((0, 0, 0), axis=1, material=rock)
if p.get("wallDofs") is not None:
    w.state.blockedDOFs = p["wallDofs"]
O.bodies.append(w)
b = O.bodies[O.bodies.append(polygon2d([(0, 0), (4, 0), (4, 0.5), (0, 0.5)], rock))]
O.engines = mixed_engines(gravity=(0, -9.81, 0), contact_damping=0.3)
y0 = b.state.pos[1]
O.run(p.get("steps", 200), True)
ts = O.engines[3]
finite = all(math.isfinite(x) for x in list(b.state.pos) + list(b.state.vel) + [b.state.angVel[2], O.dt])
emit({"iter": O.iter, "dt": O.dt, "criticalDt": ts.criticalDt, "criticalBody": ts.criticalBody, "dy": b.state.pos[1] - y0,
      "finite": finite, "wallMass": w.state.mass, "blockedDOFs": w.state.blockedDOFs})
