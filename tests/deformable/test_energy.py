"""Undamped deformable blocks conserve energy, and a saved scene continues like the uninterrupted run (issue 38).

A plate of Voronoi blocks, welded as built, floats without gravity or damping after random velocities, spins
and strain rates. O.energy's total (kinetic, strainKinetic, elastPotential, strainElastic) oscillates by the
leapfrog's half-step staggering (NewtonIntegrator's kinetic energy is half a step behind the springs': the same
in a rigid scene, printed next to it) and must not drift: the mean of the last tenth of the run within 0.2 % of
the first tenth's, at the stepper's own step (safety 0.8) and at a twentieth of it, where the oscillation is
within 1 %. The strain modes must take part (strainElastic, strainKinetic > 1 % of the total). Plates of 0.05 m
and 5 m, two seeds. Fails on da6a37e (no RbsmMat.deformable, no DeformableState)."""
import os

import pytest

from conftest import run_scene


@pytest.mark.parametrize("size,seed", [(0.05, 1), (5.0, 2)], ids=["5cm-seed1", "5m-seed2"])
def test_undamped_deformable_blocks_conserve_energy(size, seed):
    args = {"size": size, "seed": seed, "v": 0.01 * size, "steps": 4000}
    fine = run_scene("energy", dict(args, safety=0.05))
    coarse = run_scene("energy", dict(args, safety=0.8, steps=8000))
    rigid = run_scene("energy", dict(args, safety=0.05, deformable=False))
    print("size %g m seed %d: deformable worst %.2e drift %+.2e (safety 0.05), drift %+.2e (safety 0.8); rigid worst %.2e drift %+.2e"
          % (size, seed, fine["worst"], fine["drift"], coarse["drift"], rigid["worst"], rigid["drift"]))
    assert fine["welded"] > 50
    assert fine["worst"] < 0.01
    assert abs(fine["drift"]) < 2e-3
    assert abs(coarse["drift"]) < 2e-3 and coarse["worst"] < 0.2
    e = fine["energies"]
    total = e["kinetic"] + e["strainKinetic"] + e["elastPotential"] + e["strainElastic"]
    assert e["strainElastic"] > 0.01 * total and e["strainKinetic"] > 0.01 * total


def test_joint_dashpots_close_the_balance():
    """The welded joints' dashpots (contact_damping) act on the same mean and bending of the jump as their springs
    (RbsmPhys.linearShare): what they take is in viscDamp, and the balance still closes."""
    r = run_scene("energy", {"size": 5.0, "seed": 2, "v": 0.05, "steps": 4000, "safety": 0.05, "contact_damping": 0.05})
    e = r["energies"]
    print("contact damping 0.05: viscDamp %.3g of the initial energy, balance worst %.2e drift %+.2e" % (e["viscDamp"] / r["e0"], r["worst"], r["drift"]))
    assert e["viscDamp"] > 0.01 * r["e0"]  # the dashpots act (3 % in these 4000 steps)
    assert r["worst"] < 0.01 and abs(r["drift"]) < 2e-3


def test_saved_scene_continues_like_the_uninterrupted_run(tmp_path):
    args = {"steps": 600, "safety": 0.8}
    straight = run_scene("energy", args, threads=1)
    resumed = run_scene("energy", dict(args, save=os.path.join(str(tmp_path), "deformable.xml.bz2")), threads=1)
    assert resumed["state"] == straight["state"]  # positions and strains, to the bit
