"""A 1 m square tilted 20 deg dropped 2 mm onto a fixed base, landing on a corner (E = 1e9 Pa), with joint
dashpots (params {"xi": ξ}: engines(contact_damping=ξ)): 6000 steps; emits the smallest O.dt and the
time reached, and the largest total energy (kinetic + potential) after the first step against the start
(a new user's trial 14b: ξ = 0.2 took O.dt down to 2.2e-6 s at a 0.26 mm contact, 6000 steps reached 0.095 s)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite  # noqa: E402
from yade_rbsm import polygon2d, engines, advance  # noqa: E402

xi = params()["xi"]
m = RbsmMat(young=1e9, poisson=0.2, density=2500, frictionAngle=0.6)
O.materials.append(m)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], m, fixed=True))
a = math.radians(20)
c, s = math.cos(a), math.sin(a)
y0 = 0.5 * (c + s) + 0.002
O.bodies.append(polygon2d([(x * c - y * s, y0 + x * s + y * c) for x, y in [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]], m))
O.engines = engines(contact_damping=xi)
b = O.bodies[1]


def energy():
    st = b.state
    return 0.5 * st.mass * st.vel.squaredNorm() + 0.5 * st.inertia[2] * st.angVel[2] ** 2 + st.mass * 9.81 * st.pos[1]


e0 = energy()
dts, top = [], -1e300
for k in range(6000):
    advance(1)
    dts.append(O.dt)
    top = max(top, energy())
emit(dict(min_dt=min(dts), time=O.time, gain=(top - e0) / (b.state.mass * 9.81), finite=all_finite(O), y=b.state.pos[1]))
