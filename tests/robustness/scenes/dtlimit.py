"""Critical time step: the project's estimate against the true limit found by bisection.
kind: 'single' (one unit block bonded to a fixed base), 'column5' (5 bonded unit blocks on a base),
'grid3' (3 × 3 bonded unit blocks on a base). Bonded (c = σt = 1e9 Pa), no gravity, undamped, initial
velocities of every block (all modes excited), E = 1e8 Pa, ν = 0.2, ρ = 2000.
mode 'ratio': est = RbsmTimeStepper().estimate() after the first step, then the true limit by bisection:
  a dt is unstable if the leapfrog energy grows 10× within N steps (default 2000); 'iters' bisections.
mode 'refuse': engines(set_dt=False, safety=1) with O.dt = factor × the true limit given; one O.step():
  returns the exception and whether any body moved.
mode 'run': engines(set_dt=True, safety, contact damping xi) and steps: returns the leapfrog energy e0/e1
  and the kinetic energy ke0/ke1 at the start and the end."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, measured_step, body_states, kinetic_energy
from yade_rbsm import polygon2d, engines

p = params()
kind, mode = p.get("kind", "single"), p.get("mode", "ratio")
G = (0.0, 0.0)


def rect(x0, y0, w, h):
    return [(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)]


def build(set_dt=True, safety=0.8, stepper=True, xi=0.0):
    O.reset()
    m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=1e9, tensileStrength=1e9)
    O.materials.append(m)
    O.bodies.append(polygon2d(rect(-1, -1, 5, 1), m, fixed=True))
    cells = {"single": [(0, 0)], "column5": [(0, j) for j in range(5)],
             "grid3": [(i, j) for i in range(3) for j in range(3)]}[kind]
    for k, (i, j) in enumerate(cells):
        b = O.bodies[O.bodies.append(polygon2d(rect(i, j, 1, 1), m))]
        b.state.vel = (1e-3 * math.sin(k + 1), 1e-3 * math.cos(2 * k + 1), 0)
        b.state.angVel = (0, 0, 1e-3 * math.sin(3 * k + 2))
    eng = engines(gravity=(0, 0, 0), safety=safety, set_dt=set_dt, interval=1, contact_damping=xi)
    O.engines = eng if stepper else [e for e in eng if type(e).__name__ != "RbsmTimeStepper"]
    O.engines[2].physDispatcher.functors[0].setCohesionNow = True
    O.trackEnergy = True


def grows(dt, n):
    build(stepper=False)
    O.dt = dt
    e0 = measured_step(O, G)
    O.run(n - 2, True)
    e1 = measured_step(O, G)
    return not (math.isfinite(e1) and e1 < 10 * e0)


if mode == "ratio":
    n = p.get("N", 2000)
    build(stepper=False)
    O.dt = 1e-9
    O.step()
    est = RbsmTimeStepper().estimate()
    lo, hi = est, est
    assert not grows(lo, n), "unstable at the estimate"
    while not grows(hi, n):
        lo, hi = hi, hi * 1.5
    for _ in range(p.get("iters", 14)):
        mid = 0.5 * (lo + hi)
        if grows(mid, n):
            hi = mid
        else:
            lo = mid
    emit({"est": est, "true_lo": lo, "true_hi": hi, "ratio": est / hi, "N": n})
elif mode == "refuse":
    build(set_dt=False, safety=1.0)
    O.dt = p["dt"]
    before = body_states(O)
    try:
        O.step()
        exc = None
    except Exception as e:  # noqa: BLE001
        exc = [type(e).__name__, str(e)]
    emit({"exc": exc, "moved": body_states(O) != before, "iter": O.iter})
else:
    build(set_dt=True, safety=p.get("safety", 0.8), xi=p.get("xi", 0.0))
    ke0 = kinetic_energy(O)
    e0 = measured_step(O, G)
    O.run(p.get("steps", 5000) - 2, True)
    e1 = measured_step(O, G)
    emit({"e0": e0, "e1": e1, "ke0": ke0, "ke1": kinetic_energy(O), "dt": O.dt, "est": RbsmTimeStepper().estimate(),
          "finite": all(math.isfinite(x) for b in body_states(O) for x in b)})
