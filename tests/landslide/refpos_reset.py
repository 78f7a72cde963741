"""Issue 36: set_joint_strength and joints_on found a set's joints through State.refPos, so YADE's idiom
of resetting displacements (b.state.refPos = b.state.pos) after settling changed which joints they found
later. A soft layer settles on a bedding plane (its joints sink by the springs' overlap), the script resets
refPos, the layer slides 3 m along the plane onto new neighbours: the contacts on the plane, counted by their
geometry now, against those joints_on finds.
  yade-rbsm -n -x refpos_reset.py [reset|keep]"""
import json
import math
import sys

from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import omega
from yade_rbsm import slope as sl

reset = (sys.argv[1] if len(sys.argv) > 1 else "reset") == "reset"
soil = wrapper.RbsmMat(young=2e6, poisson=0.25, density=2000, frictionAngle=0.7, cohesion=5e6, tensileStrength=2e6)
O.materials.append(soil)
plane = [(-1.0, 2.0), (41.0, 2.0)]
sb = sl.brick_blocks([(0.0, 3.0), (40.0, 3.0)], 0.0, 2.0, 1.0, joints=[plane], wall=0)
sl.build_scene(sb, soil)
O.engines = yr.engines()
sl.bond_and_break(sb)
sl.settle(tol=1e-3, max_steps=20000)
sunk = -min(O.bodies[b.id].state.pos[1] - O.bodies[b.id].state.refPos[1] for b in sb.free if b.vertices[0][1] >= 2.0 - 1e-9)
if reset:
    for b in O.bodies:
        b.state.refPos, b.state.refOri = b.state.pos, b.state.ori
sl.set_joint_strength([plane], cohesion=0.0, friction_angle=math.radians(5))
upper = [b.id for b in sb.free if min(y for _, y in b.vertices) >= 2.0 - 1e-9]
for i in upper:
    O.bodies[i].state.vel = (3.0, 0, 0)
omega.newton(O).gravity = (0, -9.81, 0)
t0 = O.time
while O.time - t0 < 1.0:
    O.run(200, True)
moved = min(O.bodies[i].state.pos[0] - O.bodies[i].state.refPos[0] for i in upper) if reset else None


def on_plane_now(I):
    y1, y2 = O.bodies[I.id1].state.pos[1], O.bodies[I.id2].state.pos[1]
    return (y1 - 2.0) * (y2 - 2.0) < 0 and abs(I.geom.p0[1] - 2.0) < 0.05 and abs(I.geom.p1[1] - 2.0) < 0.05 and I.geom.length > 1e-3


now = {(I.id1, I.id2) for I in omega.joints(O) if on_plane_now(I)}
found = {(I.id1, I.id2) for I in sl.joints_on([plane])}
recorded = {(r[0], r[1]) for r in json.loads(O.tags["yade_rbsm.cut_joints"])}
print("RESULT " + json.dumps(dict(sunk=sunk, moved=moved, now=len(now), found=len(found & now), new=len(now - recorded),
                                  missed=sorted(now - found))))
