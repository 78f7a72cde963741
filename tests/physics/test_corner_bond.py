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
        assert r["bonded"] <= 2e-6 * (1 + 1e-3), r  # never longer than where it was bonded
