# -*- coding: utf-8 -*-
"""Where a step of a large running-bond wall goes, per engine (issue 22: locality at scale).

    build/yade-rbsm -j1 -n -x scripts/benchmarks/engine_shares.py [--n 316] [--steps 40]

Builds an n x n wall (scripts/benchmark_contacts.py's), runs 301 steps (so that the timed steps hold no
full estimate of RbsmTimeStepper, which runs every 100), then times --steps steps with O.timingEnabled:
prints ms per step, ns per contact-step and YADE's timing.stats() (each engine's share).
"""
import os
import sys
import time

from yade import O, timing

import yade_rbsm
from yade_rbsm import advance

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(yade_rbsm.__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from benchmark_contacts import build_wall  # noqa: E402


def arg(name, default):
    return type(default)(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


n, steps = arg("--n", 316), arg("--steps", 40)
build_wall(nx=n, ny=n)
advance(301)
O.timingEnabled = True
timing.reset()
contacts = sum(1 for I in O.interactions if I.isReal)
t0 = time.time()
advance(steps)
wall = time.time() - t0
print("%d blocks, %d contacts: %.2f ms per step, %.0f ns per contact-step" % (n * n, contacts, wall / steps * 1e3,
                                                                           wall / steps / contacts * 1e9))
timing.stats()
