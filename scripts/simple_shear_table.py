# Table of simple-shear strengths of a 24 x 6 Voronoi sample (seed 1, 1 m cells) for a grid of ductile joints
# (phi_j 2-22 deg x c_j 0-20 kPa; sigma_n 50 / 100 / 150 kPa; tensile strength 11.9 kPa, E 100 MPa): the peak
# and the 6-8 % H (large) tau fitted by tau = c + sigma_n tan phi. Written to simple_shear_table.json, read by
# scripts/slope_fs_study.py --mode table. About 11 minutes (90 tests).
#
#   build/yade-rbsm -j1 -n -x scripts/simple_shear_table.py
import math, json, sys, time
from yade_rbsm.calibration import simple_shear_test, fit_coulomb
rows = []
t0 = time.time()
for pj in (2.0, 6.0, 10.0, 14.0, 18.0, 22.0):
    tj = math.tan(math.radians(pj))
    for cj in (0.0, 5e3, 10e3, 15e3, 20e3):
        pk, lg = [], []
        for sn in (50e3, 100e3, 150e3):
            r = simple_shear_test(sn, cj, tj, 100e6, 0.3, spacing=1.0, seed=1, density=20e3 / 9.81,
                                  tensile_strength=10e3 / math.tan(math.radians(40)), max_disp=0.08)
            pk.append(r.peak); lg.append(r.large)
        cp, fp = fit_coulomb([50e3, 100e3, 150e3], pk)
        cl, fl = fit_coulomb([50e3, 100e3, 150e3], lg)
        rows.append(dict(tan_phi_j=tj, c_j=cj, peak=pk, large=lg, c_peak=cp, phi_peak=math.degrees(fp), c_large=cl, phi_large=math.degrees(fl)))
        print("ROW phi_j %4.1f c_j %6.0f | peak %s c %.2f kPa phi %.2f | large %s c %.2f kPa phi %.2f | %.0f s" % (
            pj, cj, " ".join("%.1f" % (x / 1e3) for x in pk), cp / 1e3, math.degrees(fp),
            " ".join("%.1f" % (x / 1e3) for x in lg), cl / 1e3, math.degrees(fl), time.time() - t0), flush=True)
        json.dump(rows, open("simple_shear_table.json", "w"))
