# yade script (run by test_strength_reduction.py): a 2 m x 1 m block on a fixed block along a plane
# joint inclined at psi (argv[1], deg), phi = 30 deg, c = 0; damped gravity stage, then the factor of
# safety by strength reduction; prints it with the closed form tan(phi)/tan(psi). argv[2] "stop": a trial
# stopped by a report of the plugin (prints SRSTOP and the message).
import math, os, sys
from yade import O, wrapper, Vector3
import yade_rbsm as yr
sys.path.insert(0, os.getcwd())  # the tests run these scripts in their own directory
from plane_blocks import bonded_gravity_stage, plane_frame  # noqa: E402
from yade_rbsm.strength_reduction import strength_reduction
psi, phi = math.radians(float(sys.argv[1])), math.radians(30)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=0, tensileStrength=0)
O.materials.append(mat)
rot = plane_frame(psi)
O.bodies.append([yr.polygon2d([rot(-1, -1), rot(3, -1), rot(3, 0), rot(-1, 0)], mat, fixed=True),
                 yr.polygon2d([rot(0, 0), rot(2, 0), rot(2, 1), rot(0, 1)], mat)])
ok, n, r = bonded_gravity_stage()
pos0 = Vector3(O.bodies[1].state.pos)
if sys.argv[2:3] == ["args"]:  # argv[3]: where the drawings go  # issue 37: what strength_reduction and settle leave and write, and their flags
    import glob, json
    from yade_rbsm import slope as sl
    res = strength_reduction(start=1.0, grow=1.5, rtol=0.02, tol=1e-4, d_fail=2e-3, max_steps=1500, check=100,
                             damping=0.7, density_scaling=True, png=os.path.join(sys.argv[3], "srm.png"))
    out = dict(scaling=yr.time_stepper().densityScaling, pngs=sorted(os.path.basename(f) for f in glob.glob(
        os.path.join(sys.argv[3], "srm*.png"))), errors={})
    for name, call in (("settle", lambda: sl.settle(density_scaling="no", max_steps=10)),
                       ("srm", lambda: strength_reduction(density_scaling="yes"))):
        try:
            call()
        except ValueError as e:
            out["errors"][name] = str(e)
    out["scaling_after"] = yr.time_stepper().densityScaling
    print("RESULT " + json.dumps(out))
    sys.exit(0)
if sys.argv[2:] == ["stop"]:  # a report of the plugin in a trial (here: any motion beyond 1e-4 of the inradius)
    yr.time_stepper().maxStepMotion = 1e-4
    try:
        strength_reduction(start=1.0, grow=1.5, rtol=0.005, tol=1e-4, d_fail=2e-3, max_steps=1500, check=100,
                           damping=0.7, verbose=False)
    except RuntimeError as e:
        print("SRSTOP %s" % e)
    sys.exit(0)
res = strength_reduction(start=1.0, grow=1.5, rtol=0.005, tol=1e-4, d_fail=2e-3, max_steps=1500, check=100,
                         damping=0.7, verbose=True)
print(res)
print("RESULT %r %.9g %.9g %.9g %.9g %d %.3e %.9g %s %d" % (ok, res.fs, res.lo, res.hi, math.tan(phi) / math.tan(psi),
      len(res.trials), (O.bodies[1].state.pos - pos0).norm(), O.interactions[0, 1].phys.tanPhi,
      res.mechanism.replace(" ", "_"), len(res.warnings)))
