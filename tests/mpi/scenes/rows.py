"""Two rows of blocks (1 x 0.5 m, 2 mm gaps) dropped on a fixed base, each block with its own
horizontal velocity and spin: they land, collide with their neighbours and rotate; every joint forms
during the run (none at the start). Run as a user of yade.mpy would (YADE's testMPI_2D.py pattern):
the base on rank 0, the left half of each row on rank 1, the right half on rank 2, so that joints cross
both borders (blocks 20|21 and 60|61, the upper block astride the border, and every block with the base).

argv[1]: JSON {"mode": "serial" | "mpi" (under mpiexec) | "spawn" (mpy.initialize(3) here), "n": blocks
per row (40), "steps": 300, "vx", "vy", "w": velocity amplitudes (0.3, 0.1 m/s, 0.05 rad/s), "cd":
contact damping (0.1), "sorted": InteractionLoop.loopOnSortedInteractions, "mpy_collider": the
collider's targetInterv = 0 serially, as yade.mpy sets it when it splits a scene (fixed Verlet sweeps:
its boxes, and so the steps where the time stepper asks for a collider run, are then yade.mpy's),
"decomposition": "halves" (as above, by hand), "by_x" (yade_rbsm.mpi.decompose_by_x: the free blocks
in two slices of 40, the base on rank 0) or "bisection" (YADE's mpy.DOMAIN_DECOMPOSITION: recursive
bisection of the centroids, the base too), "interval": RbsmTimeStepper.interval (100), "serial_after":
run that many steps distributed, then merge and continue on rank 0 alone (yade_rbsm.mpi.to_serial)}.
Rank 0 writes one result (after mergeScene) to the file "out" if given (mpiexec may cut a long line
of rank 0 with the other ranks' output), else prints it: per rank the final (time, iter, dt), the O.dt of every
step, the steps where its RbsmTimeStepper asked for a collider run (Scene.doSort) and, under yade.mpy,
the steps after which yade.mpy's collider ran; the blocks' positions and rotations; the joints at the
start and at the end, and those at the end whose blocks belong to different ranks.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), "..", "..", "support"))
from yadescene import emit  # noqa: E402

p = json.loads(sys.argv[1]) if len(sys.argv) > 1 else {}
mode = p.get("mode", "serial")
mpi = mode != "serial"
if mpi:
    from yade import mpy as mp
    if mode == "spawn":
        mp.initialize(3)
from yade_rbsm import polygon2d, engines  # noqa: E402

N, steps = p.get("n", 40), p.get("steps", 300)
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, deformable=p.get("deformable", False))
O.materials.append(rock)
w, h, gap = 1.0, 0.5, p.get("gap", 2e-3)
O.bodies.append(polygon2d([(-1, -1), (N * (w + gap) + 1, -1), (N * (w + gap) + 1, 0), (-1, 0)], rock, fixed=True))
for row in range(2):
    for i in range(N):
        x0 = i * (w + gap) + (0.5 * w if row else 0) + 1e-3 * math.sin(i)
        y0 = row * (h + gap) + gap / 2
        b = polygon2d([(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)], rock)
        b.state.vel = (p.get("vx", 0.3) * math.sin(1.7 * i + row), -p.get("vy", 0.1), 0)
        b.state.angVel = (0, 0, p.get("w", 0.05) * math.cos(i))
        if mpi and p.get("decomposition", "halves") == "halves":  # (serially a subdomain other than 0 would
            b.subdomain = 1 if i < N // 2 else 2                     # freeze the block: NewtonIntegrator skips it)
        O.bodies.append(b)
# impact_safety = safety: the rows land and join across the ranks within the 300 steps (the test is about
# equal runs, not restitution; at the default 0.25 the same time takes 3.2 x the steps)
O.engines = engines(contact_damping=p.get("cd", 0.1), interval=p.get("interval", 100), impact_safety=0.8)
if p.get("sorted"):
    O.engines[2].loopOnSortedInteractions = True
if p.get("mpy_collider"):
    O.engines[1].targetInterv = 0
O.dt = 1e-4

dts, sorts, collides = [], [], []
newton = [i for i, e in enumerate(O.engines) if type(e).__name__ == "NewtonIntegrator"][0]
# before NewtonIntegrator (after the time stepper and whatever follows it): the step's O.dt and whether
# the stepper asked for a collider run; first engine: did yade.mpy's collider run after the last step
O.engines = ([PyRunner(iterPeriod=1, initRun=True, command="probeStart()")] + O.engines[:newton]
             + [PyRunner(iterPeriod=1, initRun=True, command="probeDt()")] + O.engines[newton:])
count0 = [None]


def probeStart():
    c = [e for e in O.engines if type(e).__name__ == "InsertionSortCollider"][0].execCount
    if count0[0] is not None and c != count0[0]:
        collides.append(O.iter - 1)
    count0[0] = c


def probeDt():
    dts.append(O.dt)
    if O._sceneObj.doSort:
        sorts.append(O.iter)


joints0 = sum(1 for i in O.interactions if i.isReal)
if mpi and p.get("decomposition") == "by_x":
    import yade_rbsm.mpi
    yade_rbsm.mpi.decompose_by_x()
if mpi and p.get("decomposition") == "bisection":
    mp.DOMAIN_DECOMPOSITION = True
if mpi:
    mp.mpirun(p.get("serial_after") or steps, withMerge=True)
    ranks = mp.comm.gather({"time": O.time, "iter": O.iter, "dt": O.dt, "dts": dts, "sorts": sorts, "collides": collides}, root=0)
    rank = mp.rank
    if p.get("serial_after") and rank == 0:
        import yade_rbsm.mpi
        yade_rbsm.mpi.to_serial()
        O.run(steps - p["serial_after"], True)
else:
    O.run(steps, True)
    ranks = [{"time": O.time, "iter": O.iter, "dt": O.dt, "dts": dts, "sorts": sorts, "collides": collides}]
    rank = 0
if rank == 0:
    blocks = [b for b in O.bodies if isinstance(b.shape, Polygon2D) and b.state.blockedDOFs != "xyzXYZ"]
    real = [i for i in O.interactions if i.isReal]
    result = {"ranks": ranks, "joints0": joints0, "joints": len(real),
          "across": sum(1 for i in real if O.bodies[i.id1].subdomain != O.bodies[i.id2].subdomain),
          "pos": {str(b.id): [b.state.pos[0], b.state.pos[1], b.state.ori.toAxisAngle()[1] * b.state.ori.toAxisAngle()[0][2]]
                  for b in blocks}}
    if p.get("deformable"):  # (mergeScene brings each rank's own blocks, their strains with them)
        result["strain"] = {str(b.id): list(b.state.strain) for b in blocks}
    if p.get("out"):
        with open(p["out"], "w") as f:
            json.dump(result, f)
    else:
        emit(result)
