"""A block slides down an incline onto a flat and runs out (issue 35, item 2).
Fixed ground: an incline at psi (deg) down to a kink at x = 0, then a flat. A block L x H (density 2000,
joint kn = ks = 1e9 Pa/m, phi, c = 0) starts at rest on the incline at its static overlap (start 'static') or
touching it (start 'touching', as a user places it: it bounces on its springs as it slides), its front
corner `slide` m up the slope from the kink (kink_only: stop there); gravity g = 9.81; contact damping ratio xi, no other damping;
impact_safety: engines()'s (default 0.25).
Returns the centroid's speed when its travel along the incline is slide − L (the front corner still L/2
up the slope) and the closed form there, sqrt(2 g s (sin psi − tan phi cos psi)); and the runout: the
centroid's x when it stops on the flat, from the kink; and the energy balance (O.trackEnergy from the first
step): drift = O.energy.total() − its value after the first step, grav_work = −O.energy['gravWork']."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, sin, cos, tan, sqrt
from _common import params, emit
from yade_rbsm import polygon2d, engines

p = params()
psi, phi = radians(p.get("psi", 30)), radians(p.get("phi", 20))
L, H, xi, slide, g = p["L"], p["H"], p.get("xi", 0.0), p.get("slide", 10.0), 9.81
kn = p.get("kn", 1e9)
mat = RbsmMat(young=1e9, poisson=0.0, density=2000, frictionAngle=phi, jointKn=kn, jointKs=kn)
O.materials.append(mat)
X = (slide + 2 * L) * cos(psi)  # the incline's horizontal extent
O.bodies.append(polygon2d([(-X, -1), (0, -1), (0, 0), (-X, X * tan(psi))], mat, fixed=True))
O.bodies.append(polygon2d([(0, -1), (30, -1), (30, 0), (0, 0)], mat, fixed=True))
d = 2000 * H * g * cos(psi) / kn if p.get("start", "static") == "static" else 0.0  # static overlap, or touching
t_, n_ = (-cos(psi), sin(psi)), (sin(psi), cos(psi))  # up the slope, out of it
front = (t_[0] * slide - n_[0] * d, t_[1] * slide - n_[1] * d)
corners = [(0, H), (L, H), (L, 0), (0, 0)]  # (up the slope, out of it): a left-handed frame, so clockwise here
b = O.bodies[O.bodies.append(polygon2d([(front[0] + t_[0] * u + n_[0] * v, front[1] + t_[1] * u + n_[1] * v) for u, v in corners], mat))]
O.engines = engines(gravity=(0, -g, 0), contact_damping=xi, update_tolerance=p.get("ut", 0.0), impact_safety=p.get("impact_safety", 0.25))
O.trackEnergy = True
O.step()
E0 = O.energy.total()  # the energy balance: O.energy.total() - E0, against the work of gravity
c0 = b.state.pos
a = g * (sin(psi) - tan(phi) * cos(psi))
s_m, v_m, prev = slide - L, None, None
while O.time < 30:
    O.step()
    s = (b.state.pos - c0).dot(Vector3(-t_[0], -t_[1], 0))  # travel down the slope
    v = b.state.vel.norm()
    if v_m is None and s >= s_m and prev is not None:
        f = (s_m - prev[0]) / (s - prev[0])
        v_m = prev[1] + f * (v - prev[1])
    prev = (s, v)
    if v_m is not None and p.get("kink_only"):
        break
    if b.state.pos[0] > 0 and v < 1e-4 and O.iter % 10 == 0:
        break
emit({"v_kink": v_m, "v_closed": sqrt(2 * a * s_m), "runout": b.state.pos[0], "time": O.time, "steps": O.iter,
      "stopped": b.state.vel.norm() < 1e-4, "drift": O.energy.total() - E0, "grav_work": -O.energy["gravWork"],
      "energy": {k: O.energy[k] for k in O.energy.keys()}, "y": b.state.pos[1], "turn": b.state.rot()[2]})
