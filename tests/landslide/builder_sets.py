"""A Voronoi soil slope crossed by a fault trace (issue 36: the builders share the joint-set way in):
voronoi_slope_blocks(traces=[fault]); bond_and_break gives the fault its strength, joints_of('fault') finds
its joints by name. Prints RESULT with the fault's joints' (cohesion, tan phi) and the others' count."""
import json
import math

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl

soil = wrapper.RbsmMat(young=1e8, poisson=0.3, density=2000, frictionAngle=math.radians(30), cohesion=2e4,
                       tensileStrength=1e4)
O.materials.append(soil)
fault = sl.Trace([(5, -12), (30, 25)], friction_angle=20, name="fault")
sb = sl.voronoi_slope_blocks([(-10, 0), (10, 0), (20, 20), (40, 20)], -10, spacing=3, seed=1, traces=[fault])
sl.build_scene(sb, soil)
O.engines = yr.engines()
sl.bond_and_break(sb)
on = [(I.phys.cohesion, I.phys.tanPhi) for I in sl.joints_of("fault")]
others = [I for I in O.interactions if I.isReal and (I.id1, I.id2) not in {(J.id1, J.id2) for J in sl.joints_of("fault")}]
print("RESULT " + json.dumps(dict(on=on, others=len(others), others_c=sorted({I.phys.cohesion for I in others}),
                                  length=sb.joint_sets[0].length)))
