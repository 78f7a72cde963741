"""Earthquakes in the block model (issue 40), on earthquake_plane.py's wedge (Hoek & Bray's plane-failure slope
with a cohesionless bedding, psi 30 deg, phi 40 deg: Newmark's rigid block on a plane):
- SlopeModel.yield_acceleration finds k_y = tan(phi - psi) within 1 % (regula falsi on fos() under set_seismic);
- under a sine ground acceleration above k_y (SlopeModel.set_earthquake: the model in its rigid base's frame) the
  wedge slides by Newmark's integration of the same record within 2 %, and O.energy's balance of the undamped
  stage closes within 0.5 % of the work of gravity (the inertial force's work counted in gravWork).
None of these names existed on 7ea19b2 (slope.set_seismic only; no record, no Newmark, no k_y)."""
import math

import pytest

from conftest import run_yade
from verification import record


def result(*args):
    p = run_yade("earthquake_plane.py", *args)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    import json
    return json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][-1][7:]), p.stdout


def test_yield_acceleration_of_a_wedge_on_a_plane():
    r, out = result("ky")
    record("Earthquakes", "wedge on a plane (ψ 30°, φ 40°): yield acceleration k_y by fos() under kh", r["ky"],
           r["closed"], "tan(φ − ψ)", rtol=0.01)
    assert r["ky"] == pytest.approx(r["closed"], rel=0.01), r
    assert "yield acceleration" in r["stages"]
    # SlopeModel.limit_equilibrium under set_seismic(0.1): Fellenius on the plane with the scene's kh, the wedge's
    # pseudo-static closed form (cos psi - kh sin psi) tan phi / (sin psi + kh cos psi) (its weight cancels)
    psi, phi = math.radians(30), math.radians(40)
    closed = (math.cos(psi) - 0.1 * math.sin(psi)) * math.tan(phi) / (math.sin(psi) + 0.1 * math.cos(psi))
    assert r["le_kh"] == pytest.approx(closed, rel=1e-3), r


@pytest.mark.parametrize("amp,freq,cycles", [(0.35, 1.0, 2), (0.5, 2.0, 3)])
def test_wedge_slides_by_newmark(amp, freq, cycles):
    r, out = result("newmark", str(amp), str(freq), str(cycles))
    record("Earthquakes", "wedge on a plane (ψ 30°, φ 40°), sine %g g at %g Hz, %d cycles: permanent displacement"
           % (amp, freq, cycles), r["along"], r["newmark"], "Newmark's rigid sliding block", rtol=0.02, unit="m")
    assert r["newmark"] > 0.05 and r["along"] == pytest.approx(r["newmark"], rel=0.02), r
    assert r["gravity"] == [0.0, -9.81, 0.0]  # the record over: static gravity again
    import re
    off = float(re.search(r"off by (\S+) % of the work of gravity", out).group(1))
    assert abs(off) < 0.5, off


def test_main_example_takes_water_and_an_earthquake(tmp_path):
    """scripts/landslide_slope.py --water ZW --earthquake: the stages are recorded (joints wet below the line, the
    shipped synthetic record of PGA 0.3 g), the dynamic stage shakes and its energy balance still closes."""
    import json
    import os
    from conftest import SRC
    p = run_yade(os.path.join(SRC, "scripts", "landslide_slope.py"), "--small", "--time", "0.3", "--water", "0.5",
                 "--earthquake", "--no-search", "--probe-steps", "0", "--out", str(tmp_path / "out"), cwd=str(tmp_path))
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    stages = {s["name"]: s for s in json.load(open(str(tmp_path / "out" / "summary.json")))["stages"]}
    assert stages["water"]["figures"]["joints_wet"] > 10
    assert stages["earthquake"]["figures"]["pga_g"] == pytest.approx(0.3, rel=1e-3)
    import re
    assert abs(float(re.search(r"off by (\S+) % of the work of gravity", p.stdout).group(1))) < 1.0
