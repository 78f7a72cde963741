"""Save / load / continue. A wall of 2 × 4 bonded blocks (weak joints: c = 2 kPa, σt = 1 kPa, φ = 25°) on
a fixed base, under gravity tilted by 30° on a 62 m long base (so the joints break and slip), contact damping 0.1, the time
step from the stepper (set_dt, interval 7 so that checks fall between the save and the end).
mode 'full': steps = n1 + n2 at once; 'save': n1 steps then O.save(file); 'load': O.load(file), n2 steps.
Returns every body's state, the joint states (intact, slipping, open per point, shear and normal tractions,
δn, plastic dissipation), O.iter, O.time and O.dt."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, body_states, joint_states
from yade_rbsm import polygon2d, engines

p = params()
mode, n1, n2 = p.get("mode", "full"), p.get("n1", 1500), p.get("n2", 1500)
if mode in ("full", "save"):
    m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=math.radians(25), cohesion=2e3,
                tensileStrength=1e3)
    O.materials.append(m)
    O.bodies.append(polygon2d([(-2, -1), (60, -1), (60, 0), (-2, 0)], m, fixed=True))
    for j in range(4):
        for i in range(2):
            x = i + (0.5 if j % 2 else 0)
            O.bodies.append(polygon2d([(x, j * 0.5), (x + 1, j * 0.5), (x + 1, (j + 1) * 0.5), (x, (j + 1) * 0.5)], m))
    a = math.radians(30)
    O.engines = engines(gravity=(9.81 * math.sin(a), -9.81 * math.cos(a), 0), contact_damping=0.1, interval=7)
    O.engines[2].physDispatcher.functors[0].setCohesionNow = True
    O.trackEnergy = True
    O.run(n1 + n2 if mode == "full" else n1, True)
    if mode == "save":
        O.save(p["file"])
else:
    O.load(p["file"])
    O.run(n2, True)
emit({"bodies": body_states(O), "joints": joint_states(O), "iter": O.iter, "time": O.time, "dt": O.dt,
      "energy": dict(O.energy.items())})
