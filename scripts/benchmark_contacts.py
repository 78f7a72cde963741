# -*- coding: utf-8 -*-
"""Cost per contact-step: RBSM brick wall against a YADE sphere stack, in one run (headless).

Run (regenerates docs/benchmarks.md):

    /work/main/build/yade-rbsm -j1 -n -x scripts/benchmark_contacts.py

The parent run (threads as given by -j) measures:
  (a) RBSM: a wall of NY courses of NX bricks in running bond (half bricks at the ends of odd courses, frictional
      joints) on a fixed base, settled under gravity;
  (b) YADE spheres (FrictMat, Ig2_Sphere_Sphere_ScGeom, Law2_ScGeom_FrictPhys_CundallStrack): a hexagonal
      stack in a vertical plane between a floor and two side walls, a similar number of real contacts, settled under gravity;
  (c) RBSM with nIP=4 instead of 2;
  (d) RBSM with frozen contact kinematics between exact updates (Ig2 updateTolerance=UT);
and then starts itself again with the other thread count (-j1 <-> -j2) as a child (option --child) for the
thread comparison. Each scene is first settled under gravity (untimed, until no body moves faster than
V_SETTLED, at most SETTLE_MAX steps), then STEPS steps are timed with O.timingEnabled=True.
Prints a Markdown table and writes docs/benchmarks.md (table, per-engine timing, machine, command).
With --alternate it only prints CPU time per contact-step of exact RBSM, frozen RBSM and spheres, each in a scene
of its own, run in turns; the least turn of each is compared (for a noisy machine; writes nothing). With
--callgrind-window MODE it settles one scene and counts the instructions of 20 steps under callgrind
(scripts/benchmarks/floor.sh runs it).
This is a benchmark, not a test: it asserts nothing; it reports whether the RBSM contact count after settling
depends on the collider's verletDist (it should not).
"""
import json
import os
import platform
import subprocess
import sys
import time

from yade import O, timing, utils, wrapper

import yade_rbsm
from yade_rbsm.blocks import polygon2d
from yade_rbsm.scene import engines as rbsm_engines

# yade -x does not give a usable __file__; the project root is two levels above the yade_rbsm package.
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(yade_rbsm.__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "benchmark_contacts.py")
LAUNCHER = os.path.join(ROOT, "build", "yade-rbsm")
# The tracked page is rewritten only when asked (--update-docs); otherwise out/docs/benchmarks.md.
DOC = os.path.join(ROOT, "docs" if "--update-docs" in sys.argv else os.path.join("out", "docs"), "benchmarks.md")

NX, NY = 40, 40          # bricks per row, rows
BW, BH = 0.2, 0.1        # brick width, height [m]
VERLET_REL = 0.05        # collider.verletDist for the bricks = VERLET_REL * BH
NSX, NSZ = 40, 40        # spheres: hexagonal stack, spheres per row, rows
R = 0.05                 # sphere radius [m]
V_SETTLED = 1e-6         # settled: no body faster than this [m/s] (checked every 250 steps) ...
SETTLE_MAX = 15000       # ... or this many untimed steps before timing, whichever comes first
STEPS = 150              # timed steps per chunk
CHUNKS = 6               # timed chunks; the cheapest is reported
UT = 1e-4                # Ig2 updateTolerance of the frozen-kinematics variant (0 = exact geometry, the default)
END = "<!-- end of generated part; text below is kept when the script rewrites this file -->"


def threads():
    try:
        return int(O.numThreads)
    except AttributeError:
        return int(os.environ.get("OMP_NUM_THREADS", "1") or 1)


# ----------------------------------------------------------------------------------------------- scenes
def course(j, nx=NX):
    """x-extents of the bricks of course j of a running bond: nx bricks, or on odd courses a half brick at each
    end and nx-1 bricks between (as a mason lays it). Without the half bricks the end brick of every odd course
    overhangs by half its length, its centroid right above the corner below: balanced at its tipping point, it
    topples (an inverted pendulum, kinetic energy growing like exp(17/s · t)) and the wall never settles."""
    if j % 2 == 0:
        return [(i * BW, (i + 1) * BW) for i in range(nx)]
    return [(0.0, 0.5 * BW)] + [((i + 0.5) * BW, (i + 1.5) * BW) for i in range(nx - 1)] + [((nx - 0.5) * BW, nx * BW)]


def build_wall(nIP=2, verlet=VERLET_REL * BH, update_tolerance=0.0, nx=NX, ny=NY):
    """ny courses of nx bricks on a fixed base (verlet=None: the collider's verletDist as engines() sets it)."""
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=1e9, poisson=0.2, frictionAngle=0.6, cohesion=0, tensileStrength=0, density=2000)
    O.materials.append(mat)
    # fixed base, one block under the whole wall (one brick height)
    x0, x1 = -BW, (nx + 1) * BW
    O.bodies.append(polygon2d([(x0, -BH), (x1, -BH), (x1, 0), (x0, 0)], mat, fixed=True))
    for j in range(ny):
        y0, y1 = j * BH, (j + 1) * BH
        for xa, xb in course(j, nx):
            O.bodies.append(polygon2d([(xa, y0), (xb, y0), (xb, y1), (xa, y1)], mat))
    O.engines = rbsm_engines(gravity=(0, -9.81, 0), damping=0.2, nIP=nIP, safety=0.8, set_dt=True,
                             update_tolerance=update_tolerance)  # default interval (100)
    if verlet is not None:
        O.engines[1].verletDist = verlet
    O.dt = 1e-6  # replaced by RbsmTimeStepper at the first step


def build_spheres():
    O.resetThisScene()
    mat = wrapper.FrictMat(young=1e9, poisson=0.2, frictionAngle=0.6, density=2000)
    O.materials.append(mat)
    # Hexagonal stack in the x-z plane, NSX spheres per row (NSX-1 on odd rows), NSZ rows, between a floor
    # and two side walls; like the bricks, motion is planar (y translation, x and z rotation blocked).
    O.bodies.append(utils.wall(0, axis=2, sense=1, material=mat))
    O.bodies.append(utils.wall(0, axis=0, sense=1, material=mat))
    O.bodies.append(utils.wall(2 * R * NSX, axis=0, sense=-1, material=mat))
    dz = 3 ** 0.5 * R
    for k in range(NSZ):
        odd = k % 2
        for i in range(NSX - odd):
            b = utils.sphere((R + 2 * R * i + odd * R, 0, R + k * dz), R, material=mat)
            b.state.blockedDOFs = "yXZ"
            O.bodies.append(b)
    O.engines = [
        wrapper.ForceResetter(),
        wrapper.InsertionSortCollider([wrapper.Bo1_Sphere_Aabb(), wrapper.Bo1_Wall_Aabb()], label="collider"),
        wrapper.InteractionLoop(
            [wrapper.Ig2_Sphere_Sphere_ScGeom(), wrapper.Ig2_Wall_Sphere_ScGeom()],
            [wrapper.Ip2_FrictMat_FrictMat_FrictPhys()],
            [wrapper.Law2_ScGeom_FrictPhys_CundallStrack()],
        ),
        wrapper.NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.2, label="newton"),
    ]
    O.dt = 0.5 * utils.PWaveTimeStep()


def build_pile(n=400, seed=1, update_tolerance=0.0):
    """n random convex blocks (4-8 sides, 0.1-0.2 m across, flattened up to 2:1) on a grid in a 6 m wide box,
    settled into a random pile (the second scene of issue 22's instruction counts)."""
    import math
    import random
    rng = random.Random(seed)
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=1e8, poisson=0.2, frictionAngle=0.6, cohesion=0, tensileStrength=0, density=2000)
    O.materials.append(mat)
    W, cols = 6.0, 30
    O.bodies.append(polygon2d([(-1, -1), (W + 1, -1), (W + 1, 0), (-1, 0)], mat, fixed=True))
    for x0 in (-1, W):
        O.bodies.append(polygon2d([(x0, 0), (x0 + 1, 0), (x0 + 1, 10), (x0, 10)], mat, fixed=True))
    for k in range(n):
        r, sides, rot = rng.uniform(0.05, 0.1), rng.randint(4, 8), rng.uniform(0, math.pi)
        cx, cy, squash = (k % cols + 0.5) * W / cols, 0.12 + 0.2 * (k // cols), rng.uniform(0.5, 1.0)
        pts = [(r * math.cos(rot + 2 * math.pi * i / sides), squash * r * math.sin(rot + 2 * math.pi * i / sides))
               for i in range(sides)]
        O.bodies.append(polygon2d([(cx + x, cy + y) for x, y in pts], mat))
    O.engines = rbsm_engines(gravity=(0, -9.81, 0), damping=0.3, update_tolerance=update_tolerance)
    O.dt = 1e-6


# ----------------------------------------------------------------------------------------------- measure
def settle():
    """Run until no body moves faster than V_SETTLED and the number of real contacts has not changed over the last
    250 steps (or SETTLE_MAX steps): the scene the issue asks for, a settled wall, whose contacts no longer open and
    close (its head joints carry no load, and while the wall creeps some of them open and close again). Returns
    (steps, largest speed [m/s])."""
    steps, count = 0, -1
    while True:
        O.run(250, True)
        steps += 250
        vmax = max(b.state.vel.norm() for b in O.bodies)
        now = O.interactions.countReal()
        if (vmax < V_SETTLED and now == count) or steps >= SETTLE_MAX:
            return steps, vmax
        count = now


def measure(name):
    """Settle, then time STEPS steps; return a dict of figures."""
    settled = settle()
    # Timed in CHUNKS chunks of STEPS steps; the cheapest chunk is kept (other processes on the machine
    # only ever add time).
    best = None
    for _ in range(CHUNKS):
        O.timingEnabled = True
        timing.reset()
        t0 = time.perf_counter()
        O.run(STEPS, True)
        wall = time.perf_counter() - t0
        O.timingEnabled = False
        eng = {e.__class__.__name__: e.execTime * 1e-9 for e in O.engines}  # ns -> s over the timed steps
        if best is None or sum(eng.values()) < sum(best[1].values()):
            best = (wall, eng, capture_stats())
    wall, eng, stats = best
    nc = O.interactions.countReal()
    ninter = len(O.interactions)
    # Cost of a step = sum of the engines' execTime (O.run's wait polls, so the wall clock around it
    # includes idle time; it is reported separately).
    step = sum(eng.values()) / STEPS
    il = eng.get("InteractionLoop", 0.0) / STEPS
    return dict(name=name, bodies=len(O.bodies), contacts=nc, interactions=ninter, step_ms=step * 1e3,
                wall_ms=wall / STEPS * 1e3,
                us_cs=step * 1e6 / nc, il_us_cs=il * 1e6 / nc,
                share={k: v / STEPS / step for k, v in eng.items()}, threads=threads(),
                verlet=getattr(O.engines[1], "verletDist", float("nan")), dt=O.dt, stats=stats, settled=settled)


def capture_stats():
    import contextlib
    import io
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        timing.stats()
    return buf.getvalue()


def rbsm_contact_count_check():
    """Same number of real contacts after settling with verletDist = 0 and > 0."""
    out = {}
    for v in (0.0, VERLET_REL * BH):
        build_wall(verlet=v)
        settle()
        out[v] = O.interactions.countReal()
    return out


def run_child():
    res = {}
    build_wall(nIP=2)
    res["rbsm"] = measure("RBSM")
    build_wall(nIP=2, update_tolerance=UT)
    res["rbsm_frozen"] = measure("RBSM frozen")
    build_spheres()
    res["spheres"] = measure("spheres")
    for r in res.values():
        r.pop("stats")
    print("CHILD_JSON " + json.dumps(res))


# ----------------------------------------------------------------------------------------------- report
def machine():
    model = "?"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return "%s; nproc %d; %s; Python %s" % (model, os.cpu_count(), platform.platform(), platform.python_version())


def main():
    t_start = time.perf_counter()
    jn = threads()
    check = rbsm_contact_count_check()
    build_wall(nIP=2)
    rb = measure("RBSM (nIP=2)")
    build_spheres()
    sp = measure("YADE spheres")
    build_wall(nIP=4)
    rb4 = measure("RBSM (nIP=4)")
    build_wall(nIP=2, update_tolerance=UT)
    rbf = measure("RBSM (nIP=2, updateTolerance=%g)" % UT)

    other = 2 if jn == 1 else 1
    child = None
    try:
        p = subprocess.run([LAUNCHER, "-j%d" % other, "-n", "-x", SCRIPT, "--child"],
                           capture_output=True, text=True, timeout=240)
        for line in p.stdout.splitlines():
            if line.startswith("CHILD_JSON "):
                child = json.loads(line[len("CHILD_JSON "):])
        if child is None:
            print("child run failed:\n", p.stdout[-2000:], p.stderr[-2000:])
    except Exception as e:  # a benchmark reports, it does not stop
        print("child run failed:", e)

    lines = []
    lines.append("| scene | -j | bodies | real contacts | time / step [ms] | (wall clock / step [ms]) | µs / contact-step (step) | "
                 "µs / contact-step (InteractionLoop) | InteractionLoop share | collider share | Newton share | RbsmTimeStepper share |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")

    def row(r):
        s = r["share"]
        lines.append("| %s | %d | %d | %d | %.3f | %.3f | %.3f | %.3f | %.0f %% | %.0f %% | %.0f %% | %s |" % (
            r["name"], r["threads"], r["bodies"], r["contacts"], r["step_ms"], r["wall_ms"], r["us_cs"], r["il_us_cs"],
            100 * s.get("InteractionLoop", 0), 100 * s.get("InsertionSortCollider", 0),
            100 * s.get("NewtonIntegrator", 0),
            ("%.1f %%" % (100 * s["RbsmTimeStepper"])) if "RbsmTimeStepper" in s else "–"))

    for r in (rb, sp, rb4, rbf):
        row(r)
    if child:
        c_rb, c_sp, c_rbf = child["rbsm"], child["spheres"], child["rbsm_frozen"]
        c_rb["name"], c_sp["name"], c_rbf["name"] = "RBSM (nIP=2)", "YADE spheres", "RBSM (nIP=2, updateTolerance=%g)" % UT
        row(c_rb)
        row(c_sp)
        row(c_rbf)
    table = "\n".join(lines)

    ratio = ["", "", "| ratio | whole step | InteractionLoop |", "|---|---|---|",
             "| RBSM / spheres per contact-step (-j%d) | %.2f× | %.2f× |" % (jn, rb["us_cs"] / sp["us_cs"], rb["il_us_cs"] / sp["il_us_cs"]),
             "| RBSM nIP=4 / nIP=2 per contact-step (-j%d) | %.2f× | %.2f× |" % (jn, rb4["us_cs"] / rb["us_cs"], rb4["il_us_cs"] / rb["il_us_cs"]),
             "| RBSM updateTolerance=%g / spheres per contact-step (-j%d) | %.2f× | %.2f× |" % (UT, jn, rbf["us_cs"] / sp["us_cs"], rbf["il_us_cs"] / sp["il_us_cs"])]
    if child:
        ratio.append("| RBSM / spheres per contact-step (-j%d) | %.2f× | %.2f× |" % (
            other, c_rb["us_cs"] / c_sp["us_cs"], c_rb["il_us_cs"] / c_sp["il_us_cs"]))
        ratio.append("| RBSM updateTolerance=%g / spheres per contact-step (-j%d) | %.2f× | %.2f× |" % (
            UT, other, c_rbf["us_cs"] / c_sp["us_cs"], c_rbf["il_us_cs"] / c_sp["il_us_cs"]))
        j1, j2 = (rb, c_rb) if jn == 1 else (c_rb, rb)
        s1, s2 = (sp, c_sp) if jn == 1 else (c_sp, sp)
        ratio.append("| RBSM speed-up -j1 → -j2 | %.2f× | %.2f× |" % (j1["us_cs"] / j2["us_cs"], j1["il_us_cs"] / j2["il_us_cs"]))
        ratio.append("| spheres speed-up -j1 → -j2 | %.2f× | %.2f× |" % (s1["us_cs"] / s2["us_cs"], s1["il_us_cs"] / s2["il_us_cs"]))
    table += "\n".join(ratio)

    notes = ("Collider: spheres use YADE's automatic verletDist (%.4g m = 0.5·r); bricks use verletDist = %.4g m "
             "(%.0f %% of the brick height). RBSM real contacts after settling: %s "
             "(verletDist 0 vs %.4g m). Time steps: RBSM %.3g s (RbsmTimeStepper, safety 0.8), spheres %.3g s "
             "(0.5·PWaveTimeStep). Each scene settled untimed until no body moved faster than %g m/s (at most %d steps): "
             "RBSM in %d steps (largest speed %.2g m/s), spheres in %d steps (%.2g m/s); then %d chunks of %d timed steps per scene, the cheapest chunk reported; NewtonIntegrator damping 0.2. "
             "Time per step = sum of the engines' execTime (O.timingEnabled); the wall clock around O.run also "
             "contains O.run's polling. Real contacts counted at the end of the timed steps."
             % (sp["verlet"], rb["verlet"], 100 * VERLET_REL,
                " vs ".join(str(check[k]) for k in sorted(check)), VERLET_REL * BH, rb["dt"], sp["dt"], V_SETTLED, SETTLE_MAX,
                rb["settled"][0], rb["settled"][1], sp["settled"][0], sp["settled"][1], CHUNKS, STEPS))

    print(table)
    print()
    print(notes)
    print()
    print("### yade.timing.stats(), RBSM nIP=2\n" + rb["stats"])
    print("### yade.timing.stats(), spheres\n" + sp["stats"])

    cmd = "build/yade-rbsm -j%d -n -x scripts/benchmark_contacts.py --update-docs     # (without it: out/docs/benchmarks.md)" % jn
    doc = [
        "# Benchmarks",
        "",
        "## Cost per contact-step: RBSM against YADE spheres",
        "",
        "Generated by `scripts/benchmark_contacts.py` (headless; about %.0f s). Regenerate with:" % (time.perf_counter() - t_start),
        "",
        "    " + cmd,
        "",
        "Machine: " + machine() + ".",
        "",
        "Scenes (same run, same process): a wall of %d courses of %d bricks in running bond (%.2f×%.2f m, half bricks at the ends of odd courses, frictional joints, φ=0.6 rad, "
        "E=1 GPa) on one fixed base block, under gravity; a hexagonal stack of spheres in a vertical plane, %d rows of "
        "%d/%d spheres (r=%.2f m, FrictMat, φ=0.6 rad, E=1 GPa) on a floor between two side walls, under gravity; both planar "
        "(out-of-plane translation and rotations blocked). The second thread count comes from a child run of the same script."
        % (NY, NX, BW, BH, NSZ, NSX, NSX - 1, R),
        "",
        table,
        "",
        notes,
        "",
        "Target (issue 3/5): RBSM ≤ 1.0× spheres per contact-step — exact geometry (the default): %s at -j%d (whole step %.2f×, "
        "InteractionLoop %.2f×); frozen kinematics between exact updates (updateTolerance=%g): %s (whole step %.2f×, InteractionLoop %.2f×)."
        % ("met" if rb["us_cs"] <= sp["us_cs"] else "**missed**", jn, rb["us_cs"] / sp["us_cs"], rb["il_us_cs"] / sp["il_us_cs"],
           UT, "met" if rbf["us_cs"] <= sp["us_cs"] else "**missed**", rbf["us_cs"] / sp["us_cs"], rbf["il_us_cs"] / sp["il_us_cs"]),
        "",
        "### Where the time goes (`yade.timing.stats()`, -j%d)" % jn,
        "",
        "RBSM, nIP=2:",
        "",
        "```",
        rb["stats"].rstrip(),
        "```",
        "",
        "Spheres:",
        "",
        "```",
        sp["stats"].rstrip(),
        "```",
        "",
    ]
    os.makedirs(os.path.dirname(DOC), exist_ok=True)
    # Text after the END marker (hand-written analysis) is kept when the table is regenerated.
    kept = ""
    if os.path.exists(DOC):
        old = open(DOC).read()
        if END in old:
            kept = old[old.index(END):]
    with open(DOC, "w") as f:
        f.write("\n".join(doc) + "\n" + (kept or END + "\n"))
    print("written", DOC, "in %.0f s" % (time.perf_counter() - t_start))


def run_alternate(rounds=12, steps=150):
    """Exact RBSM, frozen RBSM (updateTolerance=UT) and spheres, each built and settled once in a scene of its own
    (O.addScene), then run in turns, `steps` steps at a time, `rounds` times: CPU time per contact-step of each
    turn. The least of the turns is the cost without the noise of a shared machine, which only ever adds time;
    the median shows how much noise there was. Prints only."""
    names = ("RBSM exact", "RBSM updateTolerance=%g" % UT, "spheres")
    slots = []
    for name in names:
        slots.append(O.addScene())
        O.switchToScene(slots[-1])
        if name == "spheres":
            build_spheres()
        else:
            build_wall(nIP=2, update_tolerance=0.0 if name == "RBSM exact" else UT)
        settle()
    cost = {name: [] for name in names}
    for _ in range(rounds):
        for name, slot in zip(names, slots):
            O.switchToScene(slot)
            nc0 = O.interactions.countReal()
            t0 = time.process_time()
            O.run(steps, True)
            nc = 0.5 * (nc0 + O.interactions.countReal())
            cost[name].append((time.process_time() - t0) / steps / nc * 1e6)
    sph = min(cost["spheres"])
    for name, slot in zip(names, slots):
        O.switchToScene(slot)
        c = sorted(cost[name])
        print("%-28s CPU µs / contact-step: least %.3f  median %.3f  (%d turns of %d steps, %d contacts)  least/spheres %.2f"
              % (name, c[0], c[len(c) // 2], rounds, steps, O.interactions.countReal(), c[0] / sph), flush=True)


def run_callgrind_window(mode, warm=10, steps=20):
    """Build and settle one scene (mode: exact, frozen, spheres, pile, pile-frozen, or floor: the exact wall, with the switch of
    scripts/benchmarks/floor_experiment.patch thrown after settling), run `warm` steps, then `steps` steps with
    valgrind's callgrind instrumentation on (callgrind_control; the process must run under
    `valgrind --tool=callgrind --instr-atstart=no`). Prints the real contacts. For scripts/benchmarks/floor.sh."""
    if mode == "spheres":
        build_spheres()
    elif mode.startswith("pile"):
        build_pile(update_tolerance=UT if mode == "pile-frozen" else 0.0)
    else:
        build_wall(nIP=2, update_tolerance=UT if mode == "frozen" else 0.0)
    settle()
    if mode == "floor":  # read by the patched functors (floor_experiment.patch) from this step on
        os.environ["RBSM_NULL_FROM"] = str(O.iter)
    O.run(warm, True)
    subprocess.run(["callgrind_control", "-i", "on", str(os.getpid())], stdout=subprocess.DEVNULL, check=True)
    O.run(steps, True)
    subprocess.run(["callgrind_control", "-i", "off", str(os.getpid())], stdout=subprocess.DEVNULL, check=True)
    print("CALLGRIND_WINDOW mode %s contacts %d steps %d" % (mode, O.interactions.countReal(), steps), flush=True)


if __name__ == "__main__":  # (scripts/benchmarks/loaded_scene.py imports build_wall)
    if "--child" in sys.argv:
        run_child()
    elif "--alternate" in sys.argv:
        run_alternate()
    elif "--callgrind-window" in sys.argv:
        run_callgrind_window(sys.argv[sys.argv.index("--callgrind-window") + 1])
    else:
        main()
