# Goodman & Bray's toppling on a stepped base (Hoek & Bray's ch. 10 geometry), gravity tilted 13.5 deg towards
# the toe, joints frictional (c = 0), built by column_blocks on a stepped ground, settled with the friction held
# (the columns' in-situ state), then fos() at the blocks' Young's modulus E (the joints' stiffness ~ E / size).
#   pair: the toe column A 2 x 3 m, behind it B 2 x 9 m on a step 0.5 m higher, phi 40 deg: B topples alone
#         and A, low, holds it by friction: Goodman & Bray's FS 2.572.
#   ten:  ten columns 2 m wide on steps 1 m high, 3 to 12 m tall, phi 35 deg: the toe column slides, eight
#         topple, the crest's stands: Goodman & Bray's FS 0.668 (the slope fails at its own friction).
#   yade-rbsm -n -x toppling_columns.py <pair|ten> <E [Pa]> <max_steps>
import math
import sys

from yade import O, wrapper

from yade_rbsm import slope, toppling

case, young, max_steps = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
psi, g = math.radians(13.5), 9.81
if case == "pair":
    phi = math.radians(40.0)
    ground = [(0, 3), (2, 3), (2, 9.5), (4, 9.5)]
    base = [(0, 0), (2, 0), (2, 0.5), (4, 0.5)]
else:
    phi, ground, base = math.radians(35.0), [], []
    for i, h in enumerate([3, 5, 7, 9, 11, 12, 11, 10, 9, 8]):
        ground += [(2.0 * i, i + h), (2.0 * i + 2, i + h)]
        base += [(2.0 * i, float(i)), (2.0 * i + 2, float(i))]
rock = wrapper.RbsmMat(young=young, poisson=0.25, density=2600, frictionAngle=phi, cohesion=0.0, tensileStrength=0.0)
O.materials.append(rock)
blocks = slope.column_blocks(ground, base, 2.0, wall=0.0)
print("GB %.5f" % toppling.goodman_bray_fs(toppling.columns(blocks), psi, phi))
model = slope.SlopeModel(blocks, rock)
model.build(gravity=(-g * math.sin(psi), -g * math.cos(psi), 0))
model.settle(hold_friction=5.0, progress=None)  # tall columns would topple while gravity comes on at once
model.settle(progress=None, name="equilibrium")
r = model.fos(d_fail=0.1, max_steps=max_steps, rtol=0.003, probe=False)
print(r.to_markdown())
gb = r.estimates["Goodman & Bray, toppling (rigid columns)"]["fs"]
print("RESULT %.5f %s %.5f %d" % (r.fs, r.strength_reduction.mechanism or "-", gb, len(r.warnings)))
