"""Issue 34, item 7: a block thrown at a thin fixed wall (1 mm thick, 2 m high) went through it with overlap
warnings only (5 m/s was enough: the soft joint springs let it sink 11 mm, eleven times the wall's thickness).
An overlap deeper than the thinner block's half-width along the contact normal means the two blocks have passed
its middle, after which the axis search prefers the other side and the springs push the block through. An impact
(closing a tenth of that half-width per step or more) stops the run after that step with an ERROR naming both
bodies, the depth and the half-width; a slow squeeze (a small block pinched in a pile settling under density
scaling, tests/yade/test_density_scaling_joints.py) is a WARNING and the run goes on. A block that merely hits
a thick wall goes on. On f356525: passed through, no error."""
import re

import pytest

from yaderun import run_yade, results

SCENE = r"""
import sys
from yade_rbsm import polygon2d, engines
v, t = %(v)g, %(t)g
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(rock)
O.bodies.append(polygon2d([(1.0, -1), (1.0 + t, -1), (1.0 + t, 1), (1.0, 1)], rock, fixed=True))
b = O.bodies.append(polygon2d([(-0.5, -0.25), (0.5, -0.25), (0.5, 0.25), (-0.5, 0.25)], rock))
O.bodies[b].state.vel = (v, 0, 0)
O.engines = engines(gravity=(0, 0, 0))
O.run(3000, True)
x = O.bodies[b].state.pos[0]
report(x=x, iter=O.iter, inradius=O.bodies[0].shape.inradius, passed=x - 0.5 > 1.0 + t)
"""


@pytest.mark.parametrize("v", [5.0, 50.0])
def test_a_block_does_not_pass_through_a_thin_wall_silently(v):
    p = run_yade(SCENE % dict(v=v, t=1e-3))
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    (r,) = results(p)
    assert r["inradius"] == pytest.approx(5e-4)
    assert not r["passed"] and r["iter"] < 3000, r  # stopped before the block was through
    m = re.search(r"ERROR: Ig2_Polygon2D_Polygon2D_RbsmGeom: bodies #0 and #1 overlap by ([0-9.e-]+) m, deeper than "
                  r"the thinner block's half-width along the contact normal ([0-9.e-]+) m: one is passing through", p.stderr)
    assert m and float(m.group(1)) > float(m.group(2)), p.stderr[-2000:]


def test_a_thick_wall_stops_the_block_and_the_run_goes_on():
    p = run_yade(SCENE % dict(v=5.0, t=0.5))
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    (r,) = results(p)
    assert r["iter"] == 3000 and r["x"] < 0.5 + 1e-2, r  # bounced off (the block's face at most 1 cm in)
    assert "ERROR" not in p.stderr, p.stderr[-2000:]
