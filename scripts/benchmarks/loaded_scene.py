# -*- coding: utf-8 -*-
"""A scene loaded with O.load against the same scene freshly built (issue 22), ms per step at -j<--j>.

    build/yade-rbsm -j1 -n -x scripts/benchmarks/loaded_scene.py [--n 100] [--turns 3] [--j 1] [--no-order]

The parent builds an n x n running-bond wall (n² blocks), runs WARM steps and saves it; then, in turns,
children continue the scene for TIMED steps: "fresh" rebuilds the wall in its process and runs the WARM steps
itself, "loaded" calls O.load on the saved file. Both start the timed steps from the same state. Each child
prints the least ms/step of CHUNKS chunks (other processes only ever add time). Prints a table. --no-order:
RbsmTimeStepper.orderInteractions off in both (the interactions in YADE's order, as before it existed).
"""
import os
import subprocess
import sys
import time

from yade import O

import yade_rbsm
from yade_rbsm import advance

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(yade_rbsm.__file__))))
LAUNCHER = os.path.join(ROOT, "build", "yade-rbsm")
SCRIPT = os.path.join(ROOT, "scripts", "benchmarks", "loaded_scene.py")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from benchmark_contacts import build_wall as brick_wall  # noqa: E402 (the running-bond wall of that benchmark)
WARM, TIMED, CHUNKS = 300, 40, 5


def arg(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


def build_wall(n):
    brick_wall(nx=n, ny=n, verlet=None)


def timed():
    """ms per step: the least of CHUNKS chunks, or with --mean all of them together (what a user waits for
    on a busy machine, scripts/benchmarks/threads_under_load.py)."""
    each = []
    for _ in range(CHUNKS):
        t0 = time.perf_counter()
        advance(TIMED)
        each.append((time.perf_counter() - t0) / TIMED)
    return (sum(each) / len(each) if "--mean" in sys.argv else min(each)) * 1e3


def order_option():
    """--no-order: RbsmTimeStepper.orderInteractions off (YADE's order of the interactions, as before)."""
    for e in O.engines:
        if type(e).__name__ == "RbsmTimeStepper":
            e.orderInteractions = "--no-order" not in sys.argv


def child(kind, n, path):
    if kind == "fresh":
        build_wall(n)
        order_option()
        advance(WARM)
    else:
        O.load(path)
        order_option()
    print("LOADED_SCENE %s %d %.3f contacts %d iter %d" % (kind, len(O.bodies), timed(), O.interactions.countReal(),
                                                          O.iter), flush=True)


def main():
    n, turns = arg("--n", 100), arg("--turns", 3)
    path = arg("--file", "/tmp/rbsm_loaded_scene_%d.yade.gz" % n)
    build_wall(n)
    order_option()  # (the saved file keeps the order its run had)
    advance(WARM)
    O.save(path)
    threads = str(arg("--j", 1))
    rows = {"fresh": [], "loaded": []}
    for _ in range(turns):
        for kind in ("fresh", "loaded"):
            cmd = [LAUNCHER, "-j" + threads, "-n", "-x", SCRIPT, "--child", kind, "--n", str(n), "--file", path]
            cmd += [a for a in ("--no-order", "--mean") if a in sys.argv]
            out = subprocess.run(cmd, capture_output=True, text=True).stdout
            line = [l for l in out.splitlines() if l.startswith("LOADED_SCENE")]
            if not line:
                sys.exit("child %s printed no result:\n%s" % (kind, out[-2000:]))
            rows[kind].append(float(line[0].split()[3]))
            print(line[0], "load %.2f" % os.getloadavg()[0], flush=True)
    f, l = min(rows["fresh"]), min(rows["loaded"])
    print("| %d blocks, -j%s | fresh %.2f ms/step | loaded %.2f ms/step | loaded/fresh %.3f |" % (n * n, threads, f, l, l / f))


if "--child" in sys.argv:
    child(sys.argv[sys.argv.index("--child") + 1], arg("--n", 100), arg("--file", ""))
else:
    main()
