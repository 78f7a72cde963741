"""A block and a YADE Wall that meet mid-run (the block already seen by the time stepper, so its joints'
reduced masses are not recomputed then): params blockFixed, wallMass (the wall free along y with that mass;
0: fixed by utils.wall), release (the fixed block, driven up to the fixed wall, released two steps after they
met: its joint then has a free end). Returns the joint's RbsmGeom.reducedMass with the masses of both ends."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade import utils  # noqa: E402
from _common import params, emit  # noqa: E402
from yade_rbsm import polygon2d, mixed_engines, advance  # noqa: E402

p = params()
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(rock)
# the block's top at y = 0.5, the wall 2 mm above it
b = O.bodies[O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 0.5), (0, 0.5)], rock, fixed=p["blockFixed"]))]
w = utils.wall((0, 0.502, 0), axis=1, sense=-1, material=rock)
if p["wallMass"] > 0:  # the free wall moves down onto the block
    w.state.mass, w.state.blockedDOFs, w.state.vel = p["wallMass"], "xzXYZ", (0, -0.2, 0)
else:  # the block moves up to the fixed wall
    b.state.vel = (0, 0.2, 0)
O.bodies.append(w)
O.engines = mixed_engines(gravity=(0, 0, 0), contact_damping=0.3)
O.dt = 1e-4  # a free wall over a fixed block: no free block for the stepper's first-contact step (it keeps O.dt)
advance(5)
joints0 = sum(1 for i in O.interactions if i.isReal)
for _ in range(4000):  # a step at a time: the wall bounces off within a few dozen
    advance(1)
    if any(i.isReal for i in O.interactions):
        break
if p.get("release"):
    b.state.vel, b.state.blockedDOFs = (0, 0, 0), "zXY"
    advance(2)
I = [i for i in O.interactions if i.isReal][0]
emit({"jointsAtStart": joints0, "iter": O.iter, "reducedMass": I.geom.reducedMass, "blockMass": b.state.mass, "wallMass": w.state.mass})
