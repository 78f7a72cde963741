"""What the drawings mark as failed (snapshots.failed_joints, red in strength reduction's mechanism
PNGs): a joint slipping at its strength, or broken and open. A ductile joint that slips keeps its
cohesion (its points stay intact), and used to be left out: a new user's trial of a cohesive
ductile joint set saw its sliding plane drawn with no joint failed."""
import pytest

from yaderun import run_ok

SCENE = """
import math
from yade_rbsm import polygon2d, snapshots, omega
mat = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=math.radians(30), cohesion=1e4,
              tensileStrength=1e4, ductile=%s)
O.materials.append(mat)
lower = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat, fixed=True))
upper = O.bodies.append(polygon2d([(0, 1), (1, 1), (1, 2), (0, 2)], mat))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=True)],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()])]
O.dt = 1e-5
O.step()  # bonded, at rest: nothing failed
before = len(snapshots.failed_joints(O))
O.bodies[upper].state.vel = (1.0, 0, 0)  # sheared far beyond its elastic slip
O.bodies[upper].state.blockedDOFs = 'xyzXYZ'
for k in range(20):
    O.step()
p = O.interactions[lower, upper].phys
report(before=before, after=len(snapshots.failed_joints(O)), intact=p.nIntact, slipping=p.nSlipping)
"""


@pytest.mark.parametrize("ductile", [True, False])
def test_a_slipping_joint_is_drawn_failed(ductile):
    r = run_ok(SCENE % ductile)[0]
    assert r["before"] == 0
    if ductile:
        assert r["slipping"] == 2 and r["intact"] == 2, r  # slipping with its cohesion
    else:
        assert r["intact"] == 0, r  # broken at its first slip (and open: no overlap, no friction)
    assert r["after"] == 1, r
