"""Prandtl's strip footing on plastic deformable blocks (issue 39): how close a cut soil comes to (2 + π) c.

A rigid smooth footing of width B = 1 m is pushed at a slow constant rate into a weightless Tresca soil (φ = 0,
c = 10 kPa, E = 1000 c unless given, ν = 0.3, plane strain) 6 m wide and 2 m deep, cut into blocks of size h under
the footing, growing 15 % a cell (grids) or 1.5 × per B (Voronoi) away from it; fixed smooth sides and base.
The bearing pressure q (footing force / B t) rises to the collapse pressure; Prandtl's is 5.14 c.

    build/yade-rbsm -j1 -n -x scripts/prandtl_footing_study.py '{"cells": "triangles", "h": 0.1}'

Params (one JSON object): cells (voronoi | triangles | crossed | quads), h (/ B), rough (the footing bonded with the
soil's c), scaled (density scaling), rigidity (E / c, 1000), seed, penalty (RbsmMat.penalty, 10),
linearShare (of the welded joints, default Ip2's 1/penalty), weldYields (RbsmMat's; true here: the welds as strong
as the soil; false: elastic and unlimited), steps, settlement (final, / B), png (a picture of the blocks coloured by
plastic shear at the end).
Prints the curve q/c against settlement/B, the same for the footing's middle 80 % (its two corner cells left out),
the last fifth's means, and how close the welds come to their strength (weld_traction_ratio: at most 1 with
weldYields). Prandtl's is a small-displacement answer: with E = 1000 c the mechanism forms at 2-3 % settlement, where
the corners' cells are crushed; rigidity 10000 and settlement 0.005 read it at 0.3 %."""
import json
import math
import sys

import numpy as np
import yade_rbsm
from yade_rbsm import omega, polygon2d
from yade_rbsm.voronoi import voronoi_blocks

p = json.loads(sys.argv[1]) if len(sys.argv) > 1 else {}
B, L, D = 1.0, 3.0, 2.0
c = 1e4
E = p.get("rigidity", 1000) * c  # E / c: the settlement at collapse scales with c / E
h0 = p.get("h", 0.1) * B


def graded(hi, fine, h):
    """Node coordinates from 0 to hi: h up to fine, then 15 % larger a cell."""
    xs, x, dx = [0.0], 0.0, h
    while x < hi - 1e-9:
        x = min(hi, x + dx)
        if hi - x < 0.5 * dx:
            x = hi
        xs.append(x)
        if x > fine:
            dx *= 1.15
    return xs


def grid_cells(kind):
    xr = graded(L, 0.8 * B, h0)
    xs = sorted(set([-x for x in xr] + xr))
    ys = [-y for y in graded(D, 0.8 * B, h0)][::-1]
    cells = []
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            a, b, cc, d = (xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])
            if kind == "quads":
                cells.append([a, b, cc, d])
            elif kind == "crossed":  # both diagonals: four triangles about the centre (Nagtegaal's unlocked mesh)
                m = ((a[0] + cc[0]) / 2, (a[1] + cc[1]) / 2)
                cells += [[a, b, m], [b, cc, m], [cc, d, m], [d, a, m]]
            else:  # alternating diagonals
                cells += [[a, b, cc], [a, cc, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, cc, d]]
    return cells


def voronoi_cells():
    """Sites by dart throwing, no two closer than 0.7 of the local size h0 (1 + 1.5 d/B)."""
    rng = np.random.default_rng(p.get("seed", 1))
    size = lambda x, y: h0 * (1 + 1.5 * math.hypot(max(0.0, abs(x) - B / 2), y) / B)
    sites = []
    for _ in range(200000):
        x, y = rng.uniform(-L, L), rng.uniform(-D, 0)
        if all(math.hypot(x - a, y - b) >= 0.7 * min(size(x, y), size(a, b)) for a, b in sites):
            sites.append((x, y))
    return voronoi_blocks([(-L, -D), (L, -D), (L, 0), (-L, 0)], sites=sites)


kind = p.get("cells", "triangles")
cells = voronoi_cells() if kind == "voronoi" else grid_cells(kind)
soil = RbsmMat(young=E, poisson=0.3, density=2000, planeStrain=True, cohesion=c, frictionAngle=0, tensileStrength=10 * c,
               deformable=True, plastic=True, penalty=p.get("penalty", 10.0), weldYields=p.get("weldYields", True), label="soil")
smooth = RbsmMat(young=E, poisson=0.3, density=2000, frictionAngle=0, label="smooth")
O.materials.append(soil)
O.materials.append(smooth)
ids = [O.bodies.append(polygon2d(b, soil)) for b in cells]
for box in ([(-L - 0.5, -D - 0.5), (L + 0.5, -D - 0.5), (L + 0.5, -D), (-L - 0.5, -D)],
            [(-L - 0.5, -D), (-L, -D), (-L, 0.5), (-L - 0.5, 0.5)], [(L, -D), (L + 0.5, -D), (L + 0.5, 0.5), (L, 0.5)]):
    O.bodies.append(polygon2d(box, smooth, fixed=True))
# rough: the footing bonded to the soil with the soil's own c (full adhesion); Prandtl's 5.14 c holds for both (Hill)
rough = RbsmMat(young=E, poisson=0.3, density=2000, cohesion=10 * c, tensileStrength=10 * c, label="rough")
footing = O.bodies.append(polygon2d([(-B / 2, 0), (B / 2, 0), (B / 2, 0.2), (-B / 2, 0.2)], rough if p.get("rough") else smooth,
                                    fixed=True))
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=0.6)
omega.ip2(O).setCohesionNow = True
if p.get("scaled"):  # quasi-static: the smallest cells do not set the step
    omega.engine("timeStepper", O).densityScaling = True
O.step()
if "linearShare" in p:
    for I in O.interactions:
        if I.isReal and I.phys.welded:
            I.phys.linearShare = p["linearShare"]
steps, final = p.get("steps", 40000), p.get("settlement", 0.05) * B
v = final / (steps * O.dt)
y0 = O.bodies[footing].state.pos[1]


def middle_pressure():
    """The mean pressure on the footing's middle 80 % [Pa], away from its corners' singular cells."""
    force = length = 0.0
    for I in O.bodies[footing].intrs():
        if I.isReal and abs(0.5 * (I.geom.p0[0] + I.geom.p1[0])) < 0.4 * B:
            force, length = force + I.phys.normalForce, length + I.geom.length
    return force / length if length > 0 else 0.0


def weld_traction_ratio():
    """The largest |τ| / (c + σ tan φ) over the welded joints' points: a cut of the soil is as strong as the soil."""
    worst = 0.0
    for I in O.interactions:
        if I.isReal and getattr(I.phys, "welded", False):
            for tau, sn, intact in zip(I.phys.shearTraction, I.phys.normalTraction, I.phys.intactPoints):
                strength = max(I.phys.cohesion + sn * I.phys.tanPhi, 0.0) if intact else max(sn, 0.0) * I.phys.tanPhi
                worst = max(worst, abs(tau) / strength if strength > 0 else (math.inf if tau != 0 else 0.0))
    return worst


curve = []
for k in range(60):
    O.bodies[footing].state.vel = (0, -v * min(1.0, (k + 1) / 6.0), 0)  # a short ramp
    O.run(steps // 60, True)
    curve.append(((y0 - O.bodies[footing].state.pos[1]) / B, O.forces.f(footing)[1] / B / c, middle_pressure() / c))
tail = curve[48:]  # the last fifth
print("cells %s, h %g B, %d blocks, penalty %g, linearShare %s: q/c at settlement/B" % (kind, h0, len(ids), soil.penalty, p.get("linearShare", "1/penalty")))
print("  " + "  ".join("%.3f:%.2f" % s[:2] for s in curve[4::8]))
print("  middle 80 %: " + "  ".join("%.3f:%.2f" % (s[0], s[2]) for s in curve[4::8]))
if p.get("png"):  # the mechanism: blocks coloured by their plastic shear
    from yade_rbsm.snapshots import snapshot
    shear = sorted(O.bodies[i].state.plasticShear for i in ids)
    snapshot(p["png"], title="footing, %s, settlement %.3f B: plastic shear" % (kind, curve[-1][0]), field="plasticShear",
             vmax=max(shear[int(0.98 * len(shear))], 1e-9))  # the corners' cells off the scale: the fans show
print("RBSM_RESULT " + json.dumps({"cells": kind, "h": h0, "n": len(ids), "q_over_c": sum(q for _, q, _ in tail) / len(tail),
                              "middle_q_over_c": sum(m for _, _, m in tail) / len(tail), "prandtl": 2 + math.pi,
                              "weld_traction_ratio": weld_traction_ratio(), "yielded": sum(1 for i in ids if O.bodies[i].state.plasticShear > 0), "dt": O.dt}))
