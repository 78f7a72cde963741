"""Goodman & Bray's toppling by strength reduction (issue 36): flat-topped columns on a stepped base, built by
column_blocks on a stepped ground (toppling_columns.py: two columns, and ten with a sliding toe), at three joint
stiffnesses. fos() puts Goodman & Bray's rigid-column answer (toppling.columns of the builder's blocks, the joints'
friction, the scene's gravity) beside strength reduction, which fails by toppling below it: a column on elastic
joints turns before its weight bears on its base corner (the contact shrinks towards the corner as the column
turns, while its lean adds to the overturning moment), so it fails at a factor below the rigid one, by a margin
that shrinks with the joints' stiffness about as kn^(-1/3) (2.15 x a decade) for a no-tension elastic base.
Checked: the stiffer, the closer; the gap shrinks by 1.5-4 x a decade; extrapolated at that rate from the two
stiffest, within 1.5 % of Goodman & Bray."""
import os

import pytest

from conftest import HERE, run_yade
from verification import record

GB = {"pair": 2.57202, "ten": 0.66819}  # toppling.goodman_bray_fs (tests/python/test_toppling.py checks the formulas)
YOUNG = (1e11, 1e12, 1e13)


@pytest.fixture(scope="module", params=["pair", "ten"])
def runs(request):
    out = {}
    for young in YOUNG:
        p = run_yade(os.path.join(HERE, "toppling_columns.py"), request.param, "%g" % young, "400000", cwd=HERE,
                     timeout=300)
        assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
        gb = float([l for l in p.stdout.splitlines() if l.startswith("GB")][0].split()[1])
        f = [l for l in p.stdout.splitlines() if l.startswith("RESULT")][0].split()
        out[young] = dict(fs=float(f[1]), mechanism=f[2], gb_direct=gb, gb_fos=float(f[3]), warnings=int(f[4]),
                          stdout=p.stdout)
    return request.param, out


def test_fos_shows_goodman_bray_beside_strength_reduction(runs):
    case, runs = runs
    n = 2 if case == "pair" else 10
    for young, r in runs.items():
        assert r["gb_direct"] == pytest.approx(GB[case], abs=1e-5) and r["gb_fos"] == pytest.approx(GB[case], abs=1e-5)
        assert ("| Goodman & Bray, toppling (rigid columns) | %.3f | %d columns, base planes dipping 13.50 deg"
                % (GB[case], n)) in r["stdout"], young
    soft = runs[YOUNG[0]]
    assert soft["mechanism"] == "toppling" and soft["warnings"] == 1, soft["stdout"][-3000:]
    assert "below Goodman & Bray's rigid columns" in soft["stdout"]
    assert runs[YOUNG[-1]]["warnings"] == 0  # within 5 % of it: no warning


def test_strength_reduction_converges_to_goodman_bray_as_the_joints_stiffen(runs):
    case, runs = runs
    gb = GB[case]
    fs = [runs[y]["fs"] for y in YOUNG]
    gap = [gb - f for f in fs]
    assert all(g > 0 for g in gap), fs  # elastic joints topple first
    ratios = [a / b for a, b in zip(gap[:-1], gap[1:])]
    assert all(1.5 < r < 4.0 for r in ratios), (fs, ratios)
    r13 = 10 ** (1 / 3)
    extrapolated = fs[-1] + (fs[-1] - fs[-2]) / (r13 - 1)
    what = ("Goodman & Bray's two toppling columns (ψ 13.5°, φ 40°)" if case == "pair" else
            "Goodman & Bray's ten columns (ψ 13.5°, φ 35°, toe sliding)")
    record("Rock slopes", what + ": strength reduction at E 10 TPa", fs[-1], gb,
           "Goodman & Bray (rigid columns); elastic joints converge as kn^(-1/3)",
           tolerance="below it by a gap shrinking 1.5-4 x a decade of stiffness")
    record("Rock slopes", what + ": strength reduction extrapolated to rigid joints", extrapolated, gb,
           "Goodman & Bray (rigid columns)", rtol=0.015)
    assert extrapolated == pytest.approx(gb, rel=0.015), (fs, extrapolated)
    assert runs[YOUNG[0]]["mechanism"] == "toppling", runs[YOUNG[0]]["stdout"][-2000:]
