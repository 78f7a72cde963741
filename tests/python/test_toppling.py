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


def _slope_module():
    import importlib.util
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "py", "yade_rbsm", "slope.py")
    spec = importlib.util.spec_from_file_location("rbsm_slope_geom", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_columns_read_back_from_the_builder():
    """toppling.columns: Goodman & Bray's columns of a slope built by column_blocks on a stepped ground (flat tops,
    risers between them), from the toe up; refused, naming the column, where they are not Goodman & Bray's."""
    from yade_rbsm.toppling import columns
    S = _slope_module()
    ground = [(0, 3), (2, 3), (2, 9.5), (4, 9.5), (4, 12), (6, 12)]
    base = [(0, 0), (2, 0), (2, 0.5), (4, 0.5), (4, 1), (6, 1)]
    assert columns(S.column_blocks(ground, base, 2.0)) == [Column(0, 3, 2), Column(0.5, 9.5, 2), Column(1, 12, 2)]
    mirrored = S.column_blocks([(-x, y) for x, y in reversed(ground)], [(-x, y) for x, y in reversed(base)], 2.0)
    assert columns(mirrored) == [Column(0, 3, 2), Column(0.5, 9.5, 2), Column(1, 12, 2)]  # toe on the right
    with pytest.raises(ValueError, match=r"column 2 \(x 2 to 4\): its top is not flat"):
        columns(S.column_blocks([(0, 3), (2, 3), (4, 9.5), (6, 12)], base, 2.0))
    with pytest.raises(ValueError, match=r"column 1 \(x 0 to 2\) is 2 blocks"):
        columns(S.column_blocks(ground, base, 2.0, block_h=2.0))
    with pytest.raises(ValueError, match="toe"):
        columns(S.column_blocks([(0, 3), (2, 3), (2, 9.5), (4, 9.5), (4, 3), (6, 3)], 0.0, 2.0))
