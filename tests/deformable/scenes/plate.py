"""A W x H plate cut into Voronoi blocks, between two rigid frictionless platens, in uniaxial compression
(the patch test of issue 38). The left platen is fixed, the right one pushed by the force sigma*H*t; the
platens' joints are frictionless, so the plate expands freely in y. Once at rest (damped), the plate's
strain is the least-squares displacement gradient of its blocks' centroids (the platens' joints left out),
and E, nu follow: plane stress E = sigma/exx, nu = -eyy/exx; plane strain the apparent E/(1-nu^2), nu/(1-nu)
are turned back into E, nu. Params: n, seed, nu, planeStrain, deformable, penalty, E, sigma, steps."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, affine_fit
import yade_rbsm
from yade_rbsm import omega
from yade_rbsm import polygon2d
from yade_rbsm.voronoi import voronoi_blocks

p = params()
W = H = 10.0
E, nu, plane_strain = p.get("E", 1e9), p.get("nu", 0.3), p.get("planeStrain", False)
sigma = p.get("sigma", 1e5)
mat = RbsmMat(young=E, poisson=nu, density=2000, planeStrain=plane_strain, cohesion=1e9, tensileStrength=1e9,
              frictionAngle=0.5, deformable=p.get("deformable", True), label="plate")
if "penalty" in p:
    mat.penalty = p["penalty"]
platen = RbsmMat(young=E, poisson=nu, density=2000, planeStrain=plane_strain, frictionAngle=0, label="platen")
O.materials.append(mat)
O.materials.append(platen)
blocks = voronoi_blocks([(0, 0), (W, 0), (W, H), (0, H)], n=p.get("n", 400), seed=p.get("seed", 1), min_distance=0.3 * W / p.get("n", 400) ** 0.5)
ids = [O.bodies.append(polygon2d(b, mat)) for b in blocks]
left = O.bodies.append(polygon2d([(-1, -1), (0, -1), (0, H + 1), (-1, H + 1)], platen, fixed=True))
right = O.bodies.append(polygon2d([(W, -1), (W + 1, -1), (W + 1, H + 1), (W, H + 1)], platen))
O.bodies[right].state.blockedDOFs = "yzXYZ"
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=p.get("damping", 0.3), safety=p.get("safety", 0.5)) 
if p.get("densityScaling"):
    omega.engine("timeStepper", O).densityScaling = True
O.engines = O.engines[:-1] + [ForceEngine(ids=[right], force=(-sigma * H, 0, 0)), O.engines[-1]]
omega.ip2(O).setCohesionNow = True
x0 = {i: O.bodies[i].state.pos for i in ids}
O.step()
welded = sum(1 for I in O.interactions if I.isReal and I.phys.welded)
pts = [(x0[i][0], x0[i][1]) for i in ids]


def gradient():
    u = [(O.bodies[i].state.pos[0] - x0[i][0], O.bodies[i].state.pos[1] - x0[i][1]) for i in ids]
    return affine_fit(pts, u)


# at rest: the plate's strain changes by less than tol (relative) over a chunk of steps
chunk, last = p.get("chunk", 2000), None
while O.iter < p.get("steps", 200000):
    O.run(chunk, True)
    G, rms = gradient()
    if last is not None and abs(G[0][0] - last[0][0]) < p.get("tol", 1e-4) * abs(G[0][0]) and abs(G[1][1] - last[1][1]) < p.get("tol", 1e-4) * abs(G[0][0]):
        break
    last = G
exx, eyy = G[0][0], G[1][1]
Eapp, nuapp = -sigma / exx, -eyy / exx
if plane_strain:  # E' = E/(1-nu^2), nu' = nu/(1-nu)  ->  nu = nu'/(1+nu'), E = E'(1-nu^2)
    nuapp = nuapp / (1 + nuapp)
    Eapp = Eapp * (1 - nuapp ** 2)
strains = [O.bodies[i].state.strain for i in ids] if p.get("deformable", True) else []
mean_block = [sum(s[k] for s in strains) / len(strains) for k in range(3)] if strains else None
emit({"E": Eapp, "nu": nuapp, "exx": exx, "eyy": eyy, "rms": rms, "n": len(ids), "welded": welded,
      "dt": O.dt, "mean_block_strain": mean_block, "iter": O.iter,
      "kinetic": sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() for i in ids)})
