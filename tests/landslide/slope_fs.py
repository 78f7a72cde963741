# yade script (run by test_slope_fs.py, issue 21): the Griffiths & Lane (1999) 2:1 slope (H = 10 m, c' = 10
# kPa, phi' = 20 deg, firm base at toe level) cut into 1 m Voronoi blocks; argv[1] says what to check:
#   settle   joints broken by the gravity stage, brittle and ductile joints
#   sr       strength reduction: refused on the unsettled reference; a loose block sliding off the face is a
#            local failure (mass_fraction) and leaves the FS as it is without it (mass_fraction=0: it is the
#            slope's failure); the mechanism PNGs
#   ductile  RbsmMat.ductile reaches the joints and survives O.save / O.load
#   calibration  a small calibration grid from inside a slope scene (which it leaves as it was)
#   stress   Kulhawy's stress-based FS from the settled blocks' stresses (safety.stress_field), ductile joints
#   stress_kh  the same with the blocks settled under a pseudo-static kh = 0.1 out of the face (slope.set_seismic),
#            against Bishop and Spencer with kh
#   model_stress  SlopeModel.stress_fs (issue 37: FS along any polyline, through blocks) on Bishop's critical
#            circle and on a polyline along it, beside contact_fs on that polyline (joints cover little of it)
#   messages  what a user trying these tools ran into: bad calibrate arguments, strength reduction on an
#            empty scene and on bricks (no mechanism)
# Prints RESULT <json>.
import json, math, os, sys, tempfile
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import slope as sl
from yade_rbsm.strength_reduction import strength_reduction

what = sys.argv[1]
c, phi = 10e3, math.radians(20)


def scene(ductile=False, loose=False):
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=100e6, poisson=0.3, density=20e3 / 9.81, frictionAngle=phi, cohesion=c,
                          tensileStrength=c / math.tan(phi), ductile=ductile)
    O.materials.append(mat)
    sb = sl.voronoi_slope_blocks([(0, 0), (12, 0), (32, 10), (52, 10)], 0.0, spacing=1.0, seed=1, min_distance=0.5)
    sl.build_scene(sb, mat)
    loose_id = None
    if loose:  # a 0.3 m block of a weak material just above the face (26.6 deg > its 10 deg friction)
        weak = wrapper.RbsmMat(young=100e6, poisson=0.3, density=20e3 / 9.81, frictionAngle=math.radians(10))
        O.materials.append(weak)
        a = math.atan2(10, 20)
        ca, sa = math.cos(a), math.sin(a)
        x0, y0 = 24.0, 6.0 + 1e-3  # on the face (y = (x - 12) / 2)
        loc = [(0, 0), (0.3, 0), (0.3, 0.3), (0, 0.3)]
        loose_id = O.bodies.append(yr.polygon2d([(x0 + ca * u - sa * v, y0 + sa * u + ca * v) for u, v in loc], weak))
    O.engines = yr.engines(set_dt=True, enlarge=0.01)
    O.dt = 1e-6
    sl.bond_and_break(sb)
    return sb, loose_id


def broken():
    return sum(1 for I in O.interactions if I.isReal and I.phys.nIntact < len(I.phys.intactPoints))


out = {}
if what == "settle":
    for ductile in (False, True):
        sb, _ = scene(ductile=ductile)
        ok, steps, ratio = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
        n = sum(1 for I in O.interactions if I.isReal)
        out["ductile" if ductile else "brittle"] = dict(ok=ok, steps=steps, joints=n, broken=broken(),
                                                        open=sum(1 for I in O.interactions if I.isReal and I.phys.nOpen))
elif what == "sr":
    sb, _ = scene()
    try:
        strength_reduction(start=1.4)
        out["unsettled"] = "accepted"
    except ValueError as e:
        out["unsettled"] = str(e)
    kw = dict(start=1.4, grow=1.2, rtol=0.02, density_scaling=True, max_steps=8000, check=200, d_fail=0.1,
              verbose=False)
    sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
    out["fs"] = strength_reduction(**kw).fs
    sb, loose = scene(loose=True)
    sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
    png = os.path.join(tempfile.mkdtemp(), "mech")
    r = strength_reduction(png=png, **kw)
    out["fs_loose"] = r.fs
    out["local"] = sorted(set(i for t in r.trials for i in t.local))
    out["loose"] = loose
    out["pngs"] = sorted(os.listdir(os.path.dirname(png)))
    out["png_sizes"] = [os.path.getsize(os.path.join(os.path.dirname(png), f)) for f in out["pngs"]]
    r0 = strength_reduction(mass_fraction=0.0, **kw)
    out["fs_any_block"] = r0.fs
elif what == "stress":
    from yade_rbsm import limit_equilibrium as le
    from yade_rbsm.safety import stress_field
    sb, _ = scene(ductile=True)
    ok, steps, ratio = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
    field = stress_field()
    GL = [(0, 0), (12, 0), (32, 10), (52, 10)]
    soil = le.Slope(GL, le.Layer(c=10.0, phi=20.0, gamma=20.0))
    search = dict(x_range=(5, 40), y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0, r_range=(5, 60), nr=19)
    bishop = le.critical_circle(soil, **search)
    kul = le.critical_circle(soil, method="stress", stress=field, min_depth=2.0, **search)
    undrained = le.Slope(GL, le.Layer(c=10.0, phi=0.0, gamma=20.0))
    sxx, syy, sxy = field([40.0], [2.0])  # under the crest, 8 m deep
    try:
        stress_field(ids=[0, 10 ** 6])
        bad_ids = "accepted"
    except ValueError as e:
        bad_ids = str(e)
    # without base= (or a limit-equilibrium ground wider than the blocks) the circles may run under the blocks
    nobase = {k: v for k, v in search.items() if k != "base"}
    bishop_nb = le.critical_circle(soil, **nobase)
    kul_nb = le.critical_circle(soil, method="stress", stress=field, min_depth=2.0, **nobase)
    O.resetThisScene()
    try:
        stress_field()
        empty = "accepted"
    except ValueError as e:
        empty = str(e)
    out = dict(ok=ok, bishop=bishop.fs, stress=kul.fs, bishop_nobase=bishop_nb.fs, stress_nobase=kul_nb.fs,
               lowest_nobase=kul_nb.circle.yc - kul_nb.circle.R, empty=empty, depth=float(max(soil.ground(kul.best.slices.x) - kul.best.slices.y_base)),
               undrained_stress=le.stress_circle(undrained, bishop.circle, field).fs,
               undrained_bishop=le.bishop_circle(undrained, bishop.circle).fs,
               syy=float(syy[0]), sxx=float(sxx[0]), bad_ids=bad_ids)
elif what == "model_stress":
    from yade_rbsm import limit_equilibrium as le
    mat = wrapper.RbsmMat(young=100e6, poisson=0.3, density=20e3 / 9.81, frictionAngle=phi, cohesion=c,
                          tensileStrength=c / math.tan(phi), ductile=True)
    O.materials.append(mat)
    sb = sl.voronoi_slope_blocks([(0, 0), (12, 0), (32, 10), (52, 10)], 0.0, spacing=1.0, seed=1, min_distance=0.5)
    m = sl.SlopeModel(sb, mat)
    m.build()
    st = m.settle(tol=1e-4, density_scaling=True)
    soil = le.Slope(sb.surface, le.Layer(c=10.0, phi=20.0, gamma=20.0))
    bishop = le.critical_circle(soil, x_range=(5, 40), y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0,
                                r_range=(5, 60), nr=19)
    C = bishop.circle
    by_circle = m.stress_fs(circle=(C.xc, C.yc, C.R), name="Bishop's circle")
    # the field is linear between block centroids 1 m apart: at 50 slices the two surfaces sample it at other points
    fine = [m.stress_fs(circle=(C.xc, C.yc, C.R), n=800).fs]
    # the same circle as a 41-point polyline from above the ground at its lowest x to above it at its highest
    angles = [math.pi + (k / 40.0) * (math.pi / 2.0) for k in range(41)]  # 180 to 270 deg: the lower left quarter
    poly = [(C.xc + C.R * math.cos(t), C.yc + C.R * math.sin(t)) for t in angles]
    angles2 = [1.5 * math.pi + (k / 40.0) * (math.pi / 2.0) for k in range(1, 41)]  # 270 to 360 deg
    poly += [(C.xc + C.R * math.cos(t), C.yc + C.R * math.sin(t)) for t in angles2]
    by_polyline = m.stress_fs(polyline=poly, name="polyline on Bishop's circle")
    fine.append(m.stress_fs(polyline=poly, n=800).fs)
    errors = {}
    m.contact_fs(poly, name="polyline on Bishop's circle")  # a surface through blocks: (almost) no joint on it
    for k, kw in dict(neither={}, both=dict(circle=(C.xc, C.yc, C.R), polyline=poly), two=dict(circle=(20, 25)),
                      name=dict(circle=(C.xc, C.yc, C.R), name=5)).items():
        try:
            m.stress_fs(**kw)
            errors[k] = "accepted"
        except ValueError as e:
            errors[k] = str(e)
    out = dict(ok=st.figures["converged"], bishop=bishop.fs, circle=by_circle.fs, polyline=by_polyline.fs,
               fine=fine, table=m.fs_table(), errors=errors,
               stages=[s.name for s in m.stages])
elif what == "stress_kh":  # issue 40: the same under a pseudo-static kh = 0.1 out of the face (towards -x)
    from yade_rbsm import limit_equilibrium as le
    from yade_rbsm.safety import stress_field
    sb, _ = scene(ductile=True)
    sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
    sl.set_seismic(0.1, towards=-1)
    ok, steps, ratio = sl.settle(tol=1e-4, max_steps=50000, check=200, density_scaling=True)
    field = stress_field()
    GL = [(0, 0), (12, 0), (32, 10), (52, 10)]
    search = dict(x_range=(5, 40), y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0, r_range=(5, 60), nr=19)
    soil = le.Slope(GL, le.Layer(c=10.0, phi=20.0, gamma=20.0), kh=0.1)
    bishop = le.critical_circle(soil, **search)
    kul = le.critical_circle(soil, method="stress", stress=field, min_depth=2.0, **search)
    undrained = le.Slope(GL, le.Layer(c=10.0, phi=0.0, gamma=20.0), kh=0.1)
    static = le.critical_circle(le.Slope(GL, le.Layer(c=10.0, phi=20.0, gamma=20.0)), **search)
    out = dict(ok=ok, bishop=bishop.fs, stress=kul.fs, bishop_static=static.fs, spencer=le.spencer_circle(soil, bishop.circle).fs,
               undrained_stress=le.stress_circle(undrained, bishop.circle, field).fs,
               undrained_bishop=le.bishop_circle(undrained, bishop.circle).fs,
               undrained_static=le.bishop_circle(le.Slope(GL, le.Layer(c=10.0, phi=0.0, gamma=20.0)), bishop.circle).fs,
               gravity=list(yr.omega.newton(O).gravity))
elif what == "ductile":
    sb, _ = scene(ductile=True)
    yr.advance(1)
    out["joints_ductile"] = all(I.phys.ductile for I in O.interactions if I.isReal)
    f = os.path.join(tempfile.mkdtemp(), "s.yade.gz")
    O.save(f)
    O.load(f)
    out["loaded_mat"] = O.materials[0].ductile
    out["loaded_joints"] = all(I.phys.ductile for I in O.interactions if I.isReal)
    m = wrapper.RbsmMat()
    out["default"] = m.ductile
elif what == "calibration":
    from yade_rbsm.calibration import calibrate
    sb, _ = scene()
    n0, pos0 = len(O.bodies), O.bodies[5].state.pos[0]
    cal = calibrate(c, phi, 100e6, 0.3, 200e3, confinements=(0.05, 0.15), joint_friction_angles=(0.5, 10.0, 20.0),
                    cohesion_factors=(0.0,), density=20e3 / 9.81, cache=False, verbose=False)
    out["rows"] = sorted((math.degrees(math.atan(r["tan_phi_j"])), r["phi_macro"], r["c_macro"]) for r in cal.rows)
    out["scene_kept"] = len(O.bodies) == n0 and O.bodies[5].state.pos[0] == pos0
    try:
        cal.joint_strength(c, math.tan(phi))
        out["phi20"] = "found"
    except ValueError as e:
        out["phi20"] = str(e)
elif what == "messages":
    from yade_rbsm.calibration import calibrate

    def err(f):
        try:
            f()
            return "accepted"
        except (ValueError, RuntimeError) as e:
            return str(e)
    args = (c, phi, 100e6, 0.3, 200e3)
    out["strain0"] = err(lambda: calibrate(*args, strain_per_step=0, cache=False, verbose=False))
    out["one_confinement"] = err(lambda: calibrate(*args, confinements=(0.1,), cache=False, verbose=False))
    out["no_seeds"] = err(lambda: calibrate(*args, seeds=(), cache=False, verbose=False))
    O.resetThisScene()
    out["empty"] = err(lambda: strength_reduction())
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=100e6, poisson=0.3, density=2000, frictionAngle=phi, cohesion=c,
                          tensileStrength=c / math.tan(phi))
    O.materials.append(mat)
    sb = sl.brick_blocks([(0, 0), (4, 0), (7, 5), (10, 5)], 0.0, 1.0, 0.5)
    sl.build_scene(sb, mat)
    O.engines = yr.engines(set_dt=True, enlarge=0.01)
    O.dt = 1e-6
    sl.bond_and_break(sb)
    sl.settle(tol=1e-4, max_steps=20000, check=200)
    out["bricks"] = err(lambda: strength_reduction(start=1.0, grow=3.0, max_trials=3, max_steps=2000, check=200,
                                                   verbose=False))
print("RESULT " + json.dumps(out))
