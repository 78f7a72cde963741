"""YADE's idiom for a step of one's own, O.dt = x, in the middle of a run under engines() (setDt): a block
dropped 2 cm onto a fixed base, 50 steps, then the script sets O.dt (params "dt": a factor of the stepper's
step), 50 more steps, then (params "resume") RbsmTimeStepper.setDt = True and 50 more. Emits O.dt after each
stage, setDt, and whether a step was refused (its message). Before: the stepper set its own step again at the
next step, silently (a user's smaller step for accuracy was lost). params "assign": right after O.dt, "on":
RbsmTimeStepper.setDt = True (already True), "toggle": setDt = False then True (the script's choice: the
stepper sets the step again). params "reload": the scene saved (O.saveTmp) after the first 50 steps, run on
for 10 and loaded (O.loadTmp) before O.dt is set."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit  # noqa: E402
from yade_rbsm import polygon2d, engines, advance, time_stepper  # noqa: E402

p = params()
m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(m)
O.bodies.append(polygon2d([(-2, -1), (2, -1), (2, 0), (-2, 0)], m, fixed=True))
O.bodies.append(polygon2d([(0, 0.02), (1, 0.02), (1, 0.52), (0, 0.52)], m))
O.engines = engines(gravity=(0, -9.81, 0))
advance(50)
auto = O.dt
if p.get("reload"):
    O.saveTmp("script_dt")
    advance(10)
    O.loadTmp("script_dt")
O.dt = p["dt"] * auto
if p.get("assign") == "on":
    time_stepper().setDt = True
elif p.get("assign") == "toggle":
    time_stepper().setDt = False
    time_stepper().setDt = True
refused = ""
try:
    advance(50)
except RuntimeError as e:
    refused = str(e)
after = O.dt
set_dt_after = time_stepper().setDt
resumed = None
if p.get("resume") and not refused:
    time_stepper().setDt = True
    advance(50)
    resumed = O.dt
emit({"auto": auto, "after": after, "setDt": set_dt_after, "refused": refused, "resumed": resumed, "iter": O.iter})
