# Share of RbsmTimeStepper (and the collider) in a step of the settled brick wall of scripts/benchmark_contacts.py.
# build/yade-rbsm -j1 -n -x scripts/benchmarks/stepper_share.py .   (the argument: the source tree)
import sys, os
sys.path.insert(0, os.path.join(sys.argv[1], "scripts"))
from benchmark_contacts import build_wall, measure
build_wall()
r = measure("rbsm")
print("BENCH step_ms=%.3f us_cs=%.3f contacts=%d stepper=%.2f%% collider=%.2f%% newton=%.2f%% dt=%.3e" % (r["step_ms"], r["us_cs"], r["contacts"], 100*r["share"].get("RbsmTimeStepper",0), 100*r["share"].get("InsertionSortCollider",0), 100*r["share"].get("NewtonIntegrator",0), r["dt"]))
