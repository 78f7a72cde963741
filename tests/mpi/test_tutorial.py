"""The manual's distributed-run example, scripts/distributed_bricks.py, runs as written on 3 ranks: the slope
split before bonding, settled collectively, merged on rank 0, whose contact-force FS along the 35° plane lies
below the planar wedge's tan 40°/tan 35° = 1.198 (the crack's blocks push on it) and above 1 (it stands)."""
import os
import re

from conftest import SRC, run_mpi


def test_distributed_example_runs_on_three_ranks():
    r = run_mpi(os.path.join(SRC, "scripts", "distributed_bricks.py"), timeout=240)
    assert not r.timed_out and r.returncode == 0, r.tail()
    settled = re.search(r"^settled: \((True|False), (\d+), ([0-9.e-]+)\); (\d+) bodies on rank 0", r.output, re.M)
    assert settled and settled.group(1) == "True", r.tail()
    fs = re.findall(r"ContactFS\(fs=([0-9.]+), .* over ([0-9.]+) m\)", r.output)
    assert len(fs) == 1, r.tail()  # printed once, by rank 0
    assert 1.0 < float(fs[0][0]) < 1.198 and abs(float(fs[0][1]) - 11 / 0.819152) < 0.2, fs
