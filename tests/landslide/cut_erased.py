"""A block on a builder's cut erased after bond_and_break (a fallen block removed from the scene), then
joints_on and set_joint_strength on the cut: the joints of the other blocks are found and set. Before:
joints_on asked YADE's interactions.has() about the erased block's recorded cut joint, which aborts the
process (boost assertion px != 0; under yade.mpy every rank, for the blocks other ranks hold)."""
import json

from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import slope as sl

rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2600, frictionAngle=0.7, cohesion=5e6, tensileStrength=2e6)
O.materials.append(rock)
plane = [(0.0, 2.0), (20.0, 2.0)]
sb = sl.brick_blocks([(0.0, 3.0), (20.0, 3.0)], 0.0, 2.0, 1.0, joints=[plane])
sl.build_scene(sb, rock)
O.engines = yr.engines()
sl.bond_and_break(sb)
before = len(sl.joints_on([plane]))
victim = min(json.loads(O.tags["yade_rbsm.cut_joints"])[0][:2])
lost = sum(1 for I in sl.joints_on([plane]) if victim in (I.id1, I.id2))
O.bodies.erase(victim)
after = len(sl.joints_on([plane]))
n_set = sl.set_joint_strength([plane], cohesion=1e4, friction_angle=0.5)
print("RESULT " + json.dumps({"before": before, "lost": lost, "after": after, "set": n_set}))
