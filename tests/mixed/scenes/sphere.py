"""A sphere (disk in the x-y plane) on a Polygon2D block, issue 17. Fixed block 205 x 1 m, top at y = 0.
params: mode, grain ('frict' or 'rbsm': the sphere's material), engines ('explicit' or 'mixed': mixed_engines()).
  'rest':    sphere r = 0.2 dropped from 1 cm above, Newton damping 0.3, 20000 steps: the block's force and
             the weight.
  'incline': gravity tilted by psi (deg), the sphere's rotation blocked (it slides), phi (deg) of both
             materials, started at its static overlap: least-squares acceleration over the second half.
  'pair':    a free square block (1 x 1 m) and a free sphere pressed into its edge off-centre, moving along
             it and spinning, no gravity: force and moment sums of the two bodies after each of 50 steps.
"""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, sin, cos
from yade import utils
from _common import params, emit, lsq_slope, pair_balance
from yade_rbsm import polygon2d, mixed_engines

p = params()
mode = p.get("mode", "rest")
phi, psi, g, r = radians(p.get("phi", 20)), radians(p.get("psi", 35)), 9.81, 0.2
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=phi)
sand = FrictMat(young=1e7, poisson=0.3, density=2600, frictionAngle=phi) if p.get("grain", "frict") == "frict" else \
    RbsmMat(young=1e7, poisson=0.3, density=2600, frictionAngle=phi)
O.materials.append([rock, sand])


def engines(gravity, damping):
    if p.get("engines", "explicit") == "mixed":
        return mixed_engines(gravity=gravity, damping=damping)
    return [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(), Bo1_Sphere_Aabb()]),
            InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(), Ig2_Polygon2D_Sphere_ScGeom()],
                            [Ip2_RbsmMat_RbsmMat_RbsmPhys(), Ip2_RbsmMat_FrictMat_FrictPhys()],
                            [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(), Law2_ScGeom_FrictPhys_CundallStrack(sphericalBodies=False)]),
            NewtonIntegrator(gravity=gravity, damping=damping)]


if mode in ("rest", "incline"):
    O.bodies.append(polygon2d([(-5, -1), (200, -1), (200, 0), (-5, 0)], rock, fixed=True))
    kn = 2 * (sand.young * r) * (rock.young * r) / (sand.young * r + rock.young * r)  # Ip2_FrictMat_FrictMat_FrictPhys's rule
    m = sand.density * 4 / 3 * 3.141592653589793 * r ** 3
    y0 = r + 0.01 if mode == "rest" else r - m * g * cos(psi) / kn  # the incline starts at its static overlap
    s = utils.sphere((0.3, y0, 0), r, material=sand)
    s.state.blockedDOFs = "zXY" if mode == "rest" else "zXYZ"
    O.bodies.append(s)
    grav = (0, -g, 0) if mode == "rest" else (g * sin(psi), -g * cos(psi), 0)
    O.engines = engines(grav, 0.3 if mode == "rest" else 0.0)
    O.dt = 0.5 * r * (sand.density / sand.young) ** 0.5  # YADE's PWaveTimeStep(), also for an RbsmMat sphere
    if mode == "rest":
        O.run(20000, True)
        i = O.interactions[0, 1]
        emit({"fblock": list(O.forces.f(0)), "weight": s.state.mass * g, "geom": type(i.geom).__name__, "phys": type(i.phys).__name__,
              "normal": list(i.geom.normal), "kn": i.phys.kn, "kn_expected": kn, "y": s.state.pos[1], "id1": i.id1})
    else:
        n = p.get("steps", 4000)
        ts, vs = [], []
        for k in range(n):
            O.step()
            if k >= n // 2 and k % 10 == 0:
                ts.append(O.time)
                vs.append(s.state.vel[0])
        emit({"a": lsq_slope(ts, vs), "disp": s.state.pos[0] - 0.3, "vy": s.state.vel[1], "contact": O.interactions.has(0, 1)})
else:  # pair
    b = O.bodies[O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], rock))]
    s = utils.sphere((0.8, 1 + r - 0.002, 0), r, material=sand)
    s.state.blockedDOFs = "zXY"
    O.bodies.append(s)
    s.state.vel, s.state.angVel = (0.3, -0.05, 0), (0, 0, 4.0)
    b.state.vel, b.state.angVel = (-0.1, 0.02, 0), (0, 0, -0.7)
    O.engines = engines((0, 0, 0), 0.0)
    O.dt = 1e-5
    worst = {"fsum": 0, "msum": 0, "fscale": 0, "mscale": 0}
    for k in range(50):
        x1, x2 = Vector3(b.state.pos), Vector3(s.state.pos)
        O.step()
        bal = pair_balance(O, b.id, s.id, x1, x2)
        for key in worst:
            worst[key] = max(worst[key], bal[key])
    worst["tblock"] = bal["t1"][2]
    emit(worst)
