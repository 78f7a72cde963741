# A 1 m rock layer on a horizontal joint set with its own springs (slope.set_joint_strength's
# normal_stiffness), bricks of strong rock above and below: in the middle of the 40 m layer, far from
# the walls, the layer settles on the set by rho g h / kn (the blocks are rigid: the joint's overlap
# is all of it).   yade-rbsm -n -x joint_set_layer.py KN|kawai [after]
#   after: the set given once the layer has settled on the rock's springs (a softer set: the layer sinks onto
#   it; a stiffer one is refused, since the normal springs are total and its force would jump)
import json
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl

kn = None if sys.argv[1] == "kawai" else float(sys.argv[1])
after = len(sys.argv) > 2 and sys.argv[2] == "after"
rho, g, h = 2600.0, 9.81, 1.0
rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=rho, frictionAngle=0.7, cohesion=5e6, tensileStrength=2e6)
O.materials.append(rock)
plane = [(0.0, 2.0), (40.0, 2.0)]
sb = sl.brick_blocks([(0.0, 3.0), (40.0, 3.0)], 0.0, 2.0, 1.0, joints=[plane])
sl.build_scene(sb, rock)
O.engines = yr.engines(set_dt=True)
O.dt = 1e-6
sl.bond_and_break(sb)
springs = {} if kn is None else dict(normal_stiffness=kn, shear_stiffness=kn / 2)


def give():
    return sl.set_joint_strength([plane], 1e5, 0.6, **springs)


n_set = 0 if after else give()
sl.settle(tol=1e-6, max_steps=200000, check=200)
dt_settled = O.dt
if after:
    try:
        n_set = give()
    except ValueError as e:  # a stiffer set on loaded joints
        print("RESULT " + json.dumps(dict(error=str(e))))
        sys.exit(0)
    sl.settle(tol=1e-6, max_steps=200000, check=200)


def mean_dy(y0, y1):  # free blocks between x 15 and 25 whose centroid was between y0 and y1
    d = [b.state.pos[1] - b.state.refPos[1] for b in O.bodies
         if b.dynamic and 15 < b.state.refPos[0] < 25 and y0 < b.state.refPos[1] < y1]
    return sum(d) / len(d)


set_joints = sl.joints_on([plane])
print("RESULT " + json.dumps(dict(overlap=mean_dy(1.0, 2.0) - mean_dy(2.0, 3.0), closed=rho * g * h / (kn or float("inf")),
                                  n_set=n_set, kn=sorted({I.phys.kn for I in set_joints}),
                                  ks=sorted({I.phys.ks for I in set_joints}), dt_settled=dt_settled, dt=O.dt)))
