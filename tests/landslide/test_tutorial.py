"""scripts/tutorial_jointed_slope.py, the README's new-user slope (issue 37: joint sets, slope.SlopeModel's
stages, fos(), a dynamic run, a report in fewer than 30 lines) runs and says what it should: a conclusive
factor of safety by strength reduction, the stages with their figures, a Markdown report, a saved scene
whose stages SlopeModel.resume() finds after O.load in another process and continues (measured: FS 1.168,
0.60 m in 1 s at the joints' strength / 1.3, 11 s wall)."""
import os
import re
import subprocess

from conftest import SRC, launcher

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
