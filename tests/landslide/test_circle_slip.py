"""Contact-force factor of safety along a circle and along the surface of slipping joints found by
the program (yade_rbsm.safety), and bad input of the FS helpers.

* Circle, hand calculation (fs_circle.py): two blocks (2 m and 1.5 m) on a fixed block along a
  plane joint at psi = 20 deg, phi = 30 deg, c = 5 kPa bonded over L = 3.5 m; the circle of radius
  100 m tangent to the plane at the middle of the contact picks the two base joints (not the joint
  between the blocks, both inside the circle): N = W cos(psi), T = W sin(psi),
  FS = (c L + W cos(psi) tan(phi)) / (W sin(psi)) (the circle's tangent differs from the plane's by
  at most 1.75/100 rad: 2e-4 relative).
* Found surface (slip_wedge.py): a brick slope cut along a joint plane at psi = 30 deg daylighting
  on the face and the crest, phi = 15 deg on the plane, strongly bonded elsewhere: the wedge slides.
  The surface of the joints that slipped during a 300-step probe lies on the plane (every vertex
  within 2 cm) and covers most of it; the contact-force FS along it during the slide is 1 (every
  point at the Mohr-Coulomb limit); Fellenius along it (ends continued along the plane to the
  ground) is tan(phi)/tan(psi).
* Bad input tried (ValueError naming the problem): a circle that misses the slope, NaN centre,
  R < 0, band 0; a slip polyline that misses the slope, an empty one, one with NaN, one with x
  decreasing; the found-surface FS when nothing slips.
"""
import json
import math
import os

import pytest

from conftest import HERE, run_yade


@pytest.fixture(scope="module")
def circle_run():
    p = run_yade(os.path.join(HERE, "fs_circle.py"), cwd=HERE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return p.stdout


def test_circle_hand_calculation(circle_run):
    line = [l for l in circle_run.splitlines() if l.startswith("RESULT")][0].split()
    ok, n, r = line[1], int(line[2]), float(line[3])
    N, T, fs, N0, T0, fs0 = map(float, line[4:10])
    nj, length = int(line[10]), float(line[11])
    assert ok == "True", (n, r)
    assert nj == 2 and length == pytest.approx(3.5, rel=1e-6)
    assert N == pytest.approx(N0, rel=1e-3)
    assert T == pytest.approx(T0, rel=1e-3)
    assert fs == pytest.approx(fs0, rel=1e-3)
    pN, pT, pfs = map(float, [l for l in circle_run.splitlines() if l.startswith("POLY")][0].split()[1:])
    assert fs == pytest.approx(pfs, rel=1e-3)  # same joints as along the plane


@pytest.mark.parametrize("label", ["circle-misses", "circle-nan", "circle-radius", "circle-band", "polyline-misses",
                                   "polyline-empty", "polyline-nan", "polyline-order", "slip-none"])
def test_bad_input(circle_run, label):
    line = [l for l in circle_run.splitlines() if l.startswith("BAD %s " % label)][0]
    assert "ValueError" in line, line
    words = {"circle-misses": "misses", "circle-nan": "NaN", "circle-radius": "R must be > 0", "circle-band": "band",
             "polyline-misses": "misses", "polyline-empty": "empty", "polyline-nan": "NaN",
             "polyline-order": "increasing", "slip-none": "no joint slips"}
    assert words[label] in line


def test_found_surface_is_the_plane():
    p = run_yade(os.path.join(HERE, "slip_wedge.py"), "bricks", cwd=HERE)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "surface of slipping joints" in p.stdout and "Present method (RBSM)" in p.stdout
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    (ax, ay), (bx, by) = r["plane"]
    L = math.hypot(bx - ax, by - ay)
    for x, y in r["probe"]:
        assert abs((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / L < 0.02, (x, y)
    xs = [x for x, _ in r["probe"]]
    assert max(xs) - min(xs) > 0.6 * (bx - ax)
    assert r["broken"] >= 8 and r["n"] >= 8
    assert r["fs"] == pytest.approx(1.0, abs=0.02)
    assert r["fel"] == pytest.approx(r["closed"], rel=0.01)
    # issue 37: a named result with a short repr (a bare tuple printed 30 lines of numpy repr)
    assert r["fs_attr"] == r["fs"] and len(r["repr"].splitlines()) <= 3 and len(r["repr"]) < 400, r["repr"]
    assert "FS" in r["repr"] and "Fellenius" in r["repr"], r["repr"]
