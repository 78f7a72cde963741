"""Blocks to CSV and back (yade_rbsm.io.export_blocks / import_blocks): the same scene, also after
running it; clear errors for bad files."""
import math

import pytest
from conftest import SCENE, SNAPSHOT
from yaderun import run_ok

ROUND_TRIP = SCENE + SNAPSHOT + r"""
import yade_rbsm.io as io
if STEPS:
    O.run(STEPS, True)
assert O.iter == STEPS, O.iter
before = snapshot()
assert io.export_blocks("blocks.csv") == len(O.bodies)
O.reset()
O.bodies.append(io.import_blocks("blocks.csv"))
report(before=before, after=snapshot(), materials=[(m.label, m.dict()) for m in O.materials],
       text=open("blocks.csv").read())
"""


def close(a, b, tol):
    return all(abs(x - y) <= tol * max(1.0, abs(x), abs(y)) for x, y in zip(a, b)) and len(a) == len(b)


@pytest.mark.parametrize("steps", [0, 300])
def test_round_trip_gives_the_same_blocks(steps):
    """Export then import: every block with the same world vertices, mass, inertia, fixed flag,
    thickness, velocity and material, before a step (0) and after the blocks moved and rotated."""
    (r,) = run_ok(ROUND_TRIP.replace("STEPS", str(steps)))
    before, after = r["before"], r["after"]
    assert len(after) == len(before) == 4
    for b0, b1 in zip(before, after):
        # written with repr(); the import recomputes centroid and local vertices: round-off only
        assert close(sum(b1["world"], []), sum(b0["world"], []), 1e-14)
        assert close(b1["pos"], b0["pos"], 1e-13)
        assert b1["mass"] == pytest.approx(b0["mass"], rel=1e-13)
        assert close(b1["inertia"], b0["inertia"], 1e-12)
        assert (b1["fixed"], b1["thickness"], b1["material"]) == (b0["fixed"], b0["thickness"], b0["material"])
        assert b1["vel"] == b0["vel"] and b1["angVel"] == b0["angVel"]
    assert [m[0] for m in r["materials"]] == ["rock", "mat1"]  # the unlabelled material gets 'mat<id>'
    if steps:
        assert any(abs(b["angVel"][2]) > 1e-6 for b in before), "the scene should have moved"
    assert r["text"].startswith("# yade-rbsm blocks 1\n# material label=rock young=200000000.0")


def test_imported_scene_runs_like_the_original():
    """The imported blocks, run for 400 steps, end where the original blocks end (joints are made
    afresh in both, so the two runs are the same computation up to round-off of the centroids)."""
    script = SCENE + r"""
import yade_rbsm.io as io
io.export_blocks("blocks.csv")
O.run(400, True)
assert O.iter == 400, O.iter
orig = [list(b.state.pos) + [b.state.angVel[2]] for b in O.bodies]
O.reset()
O.bodies.append(io.import_blocks("blocks.csv"))
O.engines = engines(gravity=(0, -9.81, 0), contact_damping=0.1)
O.run(400, True)
assert O.iter == 400, O.iter
report(orig=orig, new=[list(b.state.pos) + [b.state.angVel[2]] for b in O.bodies])
"""
    (r,) = run_ok(script)
    moved = max(math.dist(a[:2], [0, 0]) for a in r["orig"])
    assert moved > 0
    for a, b in zip(r["orig"], r["new"]):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-9)


def test_hand_written_file_with_defaults(tmp_path):
    """Only the needed columns, in another order, a padded row, materials given by the caller."""
    (tmp_path / "hand.csv").write_text(
        "material,x1,y1,x2,y2,x3,y3,x4,y4\n"
        "Rock,0,0,1,0,1,1,0,1\n"
        "Rock,2,0,3,0,2.5,1,,\n")
    script = r"""
import yade_rbsm.io as io
rock = RbsmMat(density=2000)
bs = io.import_blocks("hand.csv", materials={"Rock": rock})
report(n=len(bs), areas=[b.shape.area for b in bs], fixed=[b.state.blockedDOFs for b in bs],
       thick=[b.shape.thickness for b in bs], mats=[b.material is rock for b in bs])
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert r == dict(n=2, areas=[1.0, 0.5], fixed=["zXY", "zXY"], thick=[1.0, 1.0], mats=[True, True])


BAD = [
    ("no header", "0,0,1,0,1,1\n", "blocks.csv:1: header must name the columns material"),
    ("unknown material", "material,x1,y1,x2,y2,x3,y3\nclay,0,0,1,0,1,1\n",
     "blocks.csv:2: material 'clay' is neither defined in the file"),
    ("odd coordinates", "# material label=r density=2000\nmaterial,x1,y1,x2,y2,x3,y3\nr,0,0,1,0,1\n",
     "blocks.csv:3: odd number of vertex coordinates (5)"),
    ("not a number", "# material label=r density=2000\nmaterial,x1,y1,x2,y2,x3,y3\nr,0,0,1,zero,1,1\n",
     "blocks.csv:3: a vertex coordinate is not a number"),
    ("clockwise", "# material label=r density=2000\nmaterial,fixed,x1,y1,x2,y2,x3,y3\nr,0,0,0,0,1,1,0\n",
     "blocks.csv:3: polygon2d([(0, 0), (0, 1), (1, 0)]): "),
    ("fixed not 0/1", "# material label=r density=2000\nmaterial,fixed,x1,y1,x2,y2,x3,y3\nr,2,0,0,1,0,1,1\n",
     "blocks.csv:3: column fixed must be 0 or 1"),
    ("bad material key", "# material label=r densty=2000\nmaterial,x1,y1,x2,y2,x3,y3\n",
     "blocks.csv:1: material 'r': unknown attribute(s) densty"),
    ("unknown column", "material,colour,x1,y1,x2,y2,x3,y3\n", "blocks.csv:1: unknown column(s) colour"),
]


@pytest.fixture(scope="module")
def bad_errors(tmp_path_factory):
    """The error of import_blocks for each BAD file, all read in one yade run (fast)."""
    d = tmp_path_factory.mktemp("bad")
    for k, (_, text, _) in enumerate(BAD):
        sub = d / str(k)
        sub.mkdir()
        (sub / "blocks.csv").write_text(text)
    script = r"""
import os
import yade_rbsm.io as io
errors = []
for k in range(NBAD):
    os.chdir(os.path.join(BADROOT, str(k)))
    O.reset()
    try:
        io.import_blocks("blocks.csv")
        errors.append(None)
    except ValueError as e:
        errors.append(str(e))
report(errors=errors)
""".replace("NBAD", str(len(BAD))).replace("BADROOT", repr(str(d)))
    (r,) = run_ok(script, workdir=str(d))
    return r["errors"]


@pytest.mark.parametrize("k", range(len(BAD)), ids=[b[0] for b in BAD])
def test_bad_files_name_the_line_and_problem(bad_errors, k):
    error, message = bad_errors[k], BAD[k][2]
    assert error is not None and error.startswith(message), error


def test_file_material_differing_from_scene_material_is_an_error(tmp_path):
    (tmp_path / "blocks.csv").write_text("# material label=rock density=2000\nmaterial,x1,y1,x2,y2,x3,y3\nrock,0,0,1,0,1,1\n")
    script = r"""
import yade_rbsm.io as io
O.materials.append(RbsmMat(label="rock", density=2500))
try:
    io.import_blocks("blocks.csv")
except ValueError as e:
    report(error=str(e))
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert r["error"] == "blocks.csv:1: material 'rock' of the file differs from O.materials' 'rock' in density"


def test_materials_outside_o_materials_and_a_moving_wall(tmp_path):
    """Blocks whose material is not in O.materials (two blocks share one, a third has another) get
    one definition per material; a fixed block's velocity (a wall moved kinematically) survives."""
    script = r"""
import yade_rbsm.io as io
from yade_rbsm import polygon2d
a, b = RbsmMat(density=2000), RbsmMat(density=2100, cohesion=5.0)
O.bodies.append([polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], a), polygon2d([(2, 0), (3, 0), (3, 1)], a),
                 polygon2d([(4, 0), (5, 0), (5, 1)], b), polygon2d([(0, -2), (5, -2), (5, -1)], a, fixed=True)])
O.bodies[3].state.vel = (0.25, 0, 0)
io.export_blocks("blocks.csv")
O.reset()
bs = io.import_blocks("blocks.csv")
report(text=open("blocks.csv").read(), mats=[(x.material.label, x.material.density, x.material.cohesion) for x in bs],
       n=len(O.materials), vel=list(bs[3].state.vel), fixed=bs[3].state.blockedDOFs)
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert r["text"].count("# material ") == 2, r["text"]
    assert r["mats"] == [["unlisted0", 2000, 0], ["unlisted0", 2000, 0], ["unlisted1", 2100, 5.0], ["unlisted0", 2000, 0]]
    assert r["n"] == 2 and r["vel"] == [0.25, 0, 0] and r["fixed"] == "xyzXYZ"


def test_every_material_attribute_survives_the_round_trip(tmp_path):
    """Issue 36: export_blocks wrote young ... tensileStrength only, so a material's jointKn, jointKs and
    ductile came back as the defaults (a joint set's stiffness lost without a word). Every attribute RbsmMat
    has is written now; the test compares them all, whatever RbsmMat gains later."""
    script = r"""
import math
import yade_rbsm.io as io
from yade_rbsm import polygon2d
m = RbsmMat(label="rock", young=3e8, poisson=0.27, planeStrain=False, density=2550, frictionAngle=0.61, cohesion=2e4,
            tensileStrength=1e4, ductile=True, jointKn=4e9, jointKs=1.5e9)
O.materials.append(m)
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], m))
io.export_blocks("b.csv")
before = {k: v for k, v in m.dict().items() if k != "id"}
O.reset()  # a fresh scene: the material comes from the file's definition
O.bodies.append(io.import_blocks("b.csv"))
after = {k: v for k, v in O.bodies[0].material.dict().items() if k != "id"}
report(before=before, after=after)
"""
    (r,) = run_ok(script, workdir=str(tmp_path))
    assert r["after"] == r["before"], r
