"""A block held by friction on a fixed plane, undamped, under gravity tilted slowly (issue 35, item 1).
For each case (kn [Pa/m], L x H [m], psi [deg], nIP) a block of density 2000 starts at its static
overlap W/(kn·L) on a fixed plane (joint kn = ks, phi = phi_deg, c = 0, no damping anywhere); gravity
(g = 10) tilts from 0 to psi over `ramp` natural periods of the block on its joint, 2π·sqrt(ρH/kn),
and is held `hold` more. Returns per case: the largest and smallest normal force of the joint over the
weight's normal component (after the first period), the steps without a compressed joint, the joint's
frictional dissipation, the slide of the centroid along the plane and the static overlap W/(kn·L)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from math import radians, sin, cos, pi, sqrt
from _common import params, emit
from yade_rbsm import polygon2d, engines

p = params()
g, rho = 10.0, 2000.0
phi = radians(p.get("phi_deg", 40.1))
out = []
for kn, L, H, psi_deg, nip in p["cases"]:
    O.reset()
    mat = RbsmMat(young=1e9, poisson=0.0, density=rho, frictionAngle=phi, jointKn=kn, jointKs=kn)
    O.materials.append(mat)
    O.bodies.append(polygon2d([(-20 * L, -L), (20 * L, -L), (20 * L, 0), (-20 * L, 0)], mat, fixed=True))
    d0 = rho * H * g / kn  # static overlap W/(kn L)
    b = O.bodies[O.bodies.append(polygon2d([(0, -d0), (L, -d0), (L, H - d0), (0, H - d0)], mat))]
    O.engines = engines(gravity=(0, -g, 0), nIP=nip)
    period = 2 * pi * sqrt(rho * H / kn)
    ramp, hold = p.get("ramp", 600) * period, p.get("hold", 300) * period
    O.step()
    x0 = b.state.pos[0]
    W, psi = b.state.mass * g, radians(psi_deg)
    fmax, fmin, lifted, t0 = 0.0, 1e9, 0, O.time
    newton = O.engines[-1]
    while O.time - t0 < ramp + hold:
        a = psi * min(1.0, (O.time - t0) / ramp)
        newton.gravity = (g * sin(a), -g * cos(a), 0)
        O.step()
        i = O.interactions[0, b.id] if O.interactions.has(0, b.id) else None
        fn = i.phys.normalForce if i is not None and i.isReal else 0.0
        lifted += fn <= 0
        if O.time - t0 > period:
            fmax, fmin = max(fmax, fn / (W * cos(a))), min(fmin, fn / (W * cos(a)))
    i = O.interactions[0, b.id] if O.interactions.has(0, b.id) else None
    out.append({"case": [kn, L, H, psi_deg, nip], "fmax": fmax, "fmin": fmin, "lifted": lifted, "steps": O.iter,
                "dissipated": i.phys.plasticDissipation if i is not None and i.isReal else -1.0,  # -1: the joint is gone
                "slide": b.state.pos[0] - x0, "overlap": d0, "rot": b.state.ori.toAxisAngle()[1]})
emit({"cases": out})
