"""Joint stiffness given per material (RbsmMat.jointKn / jointKs, issue 21), Pa/m as a joint set's kn, ks.

* Values: a joint takes the given stiffness (the smaller of two given, the one given if only one is),
  and so does a block's joint with a Wall.
* Closed form: a 2 x 1 m block (t = 0.5 m) at rest on a base settles by W / (kn L t) within 0.5 %.
* Stability: with kn and ks 100 x Kawai's, RbsmTimeStepper's first-contact bound is about 10 x smaller
  (sqrt(100)), and a block dropped 0.2 m lands and rebounds below its drop height, with no motion report.
* Bad input: negative or NaN values are refused naming the attribute (tests/physics/test_bad_input.py style)."""
import math

import pytest

from conftest import run_scene
from verification import record


def test_joint_takes_the_given_stiffness():
    r = run_scene("joint_stiffness", {"mode": "values"})
    assert r["a_a"] == [5e9, 2e9]
    assert r["b_a"] == [3e9, 2e9]
    assert r["kawai_a"] == [5e9, 2e9]
    assert r["wall"] == [5e9, 2e9]


def test_block_settles_by_the_closed_form():
    r = run_scene("joint_stiffness", {"mode": "settle", "kn": 2e9, "thickness": 0.5})
    assert r["kn"] == 2e9 and r["length"] == pytest.approx(2.0, rel=1e-9)
    record("Blocks and joints", "a block resting on a joint of given kn: overlap", r["overlap"], r["weight"] / (2e9 * 2.0 * 0.5),
           "W / (kn L t)", rtol=5e-3, unit="m")
    assert r["overlap"] == pytest.approx(r["weight"] / (2e9 * 2.0 * 0.5), rel=5e-3)


def test_stiff_given_joints_keep_the_step_stable():
    r = run_scene("joint_stiffness", {"mode": "drop"})
    k, g = r["kawai"], r["given"]
    assert k["err"] == "" and g["err"] == "", (k["err"], g["err"])
    assert k["landed"] and g["landed"]
    assert g["first"] == pytest.approx(k["first"] / 10, rel=0.15)
    assert g["top"] < 0.7 and k["top"] < 0.7  # dropped from y = 0.7 (centroid); nothing gains energy
    assert abs(g["y"] - 0.5) < 1e-3


@pytest.mark.parametrize("attr,value", [("jointKn", -1.0), ("jointKs", float("nan"))])
def test_bad_joint_stiffness_is_refused(attr, value):
    # constructor, assignment and updateAttrs must all refuse it
    r = run_scene("joint_stiffness_bad", {"attr": attr, "value": value})
    for how in ("ctor", "assign", "updateAttrs"):
        assert attr in r[how] and ("finite" in r[how] or ">= 0" in r[how]), r
