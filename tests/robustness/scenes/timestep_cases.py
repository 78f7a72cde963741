"""The scenes of issue 14 ("A stable, honest time step in every scene a user builds"), one per `case`;
each returns what the test asserts. E = 1e8 Pa, ν = 0.2, ρ = 2000 kg/m³, φ = 30°, g = 9.81 unless said.

gap_stack     three unit blocks 5 cm apart above a base, engines() defaults: O.dt after the first step,
              the simulated time of 3000 steps, whether the stack landed.
sizes_stack   blocks of widths 2, 1, 0.5 falling 5 cm onto each other and a base (symmetric about x = 0),
              engines() defaults (full estimate every 100 steps): the top block's highest centroid, its
              final x offset, the energy balance.
corner_square a unit square standing on a corner on a base (setDt): O.dt and the square's end state.
corner_long   a 4 × 1 block tilted 30° on a corner (setDt).
corner_drop   a tilted block dropped 1 cm, the user's O.dt = 1e-5 and setDt: the largest O.dt, the end y.
circle        a 10 000-vertex near-circle resting on a base (setDt): O.dt and its end y.
newton_damp   a thin 4 × 0.2 block bonded on a base, NewtonIntegrator damping 0.7, safety 0.8.
pwave         a block 1 cm above a base, O.dt = 0.5 × PWaveTimeStep() with set_dt=False: the first step
              must be refused (no joint exists yet).
check_new     set_dt=False at a step just below the limit of a block resting on a base; a second block
              falls onto it: the step that makes the stiffer joint must be refused.
refusal_load  check_new's refusal `tries` times (one step each) while `busy` busy-looping processes compete for
              the cores: how many refusals were not raised.
dt_zero       O.dt = 0 with set_dt=False.
nu_half       ν = 0.5 − 1e-15 (plane strain): refused by RbsmMat's constructor and assignment; then the
              scene with the kept ν = 0.2 and contact damping 0.3 runs.
rocking       a w × h block tilted by `angle` degrees, dropped `drop` m on a base (friction angle `phi`,
              engines() defaults, no damping): the largest gain of total energy (kinetic + gravity +
              springs + friction dissipated) between contacts and at the end, as a fraction of the energy it can lose
              falling flat, and its highest centroid after the first landing.
flat_drop     a 1 × 0.5 m block (E = 2e8 Pa, ρ = 2400) dropped flat from `drop` m (default 2) onto a base, undamped, engines()
              defaults or `safety` / `impact`: the highest rebound of its centroid above its resting height
              after the first landing, and the steps its first contact lasted."""
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite
from yade_rbsm import polygon2d, engines, advance

p = params()
case = p["case"]


def rect(x0, y0, w, h):
    return [(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)]


def rotated(poly, angle, about=(0.0, 0.0)):
    c, s = math.cos(angle), math.sin(angle)
    return [(about[0] + c * (x - about[0]) - s * (y - about[1]), about[1] + s * (x - about[0]) + c * (y - about[1])) for x, y in poly]


def lift(poly, dy):
    m = min(y for _, y in poly)
    return [(x, y - m + dy) for x, y in poly]


mat = RbsmMat(young=1e8, poisson=p.get("poisson", 0.2) if case != "nu_half" else 0.2, density=2000, frictionAngle=math.radians(30),
              cohesion=p.get("cohesion", 0.0), tensileStrength=p.get("cohesion", 0.0))
O.materials.append(mat)
O.bodies.append(polygon2d(rect(-10, -1, 20, 1), mat, fixed=True))


def stepper():
    return [e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0]


def run_catching(n):
    """The exception of *n* steps run in the calling thread (yade_rbsm.advance), None if they ran: O.run(n, True)
    loses an exception raised in the run's first step when the background run ends before O.wait() starts."""
    try:
        advance(n)
        return None
    except Exception as e:
        return [type(e).__name__, str(e)]


res = {}
if case == "gap_stack":
    for k in range(3):
        O.bodies.append(polygon2d(rect(-0.5, 0.05 + 1.05 * k, 1, 1), mat))
    O.engines = engines()
    O.step()
    res["dt1"] = O.dt
    O.run(2999, True)
    res["time"] = O.time
    res["landed"] = len([i for i in O.interactions if i.isReal]) > 0
elif case == "sizes_stack":
    y = 0.05
    for w in (2.0, 1.0, 0.5):
        O.bodies.append(polygon2d(rect(-w / 2, y, w, w / 2), mat))
        y += w / 2 + 0.05
    top = O.bodies[-1]
    y0 = top.state.pos[1]
    O.engines = engines()
    O.trackEnergy = True
    O.step()
    E0 = O.energy.total()
    ymax, worst = y0, 0.0
    while O.time < 1.5:
        O.run(20, True)
        ymax = max(ymax, top.state.pos[1])
        worst = max(worst, O.energy.total() - E0)
    res.update(y0=y0, ymax=ymax, x=top.state.pos[0], growth=worst, grav=abs(O.energy["gravWork"]), finite=all_finite(O), dt=O.dt)
elif case in ("corner_square", "corner_long", "corner_drop"):
    if case == "corner_square":
        poly = lift(rotated(rect(-0.5, -0.5, 1, 1), math.pi / 4), 0.0)
    elif case == "corner_long":
        poly = lift(rotated(rect(-2, -0.5, 4, 1), math.radians(30)), 0.0)
    else:
        poly = lift(rotated(rect(-1, -0.25, 2, 0.5), math.radians(10)), 0.01)
    b = O.bodies[O.bodies.append(polygon2d(poly, mat))]
    O.engines = engines()
    if case == "corner_drop":
        O.dt = 1e-5
    dts, y0, ys = [], b.state.pos[1], []
    from yade_rbsm import advance
    for k in range(p.get("chunks", 60)):
        for _ in range(10):
            advance(10)
            ys.append(b.state.pos[1])
        dts.append(O.dt)
    res.update(dt_max=max(dts), dt_end=O.dt, y=b.state.pos[1], finite=all_finite(O), first=getattr(stepper(), "firstContactDt", None),
               crit=stepper().criticalDt, time=O.time, y0=y0, y_min=min(ys), y_max=max(ys))
elif case == "circle":
    n = 10000
    poly = [(0.5 * math.cos(2 * math.pi * k / n), 0.5 + 0.5 * math.sin(2 * math.pi * k / n)) for k in range(n)]
    b = O.bodies[O.bodies.append(polygon2d(poly, mat))]
    O.engines = engines()
    dts = []
    for k in range(20):
        O.run(50, True)
        dts.append(O.dt)
    res.update(dt_max=max(dts), y=b.state.pos[1], finite=all_finite(O), time=O.time)
elif case == "newton_damp":
    b = O.bodies[O.bodies.append(polygon2d(rect(-2, 0, 4, 0.2), mat))]
    O.engines = engines(damping=0.7, safety=0.8)
    O.engines[2].physDispatcher.functors[0].setCohesionNow = True
    O.step()
    y0 = b.state.pos[1]
    O.run(3000, True)
    res.update(dy=abs(b.state.pos[1] - y0), intact=all(O.interactions[0, 1].phys.intactPoints) if O.interactions.has(0, 1) else False,
               vy=b.state.vel[1], finite=all_finite(O), dt=O.dt)
elif case == "pwave":
    b = O.bodies[O.bodies.append(polygon2d(rect(-0.5, 0.01, 1, 1), mat))]  # 1 cm above the base
    O.engines = engines(set_dt=False)
    from yade import utils
    O.dt = 0.5 * utils.PWaveTimeStep()
    res["dt"] = O.dt
    res["exc"] = run_catching(1)
    res["y"] = b.state.pos[1]
elif case == "check_new":
    O.bodies.append(polygon2d(rect(-1, 0.0, 2, 1), mat))
    falling = O.bodies[O.bodies.append(polygon2d(rect(-0.1, 1.002, 0.2, 0.2), mat))]
    O.engines = engines(set_dt=True)
    O.step()
    ts = stepper()
    res["first_dt"] = getattr(ts, "firstContactDt", None)
    # a user's step at the limit of the block on the base, above the falling block's first contact
    ts.setDt = False
    O.dt = 0.8 * ts.criticalDt
    res["dt"] = O.dt
    res["exc"] = run_catching(2000)
    res["iter"] = O.iter
    res["contacts"] = O.interactions.has(1, 2) and O.interactions[1, 2].isReal
elif case == "refusal_load":
    import subprocess
    O.bodies.append(polygon2d(rect(-1, 0.0, 2, 1), mat))
    O.bodies.append(polygon2d(rect(-0.1, 1.002, 0.2, 0.2), mat))
    O.engines = engines(set_dt=True)
    O.step()
    ts = stepper()
    ts.setDt = False
    O.dt = 0.8 * ts.criticalDt
    # busy loops that end by themselves within 2 min, should this process die before it kills them
    spin = "import time\nend = time.time() + 120\nwhile time.time() < end: pass"
    busy = [subprocess.Popen([sys.executable, "-c", spin]) for _ in range(p.get("busy", 3))]
    try:
        res["lost"] = sum(run_catching(1) is None for _ in range(p.get("tries", 300)))
    finally:
        for b in busy:
            b.kill()
    res["iter"] = O.iter
elif case == "dt_zero":
    O.bodies.append(polygon2d(rect(-0.5, 0.0, 1, 1), mat))
    O.engines = engines(set_dt=False)
    try:
        O.dt = float(p.get("dt", 0.0))
        res["assign"] = None
    except ValueError as e:  # (NaN: refused where it is set)
        res["assign"] = str(e)
    O.bodies[1].state.vel = (0, -0.1, 0)  # a moving block: its motion O.dt·v must not be what is reported
    res["exc"] = run_catching(10) if res["assign"] is None else None
    res["iter"] = O.iter
elif case == "nu_half":
    # refused where the value is given (constructor, assignment), before any step
    try:
        RbsmMat(young=1e8, poisson=p["poisson"], density=2000)
        res["ctor"] = None
    except ValueError as e:
        res["ctor"] = str(e)
    try:
        mat.poisson = p["poisson"]
        res["assign"] = None
    except ValueError as e:
        res["assign"] = str(e)
    res["poisson_kept"] = mat.poisson
    O.bodies.append(polygon2d(rect(-0.5, 0.0, 1, 1), mat))
    O.engines = engines(contact_damping=0.3)
    res["exc"] = run_catching(10)
    res["dt"] = O.dt
    res["iter"] = O.iter
elif case == "rocking":
    mat.frictionAngle = math.radians(p.get("phi", 30.0))
    w, h = p.get("w", 2.0), p.get("h", 0.5)
    poly = lift(rotated(rect(-w / 2, -h / 2, w, h), math.radians(p.get("angle", 10.0))), p.get("drop", 0.01))
    b = O.bodies[O.bodies.append(polygon2d(poly, mat))]
    O.engines = engines(safety=p.get("safety", 0.8))
    O.trackEnergy = True
    g, m, inertia, y0 = 9.81, b.state.mass, b.state.inertia[2], b.state.pos[1]

    def energy():
        v, om = b.state.vel, b.state.angVel[2]
        e = 0.5 * m * (v[0] ** 2 + v[1] ** 2) + 0.5 * inertia * om * om + m * g * (b.state.pos[1] - y0)
        return e + sum(O.energy[k] for k in ("elastPotential", "plastDissip") if k in O.energy.keys())

    # in flight (no joint) the energy is exact; in contact the central-difference energy of the
    # springs oscillates with the step, so the gain is taken between contacts and at the end
    e0, gain, ymax, landed = energy(), 0.0, -1e9, False
    while O.time < p.get("time", 2.0) and all_finite(O):
        O.step()
        touching = any(i.isReal for i in O.interactions)
        if not touching:
            gain = max(gain, energy() - e0)
        landed = landed or touching
        if landed:
            ymax = max(ymax, b.state.pos[1])
    gain = max(gain, energy() - e0)
    res.update(gain=gain / (m * g * (y0 - h / 2)), ymax=ymax, y0=y0, y=b.state.pos[1], finite=all_finite(O), steps=O.iter)
elif case == "flat_drop":
    drop = p.get("drop", 2.0)
    rock = RbsmMat(young=2e8, poisson=0.2, density=2400, frictionAngle=math.radians(30))
    O.materials.append(rock)
    O.bodies[0].material = rock
    b = O.bodies[O.bodies.append(polygon2d(rect(-0.5, drop, 1, 0.5), rock))]
    kw = {"safety": p["safety"]} if "safety" in p else {}
    O.engines = engines(**kw)
    if "impact" in p:
        stepper().impactSafety = p["impact"]
    y_rest = 0.25  # centroid at rest (the overlap under its own weight is 1e-6 m)
    landed, rebound, contact_steps, flying = False, 0.0, 0, False
    while O.time < p.get("time", 1.6) and all_finite(O):
        O.step()
        touching = any(i.isReal for i in O.interactions)
        if touching and not flying:
            landed = True
            contact_steps += 1
        if landed and not touching:
            flying = True
        if flying:
            rebound = max(rebound, b.state.pos[1] - y_rest)
    res.update(rebound=rebound, drop=drop, contact_steps=contact_steps, finite=all_finite(O), steps=O.iter,
               dt=O.dt, impact=stepper().impactSafety)
emit(res)
