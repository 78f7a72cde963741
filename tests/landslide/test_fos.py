"""slope.fos() (issue 37): one call on the settled scene, a conclusive answer with its defaults, the other
estimates beside it and the design value for the kind of slope (fos_cases.py).

* plane: Hoek & Bray's plane failure built by the joint-set cutter: strength reduction, the design value
  for jointed rock, within 1 % of the closed form 1.4818 (measured 1.479, 0.6 s), no warning.
* voronoi: a c-phi slope (c 20 kPa, phi 20 deg) cut into Voronoi blocks: a continuum; rigid blocks give
  strength reduction 4.94 against Bishop's 1.37, and the design value is Bishop's (measured 1.7 s).
"""
import json
import os

import pytest

from conftest import HERE, run_yade
from verification import record


def _run(case):
    p = run_yade(os.path.join(HERE, "fos_cases.py"), case, cwd=HERE, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:]), p.stdout


def test_fos_of_a_plane_failure_is_the_closed_form():
    r, out = _run("plane")
    record("Rock slopes", "Hoek & Bray's plane failure with a tension crack: fos() with its defaults", r["fs"], r["closed"],
           "Hoek & Bray, plane failure", rtol=0.01)
    assert r["warnings"] == [] and r["kind"] == "jointed rock" and r["method"] == "strength reduction", r
    assert r["fs"] == pytest.approx(r["closed"], rel=0.01), r
    assert set(r["estimates"]) == {"strength reduction", "contact forces, surface of slipping joints"}, r
    assert r["repr"].startswith("FosResult(fs=1.4") and "conclusive" in r["repr"], r
    assert "| strength reduction | 1.4" in out and "Warnings: none (conclusive)" in out  # to_markdown()


def test_fos_of_a_continuum_cut_into_blocks_is_limit_equilibrium():
    r, out = _run("voronoi")
    bishop = r["estimates"]["Bishop, critical circle (blocks' material)"]["fs"]
    assert r["kind"] == "continuum cut into blocks" and r["method"].startswith("Bishop") and r["fs"] == bishop, r
    assert 1.0 < bishop < 2.0 and r["estimates"]["strength reduction"]["fs"] > 1.5 * bishop, r
    assert r["warnings"] == [], r


def test_fos_of_griffiths_and_lane_is_the_critical_circle():
    """Griffiths & Lane's 2:1 slope (c' 10 kPa, phi' 20 deg, firm base at the toe) cut into Voronoi blocks: the
    design value is Bishop's critical circle, and it is the reference search's minimum (1.382) within 0.5 %:
    on 12edc9b fos() searched 9 x 9 x 9 centres and radii, refined once, and gave 1.413 (+2.3 %, unconservative).
    Strength reduction's warnings qualify its estimate (a note), not the design value: conclusive. Beside it the
    stress-based critical circle on the settled blocks' own stresses (issue 37's "other estimates: stress-based"):
    1.604 with these 2 m blocks (H/5) and brittle joints, against 1.359 with 1 m blocks and ductile joints
    (test_slope_fs.py); it was not among the estimates on 3b4a483."""
    r, out = _run("gl")
    kul = r["estimates"]["stress-based, critical circle (blocks' stresses)"]
    assert kul["fs"] is not None and 1.0 < kul["fs"] < 2.0 and "Kulhawy" in kul["note"], kul
    record("Soil slopes", "Griffiths & Lane's 2:1 slope in Voronoi blocks: fos() (Bishop's critical circle)", r["fs"],
           r["closed"], "the reference critical-circle search", rtol=0.005)
    assert r["method"].startswith("Bishop") and r["fs"] == pytest.approx(r["closed"], rel=0.005), r
    assert r["warnings"] == [], r


def test_fos_of_the_main_example_is_conclusive():
    """The main example's brick slope (scripts/fos_survey.py landslide: its joints' friction held while gravity
    comes on): fos() with its defaults. On 12edc9b the stable end F = 0.8688 had slid 7.5 cm (more than half
    of d_fail, 11 cm) and stopped: FS 0.872 with the warning that it depends on d_fail. The default d_fail is
    now halved while that happens: 0.859, then 0.828 without a warning (measured, 6 s), the onset of sliding,
    next to limit equilibrium's planar wedge 0.825 (the crack's thrust makes the contact-force FS 0.67)."""
    import subprocess
    from conftest import SRC, launcher
    p = subprocess.run([launcher(), "-n", "-x", os.path.join(SRC, "scripts", "fos_survey.py"), "landslide"], cwd=HERE,
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    assert r["conclusive"] and r["method"] == "strength reduction", r
    assert 0.80 < r["fs"] < 0.85, r


def test_fos_after_water_and_a_pseudo_static_load():
    """model_loads.py: SlopeModel.set_water and set_seismic are stages (settled, recorded) and fos() after
    each takes them. Measured: 1.168 dry, 1.168 with water (the critical wedge is above the water line: 187
    joints wet), 1.004 with kh = 0.05 out of the face (a planar wedge on the 30 deg bedding: x 0.89 by Hoek &
    Bray's factor, 1.04; settling under kh first matters: applied at once, the shaking gave 0.878)."""
    p = run_yade(os.path.join(HERE, "model_loads.py"), cwd=HERE, timeout=400)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    dry, wet, seismic = r["fs"]
    assert all(r["conclusive"]) and r["wet"] > 100, r
    assert 1.0 < dry < 1.3 and wet <= dry * 1.01 and 0.8 * dry < seismic < 0.95 * dry, r
    assert r["stages"] == ["build", "in-situ", "joint strengths", "equilibrium", "factor of safety", "water", "equilibrium",
                           "factor of safety", "pseudo-static", "equilibrium", "factor of safety"], r
