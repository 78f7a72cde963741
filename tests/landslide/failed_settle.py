# A slope that fails while settling at its joints' strength (a wedge on a 30 deg plane of 25 deg friction, no
# cohesion: Hoek & Bray's plane-failure slope of jointset_plane.py): the wedge slides off and comes to rest on the
# ground in front of the toe, where fos() finds a factor of safety of its own. RESULT: the stages' figures and fos().
import json
import math

from yade import O, wrapper

from yade_rbsm import slope as sl

xt, H = 10.0, 12.0
xcrest = xt + H / math.tan(math.radians(60))
xd, yd, xc = xt + 3 / math.tan(math.radians(60)), 3.0, 22.0
yc = yd + (xc - xd) * math.tan(math.radians(30))
rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=2600, frictionAngle=math.radians(45), cohesion=5e6,
                       tensileStrength=2e6, ductile=True)
O.materials.append(rock)
bedding = sl.Trace([(xd, yd), (xc, yc)], cohesion=0, friction_angle=25, ductile=True, name="bedding")
crack = sl.Trace([(xc, yc), (xc, H)], friction_angle=20, ductile=True, name="tension crack")
m = sl.SlopeModel(sl.jointset_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, traces=[bedding, crack]), rock)
m.build(enlarge=0.01)
m.settle()
m.give_joint_sets(max_steps=20000)
r = m.fos()
print(repr(r))
print("RESULT " + json.dumps(dict(fs=r.fs, conclusive=r.conclusive, warnings=r.warnings,
                                  stage=m.stages[-2].figures if m.stages[-2].name == "equilibrium" else None)))
