"""yade_rbsm.calibration.simple_shear_test (simple_shear.py): a long Voronoi sample sheared between glued
rigid platens under a constant normal stress, the strength a shear band of the tessellation carries.

* Bad input is refused with a ValueError that names the argument.
* Frictionless, cohesionless joints under a tiny normal stress (100 Pa) carry almost no shear (measured
  0.5 kPa on 12 x 3 blocks: the joints' viscous damping at the driving velocity, 0.4 % of the 100 kPa test's).
* With the biaxially calibrated joints of the 45 deg slope (c_j 9.2 kPa, tan phi_j 0.16) the band carries
  more than its joints (interlocking; measured 24 x 6 blocks, sigma_n 100 kPa: peak 80.7 kPa against
  c_j + sigma_n tan phi_j = 25.2 kPa), which it did not when the platens had the joints' strength (it slid
  on a platen at 20 kPa)."""
import json
import os

import pytest

from conftest import HERE, run_yade


@pytest.fixture(scope="module")
def result():
    p = run_yade(os.path.join(HERE, "simple_shear.py"), cwd=HERE, timeout=280)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])


def test_bad_input_is_refused(result):
    for name, msg in result["errors"].items():
        assert msg is not None and name in msg and "simple_shear_test" in msg, (name, msg)


def test_frictionless_joints_carry_no_shear(result):
    assert abs(result["tau0"]) < 2e3
    assert abs(result["tau0"]) < 0.02 * result["tau1"]


def test_band_is_stronger_than_its_joints(result):
    print(result)
    assert result["tau1"] > 2 * result["joint1"]
    assert result["large1"] > result["joint1"]
    assert result["curve_len"] > 100
    assert result["fit"] == pytest.approx([10e3, 0.5])
