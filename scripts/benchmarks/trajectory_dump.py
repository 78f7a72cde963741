"""Bit-identity check for refactors (issue 20): seven short scenes (random piles with exact and frozen
kinematics, one under density scaling, one of deformable blocks, a brick slope like landslide_slope.py's, a rocking block, spheres behind a block wall), every
100 steps every body's pos/ori/vel/angVel and every joint's forces and segment with repr() (17 digits).
Run before and after a change and cmp the two files:
    build/yade-rbsm -n -x scripts/benchmarks/trajectory_dump.py /tmp/before.txt
"""
import sys, math, random
from yade import O, utils
from yade_rbsm import polygon2d, engines, mixed_engines

out = open(sys.argv[1] if len(sys.argv) > 1 else "trajectory_dump.txt", "w")

def dump(tag):
    out.write("## %s iter %d time %r dt %r\n" % (tag, O.iter, O.time, O.dt))
    for b in O.bodies:
        s = b.state
        out.write("b %d %r %r %r %r %r %r %r %r\n" % (b.id, s.pos[0], s.pos[1], s.ori[3], s.ori[2], s.vel[0], s.vel[1], s.angVel[2], s.ori[0]))
    for I in sorted((I for I in O.interactions if I.isReal), key=lambda I: (I.id1, I.id2)):
        p, g = I.phys, I.geom
        line = "j %d %d" % (I.id1, I.id2)
        if type(p).__name__ == "RbsmPhys":
            line += " %r %r %r %r %r %r %r %r %r %d %d %d" % (p.normalForce, p.shearForce, g.p0[0], g.p0[1], g.p1[0], g.p1[1], g.d0, g.d1, g.separation, g.refBody, g.refEdge, g.frozenSteps)
        elif hasattr(p, "normalForce"):
            line += " %r %r %r %r %r %r" % (p.normalForce[0], p.normalForce[1], p.normalForce[2], p.shearForce[0], p.shearForce[1], p.shearForce[2])
        out.write(line + "\n")

def random_pile(seed, n, tol, steps, density_scaling=False, deformable=False):
    O.reset()
    rng = random.Random(seed)
    rock = RbsmMat(young=1e7, poisson=0.2, density=2500, frictionAngle=math.radians(30), cohesion=0, tensileStrength=0, deformable=deformable)
    O.materials.append(rock)
    def convex(size):
        nv = rng.randint(3, 9); aspect = rng.uniform(1, 4); a, b = size / 2, size / 2 / aspect
        while True:
            ang = sorted(rng.uniform(0, 2 * math.pi) for _ in range(nv))
            gaps = [(ang[(i + 1) % nv] - ang[i]) % (2 * math.pi) for i in range(nv)]
            if min(gaps) > 0.2 * 2 * math.pi / nv: break
        rot = rng.uniform(0, math.pi); c, s = math.cos(rot), math.sin(rot)
        return [(c * a * math.cos(t) - s * b * math.sin(t), s * a * math.cos(t) + c * b * math.sin(t)) for t in ang]
    sizes = sorted((math.exp(rng.uniform(math.log(0.1), math.log(1.5))) for _ in range(n)), reverse=True)
    W = 8.0; x, y, row = 0.0, 0.0, 0.0; placed = []
    for poly in (convex(s) for s in sizes):
        xs, ys = [v[0] for v in poly], [v[1] for v in poly]; w, h = max(xs) - min(xs), max(ys) - min(ys)
        gap = 0.002
        if x + w + gap > W: x, y, row = 0.0, y + row, 0.0
        dx, dy = x + gap - min(xs), y + gap - min(ys)
        placed.append([(vx + dx, vy + dy) for vx, vy in poly]); x += w + gap; row = max(row, h + gap)
    top = y + row
    O.bodies.append(polygon2d([(-1, -1), (W + 1, -1), (W + 1, 0), (-1, 0)], rock, fixed=True))
    O.bodies.append(polygon2d([(-1, 0), (0, 0), (0, top + 2), (-1, top + 2)], rock, fixed=True))
    O.bodies.append(polygon2d([(W, 0), (W + 1, 0), (W + 1, top + 2), (W, top + 2)], rock, fixed=True))
    for poly in placed:
        b = polygon2d(poly, rock)
        b.state.vel = (rng.uniform(-1, 1), rng.uniform(-1, 1), 0); b.state.angVel = (0, 0, rng.uniform(-3, 3))
        O.bodies.append(b)
    O.engines = engines(update_tolerance=tol, contact_damping=0.05, damping=0.3 if density_scaling else 0.0)
    timeStepper = [e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0]
    timeStepper.densityScaling = density_scaling
    for k in range(steps // 100):
        O.run(100, True); dump("pile seed %d tol %g%s%s" % (seed, tol, " densityScaling" if density_scaling else "", " deformable" if deformable else ""))

def landslide(steps):
    O.reset()
    from yade_rbsm import slope
    rock = RbsmMat(young=2e8, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=0, tensileStrength=0)
    O.materials.append(rock)
    surface = [(0, 2), (6, 2), (14, 12), (24, 12)]
    sb = slope.brick_blocks(surface, 0.0, 2.0, 1.0, joints=[[(6, 2), (6 + 10 / math.tan(math.radians(35)), 12)]], crack=(17, 8))
    slope.build_scene(sb, rock)
    O.engines = engines(damping=0.3, nIP=3)
    slope.bond_and_break(sb)
    for k in range(steps // 100):
        O.run(100, True); dump("landslide")

def rocking(steps):
    O.reset()
    rock = RbsmMat(young=1e8, poisson=0.2, density=2400, frictionAngle=math.radians(40), cohesion=0, tensileStrength=0)
    O.materials.append(rock)
    O.bodies.append(polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], rock, fixed=True))
    c, s = math.cos(0.05), math.sin(0.05)
    blk = [(c * x - s * y, s * x + c * y + 0.02) for x, y in [(-0.5, 0), (0.5, 0), (0.5, 2), (-0.5, 2)]]
    b = polygon2d(blk, rock); b.state.angVel = (0, 0, -0.3); O.bodies.append(b)
    b2 = polygon2d([(1.0, 0.0), (2.0, 0.0), (1.7, 0.8), (1.2, 1.0)], rock); b2.state.vel = (-0.5, 0, 0); O.bodies.append(b2)
    O.engines = engines(nIP=4)
    for k in range(steps // 100):
        O.run(100, True); dump("rocking")

def mixed(steps):
    O.reset()
    rng = random.Random(3)
    rock = RbsmMat(young=1e8, poisson=0.2, density=2400, frictionAngle=math.radians(35))
    sand = FrictMat(young=2e7, poisson=0.3, density=2600, frictionAngle=math.radians(25))
    O.materials.append([rock, sand])
    O.bodies.append(utils.wall((0, 0, 0), axis=1, material=rock))
    O.bodies.append(utils.wall((-1.5, 0, 0), axis=0, material=rock))
    for y in [0.3 * k for k in range(4)]:
        O.bodies.append(polygon2d([(0, y), (0.5, y), (0.5, y + 0.3), (0, y + 0.3)], rock))
    for i in range(6):
        for j in range(6):
            sp = utils.sphere((-1.35 + 0.21 * i + rng.uniform(-0.04, 0.04), 0.12 + 0.22 * j, 0), rng.uniform(0.06, 0.1), material=sand)
            sp.state.blockedDOFs = "zXY"; O.bodies.append(sp)
    O.engines = mixed_engines(gravity=(0, -9.81, 0), damping=0.2, contact_damping=0.3)
    for k in range(steps // 100):
        O.run(100, True); dump("mixed")

random_pile(1, 60, 0.0, 600)
random_pile(2, 60, 1e-4, 600)
landslide(400)
rocking(500)
mixed(400)
random_pile(4, 60, 0.0, 800, density_scaling=True)
random_pile(5, 60, 0.0, 600, deformable=True)
out.close()
print("TRAJECTORY DONE")
