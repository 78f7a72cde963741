"""Pairs the dispatchers cannot handle (issue 17, "no silent pass-through"). params: case, stopRun.
  'hand_frict_before': a hand-built Polygon2D with FrictMat (as scripts/polygon2d_demo.py once did) on a fixed
                       RbsmMat block, then engines(): the ValueError it raises.
  'hand_frict_after':  engines() first, then the FrictMat block: 2000 steps (RbsmPairCheck reports the pair
                       before it touches; without it (pairCheck False) the Ig2 functor refuses the contact;
                       both stop the run; before issue 17 the process aborted).
  'box':               mixed_engines(), a Box falling on a fixed block: reported by RbsmPairCheck, run stopped
                       (or not, stopRun False).
  'no_ig2':            a hand-written loop without Ig2_Polygon2D_Sphere_ScGeom (RbsmPairCheck appended): a
                       sphere dropped on a block is reported.
  'no_ip2':            a hand-written loop without Ip2_RbsmMat_FrictMat_FrictPhys (RbsmPairCheck appended): a
                       sphere falling on a block is reported before it touches (before: abort at the contact).
Returns the iteration reached, the ERROR lines are in the output."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade import utils
from _common import params, emit
from yade_rbsm import polygon2d, engines, mixed_engines, omega

p = params()
case = p["case"]
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
frict = FrictMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append([rock, frict])
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))


def hand_block():
    b = polygon2d([(0, 0.001), (1, 0.001), (1, 1), (0, 1)], rock)  # then its material is swapped, as a hand-built body
    b.material = frict
    return b


out = {}
if case == "hand_frict_before":
    O.bodies.append(hand_block())
    try:
        O.engines = engines()
    except ValueError as e:
        out["error"] = str(e)
elif case == "hand_frict_after":
    O.engines = [e for e in engines() if p.get("pairCheck", True) or e.label != "pairCheck"]
    O.dt = 1e-5
    O.bodies.append(hand_block())
    O.run(2000, True)
elif case == "box":
    O.bodies.append(utils.box((0.5, 0.6, 0), (0.5, 0.5, 0.5), material=frict))
    O.engines = mixed_engines()
    omega.engine('pairCheck').stopRun = p.get("stopRun", True)
    O.dt = 1e-4
    O.run(10000, True)
    out["reported"] = list(omega.engine('pairCheck').reported)
    out["y"] = O.bodies[1].state.pos[1]
elif case == "no_ig2":
    s = utils.sphere((0.5, 0.3, 0), 0.2, material=frict)
    s.state.blockedDOFs = "zXY"
    O.bodies.append(s)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(), Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()], [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
                 NewtonIntegrator(gravity=(0, -9.81, 0)), RbsmPairCheck()]
    O.dt = 1e-4
    O.run(2000, True)
    out["reported"] = list(omega.engine('pairCheck').reported)
elif case == "no_ip2":
    s = utils.sphere((0.5, 0.25, 0), 0.2, material=frict)  # 5 cm above the block
    s.state.blockedDOFs = "zXY"
    O.bodies.append(s)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(), Bo1_Sphere_Aabb()], verletDist=0.02),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(), Ig2_Polygon2D_Sphere_ScGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb(), Law2_ScGeom_FrictPhys_CundallStrack(sphericalBodies=False)]),
                 NewtonIntegrator(gravity=(0, -9.81, 0)), RbsmPairCheck()]
    O.dt = 1e-4
    O.run(5000, True)
    out["reported"] = list(omega.engine('pairCheck').reported)
    out["y"] = s.state.pos[1]
out["iter"] = O.iter
emit(out)
