"""Waves in a column of deformable blocks (issue 38): a free-free bar of unit-square blocks (plane stress,
E = 1e8, ν = 0.2, ρ = 2000) in its fundamental mode has the period 2L/c of a bar, c = √(E/ρ) (its sides are
free to contract), within 1 %; rigid blocks give the plate's c = √(E/(1 − ν²)/ρ), 2 % faster, whatever their
size. The same bar (100 blocks) moving at 1 cm/s onto a fixed block stays in contact for 2L/c within 1 %
(its first block chatters on the stiff contact: the duration runs from the first force to the last).
The penalty's compliance (RbsmMat.penalty = 100) makes the bar 0.5 % slower. Fails on da6a37e."""
from math import sqrt

import pytest

from conftest import run_scene
from verification import record

E, NU, RHO = 1e8, 0.2, 2000.0
C_BAR = sqrt(E / RHO)


def speed_from_mode1(r):
    t1, t2 = r["crossings"][:2]
    return 2 * r["L"] / (2 * (t2 - t1))


def test_fundamental_mode_has_the_bar_speed():
    d = run_scene("bar", {"mode": "mode1", "N": 50})
    r = run_scene("bar", {"mode": "mode1", "N": 50, "deformable": False})
    cd, cr = speed_from_mode1(d), speed_from_mode1(r)
    print("bar speed sqrt(E/rho) = %.6g m/s: deformable %.6g (%+.2f %%), rigid %.6g (%+.2f %%); dt deformable/rigid %.3f"
          % (C_BAR, cd, 100 * (cd / C_BAR - 1), cr, 100 * (cr / C_BAR - 1), d["dt"] / r["dt"]))
    record("Waves and elasticity", "deformable-block bar, 50 blocks: fundamental mode's speed", cd, C_BAR, "√(E/ρ), plane stress",
           rtol=0.01, unit="m/s")
    assert d["welded"] == 49
    assert cd == pytest.approx(C_BAR, rel=0.01)
    assert cr / C_BAR - 1 > 0.015  # rigid blocks: the plate modulus E/(1 - nu^2), no lateral contraction


def test_impact_lasts_two_transit_times():
    d = run_scene("bar", {"mode": "impact", "N": 100})
    duration, expected = d["end"] - d["start"], 2 * d["L"] / C_BAR
    print("impact of a 100 m bar at 1 cm/s: contact %.6g s, 2L/c = %.6g s (%+.2f %%), rebound %.4g m/s"
          % (duration, expected, 100 * (duration / expected - 1), d["rebound"]))
    record("Waves and elasticity", "a 100-block deformable bar hitting a wall: contact duration", duration, expected,
           "2 L / c", rtol=0.01, unit="s")
    assert duration == pytest.approx(expected, rel=0.01)
    assert d["rebound"] == pytest.approx(0.01, rel=0.05)
