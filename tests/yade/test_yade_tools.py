"""YADE's own tools on an RBSM scene: nothing may crash the process or return garbage silently.

VTKRecorder's contact recorders read every contact as a sphere contact (static casts in YADE) and
crashed YADE (segfault) on RBSM joints: RbsmTimeStepper now switches such a recorder off and says
so. Other tools work on blocks through what the plugin exposes (RbsmGeom.contactPoint), or are
replaced by yade_rbsm.measure (stress and fabric tensors, extrema).
"""
import pytest

from yaderun import results, run_ok, run_yade

STACK = """
from yade_rbsm import polygon2d, engines
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(rock)
O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(-1, 0), (1, 0), (1, 1.5), (-1, 1.5)], rock))
O.engines = engines(gravity=(0, -9.81, 0))
"""


@pytest.mark.parametrize("recorders", [["intr"], ["stress"], ["all"], ["bstresses"], ["velocity", "intr"]])
def test_vtkrecorder_with_contact_recorders_is_switched_off_not_crashing(recorders, tmp_path):
    p = run_yade(STACK + """
O.engines = O.engines + [VTKRecorder(fileName=%r, recorders=%r, iterPeriod=1)]
O.run(5, True)
report(dead=O.engines[-1].dead, iter=O.iter, index=len(O.engines) - 1)
""" % (str(tmp_path / "r-"), recorders), workdir=str(tmp_path))
    assert p.returncode == 0, "yade exited with %d (crash)\n%s" % (p.returncode, p.stderr[-3000:])
    (r,) = results(p)
    # the recorder is the last engine: after the 6 of engines() (NewtonIntegrator is the 6th)
    assert r == {"dead": True, "iter": 5, "index": 6}
    assert "VTKRecorder (O.engines[%d]) with recorders" % r["index"] in p.stderr and "switched off" in p.stderr


def test_vtkrecorder_safe_recorders_keep_running(tmp_path):
    r = run_ok(STACK + """
O.engines = O.engines + [VTKRecorder(fileName=%r, recorders=['velocity', 'ids', 'coordNumber'], iterPeriod=2)]
O.run(5, True)
report(dead=O.engines[-1].dead)
""" % str(tmp_path / "r-"), workdir=str(tmp_path))
    assert r == [{"dead": False}]


# A column of three 2 m x 1 m blocks (density 2000, thickness 1) on a fixed base, a force P pushing the
# top block down (at its centroid, like its weight W = rho g w h t), at rest. A block whose top face
# carries F_top and bottom face F_bottom = F_top + W (+ P for the top block) has the average stress
# sigma_yy = -(F_top + F_bottom) / (2 w t) (the joints' forces at +-h/2 from its centroid over its
# volume w h t), sigma_xx = sigma_xy = 0.
COLUMN = """
from yade_rbsm import polygon2d, engines, measure
rho, g, P = 2000.0, 9.81, 5.0e4
rock = RbsmMat(young=1e8, poisson=0.2, density=rho, frictionAngle=0.5)
O.materials.append(rock)
O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], rock, fixed=True))
for k in range(3):
    O.bodies.append(polygon2d([(-1, k), (1, k), (1, k + 1), (-1, k + 1)], rock))
O.engines = engines(gravity=(0, -g, 0), damping=0.8)
O.forces.setPermF(3, (0, -P, 0))
O.run(4000, True)
"""


def test_block_stresses_and_packing_stress_of_a_loaded_column():
    r = run_ok(COLUMN + """
bs = measure.block_stresses()
s = measure.stress()
report(blocks={i: [[bs[i][a, b] for b in range(3)] for a in range(3)] for i in (1, 2, 3)},
       packing=[[s[a, b] for b in range(3)] for a in range(3)], vel=max(O.bodies[i].state.vel.norm() for i in (1, 2, 3)),
       base=[[bs[0][a, b] for b in range(3)] for a in range(3)])
""")[0]
    rho, g, P, w, h = 2000.0, 9.81, 5.0e4, 2.0, 1.0
    W = rho * g * w * h
    assert r["vel"] < 1e-4
    top = {3: 0.0, 2: P + W, 1: P + 2 * W}  # force on the top face of block i
    expected = {i: -(2 * top[i] + W + (P if i == 3 else 0)) / (2 * w) for i in (1, 2, 3)}
    for i in (1, 2, 3):
        s = r["blocks"][str(i)]
        assert s[1][1] == pytest.approx(expected[i], rel=2e-3), (i, s)
        assert abs(s[0][0]) < 1e-3 * abs(s[1][1]) and abs(s[0][1]) < 1e-3 * abs(s[1][1]) and abs(s[1][0]) < 1e-3 * abs(s[1][1])
        assert s[2] == [0, 0, 0]
    # the column as a whole: the volume average of its three equal blocks
    assert r["packing"][1][1] == pytest.approx(sum(expected.values()) / 3, rel=2e-3)
    # the fixed base carries the whole column: P + 3W over its 6 m x 1 m
    assert r["base"][1][1] == pytest.approx(-(P + 3 * W) * 0.5 / 6.0, rel=2e-3)


def test_joint_table_is_the_joints_point_by_point():
    """measure.joint_table (one pass, numpy; what the VTK export and block_stresses read) holds, joint
    by joint, the ids, ends, forces and counts of each joint and the points and forces of
    joint_point_forces, on the loaded column with a sliding block added (slipping and open points)."""
    r = run_ok(COLUMN + """
O.bodies.append(polygon2d([(-3, 4.5), (-1, 3.0), (-1, 4.5)], rock))
O.bodies[-1].state.vel = (0.5, -0.2, 0)
O.run(20, True)
from yade_rbsm import omega
t = measure.joint_table()
js = list(omega.joints())
ok = len(js) == len(t.id1) > 3
for k, I in enumerate(js):
    g, ph = I.geom, I.phys
    ok &= (t.id1[k], t.id2[k]) == (I.id1, I.id2) and tuple(t.p0[k]) == (g.p0[0], g.p0[1]) and tuple(t.p1[k]) == (g.p1[0], g.p1[1])
    ok &= (t.normalForce[k], t.shearForce[k], t.nIntact[k], t.nSlipping[k], t.nOpen[k]) == (ph.normalForce, ph.shearForce, ph.nIntact, ph.nSlipping, ph.nOpen)
    mine = [(x[0], x[1], f[0], f[1]) for x, f in zip(t.x[t.joint == k], t.force[t.joint == k])]
    ref = measure.joint_point_forces(I)
    ok &= len(mine) == len(ref) == t.nPoints[k] and all(abs(a - b) <= 1e-9 * (1 + abs(b)) for m, q in zip(mine, ref) for a, b in zip(m, q))
report(ok=bool(ok), n=len(js), slipping=int(sum(t.nSlipping)))
""")[0]
    assert r["ok"] and r["n"] > 3, r


def test_fabric_extrema_porosity_of_the_column():
    r = run_ok(COLUMN + """
F, Fw = measure.fabric_tensor(), measure.fabric_tensor(weighted=True)
lo, hi = measure.aabb_extrema()
report(F=[[F[a, b] for b in range(3)] for a in range(3)], Fw=[[Fw[a, b] for b in range(3)] for a in range(3)],
       lo=list(lo), hi=list(hi), n=measure.porosity(), n2=measure.porosity(area=20.0, ids=[1, 2, 3]))
""")[0]
    # every joint of the column is horizontal: n = (0, +-1)
    assert r["F"] == [[pytest.approx(0, abs=1e-9), pytest.approx(0, abs=1e-9), 0], [pytest.approx(0, abs=1e-9), pytest.approx(1), 0], [0, 0, 0]]
    assert r["Fw"][1][1] == pytest.approx(1)
    assert r["lo"] == pytest.approx([-3, -1, -0.5], abs=5e-3) and r["hi"] == pytest.approx([3, 3, 0.5], abs=5e-3)  # (joint overlaps: mm)
    assert r["n"] == pytest.approx(1 - 12 / 24, abs=2e-3)  # base 6 + three blocks 2, box 6 x 4
    assert r["n2"] == pytest.approx(1 - 6 / 20)


def test_vtkexporter_contact_points_at_the_middle_of_the_joint(tmp_path):
    """YADE's export.VTKExporter.exportContactPoints reads i.geom.contactPoint (RbsmGeom has it, z = 0)."""
    r = run_ok(STACK + """
O.run(3, True)
from yade import export
vtk = export.VTKExporter(%r)
vtk.exportContactPoints(what={'fn': 'i.phys.normalForce'})
g = O.interactions[0, 1].geom
report(cp=list(g.contactPoint), mid=[0.5 * (g.p0[0] + g.p1[0]), 0.5 * (g.p0[1] + g.p1[1]), 0.0], fn=O.interactions[0, 1].phys.normalForce)
""" % str(tmp_path / "e"), workdir=str(tmp_path))[0]
    assert r["cp"] == pytest.approx(r["mid"], abs=1e-12)
    text = (tmp_path / "e-cps-00000000.vtk").read_text().split("\n")
    assert text[5] == "POINTS 1 double"
    assert [float(v) for v in text[6].split()] == pytest.approx(r["cp"], abs=1e-5)
    assert float(text[text.index("LOOKUP_TABLE default") + 1]) == pytest.approx(r["fn"], rel=1e-5)


def test_polygon2d_reference_position_is_where_the_block_is_made():
    """Displacements (pos - refPos: qt view, Monitor, VtkSeries, snapshots) start at 0 in a user's scene."""
    r = run_ok(STACK + """
report(ref=[list(b.state.refPos) for b in O.bodies], pos=[list(b.state.pos) for b in O.bodies])
""")[0]
    assert r["ref"] == r["pos"] and r["pos"][1] == pytest.approx([0, 0.75, 0])


def test_vtk_recorder_engine_writes_blocks_joints_and_stresses(tmp_path):
    """yade_rbsm.vtkexport.recorder: the VTKRecorder of RBSM scenes, from O.engines."""
    r = run_ok(COLUMN + """
from yade_rbsm import vtkexport, measure
rec = vtkexport.recorder(%r, 'col', iterPeriod=10)
O.engines = O.engines + [rec]
O.run(25, True)
s = vtkexport.series_of(rec)
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
rd = vtkXMLPolyDataReader(); rd.SetFileName(s.files[-2]); rd.Update()
pd = rd.GetOutput(); cd = pd.GetCellData()
ids = [cd.GetArray('id').GetValue(k) for k in range(pd.GetNumberOfCells())]
k = ids.index(2)
report(files=[f.rsplit('/', 1)[1] for f in s.files], n=pd.GetNumberOfCells(), syy=cd.GetArray('stress').GetTuple9(k)[4],
       expect=measure.block_stresses()[2][1, 1])
""" % str(tmp_path))[0]
    assert r["files"] == ["col_blocks_0000.vtp", "col_contacts_0000.vtp", "col_blocks_0001.vtp", "col_contacts_0001.vtp",
                          "col_blocks_0002.vtp", "col_contacts_0002.vtp"]
    assert r["n"] == 4 and r["syy"] == pytest.approx(r["expect"], rel=1e-9) and r["syy"] < 0


def test_text_export_of_blocks_and_back(tmp_path):
    """yade_rbsm.textexport.text / read: what YADE's export.text does for spheres (it writes only a header for blocks)."""
    r = run_ok(STACK + """
O.bodies[1].state.ori = Quaternion((0, 0, 1), 0.3)
from yade_rbsm import textexport
from yade import export
n = textexport.text(%r, comment='two blocks')
back = textexport.read(%r)
yade_lines = export.text(%r)
report(n=n, back=[[i, [list(v) for v in vs], t] for i, vs, t in back],
       world=[[list(v) for v in b.shape.worldVertices(b.state.pos, b.state.ori)] for b in O.bodies], yade=yade_lines)
""" % ((str(tmp_path / "b.txt"),) * 2 + (str(tmp_path / "y.txt"),)))[0]
    assert r["n"] == 2 and r["yade"] == 0
    assert [b[0] for b in r["back"]] == [0, 1]
    for (i, verts, t), world in zip(r["back"], r["world"]):
        assert sum(verts, []) == pytest.approx(sum(world, []), abs=1e-15) and t == 1.0
    line = (tmp_path / "b.txt").read_text().split("\n")[3].split()
    assert float(line[3]) == pytest.approx(0.3)


def test_vtk_recorder_survives_save_and_load_in_a_new_process(tmp_path):
    """A scene saved with a vtkexport.recorder in O.engines and loaded by another process (the usual
    restart of a long run): the recorder's series lived in a registry of the first process, so the loaded
    PyRunner raised KeyError at its first snapshot and stopped the run. It now finds (or makes) its series
    by directory and prefix, and a series made after O.load keeps the snapshots of the collection up to
    O.time: the .pvd lists the first run's snapshots and the new ones, files numbered on."""
    out = str(tmp_path / "vtk")
    save = str(tmp_path / "scene.yade.gz")
    run_ok(COLUMN + """
from yade_rbsm import vtkexport
O.engines = O.engines + [vtkexport.recorder(%r, 'col', iterPeriod=10)]
O.run(25, True)
O.save(%r)
""" % (out, save), workdir=str(tmp_path))
    r = run_ok("""
O.load(%r)
t0 = O.time
O.run(20, True)
import xml.etree.ElementTree as ET
ds = ET.parse(%r).getroot().find('Collection').findall('DataSet')
report(files=[d.get('file') for d in ds], times=[float(d.get('timestep')) for d in ds], t0=t0, iter=O.iter)
""" % (save, out + "/col_blocks.pvd"), workdir=str(tmp_path))[0]
    assert r["iter"] == 4025 + 20, r  # (COLUMN runs 4000 steps, then 25, then 20 after the load)
    assert r["files"] == ["col_blocks_%04d.vtp" % k for k in range(len(r["files"]))] and len(r["files"]) == 5, r
    assert sorted(r["times"]) == r["times"] and sum(t > r["t0"] for t in r["times"]) == 2, r


def test_block_stress_counts_a_sphere_resting_on_the_block():
    """measure.block_stresses in a mixed scene: a 2 x 1 m block on a fixed base with a heavy sphere on
    it. The sphere's contact (YADE's ScGeom) loads the block's top; the joints alone gave
    sigma_yy = -(Ws + W) / (2 w t) (the sphere's weight missing at the top, the block out of balance);
    with it -(2 Ws + W) / (2 w t), as for a block loaded by another block (the column test above)."""
    r = run_ok("""
from yade import utils
from yade_rbsm import polygon2d, measure, mixed_engines
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
grain = FrictMat(young=1e8, poisson=0.2, density=2e5, frictionAngle=0.5)
O.materials.append([rock, grain])
O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(-1, 0), (1, 0), (1, 1), (-1, 1)], rock))
s = O.bodies.append(utils.sphere((0.0, 1.2, 0), 0.2, material=grain))
O.bodies[s].state.blockedDOFs = "zXY"
O.engines = mixed_engines(gravity=(0, -9.81, 0), damping=0.8)
O.run(6000, True)
sg = measure.block_stresses()[1]
report(syy=sg[1, 1], sxx=sg[0, 0], sxy=sg[0, 1], syx=sg[1, 0], Ws=O.bodies[s].state.mass * 9.81,
       W=O.bodies[1].state.mass * 9.81, v=O.bodies[s].state.vel.norm())
""")[0]
    assert r["v"] < 1e-5, r
    expect = -(2 * r["Ws"] + r["W"]) / (2 * 2.0 * 1.0)
    assert r["syy"] == pytest.approx(expect, rel=2e-3), r  # (as the column test: the joints sit an overlap lower)
    assert abs(r["sxy"] - r["syx"]) < 1e-6 * abs(expect), r
