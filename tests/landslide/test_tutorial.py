"""scripts/tutorial_jointed_slope.py, the README's new-user slope (issue 37: joint sets, slope.SlopeModel's
stages, fos(), a dynamic run, a report in fewer than 30 lines) runs and says what it should: a conclusive
factor of safety by strength reduction, the stages with their figures, a Markdown report, a saved scene
whose stages SlopeModel.resume() finds after O.load in another process and continues (measured: FS 1.168,
0.60 m in 1 s at the joints' strength / 1.3, 11 s wall)."""
import os
import re
import subprocess

import pytest

from conftest import SRC, launcher
from verification import record

RESUME = r"""
import json, sys
from yade_rbsm import slope
O.load(sys.argv[1])
m = slope.SlopeModel.resume()
before = [s.name for s in m.stages]
m.run(0.1)
print("RESULT " + json.dumps(dict(before=before, after=[s.name for s in m.stages], pattern=m.sb.pattern,
                                  t=m.stages[-1].time)))
"""


def test_tutorial_runs_and_its_scene_resumes(tmp_path):
    script = os.path.join(SRC, "scripts", "tutorial_jointed_slope.py")
    assert sum(1 for _ in open(script)) < 30
    p = subprocess.run([launcher(), "-n", "-x", script, str(tmp_path)], cwd=str(tmp_path), capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    m = re.search(r"FosResult\(fs=([0-9.]+) by strength reduction, jointed rock, conclusive", p.stdout)
    assert m and 1.0 < float(m.group(1)) < 1.3, p.stdout[-3000:]
    d = re.search(r"dynamic +max_displacement ([0-9.]+)", p.stdout)
    assert d and float(d.group(1)) > 0.1, p.stdout[-2000:]  # F = 1.3 > FS: it slides
    for f in ("blocks.png", "fos.md", "report.md", "slope.yade.gz"):
        assert os.path.getsize(str(tmp_path / f)) > 0, f
    assert "Warnings: none (conclusive)" in open(str(tmp_path / "fos.md")).read()
    assert "| factor of safety |" in open(str(tmp_path / "report.md")).read()
    (tmp_path / "resume.py").write_text(RESUME)
    p = subprocess.run([launcher(), "-n", "-x", str(tmp_path / "resume.py"), str(tmp_path / "slope.yade.gz")],
                       cwd=str(tmp_path), capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    import json
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    assert r["before"] == ["build", "in-situ", "joint strengths", "equilibrium", "factor of safety", "dynamic"], r
    assert r["after"] == r["before"] + ["dynamic"] and r["pattern"] == "joint sets", r


def _run_tutorial(name, tmp_path, timeout=600):
    script = os.path.join(SRC, "scripts", name)
    assert sum(1 for _ in open(script)) < 60, "a tutorial stays short enough to read in one go"
    p = subprocess.run([launcher(), "-n", "-x", script, str(tmp_path)], cwd=str(tmp_path), capture_output=True, text=True,
                       timeout=timeout)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return p.stdout


def test_soil_slope_tutorial_gives_bishop_with_the_blocks_estimate_beside_it(tmp_path):
    """The manual's soil-slope tutorial: fos() on Griffiths & Lane's slope in Voronoi blocks is Bishop's critical
    circle (within 1 % of the tutorial's own limit-equilibrium search), conclusive, and strength reduction on the
    rigid blocks is shown beside it, above it (the interlocking the tutorial explains); the blocks' own stresses on
    their critical circle (Kulhawy) within 5 % of Bishop (1.387 against 1.382)."""
    out = _run_tutorial("tutorial_soil_slope.py", tmp_path)
    m = re.search(r"FosResult\(fs=([0-9.]+) by Bishop, critical circle.*conclusive", out)
    b = re.search(r"Bishop, critical circle: ([0-9.]+)", out)
    assert m and b, out[-3000:]
    record("Soil slopes", "Griffiths & Lane's 2:1 slope in 300 Voronoi blocks (tutorial): fos(), Bishop on the blocks' ground",
           float(m.group(1)), float(b.group(1)), "Bishop's critical circle of the slope itself", rtol=0.01)
    assert abs(float(m.group(1)) / float(b.group(1)) - 1) < 0.01, out[-3000:]
    sr = re.search(r"strength reduction[^:]*: ([0-9.]+)", out)
    assert sr and float(sr.group(1)) > float(m.group(1)), out[-3000:]
    kul = re.search(r"stress-based, critical circle \(blocks' stresses\): ([0-9.]+)", out)  # the page quotes 1.387
    assert kul and abs(float(kul.group(1)) / float(b.group(1)) - 1) < 0.05, out[-3000:]
    assert os.path.getsize(str(tmp_path / "report.md")) > 0


def test_water_and_earthquake_tutorial_matches_hoek_and_bray(tmp_path):
    """The manual's loads tutorial: Hoek & Bray's plane failure dry, with 2 m of water on the bedding and with
    kh = 0.1, each by strength reduction within 1 % of the closed form it prints; its yield acceleration too."""
    out = _run_tutorial("tutorial_water_earthquake.py", tmp_path)
    rows = re.findall(r"^(dry|water, zw 2 m|kh 0\.1) +FS ([0-9.]+) by strength reduction, Hoek & Bray ([0-9.]+)", out, re.M)
    assert [r[0] for r in rows] == ["dry", "water, zw 2 m", "kh 0.1"], out[-3000:]
    for name, fs, closed in rows:
        record("Rock slopes", "Hoek & Bray's plane failure with a tension crack, %s (tutorial): fos()" % name, float(fs),
               float(closed), "Hoek & Bray, plane failure", rtol=0.01)
        assert abs(float(fs) / float(closed) - 1) < 0.01, (name, fs, closed)
    assert float(rows[1][1]) < float(rows[0][1]) and float(rows[2][1]) < float(rows[0][1])  # both loads weaken it
    ky, closed = map(float, re.search(r"yield acceleration k_y ([0-9.]+), Hoek & Bray ([0-9.]+)", out).groups())
    record("Earthquakes", "Hoek & Bray's plane failure with a tension crack (tutorial): yield acceleration k_y", ky, closed,
           "Hoek & Bray's FS(kh) = 1", rtol=0.01)
    assert ky == pytest.approx(closed, rel=0.01)
