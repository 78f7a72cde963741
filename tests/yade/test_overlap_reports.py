"""Deep overlaps are reported five times per process (a warning per step would flood a landslide's log); a
new user's trial (issue 37) then watched a pair of blocks go from 5 % to 16.5 % of the smaller block without a
word. After the first five, an overlap twice the deepest reported so far is reported again: a soft block
settling on a base (five lines, 5.1 to 10.1 % of its diameter while it bounces; 8.8 % settled), then under
three times the gravity: reported at 21.2 %; on 4565c83 nothing was printed after the fifth line."""
import re

from yaderun import results, run_yade

SCENE = """
from yade_rbsm import polygon2d, engines, advance, omega
soft = RbsmMat(young=2e5, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(soft)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], soft, fixed=True))
b = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], soft))
O.bodies[b].state.blockedDOFs = "zXYZ"  # it sinks (a block half sunk in a soft base would topple)
O.engines = engines(damping=0.5)
for k in range(40):
    advance(200)
settled = 0.5 - O.bodies[b].state.pos[1]
omega.newton(O).gravity = (0, -3 * 9.81, 0)
for k in range(40):
    advance(200)
report(settled=settled, loaded=0.5 - O.bodies[b].state.pos[1])
"""


def test_a_growing_overlap_is_reported_again():
    p = run_yade(SCENE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    lines = [l for l in p.stderr.splitlines() if "yade-rbsm: WARNING: bodies #0 and #1 overlap by" in l]
    print(r, "\n".join(lines))
    assert 0.08 < r["settled"] < 0.1 and r["loaded"] > 2.5 * r["settled"]  # the scene: 8.8 %, then about 3 x
    assert len(lines[:5]) == 5 and "further overlap warnings only for twice the deepest before" in lines[4]
    again = [float(re.search(r", ([0-9.]+) % of the smaller", l).group(1)) for l in lines[5:]]
    deepest = max(float(re.search(r", ([0-9.]+) % of the smaller", l).group(1)) for l in lines[:5])
    assert again and again[0] > 2 * deepest and all("overlaps are growing" in l for l in lines[5:]), lines
    assert len(lines) <= 8  # each report at least doubles the last: a few lines, not one per step
