"""Issue 34, item 10: a hand-built engine list without RbsmTimeStepper ran O.dt = 1000 x the critical step
until it exploded, and O.dt = 0 without advancing, with no message; one without RbsmPairCheck let a sphere
pass through a block. The plugin says so once, when it makes its first joint: which engine is missing and
what then goes unchecked. yade_rbsm.engines()' list has both and prints nothing."""
from yaderun import run_yade, results

SCENE = """
from yade_rbsm import polygon2d, engines
mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(mat)
O.bodies.append(polygon2d([(-2, -1), (2, -1), (2, 0), (-2, 0)], mat, fixed=True))
O.bodies.append(polygon2d([(-0.5, 0.0), (0.5, 0.0), (0.5, 1), (-0.5, 1)], mat))
if HAND_BUILT:
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()], verletDist=0.01),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
                 NewtonIntegrator(gravity=(0, -9.81, 0))]
    O.dt = 1e-4
else:
    O.engines = engines()
O.run(200, True)
report(iter=O.iter, contacts=O.interactions.countReal())
"""


def _run(hand_built):
    p = run_yade("HAND_BUILT = %r\n" % hand_built + SCENE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    return r, p.stderr


def test_a_list_without_the_stepper_or_the_pair_check_is_said_once():
    r, err = _run(True)
    lines = [l for l in err.splitlines() if "yade-rbsm: WARNING" in l]
    print(r, lines)
    assert r["contacts"] == 1 and r["iter"] == 200  # it still runs: the user's list, the user's step
    assert len(lines) == 1, lines
    assert "RbsmTimeStepper" in lines[0] and "stable" in lines[0] and "RbsmPairCheck" in lines[0], lines


def test_the_list_of_engines_says_nothing():
    r, err = _run(False)
    print(r)
    assert r["contacts"] == 1 and "yade-rbsm: WARNING" not in err


TWO_NEWTONS = """
import yade_rbsm
from yade_rbsm import polygon2d, engines
mat = RbsmMat(young=1e8, poisson=0.2, density=2000)
O.materials.append(mat)
O.bodies.append(polygon2d([(-0.5, 10.0), (0.5, 10.0), (0.5, 11), (-0.5, 11)], mat))
O.engines = engines() + ([NewtonIntegrator(gravity=(0, -9.81, 0))] if TWO else [])
O.dt = 1e-3
try:
    yade_rbsm.advance(300)
    stopped = False
except RuntimeError:
    stopped = True
report(stopped=stopped, iter=O.iter, fell=10.0 - O.bodies[0].state.pos[1] + 0.5, free=0.5 * 9.81 * O.time ** 2)
"""


def test_two_newton_integrators_stop_the_run():
    """Issue 34's closing pass: engines() plus a second NewtonIntegrator let a block fall 3.6 times as far as in free
    fall, without a word. RbsmPairCheck stops the run naming the count; with one, the block falls as it should."""
    p = run_yade("TWO = True\n" + TWO_NEWTONS)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    print(r, [l for l in p.stderr.splitlines() if "yade-rbsm" in l])
    assert r["stopped"] and r["iter"] <= 2 and "2 NewtonIntegrators" in p.stderr, r
    (r,) = results(run_yade("TWO = False\n" + TWO_NEWTONS))
    assert not r["stopped"] and abs(r["fell"] - r["free"]) < 0.01 * r["free"], r
