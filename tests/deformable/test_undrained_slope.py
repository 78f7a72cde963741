"""Strength reduction on an undrained slope of plastic deformable blocks (issue 39): Griffiths & Lane's 2:1 slope with
φ 0 and c_u/γH 0.25 on a firm base at the toe (Taylor's D = 1; the critical circle, Taylor's, 2.060) cut into
triangles. Plastic flow at φ = ψ = 0 keeps volume, where constant-strain elements that lock stand far above the
continuum and do not come down as they shrink; these triangles come down (2 m +9.2 %). Fails on 57ec427 (no
triangle_slope_blocks)."""
from test_plastic_slope import converges


def test_undrained_slope_of_triangles_converges_to_the_continuum():
    converges(dict(slope="taylor"), "undrained, c_u/γH 0.25")
