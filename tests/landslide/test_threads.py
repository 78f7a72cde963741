"""The landslide example at -j1 and -j2 (issue 35, item 4).

With two threads YADE sums the joint forces of a block in another order, and the undamped 300-step probe that
finds the surface of slipping joints amplifies round-off: on 027abd9 the -j2 run printed "the slipping surface
is a single point" where -j1 found it. On bc042d0 the probe took every joint that slipped at some check (about
190 of them, most by chatter that round-off switches on and off): 12 runs at -j2 found four surfaces, 13.59 to
15.30 m, with RBSM factors of safety 0.707 to 0.767 (-j1 0.759), and CI drew the 0.707 one. The probe now keeps
the joints that dissipated at least a tenth of the most any joint did (eleven joints carry 94 % of the energy,
in the same order at -j1 and -j2): 10 runs gave 10.87-10.88 m and 0.722-0.723. Asserted over one -j1 and four
-j2 runs: the same number of joints, the length within 1 %, both factors within 1 % (half the old spread's
smallest step), Table 2 on the given slip polyline the same to the printed digit (read before the probe).
"""
import os
import re
import subprocess

import pytest

from conftest import SRC, launcher


def _run(threads, tmp):
    p = subprocess.run([launcher(), "-j", str(threads), "-n", "-x", os.path.join(SRC, "scripts", "landslide_slope.py"), "--no-search",
                        "--time", "0.05", "--out", str(tmp / ("out%d" % threads))], cwd=str(tmp), capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    s = p.stdout
    surface = re.search(r"^slipping surface: (\d+) slipping joints, ([0-9.]+) m, polyline", s, re.M)
    assert surface, "no slipping surface found at -j%d:\n%s" % (threads, s[-3000:])

    def row(label):
        m = re.search(r"^%s\s+([0-9.]+)" % re.escape(label), s, re.M)
        assert m, "row %r missing at -j%d" % (label, threads)
        return float(m.group(1))

    return {"joints": int(surface.group(1)), "length": float(surface.group(2)), "rbsm": row("RBSM contact forces, found surface"),
            "fellenius": row("Fellenius, found surface"), "table2": row("RBSM contact forces, slip polyline")}


def test_found_surface_at_one_and_two_threads(tmp_path):
    r1 = _run(1, tmp_path)
    print("-j1", r1)
    for _ in range(4):  # OpenMP's order changes from run to run: several draws
        r2 = _run(2, tmp_path)
        print("-j2", r2)
        assert r2["table2"] == r1["table2"]
        assert r2["joints"] == r1["joints"]
        assert r2["length"] == pytest.approx(r1["length"], rel=0.01)
        assert r2["rbsm"] == pytest.approx(r1["rbsm"], rel=0.01)
        assert r2["fellenius"] == pytest.approx(r1["fellenius"], rel=0.01)
