"""Cases a new user hit (session 8 trial): param case =
'engines_wall'   a block resting on utils.wall / utils.facet (param boundary) under engines(): the pair
                 must be reported and the run stopped, not passed through silently;
'wall_first'     a block 1 m above a wall or facet under mixed_engines(), nothing else: the first step
                 must not stay at YADE's 1e-8 (first contact with a rigid boundary);
'z_velocity'     a block on a base given state.vel z = 2 (or angVel x): reported by id, the run stops;
'advance_frac'   advance(2.7) must be a ValueError, not 2 steps."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade import utils  # noqa: E402
from _common import params, emit  # noqa: E402
import yade_rbsm  # noqa: E402
from yade_rbsm import polygon2d, engines, mixed_engines, advance  # noqa: E402

p = params()
case = p["case"]
m = RbsmMat(young=2e8, poisson=0.2, density=2400, frictionAngle=math.radians(30))
O.materials.append(m)
res = {}


def boundary(kind):
    if kind == "wall":
        return utils.wall((0, 0, 0), axis=1, material=m)
    return utils.facet([Vector3(-10, 0, -1), Vector3(10, 0, -1), Vector3(0, 0, 1)], material=m)


def rect(x0, y0, w, h):
    return polygon2d([(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)], m)


def run(n):
    try:
        advance(n)
        return None
    except Exception as e:
        return str(e)


if case == "engines_wall":
    O.bodies.append(boundary(p["boundary"]))
    b = O.bodies[O.bodies.append(rect(-0.5, 0.0, 1, 0.5))]
    O.engines = engines()
    O.dt = 1e-3
    res.update(exc=run(1000), iter=O.iter, y=b.state.pos[1])
elif case == "wall_first":
    O.bodies.append(boundary(p["boundary"]))
    b = O.bodies[O.bodies.append(rect(-0.5, 1.0, 1, 0.5))]
    O.engines = mixed_engines()
    res.update(exc=run(100), dt=O.dt, time=O.time, y=b.state.pos[1])
elif case == "z_velocity":
    O.bodies.append(rect(-5, -1, 10, 1))
    O.bodies[0].state.blockedDOFs = "xyzXYZ"
    b = O.bodies[O.bodies.append(rect(-0.5, 0.0, 1, 0.5))]
    O.engines = engines()
    advance(10)
    if p.get("what") == "angVel":
        b.state.angVel = (0.5, 0, 0)
    else:
        b.state.vel = (0, 0, 2)
    res.update(exc=run(2000), iter=O.iter, y=b.state.pos[1])
elif case == "advance_frac":
    O.bodies.append(rect(-0.5, 0.0, 1, 0.5))
    O.engines = engines()
    res.update(exc=run(2.7), iter=O.iter)
emit(res)
