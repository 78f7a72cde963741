"""A run stopped by the plugin on one rank: a row of 20 blocks (1 x 0.5 m) falling 1 mm onto a fixed
base, blocks 0-9 on rank 1 and 10-19 on rank 2 (the base on rank 0), plain yade.mpy (mpy.mpirun).

argv[1]: JSON {"mode": "serial" | "mpi" | "spawn", "case":
  "mixed":  block 17 (rank 2) of a plane-stress material on a plane-strain base: Ip2 reports the pair
            and stops the run after the step where they meet (Scene.stopAtIter, on rank 2 only);
  "refuse": blocks 10-19 (rank 2) 100 x stiffer, RbsmTimeStepper.setDt=False and O.dt = "dt" (5e-4 s),
            above their stable step only: the stepper refuses the step before NewtonIntegrator;
  "throw":  block 3 (rank 1) thrown down at 3 km/s: the stepper reports it (a block moving more than
            maxStepMotion in one step) and stops the run after the step;
  "user":   a user's PyRunner raises on rank 1 only (an error the plugin knows nothing about),
  "before": a value refused on rank 1 only before the run (RbsmTimeStepper.safetyFactor = 5: ValueError),
  "nosync": the engines built as before yade.mpy was imported (engines(mpi=False): no sync engine), plain
            mpy.mpirun: each rank would choose its own O.dt,
  "sync_removed", "sync_first", "sync_last": engines(mpi=True) with the sync engine taken out, moved before
            RbsmTimeStepper or after NewtonIntegrator, plain mpy.mpirun (issue 34's closing pass: all drifted),
 "steps": 100, "runner": "mpy" (mpy.mpirun) | "rbsm" (yade_rbsm.mpi.mpirun)}.
Every rank that gets to the end prints its result: rank, O.iter, O.time, the exception of the run (if
any, first 600 characters) and the wall time of the run.
"""
import json
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), "..", "..", "support"))
from yadescene import emit  # noqa: E402

p = json.loads(sys.argv[1]) if len(sys.argv) > 1 else {}
mode, case = p.get("mode", "serial"), p.get("case")
mpi = mode != "serial"
if mpi:
    from yade import mpy as mp
    if mode == "spawn":
        mp.initialize(3)
from yade_rbsm import engines, polygon2d  # noqa: E402

rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
hard = RbsmMat(young=1e10, poisson=0.2, density=2000, frictionAngle=0.5)
stress = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, planeStrain=False)
for m in (rock, hard, stress):
    O.materials.append(m)
N, w, h, gap = 20, 1.0, 0.5, 2e-3
O.bodies.append(polygon2d([(-1, -1), (N * (w + gap) + 1, -1), (N * (w + gap) + 1, 0), (-1, 0)], rock, fixed=True))
for i in range(N):
    m = rock
    if case == "refuse" and i >= N // 2:
        m = hard
    if case == "mixed" and i == N - 3:
        m = stress
    x0 = i * (w + gap)
    b = polygon2d([(x0, 1e-3), (x0 + w, 1e-3), (x0 + w, 1e-3 + h), (x0, 1e-3 + h)], m)
    b.state.vel = (0, -0.05, 0)
    if case == "throw" and i == 3:
        b.state.vel = (0, -3e3, 0)
    if mpi:
        b.subdomain = 1 if i < N // 2 else 2
    O.bodies.append(b)
O.engines = engines(contact_damping=0.3, mpi=False if case == "nosync" else None)
O.dt = 1e-4
if case in ("sync_removed", "sync_first", "sync_last") and mpi:
    sync = [e for e in O.engines if getattr(e, "label", "") == "rbsmMpiSync"][0]
    rest = [e for e in O.engines if e is not sync]
    O.engines = rest if case == "sync_removed" else ([sync] + rest if case == "sync_first" else rest + [sync])
if case == "refuse":
    O.engines[3].setDt = False
    O.dt = p.get("dt", 5e-4)
if case == "user":
    cond = "__import__('yade.mpy').mpy.rank == 1" if mpi else "True"
    O.engines = O.engines + [PyRunner(iterPeriod=1, command="if O.iter == 20 and %s: raise ValueError('a user error on one rank')" % cond)]

if case == "before" and mpi and mp.rank == 1:
    O.engines[3].safetyFactor = 5.0  # refused: the script ends here on rank 1 only

t0 = time.time()
exc = None
try:
    if not mpi and case == "refuse":  # O.run(n, True) can lose an exception of the run's first step
        from yade_rbsm import advance
        advance(p.get("steps", 100))
    elif not mpi:
        O.run(p.get("steps", 100), True)
    elif p.get("runner", "mpy") == "rbsm":
        import yade_rbsm.mpi as rmpi
        rmpi.mpirun(p.get("steps", 100))
    else:
        mp.mpirun(p.get("steps", 100))
except Exception as e:  # noqa: BLE001 - the test reads the message
    exc = str(e)[:600]
    if case in ("nosync", "sync_removed", "sync_first", "sync_last"):
        raise  # as in a user's script: the error ends the script on this rank
emit({"rank": mp.rank if mpi else 0, "iter": O.iter, "time": O.time, "exc": exc, "wall": time.time() - t0})
