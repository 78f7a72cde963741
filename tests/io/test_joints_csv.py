"""Joints' state to CSV (yade_rbsm.io.export_joints): every real joint once, with the values of its
RbsmGeom/RbsmPhys; per integration point, tractions that add up to the joint's forces."""
import csv
import io as _io

import pytest
from conftest import SCENE
from yaderun import run_ok

SCRIPT = SCENE + r"""
import yade_rbsm.io as io
O.engines[2].physDispatcher.functors[0].setCohesionNow = True   # bonded joints: some points stay intact
O.run(300, True)
n = io.export_joints("joints.csv")
io.export_joints("points.csv", points=True)
joints = {}
for I in O.interactions:
    if I.isReal:
        g, ph = I.geom, I.phys
        joints["%d-%d" % (I.id1, I.id2)] = dict(normalForce=ph.normalForce, shearForce=ph.shearForce,
            strength=ph.strength, length=g.length, p0x=g.p0[0], d1=g.d1, kn=ph.kn, nIntact=ph.nIntact,
            nSlipping=ph.nSlipping, nOpen=ph.nOpen, thickness=g.thickness)
report(n=n, joints=joints, iter=O.iter, time=O.time, text=open("joints.csv").read(), points=open("points.csv").read())
"""


@pytest.fixture(scope="module")
def result():
    (r,) = run_ok(SCRIPT)
    return r


def rows(text):
    lines = text.splitlines()
    return lines[0], list(csv.DictReader(_io.StringIO("\n".join(lines[1:]))))


def test_one_row_per_joint_with_its_values(result):
    comment, table = rows(result["text"])
    assert comment == "# yade-rbsm joints 1, iter=%d time=%r" % (result["iter"], result["time"])
    joints = result["joints"]
    assert result["n"] == len(table) == len(joints) >= 2
    for row in table:
        ref = joints["%s-%s" % (row["id1"], row["id2"])]
        for k in ("normalForce", "shearForce", "strength", "length", "p0x", "d1", "kn"):
            assert float(row[k]) == ref[k], k  # repr(): exact
        for k in ("nIntact", "nSlipping", "nOpen"):
            assert int(row[k]) == ref[k]
        state = 2 if ref["nOpen"] else (1 if ref["nSlipping"] else 0)
        assert int(row["state"]) == state
    assert any(float(r["normalForce"]) > 0 for r in table)
    assert any(int(r["nIntact"]) > 0 for r in table)


def test_points_add_up_to_the_joint_forces(result):
    _, table = rows(result["points"])
    by_joint = {}
    for row in table:
        by_joint.setdefault("%s-%s" % (row["id1"], row["id2"]), []).append(row)
    assert set(by_joint) == set(result["joints"])
    for key, pts in by_joint.items():
        ref = result["joints"][key]
        area = ref["length"] * ref["thickness"]
        assert [int(p["k"]) for p in pts] == list(range(len(pts)))
        n = sum(float(p["normalTraction"]) * float(p["weight"]) * area for p in pts)
        s = sum(float(p["shearTraction"]) * float(p["weight"]) * area for p in pts)
        assert n == pytest.approx(ref["normalForce"], rel=1e-12, abs=1e-9 * (1 + abs(ref["normalForce"])))
        assert s == pytest.approx(ref["shearForce"], rel=1e-12, abs=1e-9 * (1 + abs(ref["normalForce"])))
        assert sum(int(p["intact"]) for p in pts) == ref["nIntact"]
