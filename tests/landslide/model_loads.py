"""SlopeModel with loads (issues 37, 40): the tutorial's slope, its factor of safety, then water below a
phreatic line from 8 m under the crest to the toe, then a pseudo-static kh = 0.05 out of the face, each stage
recorded and settled, fos() after each. Prints RESULT with the three factors and the stage names."""
import json
import math

from yade import O, wrapper

from yade_rbsm import slope

rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=2600, frictionAngle=math.radians(40), cohesion=1e6,
                       tensileStrength=5e5)
O.materials.append(rock)
bedding = slope.JointSet(dip=-30, spacing=3, friction_angle=35, cohesion=5e4, name="bedding")
cross = slope.JointSet(dip=75, spacing=4, friction_angle=35, name="cross joints")
m = slope.SlopeModel(slope.jointset_blocks([(0, 20), (18, 20), (30, 0), (48, 0)], base=-6, sets=[bedding, cross]), rock)
m.build()
m.settle()
m.give_joint_sets()
fs = [m.fos()]
m.set_water([(0, 12), (30, 0), (48, 0)])
fs.append(m.fos())
m.set_seismic(0.05, towards=1)  # the face looks to +x
fs.append(m.fos())
print(m)
print("RESULT " + json.dumps(dict(fs=[r.fs for r in fs], conclusive=[r.conclusive for r in fs],
                                  stages=[s.name for s in m.stages], wet=m.stages[5].figures["joints_wet"])))
