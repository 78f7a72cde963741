# -*- coding: utf-8 -*-
"""-j2 against -j1 on a busy machine (issue 22): ms per step of a settled-in running-bond wall while other
processes keep the cores busy, for OpenMP wait policies set in the environment.

    /usr/bin/python3 scripts/benchmarks/threads_under_load.py [--n 40 100] [--loads 0 3] [--turns 2]

A load of k is k extra processes spinning in a loop (so on 2 cores, load 3 leaves each yade thread about
2/5 of a core). Each run is a child of scripts/benchmarks/loaded_scene.py (the wall built, WARM steps, then
5 × 40 timed steps; --mean: all timed steps, what a user waits for). Variants: -j1; -j2 with libgomp's
default (threads spin 300 000 times at a barrier before they sleep; build/yade-rbsm leaves it alone when
GOMP_SPINCOUNT is set); -j2 with OMP_WAIT_POLICY=PASSIVE (sleep at once: what build/yade-rbsm sets by
default); -j2 with GOMP_SPINCOUNT=10000 (spin briefly). Prints a Markdown table, the least of the turns.
"""
import argparse
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAUNCHER = os.path.join(ROOT, "build", "yade-rbsm")
CHILD = os.path.join(ROOT, "scripts", "benchmarks", "loaded_scene.py")
VARIANTS = [("-j1", 1, {}), ("-j2 GOMP_SPINCOUNT=300000 (libgomp's default)", 2, {"GOMP_SPINCOUNT": "300000"}),
            ("-j2 OMP_WAIT_POLICY=PASSIVE", 2, {"OMP_WAIT_POLICY": "PASSIVE"}),
            ("-j2 GOMP_SPINCOUNT=10000", 2, {"GOMP_SPINCOUNT": "10000"})]


def run(n, jobs, env):
    full = dict(os.environ)
    for k in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT"):
        full.pop(k, None)
    full.update(env)
    out = subprocess.run([LAUNCHER, "-j%d" % jobs, "-n", "-x", CHILD, "--child", "fresh", "--n", str(n), "--mean"],
                         capture_output=True, text=True, env=full).stdout
    line = [l for l in out.splitlines() if l.startswith("LOADED_SCENE")]
    if not line:
        sys.exit("no result from the child:\n" + out[-2000:])
    return float(line[0].split()[3])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, nargs="+", default=[40, 100])
    ap.add_argument("--loads", type=int, nargs="+", default=[0, 3])
    ap.add_argument("--turns", type=int, default=2)
    a = ap.parse_args()
    rows = []
    for load in a.loads:
        hogs = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(load)]
        try:
            time.sleep(1.0)
            for n in a.n:
                best = {}
                for _ in range(a.turns):
                    for name, jobs, env in VARIANTS:
                        t = run(n, jobs, env)
                        best[name] = min(best.get(name, t), t)
                        print("load +%d, %d blocks, %s: %.2f ms/step (load average %.2f)"
                              % (load, n * n, name, t, os.getloadavg()[0]), flush=True)
                rows.append((load, n, best))
        finally:
            for h in hogs:
                h.kill()
    print("\n| extra busy processes | blocks | " + " | ".join(v[0] for v in VARIANTS) + " |")
    print("|---|---|" + "---|" * len(VARIANTS))
    for load, n, best in rows:
        j1 = best["-j1"]
        print("| %d | %d | " % (load, n * n) + " | ".join("%.2f ms (%.2f×)" % (best[v[0]], j1 / best[v[0]])
                                                          for v in VARIANTS) + " |")
    print("(× = speed-up against -j1; machine: %d cores)" % os.cpu_count())


if __name__ == "__main__":
    main()
