"""Energy of undamped deformable blocks (issue 38): a plate of Voronoi blocks (welded, as built) given random
velocities, spins and strain rates floats freely without gravity or damping; O.energy's total (kinetic, the
strain modes' kinetic energy, the joints' springs, the blocks' strain energy) must stay constant.
With plastic blocks (param plastic = [c, φ, ψ]) their yield is in plastDissip and the balance still closes.
Params: n, seed, steps, plastic, weldYields, save (a path: save half-way, load and go on, compare with the uninterrupted run)."""
import os, sys, random
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
import yade_rbsm
from yade_rbsm import polygon2d, omega
from yade_rbsm.voronoi import voronoi_blocks

p = params()
rng = random.Random(p.get("seed", 1))
mat = RbsmMat(young=1e8, poisson=p.get("nu", 0.25), density=2000, planeStrain=True, deformable=p.get("deformable", True), cohesion=1e9, tensileStrength=1e9)
if "plastic" in p:  # yielding blocks (issue 39; the welded joints use no strength unless weldYields): c, φ, ψ = plastic
    mat.plastic, mat.cohesion, mat.frictionAngle, mat.dilatancy = True, p["plastic"][0], p["plastic"][1], p["plastic"][2]
    mat.weldYields = p.get("weldYields", False)  # and the welds slip at the same strength
O.materials.append(mat)
size = p.get("size", 4.0)
ids = [O.bodies.append(polygon2d(b, mat)) for b in voronoi_blocks([(0, 0), (size, 0), (size, size), (0, size)], n=p.get("n", 30), seed=p.get("seed", 1))]
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=0, safety=p.get("safety", 0.8), impact_safety=p.get("safety", 0.8),
                              contact_damping=p.get("contact_damping", 0.0))
omega.ip2(O).setCohesionNow = True
O.trackEnergy = True
O.step()  # the joints are made (welded) at rest
v = p.get("v", 0.05)
for i in ids:
    s = O.bodies[i].state
    s.vel = (rng.uniform(-v, v), rng.uniform(-v, v), 0)
    s.angVel = (0, 0, rng.uniform(-v, v) / size)
    if p.get("deformable", True):
        s.strainRate = tuple(rng.uniform(-v, v) / size for _ in range(3))


def total():
    return sum(O.energy[k] for k in O.energy.keys() if k in ("kinetic", "strainKinetic", "elastPotential", "strainElastic", "viscDamp", "plastDissip"))


def snapshot():
    return [tuple(O.bodies[i].state.pos) + (tuple(O.bodies[i].state.strain) if p.get("deformable", True) else ()) for i in ids]


O.step()
e0 = total()
steps = p.get("steps", 4000)
worst, history = 0.0, []
save = p.get("save")
for k in range(steps):
    if save and k == steps // 2:
        O.save(save)
        O.load(save)
    O.step()
    history.append(total())
    worst = max(worst, abs(history[-1] - e0) / e0)
window = max(1, steps // 10)  # the leapfrog's oscillation averages out over a window: what is left is drift
drift = (sum(history[-window:]) - sum(history[:window])) / window / e0
energies = {k: O.energy[k] for k in O.energy.keys()}
emit({"e0": e0, "worst": worst, "drift": drift, "energies": energies, "dt": O.dt, "welded": sum(1 for I in O.interactions if I.isReal and I.phys.welded),
      "state": snapshot(), "strain_energy": O.energy["strainElastic"] if p.get("deformable", True) else 0})
