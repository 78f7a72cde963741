# -*- coding: utf-8 -*-
"""Block numbering and time per step on a large Voronoi slope (issue 22): the builder's order against
build_scene's Z-order numbering, -j as given.

    build/yade-rbsm -j1 -n -x scripts/benchmarks/voronoi_order.py builder|z [--spacing 0.25]

A 20 m high slope (surface (0,5)-(20,5)-(40,25)-(60,25)) cut into Voronoi blocks (seed 1, min_distance half
the spacing), frictional joints (E 100 MPa, tan φ 0.6), gravity, damping 0.5; 300 steps, then the least of
5 × 40 timed steps. "builder": the bodies appended in voronoi_slope_blocks' order (random in space);
"z": slope.build_scene, which numbers them along a Z-order curve.
"""
import sys
import time

from yade import O, wrapper

from yade_rbsm import advance, engines, polygon2d
from yade_rbsm import slope as sl

order = sys.argv[1] if len(sys.argv) > 1 else "z"
spacing = float(sys.argv[sys.argv.index("--spacing") + 1]) if "--spacing" in sys.argv else 0.25
sb = sl.voronoi_slope_blocks([(0, 5), (20, 5), (40, 25), (60, 25)], 0.0, spacing=spacing, seed=1,
                             min_distance=0.5 * spacing, foundation=1.0, wall=1.0)
mat = wrapper.RbsmMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.6)
O.materials.append(mat)
if order == "builder":
    O.bodies.append([polygon2d(b.vertices, mat, fixed=b.fixed) for b in sb.blocks])
else:
    sl.build_scene(sb, mat)
O.engines = engines(damping=0.5)
advance(300)
best = float("inf")
for _ in range(5):
    t0 = time.perf_counter()
    advance(40)
    best = min(best, (time.perf_counter() - t0) / 40)
n = O.interactions.countReal()
print("VORONOI_ORDER %s blocks %d contacts %d %.3f ms/step %.0f ns/contact-step"
      % (order, len(O.bodies), n, best * 1e3, best * 1e9 / n))
