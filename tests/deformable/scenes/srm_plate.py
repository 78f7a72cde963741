"""Strength reduction of plastic blocks against a closed form (issue 39): a W x H plate of Voronoi blocks between
frictionless platens on a frictionless base (in a gravity of 0.01 m/s²), the left one fixed, the right one pushed by a constant force q H t. The plate's strength in
plane-strain uniaxial compression is 2c cos φ/(1 − sin φ), so strength reduction (c/F, tan φ/F on the blocks)
must fail it at the F where that strength falls to q. Settles under the load, then runs
yade_rbsm.strength_reduction.strength_reduction on the plate and the platen.
Params: n, seed, c, phi (deg), q (the load [Pa]; default the strength / fs), rtol, max_steps."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
import yade_rbsm
from yade_rbsm import omega, polygon2d
from yade_rbsm.strength_reduction import strength_reduction
from yade_rbsm.voronoi import voronoi_blocks

p = params()
W = H = 10.0
c, phi = p.get("c", 1e5), math.radians(p.get("phi", 0.0))
strength = 2 * c * math.cos(phi) / (1 - math.sin(phi))
mat = RbsmMat(young=1e8, poisson=0.3, density=2000, planeStrain=True, cohesion=c, frictionAngle=phi, tensileStrength=c,
              deformable=True, plastic=True, penalty=10, label="soil")
platen = RbsmMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0, label="platen")
O.materials.append(mat)
O.materials.append(platen)
n = p.get("n", 100)
blocks = voronoi_blocks([(0, 0), (W, 0), (W, H), (0, H)], n=n, seed=p.get("seed", 1), min_distance=0.3 * W / n ** 0.5)
ids = [O.bodies.append(polygon2d(b, mat)) for b in blocks]
O.bodies.append(polygon2d([(-1, 0), (0, 0), (0, H + 1), (-1, H + 1)], platen, fixed=True))
O.bodies.append(polygon2d([(0, -1), (W + 2, -1), (W + 2, 0), (0, 0)], platen, fixed=True))  # a frictionless base
right = O.bodies.append(polygon2d([(W, 0), (W + 1, 0), (W + 1, H + 1), (W, H + 1)], platen))  # standing on it
O.bodies[right].state.blockedDOFs = "zXYZ"
q = p["q"] if "q" in p else strength / p.get("fs", 1.5)
O.engines = yade_rbsm.engines(gravity=(0, -0.01, 0), damping=0.7)  # (weight 2e-3 of q: strength reduction wants some)
O.engines = O.engines[:-1] + [ForceEngine(ids=[right], force=(-q * H, 0, 0), label="load"), O.engines[-1]]
omega.ip2(O).setCohesionNow = True
O.run(30000, True)  # settled under the load (elastic: q below the strength)
r = strength_reduction(ids=ids + [right], rtol=p.get("rtol", 0.01), max_steps=p.get("max_steps", 5000), d_fail=0.05, verbose=False)
emit({"fs": r.fs, "q": q, "warnings": list(getattr(r, "warnings", [])), "text": str(r),
      "yielded_at_start": sum(1 for i in ids if O.bodies[i].state.plasticShear > 0)})
