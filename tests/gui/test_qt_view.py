"""The qt view draws RBSM blocks and joints (Gl1_Polygon2D, Gl1_RbsmPhys, Gl1_RbsmGeom).

Each test runs a scene in YADE's qt view under Xvfb, saves the view with SnapshotEngine (PNG) and
checks its pixels: blocks of known colours where they are, relative to the fixed base block, whose
width in pixels gives the scale of the view (the view looks down the z axis at the x-y plane), and
the joints drawn along the contact. Without the functors the view draws nothing of the blocks.
"""
import numpy as np
import pytest

from qtview import bbox, load_rgb, mask, snapshot

BLUE, RED, YELLOW = (0, 0, 1), (1, 0, 0), (1, 1, 0)
INTACT, BROKEN, GEOM = (0, 1, 0), (1, 0, 1), (1, 1, 1)

# base 6 x 1 (top at y = 0); a red 2 x 1.5 block on it, bonded; a fixed yellow right triangle (legs 2
# along x, 1 along y, centroid (8/3, 4/3)) turned by 90 degrees about its centroid, touching nothing;
# a block on the base's right end whose joint is broken.
SCENE = """
from yade_rbsm import polygon2d, engines
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.6, cohesion=1e5, tensileStrength=1e5)
O.materials.append(rock)
O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], rock, fixed=True, color=%(blue)s))
O.bodies.append(polygon2d([(-1, 0), (1, 0), (1, 1.5), (-1, 1.5)], rock, color=%(red)s))
tri = polygon2d([(2, 1), (4, 1), (2, 2)], rock, fixed=True, color=%(yellow)s)
tri.state.ori = Quaternion((0, 0, 1), pi / 2)
O.bodies.append(tri)
O.bodies.append(polygon2d([(2, 0), (3, 0), (3, 0.5), (2, 0.5)], rock, color=%(red)s))
O.engines = engines(gravity=(0, -9.81, 0))
O.engines[2].physDispatcher.functors[0].setCohesionNow = True
O.run(2, True)
O.interactions[0, 3].phys.breakJoint()
assert O.interactions[0, 1].phys.nIntact == 2 and O.interactions[0, 3].phys.nIntact == 0
Gl1_RbsmPhys.intactColor, Gl1_RbsmPhys.brokenColor = %(intact)s, %(broken)s
""" % dict(blue=BLUE, red=RED, yellow=YELLOW, intact=INTACT, broken=BROKEN)


@pytest.fixture(scope="module")
def filled():
    png, _ = snapshot(SCENE + "\nfrom yade import qt\nqt.Renderer().intrPhys = True\n")
    return load_rgb(png)


def scale_and_origin(img):
    """Pixels per metre and the pixel of the world point (0, 0), from the blue base (6 x 1 m, top centre at (0, 0))."""
    b = bbox(mask(img, BLUE))
    assert b, "no pixel of the base block's colour: the blocks are not drawn"
    x0, y0, x1, y1 = b
    s = (x1 - x0 + 1) / 6.0
    assert (y1 - y0 + 1) / s == pytest.approx(1.0, abs=0.08), "base block 6 x 1 m drawn as %s px" % (b,)
    return s, (0.5 * (x0 + x1), y0)


def to_pixel(origin, s, x, y):
    return origin[0] + s * x, origin[1] - s * y


def test_blocks_filled_in_their_colour_at_their_place(filled):
    img = filled
    s, o = scale_and_origin(img)
    assert s > 20, "the view shows the 6 m base only %.1f px wide" % (6 * s)
    red = mask(img, RED)
    red[:, int(to_pixel(o, s, 1.5, 0)[0]):] = False  # the bonded block only (the other red one is at x > 2)
    x0, y0, x1, y1 = bbox(red)
    cx, cy = to_pixel(o, s, 0, 0.75)
    assert (x1 - x0 + 1) / s == pytest.approx(2.0, abs=0.1) and (y1 - y0 + 1) / s == pytest.approx(1.5, abs=0.1)
    assert abs(0.5 * (x0 + x1) - cx) < 3 and abs(0.5 * (y0 + y1) - cy) < 3
    # filled: nearly all of its box is red (not only an outline)
    assert red[y0:y1 + 1, x0:x1 + 1].mean() > 0.9


def test_block_drawn_at_its_orientation(filled):
    """The triangle, turned by 90 degrees: its box is 1 m wide and 2 m high, its pixels' centroid at the centroid."""
    img = filled
    s, o = scale_and_origin(img)
    m = mask(img, YELLOW)
    x0, y0, x1, y1 = bbox(m)
    assert (x1 - x0 + 1) / s == pytest.approx(1.0, abs=0.1) and (y1 - y0 + 1) / s == pytest.approx(2.0, abs=0.1)
    ys, xs = np.nonzero(m)
    cx, cy = to_pixel(o, s, 8 / 3, 4 / 3)
    assert abs(xs.mean() - cx) < 3 and abs(ys.mean() - cy) < 3
    assert m.sum() / s**2 == pytest.approx(1.0, rel=0.1)  # area 1 m2


def test_joints_coloured_by_state_along_the_contact(filled):
    img = filled
    s, o = scale_and_origin(img)
    _, ytop = to_pixel(o, s, 0, 0)
    for colour, (xa, xb), what in ((INTACT, (-1, 1), "intact joint under the bonded block"),
                                   (BROKEN, (2, 3), "broken joint under the right block")):
        m = mask(img, colour)
        ys, xs = np.nonzero(m)
        assert len(xs) > 1.5 * s, "%s: %d pixels of its colour" % (what, len(xs))
        assert abs(ys - ytop).max() <= 4, "%s: pixels off the contact line" % what
        pa, pb = to_pixel(o, s, xa, 0)[0], to_pixel(o, s, xb, 0)[0]
        assert xs.min() >= pa - 3 and xs.max() <= pb + 3 and xs.max() - xs.min() >= 0.9 * (pb - pa), what


def test_wire_mode_and_joint_geometry():
    png, _ = snapshot(SCENE + """
O.bodies[1].shape.wire = True
from yade import qt
qt.Renderer().intrGeom = True
Gl1_RbsmGeom.color = %s
""" % (GEOM,))
    img = load_rgb(png)
    s, o = scale_and_origin(img)
    red = mask(img, RED)
    red[:, int(to_pixel(o, s, 1.5, 0)[0]):] = False
    x0, y0, x1, y1 = bbox(red)
    assert (x1 - x0 + 1) / s == pytest.approx(2.0, abs=0.1) and (y1 - y0 + 1) / s == pytest.approx(1.5, abs=0.1)
    assert red[y0:y1 + 1, x0:x1 + 1].mean() < 0.2, "wire block drawn filled"
    # the contact segment and its normal tick (upwards, from the base to the block) in the geometry's colour
    g = mask(img, GEOM)
    _, ytop = to_pixel(o, s, 0, 0)
    x0, y0, x1, y1 = bbox(mask(img, BLUE))
    g[:int(ytop - 2 * s)], g[y1 + 1:], g[:, :x0], g[:, x1 + 1:] = False, False, False, False  # not the view's texts
    ys, xs = np.nonzero(g)
    assert len(xs) > 1.5 * s and ys.max() <= ytop + 4
    assert ys.min() < ytop - 0.3 * s, "no normal tick above the contact"


def test_joint_line_width_grows_with_normal_force(filled):
    """Gl1_RbsmPhys.maxWidth: the bonded joint, at refForce or above, is drawn maxWidth (9 px) wide instead of lineWidth (3 px)."""
    png, _ = snapshot(SCENE + """
from yade import qt
qt.Renderer().intrPhys = True
assert O.interactions[0, 1].phys.normalForce > 1
Gl1_RbsmPhys.maxWidth, Gl1_RbsmPhys.refForce = 9, 1.0
""")
    wide, thin = mask(load_rgb(png), INTACT), mask(filled, INTACT)
    ys_w, ys_t = np.nonzero(wide)[0], np.nonzero(thin)[0]
    assert wide.sum() > 2.2 * thin.sum(), (wide.sum(), thin.sum())
    assert ys_w.max() - ys_w.min() + 1 >= 8 and ys_t.max() - ys_t.min() + 1 <= 4
