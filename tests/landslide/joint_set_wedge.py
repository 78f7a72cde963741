# A rock wedge on one daylighting joint with a tension crack (Hoek & Bray's planar failure), cut into
# Voronoi blocks or bricks of strong rock; the joint plane gets its own strength with
# slope.set_joint_strength. Prints the strength-reduction FS against the closed form
#   FS = (c A + W cos(psi) tan(phi)) / (W sin(psi))   (dry, vertical crack to the crest).
#   yade-rbsm -n -x joint_set_wedge.py [voronoi|bricks] c_kPa phi_deg psi_deg [ductile|brittle] [before|after]
#   yade-rbsm -n -x joint_set_wedge.py bricks 50 30 35 ductile errors   (bad input: prints ERROR <message>)
#   yade-rbsm -n -x joint_set_wedge.py voronoi 50 30 35 ductile network  (a joint network: found again once settled?)
#   yade-rbsm -n -x joint_set_wedge.py bricks 500 30 35 ductile stiff KN KS  (the set's own springs [Pa/m], before
#     settling: the wedge's elastic slip and settlement on the plane against W sin(psi)/(KS L), W cos(psi)/(KN L))
# Optional 7th and 8th arguments: the rock's Young's modulus [Pa] (default 1e9) and "nofs" (no strength
# reduction). RESULT's "missed": joints of the plane bonded at the start that set_joint_strength did not set.
import json
import math
import sys

from yade import O, Vector3, wrapper

import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

pattern, c_kpa, phi_deg, psi_deg, law, when = sys.argv[1:7]
young = float(sys.argv[7]) if len(sys.argv) > 7 and when != "stiff" else 1e9
with_fs = not (len(sys.argv) > 8 and sys.argv[8] == "nofs")
springs = dict(normal_stiffness=float(sys.argv[7]), shear_stiffness=float(sys.argv[8])) if when == "stiff" else {}
c, phi, psi = float(c_kpa) * 1e3, math.radians(float(phi_deg)), math.radians(float(psi_deg))
rho, g, H, beta = 2600.0, 9.81, 20.0, math.radians(65)
y0, xt, xk = 4.0, 8.0, 26.0  # toe level, toe, tension crack
xcr = xt + H / math.tan(beta)
xd, yd = xt + 4.0 / math.tan(beta), y0 + 4.0  # the joint daylights 4 m above the toe
yk = yd + (xk - xd) * math.tan(psi)
surface = [(0, y0), (xt, y0), (xcr, y0 + H), (40.0, y0 + H)]
plane, crack = [(xd, yd), (xk, yk)], [(xk, yk), (xk, y0 + H)]
rock = wrapper.RbsmMat(young=young, poisson=0.25, density=rho, frictionAngle=math.radians(40), cohesion=5e6,
                       tensileStrength=2e6, label="rock")
O.materials.append(rock)
if when == "network":  # bedding dipping 30 deg every 3 m and cross joints every 4 m, cut through Voronoi blocks
    plane = [[(0.0, yb + math.tan(math.radians(30)) * 0.0), (40.0, yb + math.tan(math.radians(30)) * 40.0)]
             for yb in range(-24, 24, 3)] + [[(x, 0.0), (x, y0 + H)] for x in range(4, 40, 4)]

    def ground(x):
        return y0 if x <= xt else y0 + H if x >= xcr else y0 + (x - xt) * math.tan(beta)
    plane = [l for l in plane if any(0.5 < l[0][1] + (l[1][1] - l[0][1]) * k / 40.0 < ground(l[0][0] + (l[1][0] - l[0][0])
                                                                                           * k / 40.0) - 0.5
                                     for k in range(41))]
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=2.0, seed=5, min_distance=1.0, joints=plane)
elif pattern == "voronoi":
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=2.0, seed=3, min_distance=1.0, joints=[plane], cracks=[crack])
else:
    sb = sl.brick_blocks(surface, 0.0, 1.5, 1.5, joints=[plane], cracks=[crack])
sl.build_scene(sb, rock)
O.engines = yr.engines(set_dt=True, enlarge=0.01)
O.dt = 1e-6
nj, nb = sl.bond_and_break(sb)
cuts = plane if when == "network" else [plane]
bonded_on_plane = {(I.id1, I.id2) for I in sl.joints_on(cuts)}  # found in the pose they were bonded in
strength = dict(cohesion=c, friction_angle=phi, ductile=(law == "ductile"))
if when == "errors":
    for args, kw in [(([[(30.0, 30.0), (35.0, 31.0)]],), strength),  # above the slope: no joint on it
                     (([plane],), dict(strength, cohesion=-1.0)),
                     (([plane],), dict(strength, friction_angle=math.pi / 2)),
                     (([plane],), dict(cohesion=c, friction_angle=0.0)),  # no default tensile strength
                     (([[(xd, yd)]],), strength),  # a polyline of one point
                     (([],), strength),
                     ((plane,), strength),  # one polyline, not a list of them
                     (([plane],), dict(strength, ductile="no")),  # (was taken as True)
                     (([plane],), dict(strength, tol=-1.0))]:
        try:
            sl.set_joint_strength(*args, **kw)
            print("NO ERROR", kw)
        except ValueError as e:
            print("ERROR", e)
    class OneStrength:  # a calibration's interface: the joints' strength for the assembly's (c, tan phi)
        def joint_strength(self, cohesion, tan_phi):
            return cohesion, tan_phi
    sl.set_joint_strength([plane], **strength)
    try:  # a calibration would give the joint set the rock's calibrated strength: refused
        strength_reduction(calibration=OneStrength(), soil=(c, phi), verbose=False)
        print("NO SRERROR")
    except ValueError as e:
        print("SRERROR", e)
    for F in (-2.0, 0.0, float("nan")):  # (F = -2 wrote negative strengths to 33 joints, 0 divided by zero)
        try:
            sl.apply_joint_sets(F)
            print("NO APPLYERROR", F)
        except ValueError as e:
            print("APPLYERROR", e)
    import os
    import tempfile
    saved = os.path.join(tempfile.mkdtemp(), "scene.xml.bz2")
    O.save(saved)
    before = len(sl.joint_sets())
    O.load(saved)
    print("SETS %d %d" % (before, len(sl.joint_sets())))
    for b in O.bodies:  # refPos reset (here: moved 1 cm) since build_scene: the cut is not found there
        b.state.refPos = b.state.refPos + Vector3(0, 0.01, 0)
    try:
        sl.set_joint_strength([plane], **strength)
        print("NO ERROR refPos moved")
    except ValueError as e:
        print("ERROR", e)
    newton = [e for e in O.engines if type(e).__name__ == "NewtonIntegrator"][0]
    newton.gravity = (0, 0, 0)  # no weight: settle "converged" at once, strength reduction found "no mechanism"
    for f in (lambda: sl.settle(), lambda: strength_reduction(verbose=False)):
        try:
            f()
            print("NO GERROR")
        except ValueError as e:
            print("GERROR", e)
    sys.exit(0)
n_set = sl.set_joint_strength([plane], **strength, **springs) if when in ("before", "stiff") else 0
sl.settle(tol=1e-4, max_steps=60000, check=200, density_scaling=True)
if when == "network":
    # the joints of the cuts found again on the settled slope, and what lies on a cut seen from either block's
    # reference pose (10 um), joints longer than 0.1 mm
    from yade_rbsm.geometry import point_segment_distance
    found = {(I.id1, I.id2) for I in sl.joints_on(plane)}
    lost = sum(1 for k in bonded_on_plane if O.interactions.has(*k) and O.interactions[k].isReal and k not in found)
    segs = [(a, b) for l in plane for a, b in zip(l[:-1], l[1:])]

    def on_a_cut(I, s):
        back = s.refOri * s.ori.conjugate()
        p = [s.refPos + back * (Vector3(x[0], x[1], 0) - s.pos) for x in (I.geom.p0, I.geom.p1)]
        return any(point_segment_distance((p[0][0], p[0][1]), a, b) < 1e-5 and
                   point_segment_distance((p[1][0], p[1][1]), a, b) < 1e-5 for a, b in segs)
    seen = {(I.id1, I.id2) for I in O.interactions if I.isReal and I.geom.length > 1e-4
            and any(on_a_cut(I, O.bodies[i].state) for i in (I.id1, I.id2))}
    print("RESULT " + json.dumps(dict(on_cut=len(bonded_on_plane), found=len(found), missed=lost, seen=len(seen),
                                      unseen=len(seen - found))))
    sys.exit(0)
if when == "stiff":  # the wedge's mean displacement along and across the plane against the set's springs alone
    wedge = [(xd, yd), (xk, yk), (xk, y0 + H), (xcr, y0 + H)]

    def inside(p):
        return all((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0
                   for a, b in zip(wedge, wedge[1:] + wedge[:1]))
    def mean_displacement(blocks):
        m = sum(b.state.mass for b in blocks)
        return m, [sum(b.state.mass * (b.state.pos[k] - b.state.refPos[k]) for b in blocks) / m for k in (0, 1)]

    def below(p):  # within 3 m under the plane, between daylight and crack
        d = (p[0] - xd) * math.sin(psi) - (p[1] - yd) * math.cos(psi)  # distance below the plane
        return 0 < d < 3.0 and xd < p[0] < xk
    m, uw = mean_displacement([b for b in O.bodies if b.dynamic and inside(b.state.refPos)])
    _, uf = mean_displacement([b for b in O.bodies if b.dynamic and below(b.state.refPos)])
    u = [uw[k] - uf[k] for k in (0, 1)]  # the wedge relative to the rock under the plane
    t = (math.cos(psi), math.sin(psi))  # up the plane
    L = math.hypot(xk - xd, yk - yd)
    W = m * g
    set_joints = sl.joints_on([plane])
    print("RESULT " + json.dumps(dict(
        slip=-(u[0] * t[0] + u[1] * t[1]), settlement=-(-u[0] * t[1] + u[1] * t[0]),
        slip_closed=W * math.sin(psi) / (springs["shear_stiffness"] * L),
        settlement_closed=W * math.cos(psi) / (springs["normal_stiffness"] * L),
        n_set=n_set, kn=sorted({I.phys.kn for I in set_joints}), ks=sorted({I.phys.ks for I in set_joints}),
        slipping=sum(I.phys.nSlipping for I in set_joints),
        sets=sl.joint_sets())))
    sys.exit(0)
if when == "after":
    n_set = sl.set_joint_strength([plane], **strength)
missed = sum(1 for k in bonded_on_plane if O.interactions.has(*k) and O.interactions[k].isReal
             and O.interactions[k].phys.cohesion != c)
on_plane = sum(1 for I in O.interactions if I.isReal and I.phys.cohesion == c and I.phys.tanPhi == math.tan(phi))
rock_strength = sum(1 for I in O.interactions if I.isReal and I.phys.cohesion == rock.cohesion)
wedge = [(xd, yd), (xk, yk), (xk, y0 + H), (xcr, y0 + H)]
A = abs(0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1])))
W = rho * g * A
fs0 = (c * math.hypot(xk - xd, yk - yd) + W * math.cos(psi) * math.tan(phi)) / (W * math.sin(psi))
if not with_fs:
    print("RESULT " + json.dumps(dict(n_set=n_set, missed=missed, bonded_on_plane=len(bonded_on_plane), cracked=nb)))
    sys.exit(0)
r = strength_reduction(start=1.0, grow=1.2, rtol=0.005, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
                       verbose=False)
print("RESULT " + json.dumps(dict(fs=r.fs, lo=r.lo, hi=r.hi, closed=fs0, n_set=n_set, on_plane=on_plane,
                                  rock_strength=rock_strength, joints=nj, blocks=len(sb.free), missed=missed,
                                  warnings=r.warnings)))
