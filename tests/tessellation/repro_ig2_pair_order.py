# Scene of test_yade_voronoi.test_shared_edge_is_a_joint_in_either_body_order: two Voronoi blocks
# sharing an edge exactly (same two vertices, bit for bit) must make a joint in either body order.
# (Fixed bug: with zero overlap and no cohesion the law dropped the joint when the round-off
# separation came out +0, which happened in one order only.)
#   build/yade-rbsm -n -x tests/tessellation/repro_ig2_pair_order.py   -> PAIR True True, twice
import math
from yade_rbsm import polygon2d, engines
A=[(4.37601772786057, 1.6817020136806937), (5.380494823864725, 0.0), (6.7557150031188575, 0.0), (6.81692363617913, 0.15878722372036985), (6.245753448128187, 1.5603589517472494), (4.438850593428841, 1.7861606909480725)]
B=[(3.547937855731138, 0.0), (5.380494823864725, 0.0), (4.37601772786057, 1.6817020136806937), (4.298037874843168, 1.646525535731799)]
rock = RbsmMat(young=200e6, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=1e9, tensileStrength=1e9)
O.materials.append(rock)
for order in ((A,B),(B,A)):
    O.bodies.clear(); O.interactions.clear()
    O.bodies.append([polygon2d(order[0], rock), polygon2d(order[1], rock)])
    O.engines = engines(gravity=(0, 0, 0), verlet_dist=0)[:3]  # no NewtonIntegrator: no verletDist
    O.dt=1e-5
    O.step()
    print("PAIR", O.interactions.has(0,1), O.interactions.has(0,1) and O.interactions[0,1].isReal, [ (b.bound.min, b.bound.max) for b in O.bodies])
