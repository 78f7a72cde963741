"""Energy of a sphere bouncing on a fixed block (issue 17): r = 0.2 m FrictMat sphere dropped from a gap of
`drop` m onto a fixed Polygon2D block, rotation blocked, no damping anywhere: Cundall-Strack's elastic normal
spring keeps the energy. Returns the apex heights of the first `bounces` rebounds and YADE's energy
tracker's relative error (O.energy.total() against the initial potential energy) at the end, at an apex,
and its largest value (during contact: YADE's tracker sums energies of different half-steps)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade import utils
from _common import params, emit
from yade_rbsm import polygon2d

p = params()
r, g, drop = 0.2, 9.81, p.get("drop", 0.5)
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
sand = FrictMat(young=1e7, poisson=0.3, density=2600, frictionAngle=0.5)
O.materials.append([rock, sand])
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
s = utils.sphere((0.3, r + drop, 0), r, material=sand)
s.state.blockedDOFs = "zXYZ"
O.bodies.append(s)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(), Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Polygon2D_Sphere_ScGeom()], [Ip2_RbsmMat_FrictMat_FrictPhys()],
                             [Law2_ScGeom_FrictPhys_CundallStrack(sphericalBodies=False)]),
             NewtonIntegrator(gravity=(0, -g, 0), damping=0)]
O.dt = p.get("safety", 0.1) * r * (sand.density / sand.young) ** 0.5
O.trackEnergy = True
y0 = s.state.pos[1]
apexes, rising, worst = [], False, 0.0
e0 = s.state.mass * g * drop  # potential energy above the touching height, which the energies below are measured from
while len(apexes) < p.get("bounces", 3) and O.iter < 2000000:
    O.step()
    vy = s.state.vel[1]
    if vy > 0:
        rising = True
    elif rising:
        apexes.append(s.state.pos[1] - r)
        rising = False
    worst = max(worst, abs(O.energy.total()) / e0)
emit({"apexes": apexes, "drop": drop, "energy_error_max": worst, "energy_error_end": abs(O.energy.total()) / e0, "energies": dict(O.energy.items()), "iter": O.iter})
