"""The landslide example at -j1 and -j2 (issue 35, item 4).

With two threads YADE sums the joint forces of a block in another order, and the undamped 300-step probe that
finds the surface of slipping joints amplifies round-off: on 027abd9 the -j2 run printed "the slipping surface
is a single point" where -j1 found it. Asserted: both runs find a surface, and the figures read on it agree
within a stated tolerance. The probe is chaotic and OpenMP's order changes from run to run, so -j2 is not even
repeatable: 13 runs at -j2 found 13-14 joints, 13.59-14.98 m (-j1: 13, 14.50 m), the RBSM factor of safety on
them 0.759-0.768 (-j1 0.759) and Fellenius 0.825-0.835 (-j1 0.825), where the toe's first joint differs. So:
both factors within 2.5 %, the length within 12 % (twice the spread); Table 2 on the given slip polyline the
same to the printed digit (it is read from the settled state, before the probe).
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
    surface = re.search(r"^slipping surface: (\d+) joints, ([0-9.]+) m, polyline", s, re.M)
    assert surface, "no slipping surface found at -j%d:\n%s" % (threads, s[-3000:])

    def row(label):
        m = re.search(r"^%s\s+([0-9.]+)" % re.escape(label), s, re.M)
        assert m, "row %r missing at -j%d" % (label, threads)
        return float(m.group(1))

    return {"length": float(surface.group(2)), "rbsm": row("RBSM contact forces, found surface"),
            "fellenius": row("Fellenius, found surface"), "table2": row("RBSM contact forces, slip polyline")}


def test_found_surface_at_one_and_two_threads(tmp_path):
    r1, r2 = _run(1, tmp_path), _run(2, tmp_path)
    print("-j1", r1, "\n-j2", r2)
    assert r2["table2"] == r1["table2"]
    assert r2["rbsm"] == pytest.approx(r1["rbsm"], rel=0.025)
    assert r2["fellenius"] == pytest.approx(r1["fellenius"], rel=0.025)
    assert r2["length"] == pytest.approx(r1["length"], rel=0.12)
