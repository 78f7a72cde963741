"""Two bonded unit blocks (E = 1e8 Pa, ρ = 2000, bonded c = σt = 1e9 Pa), free, no gravity, no damping,
vibrating: initial velocities ±(1e-3, 2e-4) m/s and spins, so the normal, shear and rocking modes ring.
The stepper sets O.dt (0.8 × estimate). Every steps/samples steps the leapfrog energy (see
_common.measured_step) is recorded. Returns the list of energies, O.dt, the joint's state."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, measured_step
from yade_rbsm import polygon2d, engines

p = params()
m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=1e9, tensileStrength=1e9)
O.materials.append(m)
a = O.bodies[O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], m))]
b = O.bodies[O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], m))]
a.state.vel, b.state.vel = (1e-3, 2e-4, 0), (-1e-3, -2e-4, 0)
a.state.angVel, b.state.angVel = (0, 0, 1e-3), (0, 0, -5e-4)
O.engines = engines(gravity=(0, 0, 0))
O.engines[2].physDispatcher.functors[0].setCohesionNow = True
O.trackEnergy = True
G = (0.0, 0.0)
steps, samples = p.get("steps", 100000), p.get("samples", 20)
O.step()                               # joint made, O.dt set
e = [measured_step(O, G)]
for k in range(samples):
    O.run(steps // samples - 1, True)
    e.append(measured_step(O, G))
i = O.interactions[0, 1]
emit({"energy": e, "dt": O.dt, "iter": O.iter, "intact": list(i.phys.intactPoints), "n_inter": len(O.interactions)})
