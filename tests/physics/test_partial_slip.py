"""A rigid block that friction holds must not move (issue 35, item 1).

A block on a fixed plane (φ = 40.1°, c = 0, kn = ks, no damping at all) under gravity tilted slowly from
0 to ψ and held, for joint stiffnesses 1e8–1e10 Pa/m, blocks 0.1 to 10 m of aspect 0.5 to 1 (none of
which topples at ψ: H/L < 1/tan ψ), ψ up to 38° (tan ψ/tan φ = 0.93), with 2 and 4 integration points.
Friction holds every one: the joint must not slip (no frictional dissipation), never open, and carry
W cos ψ within 2 %; the block moves by its elastic compliance only (a few static overlaps W/(kn·L),
the shear spring's and the rocking of a partly open base), where before a block whose base was
partly open or partly slipping chattered, its normal force peaking at 12–75 W, and slid metres.
"""
import pytest

from conftest import run_scene

SIZES = [(10.0, 10.0), (4.0, 2.0), (0.5, 0.5), (0.1, 0.08)]


def _cases(kn, psis, nips):
    return [[kn, L, H, psi, nip] for (L, H) in SIZES for psi in psis for nip in nips]


@pytest.mark.parametrize("kn", [1e8, 1e9, 1e10])
def test_block_held_by_friction_does_not_move(kn):
    r = run_scene("partial_slip", {"cases": _cases(kn, [20, 30, 38], [2]) + _cases(kn, [38], [4])})
    bad = []
    for c in r["cases"]:
        kn_, L, H, psi, nip = c["case"]
        print("kn %g L %g H %g psi %g nIP %d: N/(W cos psi) %.4f..%.4f, open steps %d, dissipated %.3g J, "
              "slide %.3g m = %.2f static overlaps, rotation %.2e" % (kn_, L, H, psi, nip, c["fmin"], c["fmax"], c["lifted"],
                                                                    c["dissipated"], c["slide"], c["slide"] / c["overlap"], c["rot"]))
        if not (c["lifted"] == 0 and c["dissipated"] == 0 and 0.98 < c["fmin"] and c["fmax"] < 1.02
                and abs(c["slide"]) < 20 * c["overlap"]):
            bad.append(c["case"])
    assert not bad, "blocks held by friction that moved: %s" % bad
