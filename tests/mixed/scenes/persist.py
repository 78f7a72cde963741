"""Save and load of a mixed scene (issue 17): a block launched at 1 m/s along a YADE Wall with a sphere on
it, a sphere launched at 0.5 m/s along a Facet, both stopped by friction within about 0.2 s; mixed_engines(). params: split (steps before O.save/O.load; 0: no
save), steps (total), fmt ('xml' or 'bin'). Returns the final positions and the interaction classes."""
import os, sys, tempfile
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, sin, cos
from yade import utils
from _common import params, emit
from yade_rbsm import polygon2d, mixed_engines

p = params()
rock = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=radians(30))
sand = FrictMat(young=1e7, poisson=0.3, density=2600, frictionAngle=radians(20))
O.materials.append([rock, sand])
O.bodies.append(utils.wall((0, 0, 0), axis=1, material=rock))
O.bodies.append(polygon2d([(0, 0), (4, 0), (4, 0.5), (0, 0.5)], rock))
s = utils.sphere((2, 0.7, 0), 0.2, material=sand)
s.state.blockedDOFs = "zXY"
O.bodies.append(s)
O.bodies.append(utils.facet([(-20, 0, -1), (-5, 0, -1), (-12, 0, 1)], material=sand))
s2 = utils.sphere((-12, 0.21, 0), 0.2, material=sand)
s2.state.blockedDOFs = "zXY"
O.bodies.append(s2)
O.bodies[1].state.vel = (1, 0, 0)
s2.state.vel = (0.5, 0, 0)
O.engines = mixed_engines(contact_damping=0.3)
split, steps = p.get("split", 0), p.get("steps", 300)
if split:
    O.run(split, True)
    path = os.path.join(tempfile.mkdtemp(), "mixed." + ("xml" if p.get("fmt", "xml") == "xml" else "bin"))
    O.save(path)
    O.load(path)
O.run(steps - O.iter, True)
emit({"pos": [list(b.state.pos) for b in O.bodies], "iter": O.iter, "dt": O.dt,
      "classes": sorted("%d-%d %s %s" % (i.id1, i.id2, type(i.geom).__name__, type(i.phys).__name__) for i in O.interactions if i.isReal)})
