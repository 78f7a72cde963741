"""slope.fos() on slopes with a known answer (issue 37): one call on the settled scene, defaults only.
  yade-rbsm -n -x fos_cases.py plane|voronoi|gl
plane: Hoek & Bray's plane failure built by the joint-set cutter (jointset_plane.py's slope), FS 1.4818.
voronoi: a c-phi slope cut into Voronoi blocks (a continuum): the design value is limit equilibrium's.
gl: Griffiths & Lane's slope cut into Voronoi blocks: the design value is Bishop's critical circle."""
import json
import math
import os
import sys
import time

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl

case = sys.argv[1] if len(sys.argv) > 1 else "plane"
# (yade -x: the scripts folder from the package's place)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(sl.__file__)))), "scripts"))
if case == "plane":  # scripts/fos_survey.py's: Hoek & Bray's plane failure, and its closed form
    from fos_survey import blocks_and_rock
    sb, rock, closed, _ = blocks_and_rock("plane")
elif case == "gl":  # Griffiths & Lane's 2:1 slope on a firm base at toe level (scripts/reference_slopes.py)
    from reference_slopes import GAMMA, ground, search, soil
    from yade_rbsm import limit_equilibrium as le
    closed = le.critical_circle(soil("gl"), **search("gl")).fs  # the reference search's minimum, 1.382
    rock = wrapper.RbsmMat(young=1e8, poisson=0.3, density=GAMMA * 1e3 / 9.81, frictionAngle=math.radians(20), cohesion=1e4,
                           tensileStrength=0, ductile=True)
    sb = sl.voronoi_slope_blocks(ground("gl"), 0.0, spacing=2.0, seed=1)
else:
    closed = None
    rock = wrapper.RbsmMat(young=1e8, poisson=0.3, density=2000, frictionAngle=math.radians(20), cohesion=2e4,
                           tensileStrength=1e4, ductile=True)
    sb = sl.voronoi_slope_blocks([(0, 0), (10, 0), (20, 10), (30, 10)], base=-5, spacing=2.0, seed=1)
O.materials.append(rock)
sl.build_scene(sb, rock)
O.engines = yr.engines(enlarge=0.01)
sl.bond_and_break(sb, give_sets=False)
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
sl.give_joint_sets(sb)
t0 = time.time()
r = sl.fos(sb)
print(repr(r))
print(r.to_markdown())
d = json.loads(r.to_json())
print("RESULT " + json.dumps(dict(fs=r.fs, method=r.method, kind=r.kind, warnings=r.warnings, closed=closed,
                                  estimates=d["estimates"], wall=time.time() - t0, repr=repr(r))))
