"""Issue 15's cases, one per run (params {"case": name}; some used to abort YADE): a base, a block on it
and a block beside it, one step run (joints exist), then the case; emits what happened."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite  # noqa: E402
from yade_rbsm import polygon2d, engines, advance  # noqa: E402

case = params()["case"]
nan = float("nan")
m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.6, label="rock")
O.materials.append(m)
O.bodies.append(polygon2d([(-4, -1), (4, -1), (4, 0), (-4, 0)], m, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], m))
O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], m))
O.engines = engines(contact_damping=0.1)
O.step()
out = {"case": case}


def attempt(f):
    try:
        f()
        return None
    except Exception as e:  # noqa: BLE001 - the test reads type and message
        return [type(e).__name__, str(e)]


def run(n, watch=None):
    """n steps in the calling thread (yade_rbsm.advance: O.run(n, True) can lose an exception of its first step);
    the exception, if any, in out["exc"]; with a State `watch`, whether its pose and velocity are unchanged."""
    it = O.iter
    before = (tuple(watch.pos), tuple(watch.vel), watch.angVel[2]) if watch is not None else None
    out["exc"] = attempt(lambda: advance(n))
    out["steps"] = O.iter - it
    out["finite"] = all_finite(O)
    if watch is not None:
        out["unchanged"] = before == (tuple(watch.pos), tuple(watch.vel), watch.angVel[2])


def energy():
    e = 0.0
    for b in O.bodies:
        if b.state.blockedDOFs != "xyzXYZ":
            s = b.state
            e += 0.5 * s.mass * (s.vel[0] ** 2 + s.vel[1] ** 2) + 0.5 * s.inertia[2] * s.angVel[2] ** 2 + s.mass * 9.81 * s.pos[1]
    return e


if case == "updateattrs_material":
    # every checked attribute set through updateAttrs: refused, and the old value kept
    bad = {"young": -2e8, "poisson": 0.7, "frictionAngle": 2.0, "cohesion": -1.0, "tensileStrength": nan, "density": 0}
    out["refused"], out["kept"] = {}, {}
    for k, v in bad.items():
        old = getattr(m, k)
        out["refused"][k] = attempt(lambda: m.updateAttrs({k: v}))
        out["kept"][k] = getattr(m, k) == old
    # all or nothing: a valid value with a bad one is not applied either
    out["mixed"] = attempt(lambda: m.updateAttrs({"young": 3e8, "poisson": 0.9}))
    out["mixed_kept"] = m.young == 1e8 and m.poisson == 0.2
    run(200)
elif case == "updateattrs_clockwise":
    s = O.bodies[1].shape
    old = [tuple(v) for v in s.vertices]
    out["refused"] = attempt(lambda: s.updateAttrs({"vertices": [(-0.5, -0.5), (-0.5, 0.5), (0.5, 0.5), (0.5, -0.5)]}))
    out["kept"] = [tuple(v) for v in s.vertices] == old
    y0 = O.bodies[1].state.pos[1]
    run(300)
    out["sank"] = y0 - O.bodies[1].state.pos[1]
elif case == "updateattrs_engine":
    ts = O.engines[3]
    out["refused"] = attempt(lambda: ts.updateAttrs({"safetyFactor": 2.0}))
    out["kept"] = ts.safetyFactor == 0.8
elif case == "density_assign":
    out["refused"] = {}
    for v in (0, -1, nan):
        out["refused"][repr(v)] = attempt(lambda: setattr(m, "density", v))
    out["kept"] = m.density == 2000
    out["later_valid"] = attempt(lambda: setattr(m, "young", 2e8))
    out["young"] = m.young
elif case == "load_bad_file":
    path = os.path.join(params()["tmp"], "bad.xml")
    O.save(path)
    text = open(path).read().replace("<young>1.00000000000000000e+08</young>", "<young>-1.00000000000000000e+00</young>")
    open(path, "w").write(text)
    out["refused"] = attempt(lambda: O.load(path))
elif case.startswith("state_"):
    # state_mass_0, state_inertia_nan ...: set on the running block #2, then run
    _, what, value = case.split("_")
    v = {"0": 0.0, "nan": nan, "neg": -1.0}[value]
    s = O.bodies[2].state
    if what == "mass":
        s.mass = v
    else:
        s.inertia = (v, v, v)
    out["iter_before"] = O.iter
    run(100, watch=s)
elif case == "rotated_out_of_plane":
    s = O.bodies[2].state
    s.ori = Quaternion((1, 0, 0), 0.3)
    out["iter_before"] = O.iter
    run(100, watch=s)
elif case == "reshape_in_contact":
    # an octagon resting on the base, reshaped into a triangle mid-run while in contact
    O.resetThisScene()
    O.materials.append(m)
    r = 0.5
    octo = [(5 + r * math.cos(math.pi / 8 + k * math.pi / 4), r * math.cos(math.pi / 8) + r * math.sin(math.pi / 8 + k * math.pi / 4))
            for k in range(8)]
    O.bodies.append(polygon2d([(3, -1), (8, -1), (8, 0), (3, 0)], m, fixed=True))
    ib = O.bodies.append(polygon2d(octo, m))
    O.engines = engines(contact_damping=0.1)
    O.run(int(params().get("settle", 1000)), True)  # at rest (the impacts of its placement resolved at impactSafety)
    b = O.bodies[ib]
    # centroid at the origin, base edge where the octagon's was: the joint stays closed, on other edges
    h = 3 * 0.5 * math.cos(math.pi / 8)
    tri = [(-0.5, -h / 3), (0.5, -h / 3), (0.0, 2 * h / 3)]
    y_before = b.state.pos[1]
    b.shape.vertices = tri
    O.step()  # the step that meets the new shape
    e0 = energy()
    run(int(params().get("steps", 1000)))
    out["gain"] = energy() - e0
    out["rise"] = b.state.pos[1] - y_before  # the lighter triangle's spring relaxes: it rests higher
    out["mass"] = b.state.mass
    out["mass_expected"] = m.density * b.shape.area * b.shape.thickness
    out["inertia"] = b.state.inertia[2]
    out["inertia_expected"] = m.density * b.shape.polarMoment * b.shape.thickness
    out["revision"] = getattr(b.shape, "revision", None)  # (the old code had none)
    out["contacts"] = [[i.id1, i.id2, i.geom.refBody, i.geom.refEdge] for i in O.interactions if i.isReal]
    out["rest_height"] = b.state.pos[1]
elif case == "periodic_thick":
    O.resetThisScene()
    O.materials.append(m)
    O.periodic = True
    O.cell.hSize = Matrix3(10, 0, 0, 0, 20, 0, 0, 0, 1)  # z = the block thickness: the natural 2D set-up
    O.bodies.append(polygon2d([(0.1, 1), (3, 1), (3, 2), (0.1, 2)], m, fixed=True))
    O.bodies.append(polygon2d([(1, 2), (2, 2), (2, 3), (1, 3)], m))
    out["engines"] = attempt(lambda: setattr(O, "engines", engines()))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()], verletDist=0.01),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]), RbsmTimeStepper(setDt=True), NewtonIntegrator()]
    O.dt = 1e-5
    run(200)
elif case == "periodic_wide_floor":
    O.resetThisScene()
    O.materials.append(m)
    O.periodic = True
    O.cell.hSize = Matrix3(10, 0, 0, 0, 20, 0, 0, 0, 10)
    O.bodies.append(polygon2d([(0.01, 1), (9.985, 1), (9.985, 2), (0.01, 2)], m, fixed=True))  # 99.75 % of the width
    O.bodies.append(polygon2d([(1, 2), (2, 2), (2, 3), (1, 3)], m))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()], verletDist=0.01),
                 InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                                 [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]), RbsmTimeStepper(setDt=True),
                 NewtonIntegrator(gravity=(0, -9.81, 0))]
    O.dt = 1e-5
    run(2000)
    out["y"] = O.bodies[1].state.pos[1]
elif case == "messages":
    out["sliver"] = attempt(lambda: polygon2d([(0, 5), (1, 5), (1, 5 + 5e-10), (0, 5 + 5e-10)], m))
    out["off_centre"] = attempt(lambda: setattr(O.bodies[1].shape, "vertices", [(-0.5 + 1e-8, -0.5), (0.5 + 1e-8, -0.5), (0.5 + 1e-8, 0.5), (-0.5 + 1e-8, 0.5)]))
    out["bowtie"] = attempt(lambda: polygon2d([(0, 5), (1, 6), (1, 5), (0, 6)], m))
    out["save"] = attempt(lambda: O.save("/nonexistent-dir/scene.xml"))
elif case == "python_args":
    # numeric arguments of the public functions: check=0 looped forever, d_fail=nan switched failure off
    from yade_rbsm.strength_reduction import strength_reduction
    from yade_rbsm.slope import settle
    from yade_rbsm.safety import probe_slipping_surface, le_slope
    calls = {
        "strength_reduction check=0": lambda: strength_reduction(check=0, verbose=False),
        "strength_reduction d_fail=nan": lambda: strength_reduction(d_fail=nan, verbose=False),
        "strength_reduction max_steps=-5": lambda: strength_reduction(max_steps=-5, verbose=False),
        "strength_reduction grow=inf": lambda: strength_reduction(grow=float("inf"), verbose=False),
        "settle check=0": lambda: settle(check=0),
        "settle tol=nan": lambda: settle(tol=nan),
        "probe_slipping_surface check=0": lambda: probe_slipping_surface(steps=10, check=0),
        "le_slope density=0": lambda: le_slope([(0, 0), (1, 1)], m, density=0),
        "engines safety=nan": lambda: engines(safety=nan),
        "engines nIP=2.5": lambda: engines(nIP=2.5),
        "engines gravity nan": lambda: engines(gravity=(0, nan, 0)),
    }
    it = O.iter
    out["calls"] = {k: attempt(f) for k, f in calls.items()}
    out["steps"] = O.iter - it
elif case == "phys_stiffened":
    # a running scene's joints made 1e4 times stiffer (a user's joint set, or a script): the step
    # must follow at once, as after RbsmTimeStepper.checkNextStep(), not at the next full estimate
    O.engines = engines(gravity=(0, -9.81, 0), damping=0.0)
    for k in range(3):  # a column on the block at x 0..1
        O.bodies.append(polygon2d([(0, 1 + k), (1, 1 + k), (1, 2 + k), (0, 2 + k)], m))
    run(350)  # (between two full estimates: the stepper's interval is 100)
    out["dt_before"] = O.dt
    for I in O.interactions:
        if I.isReal:
            I.phys.kn *= 1e4
            I.phys.ks *= 1e4
    if params().get("manual"):
        [e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0].checkNextStep()
    O.step()
    out["dt_after"] = O.dt
    run(300)
    out["pos"] = [list(b.state.pos) for b in O.bodies]
elif case == "phys_bad_values":
    # every checked joint value, through assignment and updateAttrs: refused naming it, old value kept
    I = [I for I in O.interactions if I.isReal][0]
    names = ["kn", "ks", "cohesion", "tanPhi", "tensileStrength"]
    old = {k: getattr(I.phys, k) for k in names}
    out["assign"], out["update"], out["kept"] = {}, {}, {}
    for k in names:
        for v in (nan, -1.0, float("inf")):
            out["assign"][k + repr(v)] = attempt(lambda: setattr(I.phys, k, v))
            out["update"][k + repr(v)] = attempt(lambda: I.phys.updateAttrs({k: v}))
        out["kept"][k] = getattr(I.phys, k) == old[k]
    out["ctor"] = attempt(lambda: RbsmPhys(kn=-5.0))
    out["valid"] = attempt(lambda: setattr(I.phys, "cohesion", 1e3))
    run(200)
elif case == "phys_load_bad_file":
    path = os.path.join(params()["tmp"], "bad.xml")
    O.save(path)
    text = open(path).read()
    i = text.index("<kn>")  # the first joint's normal stiffness, made negative
    text = text[:i] + "<kn>-1" + text[text.index("<", i + 4):]
    open(path, "w").write(text)
    out["refused"] = attempt(lambda: O.load(path))
else:
    raise SystemExit("unknown case " + case)
emit(out)
