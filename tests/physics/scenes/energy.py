"""Energy balance scenes.
mode 'impact': two unit squares (frictionless, no gravity, no damping) approach at ±v0 and collide
  edge-on; returns the time series of kinetic and elastic (O.energy['elastPotential']) energy.
mode 'friction': a 1 x 0.5 block settles on a fixed floor (φ, g = 9.81, contact damping ξ), then is
  launched at v0 and slides to rest; returns the kinetic energy lost and the increments of the law's
  'plastDissip', 'viscDamp' and 'elastPotential' over the slide, the sliding distance and the largest
  ratio |Ft|/N of the contact force on the block to the springs' normal force N (RbsmPhys.normalForce)
  in the first 200 steps after the launch (the
  damping ratio during the slide is xi_slide, default xi).
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians
from _common import params, emit, kinetic_energy, FrozenShare
from yade_rbsm import polygon2d

p = params()
mode = p.get("mode", "impact")
O.trackEnergy = True
if mode == "impact":
    mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.0)
    O.materials.append(mat)
    gap, v0 = 1e-3, p.get("v0", 1.0)
    A = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat))
    B = O.bodies.append(polygon2d([(1 + gap, 0), (2 + gap, 0), (2 + gap, 1), (1 + gap, 1)], mat))
    O.bodies[A].state.vel = (v0, 0, 0)
    O.bodies[B].state.vel = (-v0, 0, 0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0))], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
                 NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = p.get("dt", 1e-5)
    ke, el, contact, fz = [], [], [], FrozenShare()
    for k in range(p.get("steps", 3000)):
        O.step()
        fz.sample(O)
        ke.append(kinetic_energy(O))
        el.append(O.energy["elastPotential"] if "elastPotential" in O.energy.keys() else 0.0)
        contact.append(O.interactions.has(A, B) and O.interactions[A, B].isReal)
    emit({"ke": ke, "el": el, "contact": contact, "vA": O.bodies[A].state.vel[0], "vB": O.bodies[B].state.vel[0],
          "E0": 2 * 0.5 * O.bodies[A].state.mass * v0 ** 2, "frozen_share": fz.share()})
else:
    mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=radians(p.get("phi", 30)))
    O.materials.append(mat)
    O.bodies.append(polygon2d([(-20, -1), (20, -1), (20, 0), (-20, 0)], mat, fixed=True))
    b = O.bodies[O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 0.5), (0, 0.5)], mat))]
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(updateTolerance=p.get("ut", 0.0))], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=p.get("xi", 0.3))]),
                 NewtonIntegrator(gravity=(0, -9.81, 0), damping=0)]
    O.dt = p.get("dt", 1e-5)
    O.run(p.get("settle", 20000), True)

    def en(k):
        return O.energy[k] if k in O.energy.keys() else 0.0

    v0 = p.get("v0", 1.0)
    b.state.vel = (v0, 0, 0)
    x0, ke0 = b.state.pos[0], kinetic_energy(O)
    e0 = {k: en(k) for k in ("plastDissip", "viscDamp", "elastPotential")}
    y0 = b.state.pos[1]
    law = O.engines[2].lawDispatcher.functors[0]
    law.dampingRatio = p.get("xi_slide", law.dampingRatio)
    ratio, fz = 0.0, FrozenShare()  # largest |tangential contact force| / springs' normal force
    for k in range(200):
        O.step()
        fz.sample(O)
        f, i = O.forces.f(b.id), O.interactions[0, b.id]
        ratio = max(ratio, abs(f[0]) / max(i.phys.normalForce, 1e-300))  # over the springs' normal force
    O.run(p.get("steps", 30000) - 200, True)
    emit({"ke_lost": ke0 - kinetic_energy(O), "ke0": ke0, "ke_end": kinetic_energy(O),
          "d": {k: en(k) - e0[k] for k in e0}, "dist": b.state.pos[0] - x0, "mass": b.state.mass,
          "grav_work": b.state.mass * 9.81 * (y0 - b.state.pos[1]), "vel_end": b.state.vel[0], "max_ft_over_fn": ratio,
          "frozen_share": fz.share()})
