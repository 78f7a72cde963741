"""slope.set_earthquake as a user drives it (issue 40): the record shakes through NewtonIntegrator's gravity at
every step (a sine of 0.5 g at 1 Hz: gravity.x = -a_g at mid-step), a refused record leaves the one shaking in
place, a scene saved mid-record goes on shaking after O.load in another process, and set_earthquake(None) gives
the static gravity back and removes the engine. On 7c3ff2e set_earthquake(None) raised AttributeError
(__delitem__: YADE's tags cannot be deleted) and a refused record had already removed the engine."""
import math

import pytest

from yaderun import BLOCK_ON_BASE, run_ok

SHAKE = BLOCK_ON_BASE % dict(FRICTION=0.3) + r"""
from yade_rbsm import earthquake, slope
slope.set_earthquake(earthquake.Record.sine(0.5, 1.0, 2.0), direction=1)
O.run(300, True)
t, gx = O.time, O.engines[-1].gravity[0]
refused = ""
try:
    slope.set_earthquake("kobe.csv")
except ValueError as e:
    refused = str(e)
engines_after_refusal = [e.label for e in O.engines if e.label == "earthquake"]
O.save("shaking.yade.gz")
report(t=t, dt=O.dt, gx=gx, refused=refused, kept=engines_after_refusal)
"""

LOAD = r"""
from yade_rbsm import slope
O.load("shaking.yade.gz")
O.run(10, True)
t, dt, gx = O.time, O.dt, O.engines[-1].gravity[0]
slope.set_earthquake(None)
O.run(5, True)
report(t=t, dt=dt, gx=gx, after=list(O.engines[-1].gravity), labels=[e.label for e in O.engines])
"""


def test_set_earthquake_shakes_is_kept_and_stops(tmp_path):
    (a,) = run_ok(SHAKE, workdir=str(tmp_path))
    # the last step's gravity: -0.5 g sin(2 pi f t) at the middle of the step that ended at t
    assert a["gx"] == pytest.approx(-0.5 * 9.81 * math.sin(2 * math.pi * (a["t"] - 0.5 * a["dt"])), rel=1e-3, abs=1e-6), a
    assert "give a yade_rbsm.earthquake.Record" in a["refused"] and a["kept"] == ["earthquake"], a
    (b,) = run_ok(LOAD, workdir=str(tmp_path))
    assert b["gx"] == pytest.approx(-0.5 * 9.81 * math.sin(2 * math.pi * (b["t"] - 0.5 * b["dt"])), rel=1e-3, abs=1e-6), b
    assert b["after"] == [0.0, -9.81, 0.0] and "earthquake" not in b["labels"], b
