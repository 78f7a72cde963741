"""Goodman & Bray's toppling on a stepped base (yade_rbsm.toppling), checked against what the equations
reduce to, without YADE (issue 36 asks for it as the limit-equilibrium answer of a toppling slope).

* one low block on its base: it can only slide, P0 = 0 at tan(phi) = tan(psi): FS = tan(phi)/tan(psi);
* one tall block (y/width > cot psi): it topples whatever the friction: no FS, named;
* two equal tall columns: the upper one passes its toppling force down, by the formula worked by hand;
* the modes from the top down: stable columns above, then toppling ones, sliding at the toe when the toe
  column is low and the force from above large.
"""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "py"))
from yade_rbsm.toppling import Column, goodman_bray, goodman_bray_fs  # noqa: E402
from verification import record  # noqa: E402


def test_one_low_block_slides_at_the_closed_form():
    psi, phi = math.radians(25), math.radians(35)
    fs = goodman_bray_fs([Column(0.0, 1.0, 4.0)], psi, phi)
    record("Limit equilibrium", "Goodman & Bray: one low block on a 25° base, φ 35°", fs, math.tan(phi) / math.tan(psi),
           "tan φ / tan ψ", rtol=1e-5)
    assert fs == pytest.approx(math.tan(phi) / math.tan(psi), rel=1e-5)
    r = goodman_bray([Column(0.0, 1.0, 4.0)], psi, math.radians(20))
    assert r.modes == ["sliding"] and r.P0 == pytest.approx(4.0 * (math.sin(psi) - math.tan(math.radians(20)) * math.cos(psi))
                                                            / (1 - math.tan(math.radians(20)) ** 2))


def test_one_tall_block_topples_whatever_the_friction():
    psi = math.radians(20)
    tall = [Column(0.0, 1.2 / math.tan(psi), 1.0)]  # y / width = 1.2 cot(psi)
    with pytest.raises(ValueError, match="fail even at"):
        goodman_bray_fs(tall, psi, math.radians(40))
    assert goodman_bray(tall, psi, math.radians(80)).modes == ["toppling"]


def test_two_columns_by_hand():
    psi, phi, w, g = math.radians(15), math.radians(30), 1.0, 25.0
    cols = [Column(0.0, 5.0, w), Column(0.5, 5.5, w)]  # equal heights 5, the upper one on a step 0.5 higher
    r = goodman_bray(cols, psi, phi, unit_weight=g)
    W, y, t = g * 5 * w, 5.0, math.tan(phi)
    # the upper column: nothing above; the lower one pushes at its top, 5.0, 4.5 above the upper one's base
    P1 = 0.5 * W * (y * math.sin(psi) - w * math.cos(psi)) / 4.5
    L0 = 5.0  # the toe column: nothing below, its own height
    M0 = 5.0  # the upper one pushes at the lower top of the two, its own
    P0 = (P1 * (M0 - w * t) + 0.5 * W * (y * math.sin(psi) - w * math.cos(psi))) / L0
    assert r.modes == ["toppling", "toppling"] and r.forces[1] == pytest.approx(P1) and r.P0 == pytest.approx(P0)


def test_stable_crest_toppling_face_and_more_friction_holds_more():
    psi = math.radians(13.5)
    cols = [Column(i * 1.0, i * 1.0 + h, 2.0) for i, h in enumerate([3, 5, 7, 9, 11, 12, 11, 10, 9, 8])]
    r = goodman_bray(cols, psi, math.radians(30))
    assert r.modes[-1] == "stable" and "toppling" in r.modes
    f35, f45 = (goodman_bray_fs(cols, psi, math.radians(p)) for p in (35, 45))
    assert 0 < f35 < f45
    # the factor is on tan(phi): at phi reduced by it, the toe needs no force
    assert goodman_bray(cols, psi, math.atan(math.tan(math.radians(45)) / f45 * 1.001)).P0 == pytest.approx(0, abs=1e-3)
