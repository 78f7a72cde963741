# yade script (run by test_density_scaling.py): a 10 m high Voronoi slope (1 m blocks, about 300, c' = 20 kPa,
# phi' = 30 deg, bonded) settled under gravity with settle(tol=1e-4) twice, without and with
# density_scaling; prints RESULT <json> with the steps, the time steps, the scaled blocks and the largest
# difference of the settled positions.
import json, math
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import slope as sl

surface = [(0, 5), (10, 5), (20, 15), (30, 15)]


def settled(density_scaling):
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=100e6, poisson=0.3, density=2000, frictionAngle=math.radians(30), cohesion=20e3,
                          tensileStrength=20e3 / math.tan(math.radians(30)))
    O.materials.append(mat)
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=1.0, seed=1, min_distance=0.5)
    sl.build_scene(sb, mat)
    O.engines = yr.engines(set_dt=True, enlarge=0.01)
    O.dt = 1e-6
    sl.bond_and_break(sb)
    ts = yr.time_stepper()
    dts = []
    ok, steps, ratio = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=density_scaling,
                                 progress=lambda s, r: dts.append(O.dt))
    out = dict(ok=ok, steps=steps, ratio=ratio, dt=max(dts), scaled=sum(1 for s in ts.massScale if s > 1),
               smax=max(ts.massScale) if len(ts.massScale) else 1.0, restored=ts.densityScaling,
               pos=[tuple(O.bodies[b.id].state.pos)[:2] for b in sb.free])
    yr.advance(1)  # off again: the scales go at the next step
    out["after_off"] = len(ts.massScale)
    return out


plain, scaled = settled(False), settled(True)
d = max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(plain["pos"], scaled["pos"]))
for r in (plain, scaled):
    del r["pos"]
print("RESULT " + json.dumps(dict(plain=plain, scaled=scaled, dmax=d)))
