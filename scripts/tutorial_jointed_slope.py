# A jointed rock slope from two joint sets to a factor of safety and a runout, in YADE's loop.
#   build/yade-rbsm -n -x scripts/tutorial_jointed_slope.py [out_dir]
import math, os, sys
from yade_rbsm import slope, joint_sets, snapshots
out = sys.argv[1] if len(sys.argv) > 1 else "out/tutorial"
os.makedirs(out, exist_ok=True)
rock = RbsmMat(young=2e8, poisson=0.2, density=2600, frictionAngle=math.radians(40), cohesion=1e6,
               tensileStrength=5e5, label="rock")                          # intact rock, SI units
O.materials.append(rock)
bedding = slope.JointSet(dip=-30, spacing=3, friction_angle=35, cohesion=5e4, name="bedding")  # daylights
cross = slope.JointSet(dip=75, spacing=4, friction_angle=35, name="cross joints")
blocks = slope.jointset_blocks([(0, 20), (18, 20), (30, 0), (48, 0)], base=-6, sets=[bedding, cross])
print(joint_sets.report(blocks))
model = slope.SlopeModel(blocks, rock)
model.build()              # blocks in O.bodies, engines(), joints bonded at the rock's strength
snapshots.snapshot(os.path.join(out, "blocks.png"), "two joint sets", O=O)
model.settle()             # in-situ stress (UDEC's practice: elastic equilibrium first)
model.give_joint_sets()    # then the joints' own strength, and equilibrium again
r = model.fos()            # strength reduction, and what it is compared with
print(r)
r.to_markdown(os.path.join(out, "fos.md"))
model.run(1.0, strength_factor=1.3)     # dynamic stage, undamped, at the joints' strength / 1.3
print(model)
model.report(os.path.join(out, "report.md"))
O.save(os.path.join(out, "slope.yade.gz"))   # SlopeModel.resume() after O.load continues it
