"""Blocks in open water (issue 40: "a block on an inclined joint submerged to half its height"), on
submerged_block.py: slope.set_water(..., open_water=True) puts the still water's pressure on the blocks' whole
boundary below the water table (OpenWaterPressure), not only in their joints (the law's joint water):
- a 2 x 1 m block of 500 kg/m3 floats at Archimedes' draft of 0.5 m (within 0.1 %), and its undamped heave keeps
  O.energy's balance (kinetic, gravWork, waterWork) within 0.5 % of the heave's energy;
- a 2 x 1 m block on a plane at 35 deg (c 5 kPa, phi 30 deg) submerged to half its height: strength reduction
  gives the closed form (c L + (W - B) cos psi tan phi) / ((W - B) sin psi) with the buoyancy B within 0.5 %;
  the same block with water in its base joint only (the default, UDEC's joint water) is far from it.
Fails on 270f63f: set_water had no open_water (only joints took water: 1.063 against 1.417)."""
import json

import pytest

from conftest import run_yade
from verification import record


def result(*args):
    p = run_yade("submerged_block.py", *args)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][-1][7:])


def test_a_block_floats_at_archimedes_draft():
    r = result("float")
    print("draft %.5f m (Archimedes %.5f); heave %.4g J, balance off by %.3g J" % (r["draft"], r["closed"], r["heave_peak"],
                                                                                r["heave_drift"]))
    record("Water", "a 2 × 1 m block of 500 kg/m³ floating in open water: draft", r["draft"], r["closed"], "Archimedes",
           rtol=1e-3, unit="m")
    assert r["draft"] == pytest.approx(r["closed"], rel=1e-3)
    assert "OpenWaterPressure" in r["engines"] and r["engines"][-1] == "NewtonIntegrator"
    assert r["heave_drift"] < 0.005 * r["heave_peak"], r
    assert "open_water must be True or False" in r["refused"]
    assert "OpenWaterPressure" not in r["after_none"] and r["law_open"] is False  # set_water(None): no water left


def test_half_submerged_block_on_a_plane_is_the_closed_form():
    r = result("plane", "open")
    print("open water: FS %.4f against %.4f (dry %.4f)" % (r["fs"], r["closed"], r["dry"]))
    record("Water", "2 × 1 m block on a 35° plane (c 5 kPa, φ 30°) submerged to half its height: FS by strength reduction",
           r["fs"], r["closed"], "(cL + (W − B) cos ψ tan φ) / ((W − B) sin ψ)", rtol=0.005)
    assert r["settled"] and not r["warnings"], r
    assert r["fs"] == pytest.approx(r["closed"], rel=0.005)
    joints = result("plane", "joints")
    print("water in the joint only: FS %.4f" % joints["fs"])
    assert joints["fs"] < 0.9 * r["closed"]  # the uplift without the water on the faces: not a submerged block
