"""A horizontal bar of bonded square blocks, or one bonded joint pulled apart.
mode 'mode1': N unit squares (a), no gravity, bonded (strong), initial velocity of the free-free
  fundamental mode v_i = v0 cos(π x_i/L); returns the times of the zero crossings of block 0's velocity.
mode 'tension': a fixed block and a kinematic block (thickness t) pulled apart at constant speed until
  the joint breaks and separates, pushed back into contact (compression), then pulled again; returns the
  largest tension before the break, the joint state after it and the largest tension afterwards.
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import pi, cos, sqrt
from _common import params, emit, FrozenShare
from yade_rbsm import polygon2d

p = params()
E, nu, rho = p.get("E", 1e8), p.get("nu", 0.2), p.get("rho", 2000.0)
mode = p.get("mode", "mode1")
ip2 = Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=True)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01)]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(interactionDistance=1e-9, updateTolerance=p.get("ut", 0.0))], [ip2],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
             NewtonIntegrator(gravity=(0, 0, 0), damping=0)]

if mode == "mode1":
    N, a, v0 = p.get("N", 100), 1.0, p.get("v0", 0.01)
    mat = RbsmMat(young=E, poisson=nu, density=rho, planeStrain=p.get("planeStrain", False), cohesion=1e9,
                  tensileStrength=1e9)
    O.materials.append(mat)
    L = N * a
    ids = [O.bodies.append(polygon2d([(i * a, 0), ((i + 1) * a, 0), ((i + 1) * a, a), (i * a, a)], mat)) for i in range(N)]
    for i in ids:
        O.bodies[i].state.vel = (v0 * cos(pi * O.bodies[i].state.pos[0] / L), 0, 0)
    m, kn_l = O.bodies[0].state.mass, None
    O.dt = p.get("dt", 2e-4)
    crossings, prev = [], O.bodies[0].state.vel[0]
    nsteps, fz = p.get("steps", 6000), FrozenShare()
    for k in range(nsteps):
        O.step()
        fz.sample(O)
        if k == 0:
            i0 = O.interactions[ids[0], ids[1]]
            kn_l = i0.phys.kn * i0.geom.length * i0.geom.thickness
        v = O.bodies[0].state.vel[0]
        if (v > 0) != (prev > 0):
            crossings.append(O.time - O.dt * v / (v - prev))   # linear interpolation within the step
        prev = v
    emit({"crossings": crossings, "L": L, "mass": m, "kn_l": kn_l, "n_inter": sum(1 for i in O.interactions if i.isReal),
          "frozen_share": fz.share(), "n_intact": sum(1 for i in O.interactions if i.isReal and i.phys.nIntact == len(i.phys.intactPoints))})
else:
    t, st, v = p.get("thickness", 0.5), p.get("sigmaT", 1e5), p.get("speed", 1e-2)
    mat = RbsmMat(young=E, poisson=nu, density=rho, planeStrain=False, cohesion=2 * st, tensileStrength=st,
                  frictionAngle=0.5)
    O.materials.append(mat)
    A = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat, thickness=t, fixed=True))
    B = O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], mat, thickness=t, fixed=True))
    O.dt = p.get("dt", 1e-4)
    bB = O.bodies[B]

    def joint():
        return O.interactions[A, B] if O.interactions.has(A, B) and O.interactions[A, B].isReal else None

    O.step()                                    # bonded joint made at zero strain
    j = joint()
    length = j.geom.length
    res = {"length": length, "thickness": j.geom.thickness, "intact0": list(j.phys.intactPoints)}
    bB.state.vel = (v, 0, 0)
    maxT, broke_step, k = 0.0, None, 0
    while k < 100000:
        O.step(); k += 1
        j = joint()
        if j is None or j.phys.nIntact < len(j.phys.intactPoints):
            broke_step = k
            res["intact_after"] = list(j.phys.intactPoints) if j else None
            res["force_at_break_step"] = j.phys.normalForce if j else None
            break
        maxT = max(maxT, -j.phys.normalForce)
    res["maxT_before"], res["broke_step"] = maxT, broke_step
    res["gap_at_break"] = bB.state.pos[0] - 1.5
    # keep pulling to a clear gap, then push back into compression, then pull again
    maxT_after, seen_intact, steps_open = 0.0, False, 0
    for vel, nst in ((v, 1000), (-v, 2500), (v, 3000)):
        bB.state.vel = (vel, 0, 0)
        for _ in range(nst):
            O.step()
            j = joint()
            if j is not None:
                maxT_after = max(maxT_after, -j.phys.normalForce)
                seen_intact = seen_intact or j.phys.nIntact > 0
        if vel < 0:
            j = joint()
            res["compression_after_push"] = j.phys.normalForce if j else None
    res["maxT_after"], res["intact_seen_after"] = maxT_after, seen_intact
    res["kn"] = O.interactions[A, B].phys.kn if joint() else None
    emit(res)
