"""Issue 34, item 13: O.dt = -1 (YADE's "let the time stepper set the step") said "No TimeStepper found in
O.engines" with RbsmTimeStepper there, and left O.dt as it was (measured on 7088a3b). With yade_rbsm imported it
turns RbsmTimeStepper.setDt on: from the next step O.dt is the stepper's (safety x critical). A list without
RbsmTimeStepper keeps YADE's own error."""
from yaderun import results, run_yade

SCENE = """
from yade_rbsm import polygon2d, engines, critical_time_step
mat = RbsmMat(young=1e8, density=2000)
O.materials.append(mat)
O.bodies.append(polygon2d([(-2, -1), (2, -1), (2, 0), (-2, 0)], mat, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat))
O.engines = engines(set_dt=False)
O.dt = 1e-6
err = None
try:
    O.dt = -1
except Exception as e:
    err = str(e)
O.run(10, True)
out = dict(err=err, dt=O.dt, critical=critical_time_step(), setDt=O.engines[3].setDt)
O.engines = [ForceResetter(), NewtonIntegrator()]
try:
    O.dt = -1
    out["bare"] = None
except Exception as e:
    out["bare"] = str(e)
report(**out)
"""


def test_negative_dt_lets_the_rbsm_stepper_set_the_step():
    p = run_yade(SCENE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    print(r)
    assert r["err"] is None and r["setDt"] is True
    assert 0.2 * r["critical"] < r["dt"] <= 0.8 * r["critical"] * (1 + 1e-9), r  # the stepper's, not 1e-6
    assert "No TimeStepper found" in r["bare"]  # YADE's own, without RbsmTimeStepper


NOT_A_STEP = """
from yade_rbsm import polygon2d, engines
mat = RbsmMat(young=1e8, density=2000)
O.materials.append(mat)
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat))
O.engines = engines(set_dt=False)
O.dt = 1e-6
out = {}
for key, v in (("nan", float("nan")), ("inf", float("inf")), ("none", None), ("text", "1e-3")):
    try:
        O.dt = v
        out[key] = "accepted %r" % O.dt
    except Exception as e:
        out[key] = "%s: %s" % (type(e).__name__, e)
out["dt"] = O.dt
report(**out)
"""


def test_dt_that_is_not_a_step_is_refused():
    """The closing adversarial pass (issue 34): O.dt = NaN was accepted (positions and O.time NaN after 300 steps,
    no message) and O.dt = None said "'<' not supported between instances of 'NoneType' and 'int'". Both, inf and
    a string are refused naming O.dt, and O.dt stays as it was."""
    p = run_yade(NOT_A_STEP)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    print(r)
    for key in ("nan", "inf", "none", "text"):
        assert r[key].startswith("ValueError") and "O.dt" in r[key], r
    assert r["dt"] == 1e-6
