# -*- coding: utf-8 -*-
"""Settling plus strength reduction of a Voronoi slope with and without density scaling (issue 22).

    build/yade-rbsm -j1 -n -x scripts/benchmarks/density_scaling.py [--spacing 0.5] [--min-distance 0]
                                                                   [--seed 1] [--rtol 0.01] [--trials]
                                                                   [--target-factor K]

Griffiths & Lane's 2:1 slope (H = 10 m, c' = 10 kPa, phi' = 20 deg, E = 100 MPa, brittle joints; the scene
of scripts/slope_fs_study.py --mode raw), cut by ``voronoi_slope_blocks`` at *spacing* with the builder's
*min_distance* (0, its default: Poisson sites, blocks of many sizes; 0.5: sites at least half a spacing
apart, blocks of similar size). Each mode runs in its own process: ``settle(tol=1e-4)`` then
``strength_reduction(start=1.4, grow=1.2, rtol)``, a trial's max_steps 8000 scaled, 24000 plain (the same
simulated time at a 3x shorter step). Prints one line per mode and the ratios (--trials: every trial too).
--target-factor K: the scaled mode only, its RbsmTimeStepper.targetDt set to K times the median block's step
after one step from the bonded state (instead of targetDt 0, which follows the median as joints change).
"""
import json
import math
import os
import subprocess
import sys
import time

MARK = "DENSITY_SCALING "


def arg(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


def child(scaled, spacing, min_distance, seed, rtol, target_factor=0.0):
    from yade import O, wrapper
    import yade_rbsm as yr
    from yade_rbsm import slope as sl
    from yade_rbsm.strength_reduction import strength_reduction
    H, gamma, c, phi = 10.0, 20e3, 10e3, math.radians(20)
    surface = [(0, 0), (12, 0), (12 + 2 * H, H), (32 + 2 * H, H)]
    mat = wrapper.RbsmMat(young=100e6, poisson=0.3, density=gamma / 9.81, frictionAngle=phi, cohesion=c,
                          tensileStrength=c / math.tan(phi))
    O.materials.append(mat)
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=spacing, seed=seed, min_distance=min_distance * spacing)
    sl.build_scene(sb, mat)
    O.engines = yr.engines(set_dt=True, enlarge=0.01)
    O.dt = 1e-6
    sl.bond_and_break(sb)
    if target_factor > 0:
        ts = yr.time_stepper()
        ts.densityScaling = True
        yr.advance(1)
        ts.targetDt = target_factor * ts.scaledDt
    t0 = time.time()
    ok, settle_steps, _ = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=scaled)
    t1 = time.time()
    dt = O.dt
    r = strength_reduction(start=1.4, grow=1.2, rtol=rtol, density_scaling=scaled, max_steps=8000 if scaled else 24000,
                           check=200, d_fail=0.1, verbose=False)
    t2 = time.time()
    for t in r.trials:
        print("TRIAL %s: %s" % ("scaled" if scaled else "plain", t), flush=True)
    print(MARK + json.dumps(dict(scaled=scaled, blocks=len(sb.free), dt=dt, settled=ok, settle_steps=settle_steps,
                                 settle_wall=t1 - t0, sr_steps=sum(t.steps for t in r.trials), trials=len(r.trials),
                                 sr_wall=t2 - t1, fs=r.fs, lo=r.lo, hi=r.hi)), flush=True)


def main():
    import yade_rbsm  # (under yade -x, __file__ is yade's own script)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(yade_rbsm.__file__))))
    opts = ["--spacing", str(arg("--spacing", 0.5)), "--min-distance", str(arg("--min-distance", 0.0)),
            "--seed", str(arg("--seed", 1)), "--rtol", str(arg("--rtol", 0.01)),
            "--target-factor", str(arg("--target-factor", 0.0))]
    rows = {}
    for scaled in ((True,) if arg("--target-factor", 0.0) > 0 else (False, True)):
        cmd = [os.path.join(root, "build", "yade-rbsm"), "-j1", "-n", "-x", os.path.join(root, "scripts", "benchmarks", "density_scaling.py"), "--child",
               "1" if scaled else "0"] + opts
        out = subprocess.run(cmd, capture_output=True, text=True).stdout
        lines = [l for l in out.splitlines() if l.startswith(MARK)]
        if not lines:
            sys.exit("density_scaling.py: the %s run printed no result:\n%s" % ("scaled" if scaled else "plain", out[-3000:]))
        rows[scaled] = json.loads(lines[0][len(MARK):])
        if "--trials" in sys.argv:
            print("\n".join(l for l in out.splitlines() if l.startswith("TRIAL ")))
    print("| density scaling | blocks | O.dt [s] | settle steps | SR steps (trials) | FS [bracket] | settle + SR wall [s] |")
    print("|---|---|---|---|---|---|---|")
    for scaled, r in rows.items():
        print("| %s | %d | %.3g | %d | %d (%d) | %.4f [%.4f, %.4f] | %.1f + %.1f = %.1f |"
              % ("on" if scaled else "off", r["blocks"], r["dt"], r["settle_steps"], r["sr_steps"], r["trials"], r["fs"],
                 r["lo"], r["hi"], r["settle_wall"], r["sr_wall"], r["settle_wall"] + r["sr_wall"]))
    if False not in rows:
        return
    p, s = rows[False], rows[True]
    print("steps %.2fx fewer, wall %.2fx less, FS %+.2f %% (%s)"
          % ((p["settle_steps"] + p["sr_steps"]) / (s["settle_steps"] + s["sr_steps"]),
             (p["settle_wall"] + p["sr_wall"]) / (s["settle_wall"] + s["sr_wall"]), 100 * (s["fs"] / p["fs"] - 1),
             " ".join(opts)))


if "--child" in sys.argv:
    child(sys.argv[sys.argv.index("--child") + 1] == "1", arg("--spacing", 0.5), arg("--min-distance", 0.0),
          arg("--seed", 1), arg("--rtol", 0.01), arg("--target-factor", 0.0))
else:
    main()
