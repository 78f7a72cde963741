# -*- coding: utf-8 -*-
"""What deformable blocks cost (issue 38): the same plate of Voronoi blocks, welded (deformable) or bonded
(rigid), in uniaxial compression, timed per contact-step after it has settled for a while, and the step
size each gets. Prints the time per contact-step (least of --repeats windows, the two kinds interleaved in
one process: A B A B, each built and settled for 200 steps anew), their ratio, the ratio of their steps O.dt, and so the cost of a simulated second.

    build/yade-rbsm -j1 -n -x scripts/benchmarks/deformable_cost.py [--n 400] [--steps 300] [--repeats 5]

Instructions instead of time (--callgrind KIND, KIND rigid or deformable: 100 steps of one plate counted under
`valgrind --tool=callgrind --instr-atstart=no`; the total over contacts x steps is the count per contact-step):
    YADE_PREFIX=build/yade-prefix PYTHONPATH=py:build/python valgrind --tool=callgrind --instr-atstart=no \
        /usr/bin/yade -j1 -n -x scripts/benchmarks/deformable_cost.py --callgrind deformable
"""
import os
import subprocess
import sys
import time

from yade import O

import yade_rbsm
from yade_rbsm import omega, polygon2d
from yade_rbsm.voronoi import voronoi_blocks


def arg(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


N, STEPS, REPEATS = arg("--n", 400), arg("--steps", 300), arg("--repeats", 5)


def build(deformable):
    O.reset()
    mat = RbsmMat(young=1e9, poisson=0.3, density=2000, planeStrain=False, cohesion=1e9, tensileStrength=1e9, deformable=deformable)
    platen = RbsmMat(young=1e9, poisson=0.3, density=2000, planeStrain=False, frictionAngle=0)
    O.materials.append(mat)
    O.materials.append(platen)
    for b in voronoi_blocks([(0, 0), (10, 0), (10, 10), (0, 10)], n=N, seed=1, min_distance=0.3 * 10 / N ** 0.5):
        O.bodies.append(polygon2d(b, mat))
    O.bodies.append(polygon2d([(-1, -1), (0, -1), (0, 11), (-1, 11)], platen, fixed=True))
    right = O.bodies.append(polygon2d([(10, -1), (11, -1), (11, 11), (10, 11)], platen))
    O.bodies[right].state.blockedDOFs = "yzXYZ"
    O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=0.5)
    O.engines = O.engines[:-1] + [ForceEngine(ids=[right], force=(-1e6, 0, 0)), O.engines[-1]]
    omega.ip2(O).setCohesionNow = True
    O.run(200, True)


def window(tag):
    build(tag == "deformable")  # (built anew each time: O.loadTmp refuses the ForceEngine of this scene)
    contacts = sum(1 for I in O.interactions if I.isReal)
    t0 = time.perf_counter()
    O.run(STEPS, True)
    return (time.perf_counter() - t0) / (STEPS * contacts) * 1e9, O.dt, contacts


if "--callgrind" in sys.argv:
    build(arg("--callgrind", "rigid") == "deformable")
    subprocess.run(["callgrind_control", "-i", "on", str(os.getpid())], stdout=subprocess.DEVNULL, check=True)
    O.run(100, True)  # (one full estimate of the time stepper, as in every 100 steps)
    subprocess.run(["callgrind_control", "-i", "off", str(os.getpid())], stdout=subprocess.DEVNULL, check=True)
    print("CALLGRIND_WINDOW mode %s contacts %d steps %d" % (arg("--callgrind", "rigid"), O.interactions.countReal(), 100), flush=True)
    sys.exit(0)

tags = ["rigid", "deformable"]
best = {t: (float("inf"), 0, 0) for t in tags}
for r in range(REPEATS):
    for t in tags:
        ns, dt, c = window(t)
        if ns < best[t][0]:
            best[t] = (ns, dt, c)
(rn, rdt, rc), (dn, ddt, dc) = best["rigid"], best["deformable"]
print("%d Voronoi blocks, %d steps x %d windows (-j%s):" % (N, STEPS, REPEATS, O.numThreads))
print("  rigid      %7.1f ns per contact-step, O.dt %.4g s, %d contacts" % (rn, rdt, rc))
print("  deformable %7.1f ns per contact-step, O.dt %.4g s, %d contacts (penalty %g)" % (dn, ddt, dc, O.materials[0].penalty))
print("  time per contact-step x%.2f, step size x%.3f: a simulated second costs x%.1f" % (dn / rn, ddt / rdt, (dn / rn) * (rdt / ddt)))
