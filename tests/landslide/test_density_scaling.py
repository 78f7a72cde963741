"""Density scaling of quasi-static stages (issue 22): RbsmTimeStepper.densityScaling, through
settle(density_scaling=True). A 10 m Voronoi slope of about 300 bonded 1 m blocks settles to the same
state (settled positions within 2 mm, the slope's elastic settlement being centimetres) in fewer steps
at a longer step: the blocks below the median block's stable step are made heavier (measured: 1600
against 600 steps, O.dt 4.3e-4 against 1.39e-3 s, 151 of 301 blocks scaled, at most 15 x; largest
position difference 0.47 mm). The scaling is off again after the stage."""
import json
import os

from conftest import HERE, run_yade


def test_settle_with_density_scaling():
    p = run_yade(os.path.join(HERE, "ds_settle.py"), cwd=HERE, timeout=280)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    print(r)
    plain, scaled = r["plain"], r["scaled"]
    assert plain["ok"] and scaled["ok"], "both stages must reach the unbalanced-force ratio 1e-4"
    assert plain["scaled"] == 0 and scaled["scaled"] > 0 and scaled["smax"] > 1
    assert scaled["dt"] > 2 * plain["dt"]
    assert 2 * scaled["steps"] <= plain["steps"]
    assert r["dmax"] < 2e-3, "the settled states differ by %.3g m" % r["dmax"]
    assert scaled["restored"] is False and scaled["after_off"] == 0
