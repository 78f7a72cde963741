"""Generic robustness scene: builds the blocks and materials of the JSON parameters, runs them with
yade_rbsm.engines and reports energy, penetration, finiteness and the final state.

Parameters (all optional except blocks):
  materials: list of RbsmMat keyword dicts (default one: E = 1e8, ν = 0.2, ρ = 2000, φ = 30°)
  blocks:    list of {"v": [[x, y], ...] (world, CCW), "mat": index, "fixed": bool, "vel": [vx, vy], "w": ω, "t": thickness}
  gravity:   [gx, gy] (default [0, -9.81]);  contact_damping ξ (0), damping (Newton, 0), nIP (2),
  safety (0.8), set_dt (True), interval (100), enlarge (0), bond (False: joints at step 0 bonded if True),
  dt (sets O.dt, for set_dt False), steps (1000), check_every (10): penetration and finiteness every k steps,
  energy_every (0: off): leapfrog energy (see _common.measured_step) every k steps.
Result: dt, est (RbsmTimeStepper.estimate() at the end), n_inter, max_pen_rel, max_pen, finite, energy
(list of [step, E]), escale (initial kinetic energy + Σ weight × size of the free blocks), ke_end, max_ke, bodies (final), error (exception text of a run that stopped, or None),
steps_done, max_force."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import (params, emit, all_finite, max_penetration, measured_step, kinetic_energy, body_states,
                     free)
from yade_rbsm import polygon2d, engines

p = params()
mats = []
for kw in p.get("materials", [{}]):
    d = dict(young=1e8, poisson=0.2, density=2000, frictionAngle=math.radians(30))
    d.update(kw)
    m = RbsmMat(**d)
    O.materials.append(m)
    mats.append(m)
for b in p["blocks"]:
    i = O.bodies.append(polygon2d(b["v"], mats[b.get("mat", 0)], thickness=b.get("t", 1.0), fixed=b.get("fixed", False)))
    O.bodies[i].state.vel = tuple(b.get("vel", [0, 0])) + (0,)
    O.bodies[i].state.angVel = (0, 0, b.get("w", 0))
g = p.get("gravity", [0, -9.81])
O.engines = engines(gravity=(g[0], g[1], 0), damping=p.get("damping", 0.0), contact_damping=p.get("contact_damping", 0.0),
                    nIP=p.get("nIP", 2), safety=p.get("safety", 0.8), set_dt=p.get("set_dt", True),
                    interval=p.get("interval", 100), enlarge=p.get("enlarge", 0.0))
if p.get("bond"):
    ip2.setCohesionNow = True
if "dt" in p:
    O.dt = p["dt"]
O.trackEnergy = True
from _common import block_size
# energy scale: initial kinetic energy + weight × size of every free block (a drop by one block size)
escale = kinetic_energy(O) + sum(b.state.mass * math.hypot(*g) * block_size(b) for b in O.bodies if free(b))
steps, ce, ee = p.get("steps", 1000), p.get("check_every", 10), p.get("energy_every", 0)
res = {"max_pen_rel": 0.0, "max_pen": 0.0, "finite": True, "energy": [], "max_ke": 0.0, "error": None}
k = 0
try:
    while k < steps:
        if ee and k % ee == 0:
            res["energy"].append([k, measured_step(O, g)])
        else:
            O.step()
        k += 1
        if k % ce == 0 or k == steps:
            rel, ab = max_penetration(O)
            res["max_pen_rel"] = max(res["max_pen_rel"], rel)
            res["max_pen"] = max(res["max_pen"], ab)
            res["max_ke"] = max(res["max_ke"], kinetic_energy(O))
            if not all_finite(O):
                res["finite"] = False
                break
except Exception as e:  # noqa: BLE001 - reported to the test
    res["error"] = "%s: %s" % (type(e).__name__, e)
res["steps_done"] = k
res["escale"] = escale
res["dt"] = O.dt
res["est"] = RbsmTimeStepper().estimate()
res["n_inter"] = sum(1 for i in O.interactions if i.isReal)
res["ke_end"] = kinetic_energy(O)
res["bodies"] = body_states(O)
res["max_force"] = max(O.forces.f(b.id).norm() for b in O.bodies)
res["weight"] = sum(b.state.mass for b in O.bodies if free(b)) * math.hypot(*g)
emit(res)
