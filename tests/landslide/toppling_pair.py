# Goodman & Bray's toppling of two columns on a stepped base (Hoek & Bray's ch. 10 geometry): the toe column
# A 2 x 3 m, behind it B 2 x 9 m on a step 0.5 m higher, gravity tilted 13.5 deg towards the toe, joints
# frictional (phi 40 deg, c = 0). B topples alone and A, low, holds it by friction: Goodman & Bray's FS 2.572.
# Built by column_blocks on a stepped ground, settled with the friction held (the columns' in-situ state),
# then strength reduction at the blocks' Young's modulus E (the joints' stiffness ~ E / block size).
#   yade-rbsm -n -x toppling_pair.py <E [Pa]> <max_steps>
# Prints GB <Goodman & Bray's FS>, fos()'s table, and RESULT <FS> <mechanism> <fos()'s Goodman & Bray> <warnings>.
import math
import sys

from yade import O, wrapper

from yade_rbsm import slope, toppling

young, max_steps = float(sys.argv[1]), int(sys.argv[2])
psi, phi, g = math.radians(13.5), math.radians(40.0), 9.81
ground = [(0, 3), (2, 3), (2, 9.5), (4, 9.5)]
base = [(0, 0), (2, 0), (2, 0.5), (4, 0.5)]
rock = wrapper.RbsmMat(young=young, poisson=0.25, density=2600, frictionAngle=phi, cohesion=0.0, tensileStrength=0.0)
O.materials.append(rock)
blocks = slope.column_blocks(ground, base, 2.0, wall=0.0)
print("GB %.5f" % toppling.goodman_bray_fs(toppling.columns(blocks), psi, phi))
model = slope.SlopeModel(blocks, rock)
model.build(gravity=(-g * math.sin(psi), -g * math.cos(psi), 0))
model.settle(hold_friction=5.0, progress=None)  # B would topple while gravity comes on at once
model.settle(progress=None, name="equilibrium")
r = model.fos(d_fail=0.1, max_steps=max_steps, rtol=0.003, probe=False)
print(r.to_markdown())
gb = r.estimates["Goodman & Bray, toppling (rigid columns)"]["fs"]
print("RESULT %.5f %s %.5f %d" % (r.fs, r.strength_reduction.mechanism or "-", gb, len(r.warnings)))
