"""A block thrown onto a fixed floor with contact damping (issue 35: the energy balance of damped impacts).
No gravity; the block (density 2000, joint kn = ks = 1e9 Pa/m, phi) hits the floor at v0 = 3 m/s down and
vt along it. shape 'flat' (a 0.2 x 0.1 block face down), 'corner' (a square on a vertex, spinning) or
'random' (a random convex polygon of size 0.02-2 m, random spin and velocity, seed); contact damping ratio
xi; engines() defaults but impact_safety (param impact, default 0.25). Runs until the block has left the floor or come to
rest, then returns the energy balance: drift = O.energy.total() after - after the first step, against the
initial kinetic energy, the rebound speed ratio and each O.energy term."""
import math, os, random, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, kinetic_energy
from yade_rbsm import polygon2d, engines

p = params()
xi, shape, seed = p.get("xi", 0.3), p.get("shape", "flat"), p.get("seed", 1)
mat = RbsmMat(young=1e9, poisson=0.0, density=2000, frictionAngle=math.radians(p.get("phi", 30)), jointKn=1e9, jointKs=1e9)
O.materials.append(mat)
O.bodies.append(polygon2d([(-50, -1), (50, -1), (50, 0), (-50, 0)], mat, fixed=True))
rng = random.Random(seed)
if shape == "flat":
    verts, spin, vt = [(0, 0), (0.2, 0), (0.2, 0.1), (0, 0.1)], 0.0, p.get("vt", 0.0)
elif shape == "corner":
    a = math.radians(p.get("tilt", 20))  # a 0.2 m square on its corner, tilted so that it turns as it lands
    sq = [(0, 0), (0.2, 0), (0.2, 0.2), (0, 0.2)]
    verts, spin, vt = [(x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)) for x, y in sq], 2.0, p.get("vt", 1.0)
else:  # random convex polygon: sorted angles on an ellipse, 0.02 to 2 m
    size = 0.02 * 100 ** rng.random()
    n = rng.randint(3, 9)
    ang = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    ax, ay = size * rng.uniform(0.3, 1), size * rng.uniform(0.3, 1)
    verts = [(ax * math.cos(t), ay * math.sin(t)) for t in ang]
    spin, vt = rng.uniform(-5, 5) / size, rng.uniform(-2, 2)
lift = 1e-6 - min(y for _, y in verts)  # just above the floor
b = O.bodies[O.bodies.append(polygon2d([(x, y + lift) for x, y in verts], mat))]
b.state.vel = Vector3(vt, -p.get("v0", 3.0), 0)
b.state.angVel = Vector3(0, 0, spin)
O.engines = engines(gravity=(0, 0, 0), contact_damping=xi, impact_safety=p.get("impact", 0.25))
O.trackEnergy = True
E_kin = kinetic_energy(O)
O.step()
E0 = O.energy.total()
touched = False
while O.time < p.get("time", 0.2):
    O.step()
    contact = any(I.isReal for I in O.interactions)
    touched |= contact
    if touched and not contact and b.state.vel[1] > 0:
        break
    if touched and kinetic_energy(O) < 1e-9 * E_kin:
        break
emit({"drift": O.energy.total() - E0, "E_kin": E_kin, "touched": touched, "rebound": b.state.vel[1] / p.get("v0", 3.0),
      "energy": {k: O.energy[k] for k in O.energy.keys()}, "steps": O.iter, "size": max(math.hypot(x, y) for x, y in verts)})
