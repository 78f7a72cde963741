"""A sphere bouncing on a block keeps its energy (issue 17): undamped, the FrictMat sphere (rotation
blocked) dropped through 0.5 m onto a fixed Polygon2D rebounds to the drop height within 0.1 % three
times in a row, and YADE's energy tracker (kinetic + gravity work + elastic potential of the
Law2_ScGeom_FrictPhys_CundallStrack contact) closes to 0.1 % of m g h at the third apex.

YADE's restitution laws (Law2_ScGeom_MindlinPhys_Mindlin with en, Law2_ScGeom_ViscElPhys_Basic) need
MindlinPhys or ViscElPhys, which no IPhys functor makes for an RbsmMat block: not covered here."""
from conftest import run_scene


def test_sphere_bounces_back_to_its_drop_height():
    r = run_scene("bounce", {"drop": 0.5, "bounces": 3})
    print(r)
    assert len(r["apexes"]) == 3
    for h in r["apexes"]:
        assert abs(h - r["drop"]) < 1e-3 * r["drop"], r["apexes"]
    assert r["energy_error_end"] < 1e-3, r
