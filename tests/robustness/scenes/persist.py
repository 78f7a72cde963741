"""Save / load / continue (tests/robustness/test_persistence.py).

scene 'wall': a wall of 2 × 4 bonded blocks (weak joints: c = 2 kPa, σt = 1 kPa, φ = 25°) on a fixed base,
under gravity tilted by 30° on a 62 m long base (so the joints break and slip), contact damping 0.1, the time
step from the stepper (set_dt, interval 7 so that checks fall between the save and the end).
scene 'drop': a block resting on a fixed base (bonded at step 0 by setCohesionNow) and a second block, tilted
by 20°, falling onto the base from 5 cm: its contact forms after the save, by a corner, and the joint
stiffens as the block rocks flat, so the time stepper (interval 7) lowers O.dt at some of its checks. Saved
before the impact, the scene holds two pieces of engine state: setCohesionNow still pending (the contact
of the falling block must not be bonded, as in the uninterrupted run) and the step of the stepper's last
check (the checks after the load must fall on the same steps, or O.dt is lowered by other amounts).

mode 'full': n1 + n2 steps at once; 'save': n1 steps then O.save(file); 'load': O.load(file), n2 steps.
ut: Ig2's updateTolerance (frozen contact kinematics; default 0, exact geometry).
sorted: InteractionLoop.loopOnSortedInteractions (YADE's option: the loop visits the interactions sorted by
ids instead of in the container's order, which differs after a load, see the test).
trace: the n2 steps after the save (or after n1 in 'full') are made one by one and each one recorded: the
real interactions in the order the loop visits them, and a digest of the whole state after the step.
Returns every body's state, the joint states (intact, slipping, open per point, shear and normal tractions,
δn, plastic dissipation), O.iter, O.time, O.dt, the energies, the time stepper's lastCheck and criticalDt,
with trace the per-step records, in 'load' mode also the stepper's estimate() right after the load and in
'save' mode the same estimate of the saved state (computed after O.save)."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, body_states, joint_states, traced_steps
from yade_rbsm import polygon2d, engines, critical_time_step

p = params()
mode, n1, n2 = p.get("mode", "full"), p.get("n1", 1500), p.get("n2", 1500)
scene, sorted_loop, trace = p.get("scene", "wall"), p.get("sorted", False), p.get("trace", False)


def build_wall():
    m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=math.radians(25), cohesion=2e3,
                tensileStrength=1e3)
    O.materials.append(m)
    O.bodies.append(polygon2d([(-2, -1), (60, -1), (60, 0), (-2, 0)], m, fixed=True))
    for j in range(4):
        for i in range(2):
            x = i + (0.5 if j % 2 else 0)
            O.bodies.append(polygon2d([(x, j * 0.5), (x + 1, j * 0.5), (x + 1, (j + 1) * 0.5), (x, (j + 1) * 0.5)], m))
    a = math.radians(30)
    O.engines = engines(gravity=(9.81 * math.sin(a), -9.81 * math.cos(a), 0), contact_damping=0.1, interval=7,
                        update_tolerance=p.get("ut", 0.0))


def build_drop():
    m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=math.radians(30), cohesion=1e5,
                tensileStrength=1e5)
    O.materials.append(m)
    O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], m, fixed=True))
    O.bodies.append(polygon2d([(-2, 0), (-1, 0), (-1, 0.5), (-2, 0.5)], m))
    a, h = math.radians(20), 0.5
    c, s = math.cos(a), math.sin(a)
    corners = [(x * c - y * s, x * s + y * c) for x, y in [(-h / 2, -h / 2), (h / 2, -h / 2), (h / 2, h / 2), (-h / 2, h / 2)]]
    low = min(y for x, y in corners)
    O.bodies.append(polygon2d([(1 + x, y - low + 0.05) for x, y in corners], m))
    O.engines = engines(gravity=(0, -9.81, 0), contact_damping=0.05, interval=7, update_tolerance=p.get("ut", 0.0))


def rbsm_phys(q):
    return (list(q.intactPoints) + list(q.slippingPoints) + list(q.openPoints) + list(q.shearTraction)
            + list(q.normalTraction) + [q.plasticDissipation])


def advance(n):
    if trace:
        return traced_steps(O, n, rbsm_phys)
    O.run(n, True)
    return []


out = {}
if mode in ("full", "save"):
    {"wall": build_wall, "drop": build_drop}[scene]()
    O.engines[2].physDispatcher.functors[0].setCohesionNow = True
    O.engines[2].loopOnSortedInteractions = sorted_loop
    O.trackEnergy = True
    O.run(n1, True)
    if mode == "save":
        O.save(p["file"])
        out["estimate"] = critical_time_step()
    else:
        out["steps"] = advance(n2)
else:
    O.load(p["file"])
    out["estimate"] = critical_time_step()
    out["steps"] = advance(n2)
ts = O.engines[3]
out.update({"bodies": body_states(O), "joints": joint_states(O), "iter": O.iter, "time": O.time, "dt": O.dt,
            "energy": dict(O.energy.items()), "stepper": [ts.lastCheck, ts.criticalDt],
            "cohesionPending": O.engines[2].physDispatcher.functors[0].setCohesionNow,
            "frozen_joints": sum(1 for i in O.interactions if i.isReal and i.geom.frozenSteps > 0)})
emit(out)
