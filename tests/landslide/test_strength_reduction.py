"""Factor of safety by strength reduction (yade_rbsm.strength_reduction) for a single block on a
plane joint, c = 0: FS = tan(phi)/tan(psi) (phi = 30 deg; psi = 20 deg: 1.586, psi = 25 deg:
1.238) within 2 %; the bracket contains the closed form; the reference state (position, joint
strength) is restored afterwards."""
import math
import os

import pytest

from conftest import HERE, run_yade
from verification import record


@pytest.mark.parametrize("psi", [20.0, 25.0])
def test_block_on_plane(psi):
    p = run_yade(os.path.join(HERE, "sr_block.py"), str(psi), cwd=HERE, timeout=120)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    f = [l for l in p.stdout.splitlines() if l.startswith("RESULT")][0].split()
    ok = f[1]
    fs, lo, hi, fs0 = map(float, f[2:6])
    ntrials, moved, tanphi = int(f[6]), float(f[7]), float(f[8])
    assert ok == "True"
    assert fs0 == pytest.approx(math.tan(math.radians(30)) / math.tan(math.radians(psi)), rel=1e-8)
    record("Rock slopes", "a block on a %g° plane, φ 30°: strength reduction" % psi, fs, fs0, "tan φ / tan ψ", rtol=0.02)
    assert fs == pytest.approx(fs0, rel=0.02), p.stdout[-3000:]
    assert lo <= fs0 * 1.002 and hi >= fs0 * 0.998, (lo, hi, fs0)  # bracket (+ the criterion's resolution)
    assert hi > lo and (hi - lo) <= 0.0051 * lo
    assert ntrials <= 30
    assert moved < 1e-9  # reference state restored
    assert tanphi == pytest.approx(math.tan(math.radians(30)), rel=1e-8)
    assert f[9] == "sliding", f  # the failed end's mechanism
    assert f[10] == "0", f  # no warning: the bracket is the mechanism's


def test_a_reference_state_that_toppled_while_settling_is_refused():
    """A new user's columns toppled 4 m while settling and strength reduction reported an FS of the
    collapsed pile without a word: the blocks' rotation since they were built is now checked."""
    p = run_yade(os.path.join(HERE, "stepped_columns.py"), "35", "8000", cwd=HERE, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    settled = [l for l in p.stdout.splitlines() if l.startswith("SETTLED")][0].split()
    assert float(settled[-1]) > 0.5, settled  # toppled: rotated by more than 0.5 rad (the scene still does)
    refused = [l for l in p.stdout.splitlines() if l.startswith("REFUSED")]
    assert refused, p.stdout[-2000:]
    msg = refused[0]
    assert "strength_reduction: the reference state" in msg and "rotated" in msg and "#" in msg, msg
    assert "reference_rotation" in msg, msg  # says how to accept it


def test_the_failed_end_says_toppling_for_a_column_that_tips():
    """A bonded column that only its joint's tension holds upright: strength reduction (tension reduced
    too) fails it by toppling, and says so (Trial.mechanism, SRResult.mechanism; the block on a plane
    above says sliding)."""
    p = run_yade(os.path.join(HERE, "sr_column.py"), cwd=HERE, timeout=120)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    f = [l for l in p.stdout.splitlines() if l.startswith("RESULT")][0].split()
    fs, lo, hi = map(float, f[1:4])
    assert lo < fs < hi
    assert f[4] == "toppling" and float(f[5]) > 0.7, f
    assert "failing by toppling" in p.stdout


def test_a_bracket_set_by_max_steps_is_warned_about():
    """A new user's soft toppling columns (E 1 GPa): with max_steps 8000 the failed end only did not
    converge (ratio 1.9e-4, 4.5 cm of motion, nothing ran away) and the FS was 1.234 against 1.346 with
    40 000 steps; the result now says so (SRResult.warnings) when the trial cannot run on (patience 1). With
    the default patience (4) the trial runs on while its motion dies out, and that warning is gone (measured:
    FS 1.399, its stable end moved 5.9 cm and stopped, which the d_fail warning reports)."""
    p = run_yade(os.path.join(HERE, "stepped_columns.py"), "50", "8000", "1", cwd=HERE, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    warnings = [l for l in p.stdout.splitlines() if l.startswith("WARNING")]
    assert len(warnings) == 1 and "did not converge within 8000 steps" in warnings[0], p.stdout[-2000:]
    p = run_yade(os.path.join(HERE, "stepped_columns.py"), "50", "8000", cwd=HERE, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "did not converge" not in p.stdout, p.stdout[-2000:]


def test_a_trial_stopped_by_the_plugin_says_which_and_what_came_before():
    """A new user's two-wedge slope (trial 14a) lost its whole strength reduction to a 5 mm sliver spinning off
    in one trial, with only "the run was stopped at step N by an error of the plugin". The error now names the
    trial's F, the step, what to look for, and the trials before it."""
    p = run_yade(os.path.join(HERE, "sr_block.py"), "25", "stop", cwd=HERE, timeout=120)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    line = [l for l in p.stdout.splitlines() if l.startswith("SRSTOP ")][0]
    assert "strength_reduction: trial F = 1.5 was stopped at step" in line and "min_area" in line, line
    assert "F = 1.0000: stable" in line, line  # the trials before it
    assert "yade-rbsm: ERROR: RbsmTimeStepper: body #1" in p.stderr, p.stderr[-2000:]


def test_flags_are_checked_and_pngs_named_as_given(tmp_path):
    """Issue 37: settle(density_scaling="no") ran with the scaling on ("no" is a true string), and
    strength_reduction(png="x.png") wrote x.png_failed.png. The flags are now checked (True or False), a
    .png prefix loses its suffix, and density scaling is off again after strength_reduction."""
    import json
    p = run_yade(os.path.join(HERE, "sr_block.py"), "20", "args", str(tmp_path), cwd=HERE, timeout=120)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    r = json.loads([l for l in p.stdout.splitlines() if l.startswith("RESULT ")][0][7:])
    assert r["scaling"] is False and r["scaling_after"] is False, r
    assert r["pngs"] == ["srm_failed.png", "srm_stable.png"], r
    assert "density_scaling must be True or False (got 'no')" in r["errors"]["settle"], r
    assert "density_scaling must be True or False (got 'yes')" in r["errors"]["srm"], r


def test_trend_tells_a_creeping_mechanism_from_a_slope_still_settling():
    """The judgement of a trial still undecided at max_steps (issue 37): pure function of its history of
    (mass-weighted mean displacement, unbalanced ratio) at each check."""
    import sys
    sys.path.insert(0, os.path.join(HERE, "..", "..", "py"))
    from yade_rbsm.strength_reduction import _trend
    steady = [(0.01 * k, 1e-2) for k in range(12)]  # moving at a constant rate, force unbalanced
    accelerating = [(0.001 * k * k, 1e-2) for k in range(12)]
    settling = [(1 - 0.8 ** k, 1e-2 * 0.8 ** k) for k in range(12)]  # both die out
    slow_but_balanced = [(0.01 * k, 1e-2 * 0.5 ** k) for k in range(12)]  # drift while the force balances: not a mechanism
    assert _trend(steady) == _trend(accelerating) == "creeping"
    assert _trend(settling) == _trend(slow_but_balanced) == "dying"
    assert _trend(steady[:7]) == "unclear"


def test_a_creeping_trial_says_what_its_mass_fraction_is():
    """A trial failed by creeping has no block beyond d_fail; its line said "FAILED (creeping ...), moving mass
    0.0 %", which reads as a failure without motion. The fraction is named by what it counts."""
    import sys
    sys.path.insert(0, os.path.join(HERE, "..", "..", "py"))
    from yade_rbsm.strength_reduction import Trial
    line = str(Trial(1.2, True, "creeping", 4000, 3e-3, 0.004, 1.0, moving=0.0))
    assert "FAILED (creeping" in line and "mass moved beyond d_fail 0.0 %" in line and "moving mass" not in line, line


def test_the_main_example_brackets_by_mechanism_and_equilibrium(tmp_path):
    """scripts/landslide_slope.py --strength-reduction (issue 37): on e456729 its failed end F = 0.8375 'only did
    not converge within max_steps = 4000' (0.027 m moved, nothing ran away) and the FS was 0.834. Trials still
    undecided at max_steps now run on while their motion dies out: both ends are decided (converged, runaway or
    creeping) and no max_steps warning is left (measured: FS 0.878, bracket [0.875 converged, 0.881 runaway])."""
    import re
    import subprocess
    from conftest import SRC, launcher
    p = subprocess.run([launcher(), "-n", "-x", os.path.join(SRC, "scripts", "landslide_slope.py"), "--no-search", "--time",
                        "0.01", "--probe-steps", "0", "--strength-reduction", "--out", str(tmp_path / "out")],
                       cwd=str(tmp_path), capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "did not converge" not in p.stdout, p.stdout[-3000:]
    m = re.search(r"strength reduction: FS = ([0-9.]+), bracket \[([0-9.]+) stable, ([0-9.]+) failed\]", p.stdout)
    assert m, p.stdout[-3000:]
    lo, hi = float(m.group(2)), float(m.group(3))
    ends = {float(t.group(1)): t.group(2) for t in re.finditer(r"trial F = ([0-9.]+): (?:stable|FAILED) \((\w+)", p.stdout)}
    assert ends[round(lo, 4)] == "converged" and ends[round(hi, 4)] in ("runaway", "creeping"), (ends, lo, hi)
