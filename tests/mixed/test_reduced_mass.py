"""A block's joint with a YADE Wall or Facet gets its reduced mass (contact damping) from the same formula as a
block-block joint, RbsmGeom::reducedMassOf: m1·m2/(m1+m2), a fixed end or one without mass counting as
infinite. BoundaryJoint had its own, which took a fixed block's mass as finite: a free 10 kg wall landing on a
fixed block got 9.95 kg instead of the wall's 10 (the value a block-block joint, or the same joint after
O.load, gets). Met mid-run, after the time stepper first saw the block (which recomputes its joints then)."""
import pytest

from conftest import run_scene


@pytest.mark.parametrize("block_fixed,wall_mass,expected", [
    (True, 10.0, lambda m, M: M),                   # fixed block, free wall: the wall's mass
    (False, 10.0, lambda m, M: m * M / (m + M)),    # both free
    (False, 0.0, lambda m, M: m),                   # free block, utils.wall's fixed wall: the block's mass
])
def test_block_wall_joint_has_the_block_joint_reduced_mass(block_fixed, wall_mass, expected):
    r = run_scene("reduced_mass", {"blockFixed": block_fixed, "wallMass": wall_mass})
    print(r)
    assert r["jointsAtStart"] == 0 and r["iter"] > 5, r  # made mid-run
    assert r["reducedMass"] == pytest.approx(expected(r["blockMass"], r["wallMass"]), rel=1e-12), r


def test_a_fixed_block_released_in_contact_gets_its_mass_as_reduced_mass():
    """A fixed block driven up to a fixed wall (two fixed ends: reduced mass 0, no contact damping), then
    released by the script: the joint has a free end of the block's mass. Before, blockedDOFs were not
    followed and the joint kept 0 (dampingCoefficient 0 at contact_damping 0.3); before a08047a the wall
    joint took the block's mass as made, a block-block joint kept 0 too. Now a release (or a fix) is followed
    like a mass set by the script (ReshapedBlocks.hpp): the joints' reduced masses are recomputed."""
    r = run_scene("reduced_mass", {"blockFixed": True, "wallMass": 0.0, "release": True})
    print(r)
    assert r["jointsAtStart"] == 0 and r["iter"] > 5, r
    assert r["reducedMass"] == pytest.approx(r["blockMass"], rel=1e-12), r
