# -*- coding: utf-8 -*-
"""Each engine's share of a step, in ns per contact-step, on an nx × ny running-bond wall (issue 22: where a
10⁵-block wall's extra time per contact goes against a 10³ one).

    build/yade-rbsm -j1 -n -x scripts/benchmarks/engine_shares.py [--nx 32] [--ny 32] [--steps 400]
    build/yade-rbsm -j1 -n -x scripts/benchmarks/engine_shares.py --n 316 [--steps 40]   (an n x n wall)

Builds the wall of scripts/benchmark_contacts.py, runs 300 steps, then times --steps steps with
O.timingEnabled and prints the whole step and each engine per real contact, and the memory a contact
takes (the median address step between consecutive interactions). A window shorter than
RbsmTimeStepper.interval (100) may or may not hold one of its full estimates (at 10⁵ blocks about 6 ns per
contact-step averaged over 100 steps, 30 over 20). --nx 3125 --ny 32 is a 10⁵-block wall with the dynamics
of the 32 × 32 one (same height)."""
import os
import re
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


n = arg("--n", 0)  # (the first version's option: an n x n wall)
nx, ny, steps = arg("--nx", n or 32), arg("--ny", n or 32), arg("--steps", 400)
build_wall(nx=nx, ny=ny, verlet=None)
advance(300)
O.timingEnabled = True
timing.reset()
t0 = time.perf_counter()
advance(steps)
dt = (time.perf_counter() - t0) / steps
nc = sum(1 for i in O.interactions if i.isReal)
print("wall %d x %d: %d blocks, %d contacts; %.3f ms per step, %.1f ns per contact-step (%d steps after 300)"
      % (nx, ny, len(O.bodies), nc, dt * 1e3, dt * 1e9 / nc, steps))
for e in O.engines:
    ns = e.execTime / steps  # execTime: ns over the timed steps
    print("  %-28s %10.1f us per step %7.1f ns per contact-step" % (e.label or type(e).__name__, ns / 1e3, ns / nc))


def address(o):
    return int(re.search(r"0x[0-9a-f]+", repr(o)).group(0), 16)


# Memory per contact: the address step from one real interaction to the next (orderInteractions lays each
# one out with its RbsmGeom and RbsmPhys right after it), the median over the container's order.
real = [address(i) for i in O.interactions if i.isReal]
steps_in_memory = sorted(b - a for a, b in zip(real, real[1:]))
print("  memory: median step between consecutive interactions %d bytes" % steps_in_memory[len(steps_in_memory) // 2])
