"""slope.fos() on slopes with a known answer (issue 37): one call on the settled scene, defaults only.
  yade-rbsm -n -x fos_cases.py plane|voronoi|gl
plane: Hoek & Bray's plane failure built by the joint-set cutter (jointset_plane.py's slope), FS 1.4818.
voronoi: a c-phi slope cut into Voronoi blocks (a continuum): the design value is limit equilibrium's.
gl: Griffiths & Lane's slope cut into Voronoi blocks: the design value is Bishop's critical circle."""
import json
import math
import sys
import time

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl

case = sys.argv[1] if len(sys.argv) > 1 else "plane"
if case == "plane":
    psi, beta, rho = math.radians(30), math.radians(60), 2600.0
    xt, H = 10.0, 12.0
    xcrest = xt + H / math.tan(beta)
    xd, yd, xc = xt + 3 / math.tan(beta), 3.0, 22.0
    yc = yd + (xc - xd) * math.tan(psi)
    cb = 20e3
    wedge = [(xd, yd), (xc, yc), (xc, H), (xcrest, H)]
    W = rho * 9.81 * 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1]))
    L = (xc - xd) / math.cos(psi)
    closed = (cb * L + W * math.cos(psi) * math.tan(math.radians(30))) / (W * math.sin(psi))
    rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
                           tensileStrength=2e6, ductile=True)
    traces = [sl.Trace([(xd, yd), (xc, yc)], cohesion=cb, friction_angle=30, ductile=True, name="bedding"),
              sl.Trace([(xc, yc), (xc, H)], friction_angle=20, ductile=True, name="tension crack")]
    sb = sl.jointset_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, traces=traces)
elif case == "gl":  # Griffiths & Lane's 2:1 slope on a firm base at toe level (scripts/reference_slopes.py)
    import os
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(sl.__file__)))), "scripts"))
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
