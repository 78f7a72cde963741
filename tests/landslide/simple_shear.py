# Checks of yade_rbsm.calibration.simple_shear_test (test_simple_shear.py). Prints RESULT <json>.
import json
import math

from yade_rbsm.calibration import fit_coulomb, simple_shear_test

errors = {}
for name, kw in (("sigma_n", dict(sigma_n=0.0)), ("joint_tan_phi", dict(joint_tan_phi=0.0)),
                 ("length_blocks", dict(length_blocks=0)), ("max_disp", dict(max_disp=2.0))):
    args = dict(sigma_n=100e3, joint_cohesion=1e3, joint_tan_phi=0.2, young=100e6, poisson=0.3)
    args.update(kw)
    try:
        simple_shear_test(**args)
        errors[name] = None
    except ValueError as e:
        errors[name] = str(e)
small = dict(young=100e6, poisson=0.3, length_blocks=12, height_blocks=3, max_disp=0.03, density=2000.0)
# (nearly) frictionless, cohesionless joints and a tiny normal stress: nothing carries shear
r0 = simple_shear_test(100.0, 0.0, 1e-3, **small)
# the soil's range: the band interlocks, the sample is stronger than its joints (the platens are glued:
# with the joints' strength on them it slid on a platen at tau ~ c_j + sigma_n tan phi_j)
r1 = simple_shear_test(100e3, 9.2e3, 0.16, **small)
c, phi = fit_coulomb([50e3, 100e3, 150e3], [10e3 + s * 0.5 for s in (50e3, 100e3, 150e3)])
print("RESULT " + json.dumps(dict(errors=errors, tau0=r0.peak, tau1=r1.peak, large1=r1.large, joint1=9.2e3 + 100e3 * 0.16,
                                  fit=(c, math.tan(phi)), curve_len=len(r1.curve))))
