"""scripts/tutorial_jointed_slope.py, the README's new-user slope (issue 37: import, joint sets, fos(), a
dynamic run, a report in about 30 lines) runs and says what it should: a conclusive factor of safety by
strength reduction, a report in Markdown and a runout plot (measured: FS 1.168, 0.59 m in 1 s at the joints'
strength / 1.3, 38 s wall)."""
import os
import re
import subprocess

from conftest import SRC, launcher


def test_tutorial_runs(tmp_path):
    script = os.path.join(SRC, "scripts", "tutorial_jointed_slope.py")
    assert sum(1 for _ in open(script)) <= 35
    p = subprocess.run([launcher(), "-n", "-x", script, str(tmp_path)], cwd=str(tmp_path), capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    m = re.search(r"FosResult\(fs=([0-9.]+) by strength reduction, jointed rock, conclusive", p.stdout)
    assert m and 1.0 < float(m.group(1)) < 1.3, p.stdout[-3000:]
    d = re.search(r"largest displacement after 1 s: ([0-9.]+) m", p.stdout)
    assert d and float(d.group(1)) > 0.1, p.stdout[-2000:]  # F = 1.3 > FS: it slides
    for f in ("fos.md", "runout.png", "runout.txt"):
        assert os.path.getsize(str(tmp_path / f)) > 0, f
    assert "Warnings: none (conclusive)" in open(str(tmp_path / "fos.md")).read()
