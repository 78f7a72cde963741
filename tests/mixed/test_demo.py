"""scripts/mixed_scene_demo.py (issue 17's example): runs headless, writes its two PNGs, and the block wall
retains the backfill (the spheres push on it, it stands)."""
import os
import re
import subprocess

from conftest import launcher

HERE = os.path.dirname(os.path.abspath(__file__))


def test_mixed_scene_demo(tmp_path):
    script = os.path.join(HERE, "..", "..", "scripts", "mixed_scene_demo.py")
    p = subprocess.run([launcher(), "-j", "1", "-n", "-x", script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=300, env=dict(os.environ, RBSM_OUT=str(tmp_path)))
    print(p.stdout[-2000:])
    assert p.returncode == 0
    for name in ("mixed_start.png", "mixed_end.png"):
        assert (tmp_path / name).stat().st_size > 10000
    m = re.search(r"thrust of the spheres on the block wall (\d+) N per m, its top moved (\S+) m", p.stdout)
    assert m and float(m.group(1)) > 500 and abs(float(m.group(2))) < 0.05, p.stdout[-500:]
    assert "ERROR" not in p.stdout
