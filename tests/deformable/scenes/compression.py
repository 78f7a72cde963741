"""A W x H plate cut into Voronoi blocks of a plastic soil (issue 39), compressed between two rigid
frictionless platens at a constant (slow, damped) rate, free at top and bottom. The blocks' stress is uniform,
so the plate's strength is the material's: plane strain Mohr-Coulomb under uniaxial stress, q = 2c cos φ/(1 − sin φ)
(Tresca: 2c). Reports the nominal stress-strain curve (platen force / H t against platen displacement / W),
its peak and last value, the blocks' mean stress, how many yielded, the area change, and the energy balance.
Params: n, seed, c, phi (deg), psi (deg), sigmaT, nu, planeStrain, plastic, weldBreak (RbsmMat.weldBreakStrain),
ductile, strain (final), steps, damping."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
import yade_rbsm
from yade_rbsm import omega, polygon2d
from yade_rbsm.voronoi import voronoi_blocks

p = params()
W = H = 10.0
E, nu = p.get("E", 1e8), p.get("nu", 0.3)
c, phi = p.get("c", 1e5), math.radians(p.get("phi", 0.0))
mat = RbsmMat(young=E, poisson=nu, density=2000, planeStrain=p.get("planeStrain", True), cohesion=c, frictionAngle=phi,
              tensileStrength=p.get("sigmaT", c), dilatancy=math.radians(p.get("psi", 0.0)), deformable=True,
              plastic=p.get("plastic", True), weldBreakStrain=p.get("weldBreak", 0.0), ductile=p.get("ductile", False), label="soil")
platen = RbsmMat(young=E, poisson=nu, density=2000, frictionAngle=0, label="platen")
O.materials.append(mat)
O.materials.append(platen)
n = p.get("n", 100)
blocks = voronoi_blocks([(0, 0), (W, 0), (W, H), (0, H)], n=n, seed=p.get("seed", 1), min_distance=0.3 * W / n ** 0.5)
ids = [O.bodies.append(polygon2d(b, mat)) for b in blocks]
left = O.bodies.append(polygon2d([(-1, -1), (0, -1), (0, H + 1), (-1, H + 1)], platen, fixed=True))
right = O.bodies.append(polygon2d([(W, -1), (W + 1, -1), (W + 1, H + 1), (W, H + 1)], platen, fixed=True))
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=p.get("damping", 0.5))
omega.ip2(O).setCohesionNow = True
O.trackEnergy = True
O.step()
welded0 = sum(1 for I in O.interactions if I.isReal and I.phys.welded)
steps, final = p.get("steps", 20000), p.get("strain", 0.01)
v = final * W / (steps * O.dt)  # the platen's speed for the final strain in that many steps (dt is fixed by then)
x0 = O.bodies[right].state.pos[0]
area0 = sum(O.bodies[i].shape.area for i in ids)
curve = []
for k in range(50):
    O.bodies[right].state.vel = (-v * min(1.0, (k + 1) / 5.0), 0, 0)  # a short ramp: no shock at the start
    O.run(steps // 50, True)
    strain = (x0 - O.bodies[right].state.pos[0]) / W
    curve.append((strain, O.forces.f(right)[0] / (H * mat.young / mat.young)))  # force per unit height and thickness
S = [s for s in (O.bodies[i].state.stress for i in ids)]
mean = [sum(s[k] * O.bodies[i].shape.area for s, i in zip(S, ids)) / area0 for k in range(3)]
E_ = O.energy
emit({"curve": curve, "peak": max(f for _, f in curve), "last": curve[-1][1], "mean_stress": mean,
      "yielded": sum(1 for i in ids if O.bodies[i].state.plasticShear > 0), "n": len(ids),
      "modes": [O.bodies[i].state.yieldMode for i in ids].count(1),
      "area_change": sum(O.bodies[i].shape.area * (1 + O.bodies[i].state.strain[0] + O.bodies[i].state.strain[1]) for i in ids) / area0 - 1,
      "plastic_area": sum(O.bodies[i].shape.area * (O.bodies[i].state.plasticStrain[0] + O.bodies[i].state.plasticStrain[1]) for i in ids) / area0,
      "plastic_shear": sum(O.bodies[i].shape.area * O.bodies[i].state.plasticShear for i in ids) / area0,
      "welded": [welded0, sum(1 for I in O.interactions if I.isReal and I.phys.welded)],
      "sxx_range": [min(s[0] for s in S), max(s[0] for s in S)],
      "energy": dict(E_.items()), "dt": O.dt, "v": v})
