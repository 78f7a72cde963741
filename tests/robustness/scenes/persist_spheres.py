"""Save / load / continue with YADE's own spheres, the reference for the RBSM scene persist.py
(tests/robustness/test_persistence.py): 150 spheres (radius 4-5 cm, FrictMat E = 10 MPa, φ = 30°) in a
loose 5 × 5 × 6 column next to a wall, on a floor, under gravity tilted towards the wall: the column
collapses into a pile that keeps moving (no damping). Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, InsertionSortCollider (automatic
verletDist), O.dt = 0.3 × PWaveTimeStep().
Parameters as persist.py: mode ('full', 'save', 'load'), n1, n2, file, sorted (loopOnSortedInteractions),
trace (per-step records of the n2 steps). Returns O.iter and, with trace, the records."""
import os, sys, math, random
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, traced_steps
from yade import utils

p = params()
mode, n1, n2 = p.get("mode", "full"), p.get("n1", 2000), p.get("n2", 300)


def frict_phys(q):
    return [q.normalForce[i] for i in range(3)] + [q.shearForce[i] for i in range(3)]


out = {}
if mode in ("full", "save"):
    m = O.materials.append(FrictMat(young=1e7, poisson=0.3, frictionAngle=math.radians(30), density=2600))
    O.bodies.append(utils.wall((0, 0, 0), 2, material=m))  # floor z = 0
    O.bodies.append(utils.wall((0, 0, 0), 0, material=m))  # wall x = 0
    rnd = random.Random(1)
    for k in range(150):
        O.bodies.append(utils.sphere((0.05 + 0.1 * (k % 5) + 0.01 * rnd.random(), 0.05 + 0.1 * ((k // 5) % 5),
                                      0.05 + 0.1 * (k // 25) + 0.01 * rnd.random()), 0.04 + 0.01 * rnd.random(), material=m))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()], loopOnSortedInteractions=p.get("sorted", False)),
                 NewtonIntegrator(gravity=(-4.9, 0, -8.5), damping=0.0)]
    O.dt = 0.3 * PWaveTimeStep()
    O.run(n1, True)
    if mode == "save":
        O.save(p["file"])
    else:
        out["steps"] = traced_steps(O, n2, frict_phys) if p.get("trace") else O.run(n2, True)
else:
    O.load(p["file"])
    out["steps"] = traced_steps(O, n2, frict_phys) if p.get("trace") else O.run(n2, True)
out["iter"] = O.iter
out["contacts"] = sum(1 for i in O.interactions if i.isReal)
emit(out)
