"""Smoke run of scripts/landslide_slope.py on a tiny slope with a short dynamic stage: exit code 0,
density units, time-step check and Table 2 printed, PNG snapshots written."""
import os

from conftest import SRC, run_yade


def test_landslide_script_small(tmp_path):
    out = tmp_path / "out"
    p = run_yade(os.path.join(SRC, "scripts", "landslide_slope.py"), "--small", "--time", "0.05",
                 "--out", str(out), "--density-units", "si", cwd=str(tmp_path))
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "245 kg/m3 (SI as printed) -> 245.0 kg/m3" in p.stdout
    assert "seed paper: 0.003 s" in p.stdout
    assert "Table 2" in p.stdout and "Present method (RBSM)" in p.stdout and "Fellenius" in p.stdout
    assert "converged after" in p.stdout
    pngs = sorted(f.name for f in out.iterdir() if f.suffix == ".png")
    assert len(pngs) == 4 and all((out / f).stat().st_size > 1000 for f in pngs)
