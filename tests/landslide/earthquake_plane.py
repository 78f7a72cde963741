# A rock wedge on a daylighting plane under earthquake loading (issue 40): Hoek & Bray's plane-failure slope of
# jointset_plane.py (a 60 deg face 12 m high, a bedding dipping psi = 30 deg, a vertical tension crack at x = 22 m)
# with a cohesionless bedding of phi = 40 deg, so that the wedge is Newmark's rigid block on a plane: its yield
# acceleration is tan(phi - psi) = tan 10 deg, and under a ground acceleration above it the wedge slides by
# Newmark's integration of the record. The rock is stiff (E = 20 GPa: the slope's first mode near 30 Hz), so that
# the ground under the wedge moves with the base as Newmark assumes; at 200 MPa (near 3 Hz) the slope amplifies
# a 1 Hz record and the wedge slid 0.419 m against Newmark's 0.278 m.
#   yade-rbsm -n -x earthquake_plane.py ky                        -> RESULT {"ky": ..., "closed": ...}
#   yade-rbsm -n -x earthquake_plane.py newmark AMP_G FREQ CYCLES [rigid|compliant]  -> RESULT {"slide", "newmark"}
#     (compliant: the slope built without side walls, its foundation let go on Lysmer's dashpots; the wedge's slide
#     measured against the foundation)
import json
import math
import sys

from yade import O, wrapper

from yade_rbsm import earthquake, slope as sl

mode = sys.argv[1]
psi, phi, rho = 30.0, 40.0, 2600.0
xt, H = 10.0, 12.0
xcrest = xt + H / math.tan(math.radians(60))
xd, yd, xc = xt + 3 / math.tan(math.radians(60)), 3.0, 22.0
yc = yd + (xc - xd) * math.tan(math.radians(psi))
rock = wrapper.RbsmMat(young=2e10, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
                       tensileStrength=2e6, ductile=True)
O.materials.append(rock)
bedding = sl.Trace([(xd, yd), (xc, yc)], cohesion=0, friction_angle=phi, ductile=True, name="bedding")
crack = sl.Trace([(xc, yc), (xc, H)], friction_angle=20, ductile=True, name="tension crack")
base = sys.argv[5] if mode == "newmark" and len(sys.argv) > 5 else "rigid"
# (a compliant base moves: no side walls to hold the model, its sides are free)
sb = sl.jointset_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, traces=[bedding, crack],
                        wall=0 if base == "compliant" else 1.0)
m = sl.SlopeModel(sb, rock)
m.build(enlarge=0.01)
m.settle()
m.give_joint_sets()
if mode == "ky":
    ky = m.yield_acceleration(towards=-1)   # the face looks to -x
    m.set_seismic(0.1, towards=-1)          # limit equilibrium on the wedge's plane under the scene's kh
    lem = m.limit_equilibrium(polyline=[(xd, yd), (xc, yc), (xc + 1e-3, H)], c=0, phi=math.radians(phi))
    print("RESULT " + json.dumps(dict(ky=ky, closed=math.tan(math.radians(phi - psi)), stages=[s.name for s in m.stages],
                                      le_kh=lem["Fellenius, slip polyline"].fs)))
else:
    amp, freq, cycles = float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    rec = earthquake.Record.sine(amp, freq, cycles / freq)
    wedge = [b for b in sb.free if sum(p[0] for p in b.vertices) / len(b.vertices) > xd
             and sl.interp_y([(xd, yd), (xc, yc)], min(max(sum(p[0] for p in b.vertices) / len(b.vertices), xd), xc))
             < sum(p[1] for p in b.vertices) / len(b.vertices) and sum(p[0] for p in b.vertices) / len(b.vertices) < xc]
    ids = [b.id for b in wedge]
    from yade_rbsm import quiet_base
    ground = quiet_base.base_blocks(O)  # the fixed block at the bottom
    m.set_earthquake(rec, direction=1, base=base)  # ground acceleration along +x, into the slope: the wedge is thrown out
    O.trackEnergy = True
    m.run(cycles / freq + 1.5, chunks=1, progress=None)
    g = O.bodies[ground[0]].state
    moved = g.pos - g.refPos  # the ground under the slope (0 on a rigid base: the model is in its frame)
    d = [O.bodies[i].state.pos - O.bodies[i].state.refPos - moved for i in ids]
    slide = sum(math.hypot(v[0], v[1]) for v in d) / len(d)
    along = sum(-v[0] * math.cos(math.radians(psi)) - v[1] * math.sin(math.radians(psi)) for v in d) / len(d)
    nm = earthquake.newmark(rec, psi=psi, phi=phi, direction=1, face=-1)
    print("RESULT " + json.dumps(dict(slide=slide, along=along, newmark=nm.displacement, wedge=len(ids),
                                      ay=nm.ay, gravity=list(O.engines[-1].gravity), ground=list(moved),
                                      ground_record=sum(rec.velocity(k * 1e-3) for k in range(int((cycles / freq + 1.5) / 1e-3))) * 1e-3)))
