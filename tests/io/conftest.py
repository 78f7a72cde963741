"""Helpers of the yade_rbsm.io tests: scenes run through the launcher (tests/yade/yaderun.py), and
py/ on sys.path for the parts that need no YADE (describe, polyline checks)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "yade"))
sys.path.insert(0, os.path.normpath(os.path.join(HERE, "..", "..", "py")))

# A scene of blocks of several kinds: two materials (one without a label), a fixed base, a rotated
# pentagon, blocks with velocities; built by polygon2d, before any step.
SCENE = r"""
import math
from yade_rbsm import polygon2d, engines
rock = RbsmMat(young=2e8, poisson=0.25, planeStrain=False, density=2403, frictionAngle=math.radians(35), cohesion=1e4,
               tensileStrength=5e3, label="rock")
soil = RbsmMat(young=5e7, poisson=0.3, planeStrain=False, density=1800, frictionAngle=math.radians(25))
O.materials.append([rock, soil])
O.bodies.append(polygon2d([(-10, -1), (10, -1), (10, 0), (-10, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(0, 0), (2, 0), (2, 1), (0, 1)], rock, thickness=0.5))
c, s = math.cos(0.3), math.sin(0.3)
penta = [(3 + 0.8 * math.cos(a), 1.2 + 0.8 * math.sin(a)) for a in [0.4 + 2 * math.pi * k / 5 for k in range(5)]]
O.bodies.append(polygon2d(penta, soil))
O.bodies.append(polygon2d([(-3, 0), (-1.5, 0), (-2, 1.1)], soil))
O.bodies[2].state.vel = (0.3, -0.2, 0)
O.bodies[2].state.angVel = (0, 0, 0.7)
O.bodies[3].state.vel = (-0.1, 0, 0)
O.engines = engines(gravity=(0, -9.81, 0), contact_damping=0.1)
"""

# What the tests compare of a scene: per body and per material (a yade-side function).
SNAPSHOT = r"""
def snapshot():
    out = []
    for b in O.bodies:
        st = b.state
        out.append(dict(world=[list(v) for v in b.shape.worldVertices(st.pos, st.ori)], pos=list(st.pos),
                        mass=st.mass, inertia=list(st.inertia), fixed=st.blockedDOFs, thickness=b.shape.thickness,
                        vel=list(st.vel), angVel=list(st.angVel),
                        material={k: v for k, v in b.material.dict().items() if k not in ("id", "label")}))
    return out
"""
