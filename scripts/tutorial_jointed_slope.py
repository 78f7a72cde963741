# A jointed rock slope from two joint sets to a factor of safety and a runout, in YADE's loop.
#   build/yade-rbsm -n -x scripts/tutorial_jointed_slope.py [out_dir]
import math, os, sys
from yade_rbsm import engines, slope, joint_sets, monitor
out = sys.argv[1] if len(sys.argv) > 1 else "out/tutorial"
os.makedirs(out, exist_ok=True)
rock = RbsmMat(young=2e8, poisson=0.2, density=2600, frictionAngle=math.radians(40), cohesion=1e6,
               tensileStrength=5e5, label="rock")                          # intact rock, SI units
O.materials.append(rock)
bedding = slope.JointSet(dip=-30, spacing=3, friction_angle=35, cohesion=5e4, name="bedding")  # daylights
cross = slope.JointSet(dip=75, spacing=4, friction_angle=35, name="cross joints")
sb = slope.jointset_blocks([(0, 20), (18, 20), (30, 0), (48, 0)], base=-6, sets=[bedding, cross])
print(joint_sets.report(sb))
slope.build_scene(sb, rock)
O.engines = engines()
slope.bond_and_break(sb, give_sets=False)      # in-situ stress at the rock's strength (UDEC's practice)
slope.settle(tol=1e-4, density_scaling=True)
slope.give_joint_sets(sb)                      # then the joints' own strength, and equilibrium again
slope.settle(tol=1e-4, density_scaling=True)
r = slope.fos(sb)                              # strength reduction, and what it is compared with
print(r)
r.to_markdown(os.path.join(out, "fos.md"))
O.engines[-1].damping = 0.0                    # dynamic stage: the real strengths, then strengths / 1.3
slope.apply_joint_sets(F=1.3)
mon = monitor.Monitor(ids=[b.id for b in sb.free], period=200, progress=5.0)
t_end = O.time + 1.0
mon.target(time=1.0)
while O.time < t_end:
    O.run(500, True)
mon.save(os.path.join(out, "runout"), title="joint sets / 1.3: runout")
print("largest displacement after 1 s: %.2f m" % max((O.bodies[b.id].state.pos - O.bodies[b.id].state.refPos).norm()
                                                     for b in sb.free))
