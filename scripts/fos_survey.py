# slope.fos() with its defaults on the slopes the project knows the answer of (issue 37): the four c'-phi'
# slopes of docs/slope_factor_of_safety.md cut into 1 m Voronoi blocks on a firm base at toe level (a continuum:
# the design value is Bishop's critical circle), Hoek & Bray's plane failure (jointed rock: strength reduction, closed form 1.4818) and the
# main example's brick slope (strength reduction). One case per process; prints a row and RESULT <json>:
#   build/yade-rbsm -n -x scripts/fos_survey.py gl|20|30|45|plane|landslide
# or all of them, one process each, and a table:   /usr/bin/python3 scripts/fos_survey.py --all
import json
import math
import os
import subprocess
import sys
import time

CASES = ["20", "gl", "30", "45", "plane", "landslide"]
HERE = os.path.dirname(os.path.abspath(sys.argv[0]))


def blocks_and_rock(case):
    """(SlopeBlocks, RbsmMat, reference FS and what it is) of a case."""
    from yade import wrapper
    from yade_rbsm import slope as sl
    if case == "plane":  # Hoek & Bray's plane failure with a tension crack, as tests/landslide/fos_cases.py
        psi, beta, rho, xt, H, cb = math.radians(30), math.radians(60), 2600.0, 10.0, 12.0, 20e3
        xcrest = xt + H / math.tan(beta)
        xd, yd, xc = xt + 3 / math.tan(beta), 3.0, 22.0
        yc = yd + (xc - xd) * math.tan(psi)
        wedge = [(xd, yd), (xc, yc), (xc, H), (xcrest, H)]
        W = rho * 9.81 * 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1]))
        L = (xc - xd) / math.cos(psi)
        closed = (cb * L + W * math.cos(psi) * math.tan(math.radians(30))) / (W * math.sin(psi))
        rock = wrapper.RbsmMat(young=2e8, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
                               tensileStrength=2e6, ductile=True)
        traces = [sl.Trace([(xd, yd), (xc, yc)], cohesion=cb, friction_angle=30, ductile=True, name="bedding"),
                  sl.Trace([(xc, yc), (xc, H)], friction_angle=20, ductile=True, name="tension crack")]
        return sl.jointset_blocks([(0, 0), (xt, 0), (xcrest, H), (35, H)], -4.0, traces=traces), rock, closed, "Hoek & Bray"
    if case == "landslide":  # scripts/landslide_slope.py's bricks, plane and crack (Table 1, SI density)
        psi, xcrack = math.radians(35), 17.0
        ycrack = 2 + (xcrack - 6) * math.tan(psi)
        rock = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=0,
                               tensileStrength=0, planeStrain=True)
        sb = sl.brick_blocks([(0, 2), (6, 2), (14, 12), (24, 12)], 0.0, 2.0, 1.0, joints=[[(6, 2), (xcrack, ycrack)]],
                             crack=(xcrack, ycrack), foundation=1.0, wall=1.0)
        return sb, rock, None, "none (the wedge's tan(phi)/tan(psi) 0.825 without the crack's thrust)"
    sys.path.insert(0, HERE)
    from reference_slopes import GAMMA, SLOPES, ground, search, soil
    from yade_rbsm import limit_equilibrium as le
    _, c, phi, _ = SLOPES[case]
    rock = wrapper.RbsmMat(young=100e6, poisson=0.3, density=GAMMA * 1e3 / 9.81, frictionAngle=math.radians(phi),
                           cohesion=c * 1e3, tensileStrength=0, ductile=True)
    bishop = le.critical_circle(soil(case), **search(case)).fs
    return sl.voronoi_slope_blocks(ground(case), 0.0, spacing=1.0, seed=1), rock, bishop, "Bishop, critical circle"


def run(case):
    from yade import O
    from yade_rbsm import slope as sl
    import yade_rbsm as yr
    yr.quiet_yade_warnings()
    sb, rock, reference, what = blocks_and_rock(case)
    O.materials.append(rock)
    w0 = time.time()
    m = sl.SlopeModel(sb, rock)
    m.build(enlarge=0.01)
    if case == "landslide":  # it fails at its own friction: held while gravity comes on, as the example does
        m.settle(density_scaling=False, hold_friction=5.0)
    else:
        m.settle()
        m.give_joint_sets()
    t0 = time.time()
    r = m.fos()
    row = dict(case=case, blocks=len(sb.free), fs=r.fs, method=r.method, conclusive=r.conclusive, warnings=r.warnings,
               reference=reference, reference_is=what, fos_wall=time.time() - t0, wall=time.time() - w0)
    print(repr(r))
    print("RESULT " + json.dumps(row))


def main():
    rows = []
    launcher = os.path.join(HERE, "..", "build", "yade-rbsm")
    for case in CASES:
        p = subprocess.run([launcher, "-n", "-x", os.path.abspath(sys.argv[0]), case], capture_output=True, text=True)
        out = [l for l in p.stdout.splitlines() if l.startswith("RESULT ")]
        rows.append(json.loads(out[0][7:]) if out else dict(case=case, error=(p.stdout + p.stderr)[-500:]))
    print("| case | blocks | FS | method | reference | conclusive | fos() wall [s] |\n|---|---|---|---|---|---|---|")
    for r in rows:
        if "error" in r:
            print("| %s | failed: %s |" % (r["case"], r["error"].replace("\n", " ")))
            continue
        ref = "-" if r["reference"] is None else "%.3f (%s)" % (r["reference"], r["reference_is"])
        print("| %s | %d | %.3f | %s | %s | %s | %.0f |" % (r["case"], r["blocks"], r["fs"], r["method"], ref,
                                                        "yes" if r["conclusive"] else "; ".join(r["warnings"]), r["fos_wall"]))


if __name__ == "__main__" and "--all" in sys.argv:
    main()
elif __name__ == "__main__" and len(sys.argv) > 1 and sys.argv[1] in CASES:  # (yade -x runs it as __main__)
    run(sys.argv[1])
