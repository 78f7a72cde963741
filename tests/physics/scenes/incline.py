"""Block on an incline (gravity tilted by psi): ground 100 x 1 m fixed, block L x H on top.
params: psi (deg), phi (deg), c (Pa, bonded joint if > 0), L, H, dt, nIP (Ig2, default 2), mode:
  'sudden': gravity tilted from the start, run `steps`; returns the least-squares acceleration of the
            block's x velocity over the second half and its displacement.
  'ramp':   settle under vertical gravity (settle steps), then tilt gravity linearly from 0 to psi over
            `ramp` steps, then hold `hold` steps; returns the tilt at which the joint first lost an
            intact point (None if never), the displacement along the slope and the final velocity.
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, degrees, sin, cos
from _common import params, emit, lsq_slope, FrozenShare
from yade_rbsm import polygon2d

p = params()
psi, phi, c = radians(p.get("psi", 35)), radians(p.get("phi", 30)), p.get("c", 0.0)
L, H, g = p.get("L", 4.0), p.get("H", 0.5), 9.81
mode = p.get("mode", "sudden")
mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=phi, cohesion=c, tensileStrength=c)
O.materials.append(mat)
O.bodies.append(polygon2d([(-50, -1), (50, -1), (50, 0), (-50, 0)], mat, fixed=True))
b = O.bodies[O.bodies.append(polygon2d([(0, 0), (L, 0), (L, H), (0, H)], mat))]
ip2 = Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=(c > 0))
newton = NewtonIntegrator(gravity=(0, -g, 0), damping=0)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0), nIP=p.get("nIP", 2))], [ip2], [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=0.3)]),
             newton]
O.dt = p.get("dt", 1e-5)
x0 = b.state.pos[0]


def phys():
    i = O.interactions[0, b.id] if O.interactions.has(0, b.id) else None
    return i.phys if i is not None and i.isReal else None


if mode == "sudden":
    newton.gravity = (g * sin(psi), -g * cos(psi), 0)
    n = p.get("steps", 20000)
    ts, vs, fz = [], [], FrozenShare()
    for k in range(n):
        O.step()
        fz.sample(O)
        if k >= n // 2 and k % 10 == 0:
            ts.append(O.time)
            vs.append(b.state.vel[0])
    emit({"a": lsq_slope(ts, vs), "a_mean": b.state.vel[0] / O.time, "disp": b.state.pos[0] - x0,
          "mass": b.state.mass, "frozen_share": fz.share()})
else:
    O.run(p.get("settle", 20000), True)
    x0 = b.state.pos[0]
    nr, nh = p.get("ramp", 100000), p.get("hold", 20000)
    broke, chunk = None, 100
    for k in range(0, nr + nh, chunk):
        a = psi * min(1.0, (k + chunk) / nr)
        newton.gravity = (g * sin(a), -g * cos(a), 0)
        for _ in range(chunk):
            O.step()
        ph = phys()
        if broke is None and c > 0 and (ph is None or ph.nIntact < len(ph.intactPoints) or ph.nIntact == 0):
            broke = degrees(a)
    ph = phys()
    emit({"broke_deg": broke, "disp": b.state.pos[0] - x0, "vel": b.state.vel[0], "mass": b.state.mass,
          "nIntact": ph.nIntact if ph else None, "length": O.interactions[0, b.id].geom.length if ph else None})
