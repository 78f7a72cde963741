"""A random pile (issue 14): n random convex polygons (3-9 vertices, aspect 1-4, sizes log-uniform over
a 100x range), random velocities and spins, dropped into a box of fixed blocks; engines() defaults, no
contact damping. Samples the energy balance (O.trackEnergy) every `every` steps and reports the largest
growth of the total energy against the work done by gravity and its drift at the end (drift), how many blocks left the box, NaNs and
the step sizes used.
params: seed, n (300), t_end (1 s), steps (cap), every, size_min (0.05), size_max (5), E (1e7), width (60), engines (kwargs),
deformable (False: rigid blocks)."""
import os, sys, math, random
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite
from yade_rbsm import polygon2d, engines

p = params()
rng = random.Random(p.get("seed", 1))
n = p.get("n", 300)
smin, smax = p.get("size_min", 0.05), p.get("size_max", 5.0)
rock = RbsmMat(young=p.get("E", 1e7), poisson=0.2, density=2500, frictionAngle=math.radians(p.get("phi", 30)), cohesion=0, tensileStrength=0)
rock.deformable = p.get("deformable", False)  # (issue 38: the same pile of deformable blocks)
if p.get("plastic"):  # (issue 39: blocks that yield, of cohesion c = plastic [Pa])
    rock.plastic, rock.cohesion = True, p["plastic"]
O.materials.append(rock)


def random_convex(size, rng):
    """A convex polygon of 3-9 vertices on an ellipse of aspect 1-4 and diameter ~size, rotated."""
    nv = rng.randint(3, 9)
    aspect = rng.uniform(1, 4)
    a, b = size / 2, size / 2 / aspect
    while True:
        angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(nv))
        # no two vertices closer than a tenth of the mean gap: no slivers of edges
        gaps = [(angles[(i + 1) % nv] - angles[i]) % (2 * math.pi) for i in range(nv)]
        if min(gaps) > 0.2 * 2 * math.pi / nv:
            break
    rot = rng.uniform(0, math.pi)
    c, s = math.cos(rot), math.sin(rot)
    return [(c * a * math.cos(t) - s * b * math.sin(t), s * a * math.cos(t) + c * b * math.sin(t)) for t in angles]


# blocks, largest first, placed on shelves (rows) above the floor without overlap
sizes = sorted((math.exp(rng.uniform(math.log(smin), math.log(smax))) for _ in range(n)), reverse=True)
W = p.get("width", 60.0)
shapes = [random_convex(s, rng) for s in sizes]
x, y, row = 0.0, 0.2, 0.0
placed = []
for poly in shapes:
    xs, ys = [v[0] for v in poly], [v[1] for v in poly]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    gap = 0.05 * max(w, h) + 0.01
    if x + w + gap > W:
        x, y, row = 0.0, y + row + 0.02, 0.0
    dx, dy = x + gap - min(xs), y + gap - min(ys)
    placed.append([(vx + dx, vy + dy) for vx, vy in poly])
    x += w + gap
    row = max(row, h + gap)
top = y + row
wall = 1.0
O.bodies.append(polygon2d([(-wall, -wall), (W + wall, -wall), (W + wall, 0), (-wall, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(-wall, 0), (0, 0), (0, top + 2), (-wall, top + 2)], rock, fixed=True))
O.bodies.append(polygon2d([(W, 0), (W + wall, 0), (W + wall, top + 2), (W, top + 2)], rock, fixed=True))
ids = []
for poly in placed:
    b = polygon2d(poly, rock)
    b.state.vel = (rng.uniform(-1, 1), rng.uniform(-1, 1), 0)
    b.state.angVel = (0, 0, rng.uniform(-3, 3))
    ids.append(O.bodies.append(b))

O.engines = engines(**p.get("engines", {}))
O.trackEnergy = True
O.step()
ts = [e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0]
m0 = sum(O.bodies[i].state.mass for i in ids)


def total():
    return O.energy.total()


t_end, max_steps, every = p.get("t_end", 1.0), p.get("steps", 10**6), p.get("every", 100)
E0 = None
worst, gw, left, finite, dts = 0.0, 0.0, 0, True, []
stopped = False
while O.time < t_end and O.iter < max_steps:
    before = O.iter
    O.run(every, True)
    stopped = O.iter - before < every  # a check stopped the run (reported on the terminal): the last sample
    if E0 is None:
        E0 = total()
    finite = finite and all_finite(O)
    if not finite:
        break
    gw = abs(O.energy['gravWork']) if 'gravWork' in O.energy.keys() else 0.0
    growth = total() - E0
    worst = max(worst, growth)
    dts.append(O.dt)
    if stopped:
        break
left = sum(1 for i in ids if not (-0.01 < O.bodies[i].state.pos[0] < W + 0.01 and O.bodies[i].state.pos[1] > -0.01 and O.bodies[i].state.pos[1] < top + 50))
vmax = max(math.hypot(O.bodies[i].state.vel[0], O.bodies[i].state.vel[1]) for i in ids) if finite else float("inf")
emit({"worst_growth": worst, "grav_work": gw, "left": left, "finite": finite, "time": O.time, "iter": O.iter,
      "first_dt": ts.firstContactDt, "crit_dt": ts.criticalDt, "dt_min": min(dts) if dts else None, "dt_max": max(dts) if dts else None, "vmax": vmax,
      "stopped": stopped, "largest_strain": max((abs(b.state.strain[0] + b.state.strain[1]) / 2 + math.hypot((b.state.strain[0] - b.state.strain[1]) / 2, b.state.strain[2] / 2)
                                                 for b in O.bodies if hasattr(b.state, "strain")), default=0.0),
      "energy": {k: O.energy[k] for k in O.energy.keys()}, "top": top, "drift": total() - E0 if E0 is not None else 0.0})
