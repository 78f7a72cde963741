"""A joint bonded at a corner carries cohesion over the length it was bonded on, not over the edge it
grows into (a new user's step-path slope: a 0.45 mm contact bonded at the rock's 5 MPa grew to 7.9 mm
while a block slid and stopped the slide with 23 kN). Scene: a block on a broken crack, touching a
fixed block at a corner (2 um of contact), gravity tilted 30 deg, phi 20 deg: the bond can hold
c x 2 um = 2 N of the block's 12.7 kN downhill weight, so the block slides off."""
import pytest

from conftest import run_scene


@pytest.mark.parametrize("ductile", [True, False])
def test_a_corner_bond_does_not_grow_with_its_contact(ductile):
    r = run_scene("corner_bond", dict(ductile=ductile, overlap=2e-6, seconds=2.0))
    assert r["bonded0"] == pytest.approx(2e-6, rel=1e-3), r
    # a = g (sin 30 - cos 30 tan 20) = 1.81 m/s2 damped by 0.7 at most: at least 0.5 m in 2 s
    assert r["slide"] > 0.5, r
    if r["bonded"] is not None:
        # not the ~1 m the contact grew to: the bond follows a segment's growth only by closing, which the
        # blocks' tangential travel (summed step by step until the first slip) separates to tens of um
        assert r["bonded"] < 1e-3 and r["length"] > 0.5, r


@pytest.mark.parametrize("gap", [1e-9, 1e-7])
def test_a_face_bonded_across_a_misfit_bonds_as_it_closes(gap):
    """Imported geometry is not snapped: a face bonded where only one end touched (a reviewer's case: the
    bond stayed 1.4 mm of a 1 m face, or 14 um with a 1e-7 m gap) grows with the segment while the joint
    has not slipped, so gravity closing the face elastically bonds all of it."""
    r = run_scene("misfit_bond", dict(gap=gap, steps=2000))
    assert not r["slipped"], r
    assert r["length"] == pytest.approx(1.0, rel=1e-3) and r["bonded"] == pytest.approx(r["length"], rel=1e-9), r
    assert r["intact"] == 2, r
