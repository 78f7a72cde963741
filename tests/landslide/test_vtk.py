"""VTK output (yade_rbsm.vtkexport): a yade script writes two snapshots of a 3-block scene; the files
are read back with VTK's own reader (vtkXMLPolyDataReader) and compared with the scene's values the
script printed: numbers of cells, vertex coordinates, displacement/velocity point and cell data,
contact forces and states, and the .pvd collection (times, file names)."""
import json
import math
import os
import xml.etree.ElementTree as ET

import pytest

from conftest import HERE, run_yade

vtk = pytest.importorskip("vtkmodules.vtkIOXML")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("vtk")
    p = run_yade(os.path.join(HERE, "vtk_blocks.py"), str(out), cwd=str(out))
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    exp = json.loads([l for l in p.stdout.splitlines() if l.startswith("EXPECT ")][0][7:])
    return out, exp


def _read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    pd = r.GetOutput()
    assert pd.GetNumberOfCells() > 0, path
    return pd


def _cell(pd, name):
    a = pd.GetCellData().GetArray(name)
    assert a is not None, "cell array %s missing" % name
    return vtk_to_numpy(a)


def test_pvd_collections(run):
    out, exp = run
    for kind in ("blocks", "contacts"):
        root = ET.parse(out / ("t_%s.pvd" % kind)).getroot()
        assert root.get("type") == "Collection"
        ds = root.find("Collection").findall("DataSet")
        assert [d.get("file") for d in ds] == ["t_%s_0000.vtp" % kind, "t_%s_0001.vtp" % kind]
        times = [float(d.get("timestep")) for d in ds]
        assert times == pytest.approx([e["time"] for e in exp], rel=1e-12) and times[0] < times[1]
        for d in ds:
            assert (out / d.get("file")).is_file()


@pytest.mark.parametrize("snap", [0, 1])
def test_blocks(run, snap):
    out, exp = run
    exp = exp[snap]
    pd = _read(out / ("t_blocks_%04d.vtp" % snap))
    assert pd.GetNumberOfPolys() == pd.GetNumberOfCells() == exp["n_blocks"]
    ids = list(_cell(pd, "id"))
    assert sorted(ids) == [0, 1, 2]
    k = ids.index(2)
    assert _cell(pd, "fixed")[ids.index(0)] == 1 and _cell(pd, "fixed")[k] == 0
    cell = pd.GetCell(k)
    assert cell.GetNumberOfPoints() == 5  # the pentagon
    pts = [pd.GetPoint(cell.GetPointId(j))[:2] for j in range(5)]
    for p, q in zip(pts, exp["vertices2"]):
        assert p == pytest.approx(q, abs=1e-12)
    d = _cell(pd, "displacement")[k]
    assert d[:2] == pytest.approx(exp["disp2"], rel=1e-9, abs=1e-15)
    assert math.hypot(*exp["disp2"]) > (1e-3 if snap else 1e-5)  # the kick moved it: a real value is compared
    if snap == 0:  # still moving: a real velocity is compared
        assert math.hypot(*exp["vel2"]) > 0.1 and abs(exp["angvel2"]) > 0.01
    assert _cell(pd, "displacementMagnitude")[k] == pytest.approx(math.hypot(*exp["disp2"]), rel=1e-9)
    assert _cell(pd, "velocity")[k][:2] == pytest.approx(exp["vel2"], rel=1e-9, abs=1e-15)
    assert _cell(pd, "angularVelocity")[k] == pytest.approx(exp["angvel2"], rel=1e-9, abs=1e-15)
    # point data: rigid-body velocity field v + w x r at each vertex
    pv = vtk_to_numpy(pd.GetPointData().GetArray("velocity"))
    pdisp = vtk_to_numpy(pd.GetPointData().GetArray("displacement"))
    assert pv.shape == pdisp.shape == (pd.GetNumberOfPoints(), 3)
    pid = vtk_to_numpy(pd.GetPointData().GetArray("id"))
    assert all(pid[cell.GetPointId(j)] == 2 for j in range(5))
    c = _centroid(exp["vertices2"])
    for j in range(5):
        r = (pts[j][0] - c[0], pts[j][1] - c[1])
        v = pv[cell.GetPointId(j)]
        assert v[0] == pytest.approx(exp["vel2"][0] - exp["angvel2"] * r[1], rel=1e-6, abs=1e-9)
        assert v[1] == pytest.approx(exp["vel2"][1] + exp["angvel2"] * r[0], rel=1e-6, abs=1e-9)
    # the fixed base: zero displacement at its vertices
    base = pd.GetCell(ids.index(0))
    for j in range(base.GetNumberOfPoints()):
        assert list(pdisp[base.GetPointId(j)]) == [0.0, 0.0, 0.0]


def _centroid(poly):
    a = cx = cy = 0.0
    for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
        c = x0 * y1 - x1 * y0
        a += c
        cx += c * (x0 + x1)
        cy += c * (y0 + y1)
    return cx / (3 * a), cy / (3 * a)


@pytest.mark.parametrize("snap", [0, 1])
def test_contacts(run, snap):
    out, exp = run
    exp = exp[snap]
    pd = _read(out / ("t_contacts_%04d.vtp" % snap))
    assert pd.GetNumberOfLines() == pd.GetNumberOfCells() == exp["n_contacts"] == len(exp["contacts"])
    id1, id2 = _cell(pd, "id1"), _cell(pd, "id2")
    fn, fs = _cell(pd, "normalForce"), _cell(pd, "shearForce")
    ns, no, st = _cell(pd, "nSlipping"), _cell(pd, "nOpen"), _cell(pd, "state")
    for k in range(pd.GetNumberOfCells()):
        e = exp["contacts"]["%d-%d" % (id1[k], id2[k])]
        assert fn[k] == pytest.approx(e[0], rel=1e-12, abs=1e-9)
        assert fs[k] == pytest.approx(e[1], rel=1e-12, abs=1e-9)
        assert (ns[k], no[k]) == (e[2], e[3])
        assert st[k] == (2 if e[3] > 0 else 1 if e[2] > 0 else 0)
        cell = pd.GetCell(k)
        assert cell.GetNumberOfPoints() == 2
        assert pd.GetPoint(cell.GetPointId(0))[:2] == pytest.approx(e[4][:2], abs=1e-12)
        assert pd.GetPoint(cell.GetPointId(1))[:2] == pytest.approx(e[5][:2], abs=1e-12)
    # the base carries the weight of both blocks: normal force of joint 0-1 is > 0 (compression)
    k01 = [k for k in range(len(id1)) if (id1[k], id2[k]) in ((0, 1), (1, 0))][0]
    assert fn[k01] > 0
    f = _cell(pd, "force")
    assert math.hypot(f[k01][0], f[k01][1]) == pytest.approx(math.hypot(fn[k01], fs[k01]), rel=1e-9)
