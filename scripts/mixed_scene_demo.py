# Mixed scene (issue 17): a granular backfill of YADE spheres retained by a wall of Polygon2D blocks,
# all on a YADE Wall as the ground, with a second Wall closing the backfill on the left. Headless; writes
# out/mixed_scene/mixed_start.png and mixed_end.png (another directory as the first argument, or RBSM_OUT=...)
# and prints the thrust of the spheres on the block wall and how far the wall's top moved.
#   build/yade-rbsm -n -x scripts/mixed_scene_demo.py [out_dir]
import os
import random
import sys

from yade import utils
from yade_rbsm import polygon2d, mixed_engines
from yade_rbsm.snapshots import block_polygons

out = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("RBSM_OUT", os.path.join("out", "mixed_scene"))
os.makedirs(out, exist_ok=True)
random.seed(1)

rock = RbsmMat(young=1e8, poisson=0.2, density=2400, frictionAngle=radians(35), label="rock")  # blocks
sand = FrictMat(young=2e7, poisson=0.3, density=2600, frictionAngle=radians(25), label="sand")  # grains
O.materials.append([rock, sand])
O.bodies.append(utils.wall((0, 0, 0), axis=1, material=rock))    # the ground: blocks rest on it as on a fixed block
O.bodies.append(utils.wall((-2.5, 0, 0), axis=0, material=rock))  # closes the backfill on the left

# the retaining wall: six courses of 0.5 x 0.3 m blocks
wall = [O.bodies.append(polygon2d([(0, y), (0.5, y), (0.5, y + 0.3), (0, y + 0.3)], rock)) for y in [0.3 * k for k in range(6)]]
# the backfill: a loose, jittered grid of spheres, r = 0.06-0.1 m, moving in the plane, that collapses
grains = []
for i in range(11):
    for j in range(16):
        s = utils.sphere((-2.35 + 0.21 * i + random.uniform(-0.04, 0.04), 0.12 + 0.22 * j, 0), random.uniform(0.06, 0.1), material=sand)
        s.state.blockedDOFs = "zXY"
        grains.append(O.bodies.append(s))

O.engines = mixed_engines(gravity=(0, -9.81, 0), damping=0.2, contact_damping=0.3)
print("O.dt = %.3g s (the spheres' P-wave step; RbsmTimeStepper lowers it if the block joints need it)" % O.dt)


def picture(name, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Circle

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.add_collection(PolyCollection([p[1] for p in block_polygons()], facecolors="#b08060", edgecolors="k", linewidths=0.6))
    for i in grains:
        b = O.bodies[i]
        ax.add_patch(Circle((b.state.pos[0], b.state.pos[1]), b.shape.radius, facecolor="#e0c060", edgecolor="0.3", lw=0.4))
    ax.plot([-2.7, 1.5], [0, 0], "k-", lw=2)
    ax.plot([-2.5, -2.5], [0, 3.7], "k-", lw=2)
    ax.set_xlim(-2.7, 1.5)
    ax.set_ylim(-0.1, 3.8)
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


picture("mixed_start.png", "spheres (FrictMat) behind a wall of Polygon2D blocks, t = 0")
top0 = O.bodies[wall[-1]].state.pos[0]
while O.time < 3.0:
    O.run(500, True)
thrust = sum(-i.phys.normalForce[0] - i.phys.shearForce[0] for i in O.interactions
             if i.isReal and type(i.phys).__name__ == "FrictPhys" and (i.id1 in wall or i.id2 in wall))
picture("mixed_end.png", "t = %.2f s: the backfill has settled against the wall" % O.time)
print("t = %.2f s, %d steps: horizontal thrust of the spheres on the block wall %.0f N per m, its top moved %.2g m"
      % (O.time, O.iter, abs(thrust), O.bodies[wall[-1]].state.pos[0] - top0))
