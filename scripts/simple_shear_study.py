# Simple-shear tests (yade_rbsm.calibration.simple_shear_test) of the 45 deg slope's biaxially calibrated joints
# (c_j 9219 Pa, tan phi_j 0.16078; both x --k), 24 x 6 blocks of 1 m unless --lb/--hb, at --sn kPa; prints the
# peak and 6-8 % H tau, the middle-half tau/sigma and the fits (issue 21, docs/slope_factor_of_safety.md);
# with --json FILE also written there, with the curves.
#
#   build/yade-rbsm -j1 -n -x scripts/simple_shear_study.py --sn 50,100,150 --k 1.41
import math, sys, json, time
from yade_rbsm.calibration import simple_shear_test, fit_coulomb
import argparse
ap = argparse.ArgumentParser()
ap.add_argument("--cj", type=float, default=9219.11714408167)
ap.add_argument("--tj", type=float, default=0.16077931852496014)
ap.add_argument("--k", type=float, default=1.0)
ap.add_argument("--sn", default="100")
ap.add_argument("--max-disp", type=float, default=0.08)
ap.add_argument("--dps", type=float, default=1e-6)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--endp", type=float, default=0.0)
ap.add_argument("--lb", type=int, default=24)
ap.add_argument("--hb", type=int, default=6)
ap.add_argument("--verbose", action="store_true")
ap.add_argument("--json", default="", help="write the runs (and their curves) to this file")
a = ap.parse_args(sys.argv[1:])
cj, tj = a.k * a.cj, a.k * a.tj
out = []
for sn in [float(x) * 1e3 for x in a.sn.split(",")]:
    r = simple_shear_test(sn, cj, tj, 100e6, 0.3, spacing=1.0, seed=a.seed, end_pressure=a.endp * sn, length_blocks=a.lb, height_blocks=a.hb, density=20e3 / 9.81, tensile_strength=10e3 / math.tan(math.radians(40)),
                          max_disp=a.max_disp, disp_per_step=a.dps, verbose=a.verbose)
    print("SS seed=%d endp=%.3f %dx%d k=%.4f cj=%.5g tj=%.5f sn=%.0f kPa: peak %.2f kPa at %.4f H, large %.2f kPa, rise %.4f H, %d blocks, %d steps, %.1f s"
          % (a.seed, a.endp, a.lb, a.hb, a.k, cj, tj, sn / 1e3, r.peak / 1e3, r.disp_at_peak, r.large / 1e3, r.dilation, r.blocks, r.steps, r.wall), flush=True)
    print("   MID: peak tau %.2f kPa at sigma %.2f kPa (ratio %.3f), large tau %.2f kPa at sigma %.2f kPa (ratio %.3f)" % (
        r.peak_mid / 1e3, r.sigma_mid_at_peak / 1e3, r.peak_mid / r.sigma_mid_at_peak, r.large_mid / 1e3, r.sigma_mid_large / 1e3, r.large_mid / r.sigma_mid_large), flush=True)
    out.append(dict(sn=sn, peak=r.peak, large=r.large, dpeak=r.disp_at_peak, rise=r.dilation, wall=r.wall, peak_mid=r.peak_mid, sig_mid_peak=r.sigma_mid_at_peak, large_mid=r.large_mid, sig_mid_large=r.sigma_mid_large,
                    curve=r.curve[::10]))
if len(out) > 1:
    for key in ("peak", "large"):
        c, phi = fit_coulomb([o["sn"] for o in out], [o[key] for o in out])
        print("FIT %s: c = %.2f kPa, phi = %.2f deg" % (key, c / 1e3, math.degrees(phi)))
    for key, sk in (("peak_mid", "sig_mid_peak"), ("large_mid", "sig_mid_large")):
        c, phi = fit_coulomb([o[sk] for o in out], [o[key] for o in out])
        print("FIT %s (vs its own sigma): c = %.2f kPa, phi = %.2f deg" % (key, c / 1e3, math.degrees(phi)))
if a.json:
    with open(a.json, "w") as f:
        json.dump(dict(k=a.k, seed=a.seed, endp=a.endp, lb=a.lb, hb=a.hb, cj=cj, tj=tj, runs=out), f)
