"""Joints made between full estimates under RbsmTimeStepper.densityScaling (issue 22).

A strength-reduction trial that fails makes joints at many steps (blocks sliding past each other):
each one used to cost a full estimate of every block (the scales need the whole rows), which made a
density-scaled step 2x as expensive in the stepper (325 against 156 us on a 1200-block slope). A joint
made between estimates now raises the rows and the scales of its two blocks alone, by bounds
(subadditive terms): the scale a block gets then is at least the one a full estimate at that state
gives it, and the stage stays stable.
"""

from yaderun import run_ok

SCENE = """
import math, random
from yade import O, wrapper
from yade_rbsm import polygon2d, engines, time_stepper, advance
rock = wrapper.RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=1e5, tensileStrength=1e5)
O.materials.append(rock)
O.bodies.append(polygon2d([(-6, -1), (6, -1), (6, 0), (-6, 0)], rock, fixed=True))
# a row of blocks from 0.2 m to 2 m wide, bonded (the small ones set the plain step)
x = -5.0
for w in (2.0, 0.2, 1.0, 0.3, 2.0, 0.5):
    O.bodies.append(polygon2d([(x, 0), (x + w, 0), (x + w, 1), (x, 1)], rock))
    x += w
O.engines = engines(gravity=(0, -9.81, 0), damping=0.7, set_dt=True)
O.dt = 1e-6
ts = time_stepper()
ts.densityScaling, ts.interval = True, 100000  # no scheduled estimate in this test
advance(1)  # the first step: a full estimate, the row's joints
for I in O.interactions:
    I.phys.cohesion = 1e5  # (bond them: bond_and_break is for the slope builders)
first = ts.lastCheck
"""


# a box on the bonded row and 30 random convex blocks (0.1 m to 1 m) above it, apart, with random velocities
PILE30 = """
O.bodies.append(polygon2d([(-6.5, 0), (-6, 0), (-6, 12), (-6.5, 12)], rock, fixed=True))
O.bodies.append(polygon2d([(6, 0), (6.5, 0), (6.5, 12), (6, 12)], rock, fixed=True))
rng = random.Random(5)
for k in range(30):
    n, R = rng.randint(3, 8), 10 ** rng.uniform(-1, 0) / 2
    a0 = rng.uniform(0, 2 * math.pi)
    cx, cy = -4 + 2 * (k % 5) + rng.uniform(-0.3, 0.3), 2 + 1.1 * (k // 5)  # apart: no overlap at the start
    pts = [(cx + R * math.cos(a0 + 2 * math.pi * j / n), cy + R * math.sin(a0 + 2 * math.pi * j / n)) for j in range(n)]
    b = O.bodies.append(polygon2d(pts, rock))
    O.bodies[b].state.vel = (rng.uniform(-1, 1), rng.uniform(-1, 0), 0)
"""

def test_a_joint_made_between_estimates_scales_its_blocks_without_a_full_estimate():
    (r,) = run_ok(SCENE + """
# a 0.25 m block falls on the 0.3 m one: a joint made at some step, far from any scheduled estimate
drop = O.bodies.append(polygon2d([(-1.85, 1.2), (-1.6, 1.2), (-1.6, 1.45), (-1.85, 1.45)], rock))
ts.checkNextStep()  # (a body added by hand: estimate once, as a script does after O.bodies.append)
advance(1)
before = ts.lastCheck
made = None
for k in range(200000):
    advance(1)
    js = [I for I in O.interactions if I.isReal and drop in (I.id1, I.id2)]
    if js:
        made = js[0].iterMadeReal
        break
assert made is not None, "the block never landed"
ids = (js[0].id1, js[0].id2)
inc = {i: ts.massScale[i] for i in ids}
last_after_joint = ts.lastCheck
target = ts.scaledDt
ts.targetDt = target  # a full estimate at this state with the same target
ts.limit()
full = {i: ts.massScale[i] for i in ids}
report(before=before, made=made, last=last_after_joint, inc=[inc[i] for i in ids], full=[full[i] for i in ids])
""")
    assert r["last"] == r["before"] < r["made"], "a joint made between estimates ran a full estimate: %s" % r
    for s_inc, s_full in zip(r["inc"], r["full"]):
        assert s_inc >= s_full * (1 - 1e-12), "the incremental scale is below the full estimate's: %s" % r
    assert max(r["full"]) > 1, "the test needs a scaled block at the joint: %s" % r


def test_random_pile_settles_under_density_scaling_with_joints_made_between_estimates():
    """30 random convex blocks (0.1 m to 1 m) dropped into a box under density scaling, estimates only
    every 5000 steps: every joint they make in between is added incrementally; the pile comes to rest
    (no refusal, no explosion: the stepper's motion check would stop the run)."""
    (r,) = run_ok(SCENE + PILE30 + """
ts.interval = 5000
ts.checkNextStep()
checks = 0
for k in range(600):
    last = ts.lastCheck
    advance(50)
    checks += ts.lastCheck != last
vmax = max(b.state.vel.norm() for b in O.bodies if b.dynamic)
report(vmax=vmax, checks=checks, scaled=sum(1 for s in ts.massScale if s > 1), iter=O.iter)
""")
    assert r["vmax"] < 1e-2, r
    assert r["scaled"] > 0, r
    assert r["checks"] <= 7, "estimates ran at joints made between the scheduled ones (6 scheduled): %s" % r


def test_a_joint_on_a_frictmat_wall_made_between_estimates_scales_its_block():
    """A block's joint on a YADE Wall of FrictMat (Ip2_RbsmMat_FrictMat_FrictPhys makes its RbsmPhys)
    is a joint like one on an RbsmMat wall: it was not counted as made, so the stepper never added it
    between estimates. Under density scaling the 5 cm block kept massScale 1 at the median block's
    step (10x its own) and was thrown off the wall at 29 m/s, stopping the run."""
    (r,) = run_ok(SCENE + """
from yade import utils
from yade_rbsm import mixed_engines
steel = wrapper.FrictMat(young=1e8, poisson=0.2, density=7800, frictionAngle=0.5)
O.materials.append(steel)
wall = O.bodies.append(utils.wall((0, -3, 0), axis=1, material=steel))
O.engines = mixed_engines(gravity=(0, -9.81, 0), damping=0.7)
ts = time_stepper()
ts.densityScaling, ts.interval = True, 100000
drop = O.bodies.append(polygon2d([(8, -2.95), (8.05, -2.95), (8.05, -2.9), (8, -2.9)], rock))
advance(1)  # the first step of the new engines: a full estimate
before = ts.lastCheck
js = []
for k in range(20000):
    advance(1)
    js = [I for I in O.interactions if I.isReal and drop in (I.id1, I.id2)]
    if js:
        break
assert js and wall in (js[0].id1, js[0].id2), "the block never landed on the wall"
scale = ts.massScale[drop]
advance(2000)
report(before=before, last=ts.lastCheck, scale=scale, v=O.bodies[drop].state.vel.norm())
""")
    assert r["last"] == r["before"], r
    assert r["scale"] > 1, "the block's joint on the wall was not added to its rows: %s" % r
    assert r["v"] < 0.1, r


def test_blocks_dropped_without_joints_run_at_the_first_contact_step():
    """Density scaling on a scene without joints yet (a pile dropped on its base): the scaled step is
    the median jointed block's, so none (scaledDt inf), and the stepper set no step at all: O.dt stayed
    at YADE's 1e-8 s (a block 0.5 m above its base fell 2 micrometres in 20000 steps). Until the first
    joint it is now the unscaled step of the first contacts, as without scaling."""
    (r,) = run_ok("""
from yade import O, wrapper
from yade_rbsm import polygon2d, engines, time_stepper, advance
rock = wrapper.RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(rock)
O.bodies.append(polygon2d([(-2, -1), (2, -1), (2, 0), (-2, 0)], rock, fixed=True))
b = O.bodies.append(polygon2d([(-0.2, 0.5), (0.2, 0.5), (0.2, 0.9), (-0.2, 0.9)], rock))
O.engines = engines(gravity=(0, -9.81, 0), damping=0.7)
ts = time_stepper()
ts.densityScaling = True
advance(1)
dt0, first, scaled0 = O.dt, ts.firstContactDt, ts.scaledDt
advance(20000)
report(dt0=dt0, first=first, scaled0=scaled0, y=O.bodies[b].state.pos[1], v=O.bodies[b].state.vel.norm(),
       scale=ts.massScale[b], scaledDt=ts.scaledDt)
""")
    assert r["first"] < float("inf"), r
    assert abs(r["dt0"] / (r["first"] * 0.8 / 1.7 ** 0.5) - 1) < 1e-12, "no jointed block: O.dt must be the first contacts' step: %s" % r
    assert abs(r["y"] - 0.2) < 1e-3 and r["v"] < 1e-3, "the block must land and rest on its base: %s" % r


def test_a_loaded_density_scaled_scene_keeps_its_scales_and_schedule():
    """O.save / O.load mid-run under density scaling: the own-block shares of the rows (rowDiag) were
    not saved, so the first step after the load ran an unscheduled full estimate (any joint count
    differs from a fresh engine's), scales 0.7 % off the uninterrupted run's and positions 0.5 mm
    apart after 30 steps (30-block pile, 0.1-1 m). They are saved now: the loaded scene continues like the
    uninterrupted run, on the same estimate steps."""
    (r,) = run_ok(SCENE + PILE30 + """
ts.interval = 100
ts.checkNextStep()
advance(4000)
while ts.lastCheck != O.iter - 50:  # half way between two scheduled estimates
    advance(1)
O.save("ds_saved.yade.gz")
advance(40)
ref = [tuple(b.state.pos) for b in O.bodies]
ref_scale, ref_last = list(ts.massScale), ts.lastCheck
O.load("ds_saved.yade.gz")
ts = time_stepper()
last_saved = ts.lastCheck
advance(1)
last_1 = ts.lastCheck
advance(39)
d = max(max(abs(a - b) for a, b in zip(tuple(x.state.pos), r)) for x, r in zip(O.bodies, ref))
ds = max(abs(a - b) / b for a, b in zip(ts.massScale, ref_scale))
report(last_saved=last_saved, last_1=last_1, last=ts.lastCheck, ref_last=ref_last, d=d, ds=ds,
       scaled=sum(1 for s in ref_scale if s > 1))
""", jobs=1)
    assert r["scaled"] > 0, r
    assert r["last_1"] == r["last_saved"], "an unscheduled estimate ran right after the load: %s" % r
    assert r["last"] == r["ref_last"], r
    assert r["ds"] < 1e-12 and r["d"] < 1e-9, "the loaded run departs from the uninterrupted one: %s" % r


def test_a_scale_that_rises_keeps_the_blocks_energy():
    """A block keeping its velocity while density scaling made it s times heavier (at its first joint,
    or a full estimate) carried s times its kinetic energy into its joints. 20 blocks of 3 to 30 cm
    dropped on the bonded row (estimates every 100 steps): a 3 cm block scaled 235x at a joint flew on,
    hit the base and pressed that joint deep; the next estimate found its scale back at 1.16, the joint
    threw it at 8.8 m/s and the run stopped at step 702. A rise now slows the block's velocities by
    sqrt(s0/s) (kinetic energy of the scaled motion kept): the pile comes to rest."""
    (r,) = run_ok(SCENE + """
O.bodies.append(polygon2d([(-6.5, 0), (-6, 0), (-6, 12), (-6.5, 12)], rock, fixed=True))
O.bodies.append(polygon2d([(6, 0), (6.5, 0), (6.5, 12), (6, 12)], rock, fixed=True))
rng = random.Random(3)
for k in range(20):
    n, R = rng.randint(3, 9), 10 ** rng.uniform(-1.5, -0.5) / 2
    a0 = rng.uniform(0, 2 * math.pi)
    cx, cy = -4.5 + 1.0 * (k % 10), 1.4 + 0.6 * (k // 10)
    O.bodies.append(polygon2d([(cx + R * math.cos(a0 + 2 * math.pi * j / n), cy + R * math.sin(a0 + 2 * math.pi * j / n)) for j in range(n)], rock))
ts.interval = 100
ts.checkNextStep()
vmax = 0
for k in range(300):
    advance(100)  # (raises RuntimeError when the motion check stops the run)
    vmax = max(vmax, max(b.state.vel.norm() for b in O.bodies if b.dynamic))
report(vmax=vmax, vend=max(b.state.vel.norm() for b in O.bodies if b.dynamic), scaled=sum(1 for s in ts.massScale if s > 1))
""", jobs=1)
    assert r["scaled"] > 0, r
    assert r["vmax"] < 4 and r["vend"] < 1e-3, r


def test_a_pile_dropped_in_a_box_of_walls_runs_at_a_step_its_falling_blocks_allow():
    """The scaled step is the median block's: taken over the jointed blocks alone, in a pile being
    dropped it was that of the few blocks that had landed. 40 blocks (1 cm to 1 m) dropped into a box
    of YADE Walls: the first joint, a block touching a wall at a corner, made it 0.15 s (O.dt 0.015 s,
    a tenth of it, the travel limit's floor), and five falling blocks moved more than half their inner
    radius in one step: the run stopped at step 14562. The free blocks' first-contact steps now count
    in the median; the pile comes to rest."""
    (r,) = run_ok("""
import math, random
from yade import O, wrapper, utils
from yade_rbsm import polygon2d, mixed_engines, time_stepper, advance
rock = wrapper.RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=0, tensileStrength=0)
O.materials.append(rock)
for pos, axis in (((0, 0, 0), 1), ((-6, 0, 0), 0), ((6, 0, 0), 0)):
    O.bodies.append(utils.wall(pos, axis=axis, material=rock))
rng = random.Random(3)
for k in range(40):
    n, R = rng.randint(3, 12), 10 ** rng.uniform(-2, 0) / 2
    a0 = rng.uniform(0, 2 * math.pi)
    cx, cy = -5 + 1.25 * (k % 9) + rng.uniform(-0.1, 0.1), 1 + 1.1 * (k // 9)
    b = O.bodies.append(polygon2d([(cx + R * math.cos(a0 + 2 * math.pi * j / n), cy + R * math.sin(a0 + 2 * math.pi * j / n)) for j in range(n)], rock))
    O.bodies[b].state.vel = (rng.uniform(-2, 2), rng.uniform(-2, 2), 0)
    O.bodies[b].state.angVel = (0, 0, rng.uniform(-3, 3))
O.engines = mixed_engines(gravity=(0, -9.81, 0), damping=0.7)
ts = time_stepper()
ts.densityScaling = True
dtmax = 0
for k in range(600):
    advance(100)  # (raises RuntimeError when the motion check stops the run)
    dtmax = max(dtmax, O.dt)
report(dtmax=dtmax, vend=max(b.state.vel.norm() for b in O.bodies if b.dynamic), scaled=sum(1 for s in ts.massScale if s > 1))
""", jobs=1)
    assert r["scaled"] > 0, r
    assert r["dtmax"] < 0.01 and r["vend"] < 1e-3, r


def test_target_dt_is_checked_and_a_change_takes_effect_at_once():
    """RbsmTimeStepper.targetDt took -1 and NaN silently (the median step) and inf (no scaling at all),
    and a new value waited for the next scheduled estimate: with interval 100000, targetDt = 1e-4 s set
    mid-run left O.dt at 2.1e-4 s. Bad values are refused (ValueError, the old value kept) and a change
    makes a full estimate at the next step."""
    (r,) = run_ok(SCENE + """
refused = []
for v in (-1.0, float("nan"), float("inf")):
    try:
        ts.targetDt = v
    except ValueError:
        refused.append(repr(v))
advance(10)
before = (O.dt, ts.lastCheck)
ts.targetDt = before[0] / 2
advance(1)
report(refused=refused, target=ts.targetDt, before=before, dt=O.dt, last=ts.lastCheck, iter=O.iter)
""")
    assert r["refused"] == ["-1.0", "nan", "inf"], r
    assert r["target"] == r["before"][0] / 2 and r["dt"] == r["target"], r
    assert r["last"] == r["iter"] - 1 > r["before"][1], r


def test_random_piles_of_blocks_from_1_cm_to_1_m_run_under_density_scaling():
    """40 random convex blocks (1 cm to 1 m, random velocities and spins) dropped in a box of fixed blocks
    or of YADE Walls, six seeds each, under density scaling at safetyFactor 0.8: at most one run stopped by
    the motion check. With every rise of a scale slowing its block, also at the full estimates, 4 of
    these 12 runs stopped (a 1 cm 7-gon pinched under a 0.5 m block spun up to 845 rad/s, seed 4): the
    scales of blocks in contact go up and down at each estimate and the slowing acted as an energy pump
    against the joints pressed meanwhile. Only the rise at a joint's making slows a block now. Still open:
    the rows leave out the stiffness of the joint forces themselves (N x lever arm), which dominates a
    tiny block pinched under a heavy one. It is chaotic and not rare: over seeds 1-40 of the base box, 4
    runs stopped before issue 35's joint law (seeds 19, 20, 24, 27) and 6 after it (9, 14, 19, 20, 27,
    28); one stop examined was a heavy block landing on a 1 cm triangle, overlapping it by its size within
    a few steps. Which of these 12 runs stops follows round-off (walls seed 2 after issue 35), so one
    stopped run is that open case, and the pump above (4 of 12) still fails the test. Since 718695c that open
    case is named: a block closing on a thinner one deeper than its half-width stops the run as passing through
    (Ig2); 4 of these 12 runs (base seeds 1, 4, 5, walls 2) stop so, silently wrong before. They are counted
    apart from the motion check's stops, at most 5 in all."""
    (r,) = run_ok("""
import math, random
from yade import O, wrapper, utils
from yade_rbsm import polygon2d, engines, mixed_engines, time_stepper, advance
out = []
def passing():  # a contact deeper than its thinner block's half-width along its normal: Ig2 stopped the run
    for i in O.interactions:
        if not (i.isReal and type(i.geom).__name__ == "RbsmGeom" and
                all(type(O.bodies[k].shape).__name__ == "Polygon2D" for k in (i.id1, i.id2))):
            continue
        n = i.geom.normal
        w = min(0.5 * (max(v.dot(n) for v in vs) - min(v.dot(n) for v in vs))
                for vs in (O.bodies[k].shape.worldVertices(O.bodies[k].state.pos, O.bodies[k].state.ori) for k in (i.id1, i.id2)))
        if max(i.geom.d0, i.geom.d1) > w:
            return True
    return False
for walls in (False, True):
    for seed in range(1, 7):
        O.reset()
        rock = wrapper.RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5, cohesion=0, tensileStrength=0)
        O.materials.append(rock)
        if walls:
            O.bodies.append([utils.wall((0, 0, 0), axis=1, material=rock), utils.wall((-6, 0, 0), axis=0, material=rock),
                             utils.wall((6, 0, 0), axis=0, material=rock)])
        else:
            O.bodies.append([polygon2d([(-6, -1), (6, -1), (6, 0), (-6, 0)], rock, fixed=True),
                             polygon2d([(-6.5, 0), (-6, 0), (-6, 12), (-6.5, 12)], rock, fixed=True),
                             polygon2d([(6, 0), (6.5, 0), (6.5, 12), (6, 12)], rock, fixed=True)])
        rng = random.Random(seed)
        for k in range(40):
            n, R = rng.randint(3, 12), 10 ** rng.uniform(-2, 0) / 2
            a0 = rng.uniform(0, 2 * math.pi)
            cx, cy = -5 + 1.25 * (k % 9) + rng.uniform(-0.1, 0.1), 1 + 1.1 * (k // 9)
            b = O.bodies.append(polygon2d([(cx + R * math.cos(a0 + 2 * math.pi * j / n), cy + R * math.sin(a0 + 2 * math.pi * j / n))
                                           for j in range(n)], rock))
            O.bodies[b].state.vel = (rng.uniform(-2, 2), rng.uniform(-2, 2), 0)
            O.bodies[b].state.angVel = (0, 0, rng.uniform(-3, 3))
        O.engines = (mixed_engines if walls else engines)(gravity=(0, -9.81, 0), damping=0.7)
        time_stepper().densityScaling = True
        try:
            advance(20000)
            out.append(None)
        except RuntimeError as e:
            out.append(("%s seed %d stopped at step %d" % ("walls" if walls else "base", seed, O.iter), passing()))
report(stopped=[x[0] for x in out if x and not x[1]], passing=[x[0] for x in out if x and x[1]], runs=len(out))
""", jobs=1)
    assert r["runs"] == 12 and len(r["stopped"]) <= 1, r
    assert len(r["stopped"]) + len(r["passing"]) <= 5, r  # (4 of 12 on 718695c: the open case, now named)



def test_a_small_free_block_too_fast_for_the_scaled_step_is_named_with_the_cause():
    """A 0.1 mm block 1 um above a 10 m block resting on a fixed base, densityScaling on (a new user's trial
    14b): the step is the 10 m block's (the median of the two), and the small block, without joints, is not
    scaled: it falls 0.48 mm in the first step and the run stops. The report blamed an explosion; it now
    names density scaling and what to do. (Scaling such blocks for their first contact was tried: a pile
    dropped under scaling then fell as slowly, in steps, as unscaled, and one of 12 random piles stopped.)"""
    from yaderun import run_yade
    p = run_yade("""
from yade import O, wrapper
from yade_rbsm import polygon2d, engines, time_stepper, advance
m = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2500, frictionAngle=0.6)
O.materials.append(m)
O.bodies.append(polygon2d([(-20, -1), (20, -1), (20, 0), (-20, 0)], m, fixed=True))
big = O.bodies.append(polygon2d([(-5, 0), (5, 0), (5, 10), (-5, 10)], m))
s = 1e-4
O.bodies.append(polygon2d([(0, 10 + s * 0.01), (s, 10 + s * 0.01), (s, 10 + 1.01 * s), (0, 10 + 1.01 * s)], m))
O.engines = engines(damping=0.5)
time_stepper().densityScaling = True
try:
    advance(100)
except RuntimeError as e:
    print("STOPPED", O.iter)
""")
    assert p.returncode == 0 and ("STOPPED 1" in p.stdout or "STOPPED 2" in p.stdout), p.stdout[-2000:] + p.stderr[-2000:]
    line = [l for l in p.stderr.splitlines() if "body #2" in l][0]
    assert "densityScaling" in line and "no joint to scale it" in line and "targetDt" in line, line
