# A compliant (quiet) base under an earthquake record (issue 40): a 1D column of bonded unit blocks on its base
# block, shaken horizontally. The column is a shear chain (each block moves along x only: a laterally uniform
# layer), so a pulse entering at the base climbs to the free top, doubles there, comes down and, with a compliant
# base, leaves through it; a rigid base sends it up again.
#   yade-rbsm -n -x quiet_base_column.py pulse rigid|compliant  -> RESULT {"incident", "reflected", "top", ...}
#   yade-rbsm -n -x quiet_base_column.py rest                    -> RESULT {"moved", ...}: a column under gravity
#     on a compliant base and a silent record stays where it settled (the base keeps the static reaction)
#   yade-rbsm -n -x quiet_base_column.py refuse                  -> RESULT {"messages": [...]}: bad input, refused
import json
import math
import sys

from yade import O, wrapper

import yade_rbsm
from yade_rbsm import earthquake, omega, polygon2d

mode = sys.argv[1]
E, nu, rho = 1e8, 0.25, 2000.0
N = 100 if mode == "pulse" else 10
mat = wrapper.RbsmMat(young=E, poisson=nu, density=rho, cohesion=1e9, tensileStrength=1e9, frictionAngle=0.6)
O.materials.append(mat)
ids = [O.bodies.append(polygon2d([(0, i), (1, i), (1, i + 1), (0, i + 1)], mat, fixed=(i == 0))) for i in range(N)]
free = "yzXYZ" if mode == "pulse" else "zXYZ"  # a shear chain; at rest: weight on the base
for i in ids[1:]:
    O.bodies[i].state.blockedDOFs = free
O.engines = yade_rbsm.engines(gravity=(0, 0, 0) if mode == "pulse" else (0, -9.81, 0), damping=0)
omega.ip2(O).setCohesionNow = True
O.step()
ks = [I.phys.ks for I in O.interactions if I.isReal][0]
Zs = math.sqrt(rho * ks * 1.0)  # the chain's impedance: rho c, c = sqrt(ks h / rho) for blocks of height h = 1
c = math.sqrt(ks / rho)

if mode == "refuse":
    rec, messages = earthquake.Record.sine(0.1, 5.0, 0.2), []
    wall = O.bodies.append(polygon2d([(1, 1), (2, 1), (2, 3), (1, 3)], mat, fixed=True))  # beside the column
    for kw in (dict(base="compliant"), dict(base="soft"), dict(base="compliant", base_ids=[0], impedance=(0, 1)),
               dict(base="compliant", base_ids=[0, wall], impedance=(1e6,)), dict(impedance=(1, 1)),
               dict(base="compliant", base_ids=[12345])):
        try:
            earthquake.apply(rec, **kw)
            messages.append(None)
        except ValueError as e:
            messages.append(str(e))
    print("RESULT " + json.dumps(dict(messages=messages, engines=[type(e).__name__ for e in O.engines],
                                      base=O.bodies[0].state.blockedDOFs)))
    sys.exit(0)

if mode == "rest":
    omega.newton(O).damping = 0.6
    while O.iter < 4000:
        O.step()
    omega.newton(O).damping = 0
    for b in O.bodies:
        b.state.vel = (0, 0, 0)
    O.trackEnergy = True
    earthquake.apply(earthquake.Record.sine(0.0, 5.0, 0.2), base="compliant", impedance=(math.sqrt(rho * E), Zs))
    start = [O.bodies[i].state.pos for i in ids]
    end = O.time + 0.5
    peak = 0.0
    while O.time < end:
        O.step()
        peak = max(peak, max((O.bodies[i].state.pos - p).norm() for i, p in zip(ids, start)))
    free = O.bodies[0].state.blockedDOFs
    # the record given again, then stopped: the base is fixed as it was built, then let go again, then fixed
    earthquake.apply(earthquake.Record.sine(0.0, 5.0, 0.2), base="compliant", impedance=(math.sqrt(rho * E), Zs))
    again = O.bodies[0].state.blockedDOFs
    earthquake.apply(None)
    print("RESULT " + json.dumps(dict(moved=peak, top_weight=N * rho * 9.81, base_free=free, base_again=again,
                                      base_after=O.bodies[0].state.blockedDOFs, engines=[type(e).__name__ for e in O.engines])))
    sys.exit(0)

base = sys.argv[2]
amp, freq = 0.1, 5.0  # one cycle of 0.1 g at 5 Hz: a 40 m pulse on 100 blocks (80 blocks per wavelength)
rec = earthquake.Record.sine(amp, freq, 1.0 / freq)
O.trackEnergy = True
earthquake.apply(rec, direction=1, base=base, impedance=(math.sqrt(rho * E), Zs) if base == "compliant" else None)
mid, top = ids[N // 2], ids[-1]
H = N - 1.0  # from the base block's top to the column's top
series, stored = [], 0.0
while O.time < 2.9 * H / c + 1.0 / freq + 0.1:
    O.step()
    series.append((O.time, O.bodies[mid].state.vel[0], O.bodies[top].state.vel[0]))
    stored = max(stored, O.energy["kinetic"] + O.energy["elastPotential"])  # the pulse's energy, once it is all in


def peak(t0, t1, k=1):
    return max(abs(s[k]) for s in series if t0 <= s[0] <= t1)


T, ymid = 1.0 / freq, O.bodies[mid].state.pos[1] - 1.0  # the pulse enters at the base block's top (y = 1)
window = 0.25 * T
incident = peak(ymid / c - window, ymid / c + T + window)
from_top = peak((2 * H - ymid) / c - window, (2 * H - ymid) / c + T + window)
reflected = peak((2 * H + ymid) / c - window, (2 * H + ymid) / c + T + window)
v_outcrop = max(abs(rec.velocity(t)) for t in [i * T / 200 for i in range(201)])
energy = {k: v for k, v in O.energy.items()}
print("RESULT " + json.dumps(dict(incident=incident, from_top=from_top, reflected=reflected, top=peak(0, series[-1][0], 2),
                                  outcrop=v_outcrop, c=c, energy=energy, dt=O.dt, stored=stored)))
