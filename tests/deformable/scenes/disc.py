"""A disc of radius R cut into Voronoi blocks, compressed along its vertical diameter between two rigid
platens (the Brazilian test): Hertz's closed form (Timoshenko & Goodier, sec. 41) for two point loads P gives
the whole stress field, independent of E and nu (plane elasticity with given tractions), and the extension of
the horizontal diameter, which depends on both. The polygon that stands for the circle has one edge per block
size, with a horizontal edge at the top and the bottom where the platens press: the load acts on a flat about
one block wide, which tends to Hertz's point load as the blocks get smaller.
Emits: n, sxx, syy (the area-weighted stress of the blocks within R/4 of the centre, measure.block_stresses)
and hertz_sxx, hertz_syy (Hertz's field averaged over the same blocks' centroids), all / (2P/(pi D t)); lw_sxx,
lw_syy (the same from the joint forces, Love-Weber); the horizontal diameter's extension (between the centroids of
the blocks farthest left and right) and Hertz's between the same points; O.dt, steps. Params: n, seed,
deformable, nu, planeStrain, penalty, nIP, platenFriction, flat, linearShare, tol, steps, dump (a file for the
stress of every block)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
import yade_rbsm
from yade_rbsm import omega, polygon2d, measure
from yade_rbsm.voronoi import voronoi_blocks

p = params()
R, t = 1.0, 1.0
D = 2 * R
E, nu, plane_strain = 1e9, p.get("nu", 0.25), p.get("planeStrain", True)
P = 1e5 * D * t  # [N]: 2P/(pi D t) = 63.7 kPa at the centre
n = p.get("n", 200)
h = math.sqrt(math.pi * R * R / n)  # block size
nv = 4 * max(3, round(2 * math.pi * R / h / 4))  # the circle's edges, a multiple of 4: flats at the top and bottom
circle = [(R * math.cos(math.pi / 2 + (k + 0.5) * 2 * math.pi / nv), R * math.sin(math.pi / 2 + (k + 0.5) * 2 * math.pi / nv)) for k in range(nv)]
if p.get("flat"):  # a flat of half-width flat*R at the top and the bottom (the flattened Brazilian disc)
    yf = R * math.sqrt(1 - p["flat"] ** 2)
    circle = [(x, max(-yf, min(yf, y))) for x, y in circle]
    circle = [v for k, v in enumerate(circle) if v != circle[k - 1]]
top = max(y for x, y in circle)
mat = RbsmMat(young=E, poisson=nu, planeStrain=plane_strain, density=2000, cohesion=1e9, tensileStrength=1e9, frictionAngle=0.5, deformable=p.get("deformable", True), label="disc")
if "penalty" in p:
    mat.penalty = p["penalty"]
platen = RbsmMat(young=E, poisson=nu, planeStrain=plane_strain, density=2000, frictionAngle=math.radians(p.get("platenFriction", 30)), label="platen")
O.materials.append(mat)
O.materials.append(platen)
blocks = voronoi_blocks(circle, n=n, seed=p.get("seed", 1), min_distance=0.3 * h)
ids = [O.bodies.append(polygon2d(b, mat)) for b in blocks]
below = O.bodies.append(polygon2d([(-R, -top - 0.2), (R, -top - 0.2), (R, -top), (-R, -top)], platen, fixed=True))
above = O.bodies.append(polygon2d([(-R, top), (R, top), (R, top + 0.2), (-R, top + 0.2)], platen))
O.bodies[above].state.blockedDOFs = "xzXYZ"
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=0.3, safety=0.5, nIP=p.get("nIP", 2))
omega.engine("timeStepper", O).densityScaling = True
O.engines = O.engines[:-1] + [ForceEngine(ids=[above], force=(0, -P, 0)), O.engines[-1]]
omega.ip2(O).setCohesionNow = True
x0 = {i: O.bodies[i].state.pos for i in ids}
O.step()
if "linearShare" in p:  # the welded joints' share of the penalty on their bending (1: every point alike, as before 2026-11-27)
    for I in O.interactions:
        if I.isReal and type(I.phys).__name__ == "RbsmPhys" and I.phys.welded:
            I.phys.linearShare = p["linearShare"]
left = min(ids, key=lambda i: x0[i][0])
right = max(ids, key=lambda i: x0[i][0])


def extension():
    return (O.bodies[right].state.pos[0] - x0[right][0]) - (O.bodies[left].state.pos[0] - x0[left][0])


def hertz(x, y):
    """Hertz's stress (sxx, syy, sxy), tension +, of a disc under two point loads P along the y axis."""
    r1, r2 = x * x + (R - y) ** 2, x * x + (R + y) ** 2
    k = -2 * P / (math.pi * t)
    sxx = k * ((R - y) * x * x / r1 ** 2 + (R + y) * x * x / r2 ** 2 - 1 / D)
    syy = k * ((R - y) ** 3 / r1 ** 2 + (R + y) ** 3 / r2 ** 2 - 1 / D)
    sxy = -k * ((R - y) ** 2 * x / r1 ** 2 - (R + y) ** 2 * x / r2 ** 2)
    return sxx, syy, sxy


def hertz_extension(a, b):
    """Extension of the horizontal diameter between x = a < 0 and x = b > 0: the integral of exx along y = 0,
    (sxx - nu syy)/E in plane stress, (sxx - nu' syy)/E' in plane strain (E' = E/(1 - nu^2), nu' = nu/(1 - nu))."""
    from scipy.integrate import quad

    Ep, nup = (E / (1 - nu * nu), nu / (1 - nu)) if plane_strain else (E, nu)
    return quad(lambda x: (hertz(x, 0)[0] - nup * hertz(x, 0)[1]) / Ep, a, b)[0]


chunk, last = p.get("chunk", 2000), None
while O.iter < p.get("steps", 300000):
    O.run(chunk, True)
    d = extension()
    if last is not None and abs(d - last) < p.get("tol", 1e-4) * abs(d):
        break
    last = d
sigma0 = 2 * P / (math.pi * D * t)
S = measure.block_stresses(O)
M = measure._moments(O)
lxx = lyy = 0.0
area = sxx = syy = hxx = hyy = 0.0
for i in ids:
    c = O.bodies[i].state.pos
    if math.hypot(c[0], c[1]) > R / 4:
        continue
    a = O.bodies[i].shape.area
    ex = hertz(c[0], c[1])
    area += a
    sxx += a * S[i][0][0]
    syy += a * S[i][1][1]
    hxx += a * ex[0]
    hyy += a * ex[1]
    lxx += M[i][0][0] / t
    lyy += M[i][1][1] / t
emit({"n": len(ids), "h": h, "edges": nv, "sxx": sxx / area / sigma0, "syy": syy / area / sigma0, "hertz_sxx": hxx / area / sigma0,
      "hertz_syy": hyy / area / sigma0, "lw_sxx": lxx / area / sigma0, "lw_syy": lyy / area / sigma0, "extension": extension(), "hertz_extension": hertz_extension(x0[left][0], x0[right][0]),
      "dt": O.dt, "iter": O.iter})
if p.get("dump"):
    with open(p["dump"], "w") as f:
        for i in ids:
            c = O.bodies[i].state.pos
            ex = hertz(c[0], c[1])
            f.write("%g %g %g %g %g %g %g %g\n" % (c[0], c[1], S[i][0][0] / sigma0, S[i][1][1] / sigma0, S[i][0][1] / sigma0, ex[0] / sigma0, ex[1] / sigma0, ex[2] / sigma0))
