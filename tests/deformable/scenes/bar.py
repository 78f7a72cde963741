"""A bar of N unit-square blocks in a row (plane stress, E, nu, rho), deformable or rigid, no gravity.
mode 'mode1': free-free, welded, initial velocity of the fundamental mode v = v0 cos(pi x/L) (and the strain
  rate it implies, dv/dx, for deformable blocks); returns the zero crossings of block 0's velocity
  (half a period apart: the period is 2L/c).
mode 'impact': the bar, welded, moves at v0 onto a fixed block of the same material (a new, frictionless
  contact); returns the times the contact starts and ends (its duration is 2L/c) and the rebound speed."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import pi, cos, sin
from _common import params, emit
import yade_rbsm
from yade_rbsm import polygon2d, omega

p = params()
E, nu, rho, N, v0 = p.get("E", 1e8), p.get("nu", 0.2), p.get("rho", 2000.0), p.get("N", 50), p.get("v0", 0.01)
deformable = p.get("deformable", True)
mat = RbsmMat(young=E, poisson=nu, density=rho, planeStrain=False, cohesion=1e9, tensileStrength=1e9, frictionAngle=0,
              deformable=deformable)
O.materials.append(mat)
L = float(N)
ids = [O.bodies.append(polygon2d([(i, 0), (i + 1, 0), (i + 1, 1), (i, 1)], mat)) for i in range(N)]
for i in ids:
    O.bodies[i].state.blockedDOFs = "yzXYZ"  # a 1D column: its blocks move along x only (and deform)
O.engines = yade_rbsm.engines(gravity=(0, 0, 0), damping=0, safety=p.get("safety", 0.8), impact_safety=p.get("safety", 0.8))
omega.ip2(O).setCohesionNow = True
O.step()
welded = sum(1 for I in O.interactions if I.isReal and I.phys.welded)
if p.get("mode", "mode1") == "mode1":
    for i in ids:
        s = O.bodies[i].state
        s.vel = (v0 * cos(pi * s.pos[0] / L), 0, 0)
        if deformable:
            s.strainRate = (-v0 * pi / L * sin(pi * s.pos[0] / L), 0, 0)
    probe = lambda: O.bodies[ids[0]].state.vel[0]
    crossings, prev = [], probe()
    while len(crossings) < 3 and O.iter < p.get("steps", 200000):
        O.step()
        v = probe()
        if (v > 0) != (prev > 0):
            crossings.append(O.time - O.dt * v / (v - prev))  # linear interpolation within the step
        prev = v
    emit({"crossings": crossings, "L": L, "welded": welded, "dt": O.dt})
else:
    wall = O.bodies.append(polygon2d([(-2.0, 0), (-0.001, 0), (-0.001, 1), (-2.0, 1)], mat, fixed=True))
    for i in ids:
        O.bodies[i].state.vel = (-v0, 0, 0)
    touching = lambda: O.interactions.has(wall, ids[0]) and O.interactions[wall, ids[0]].isReal and O.interactions[wall, ids[0]].phys.normalForce > 0
    mean_speed = lambda: sum(O.bodies[i].state.vel[0] * O.bodies[i].state.mass for i in ids) / sum(O.bodies[i].state.mass for i in ids)
    # the contact's duration: from its first force to its last (the first block may chatter on the stiff
    # contact in between), once the bar moves away and the contact has been open for 0.1 L/c
    start = end = None
    while O.iter < p.get("steps", 200000):
        O.step()
        if touching():
            start = O.time if start is None else start
            end = O.time
        elif end is not None and mean_speed() > 0 and O.time - end > 0.1 * L / (E / rho) ** 0.5:
            break
    emit({"start": start, "end": end, "L": L, "welded": welded, "dt": O.dt, "rebound": mean_speed(),
          "gaps": None})
