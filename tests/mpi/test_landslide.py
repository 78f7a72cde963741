"""Issue 18: the landslide example (scripts/landslide_slope.py --small) under yade.mpy (--mpi, 3 ranks
by mpiexec: the free blocks in two vertical slices, one per worker, the fixed ones on rank 0) gives the
serial run's factor of safety and displacements.

* With --engines sorted_loop=True (every block's joint forces summed in id order, serially as on the ranks) the
  whole run (bonding, 800-step gravity stage, 0.05 s dynamic stage: 1057 steps) is the serial one
  bit for bit: factor of safety from the contact forces, unbalanced-force ratio, every displacement.
  Tolerance 1e-12 (relative for the FS, metres for the displacements): the same operations in the
  same order, except that rank 0 sums the FS over the merged joints in their container's order.
* Without it (the default) the sums follow each rank's container order and differ from the serial
  ones by round-off; the damped gravity stage amplifies that about tenfold every 25 steps (serially,
  -j2 against -j1 does the same), so the comparison is over a short window: 200 steps of gravity stage
  and 3 ms of dynamic stage (213 steps), FS within 1e-8 relative and displacements within 1e-10 m
  (measured: 2.4e-11 and 3e-13 m).
* Rank 0 alone prints (one table of factors of safety) and writes the snapshots and the VTK series.
"""
import json
import os

import pytest

from conftest import SRC, launcher, run_mpi

SCRIPT = os.path.join(SRC, "scripts", "landslide_slope.py")
COMMON = ["--small", "--probe-steps", "0", "--no-search"]


def _serial(tmp, args):
    import subprocess

    out = tmp / "serial"
    p = subprocess.run([launcher(), "-n", "-x", SCRIPT] + COMMON + args + ["--out", str(out)],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True, cwd=str(tmp), timeout=300)
    assert p.returncode == 0, p.stdout[-3000:]
    return _summary(out), p.stdout


def _mpi(tmp, args):
    out = tmp / "mpi"
    r = run_mpi(SCRIPT, COMMON + args + ["--mpi", "--out", str(out)], timeout=300, cwd=str(tmp))
    assert not r.timed_out and r.returncode == 0, r.tail()
    return _summary(out), r.output


def _summary(out):
    """The example's summary.json, with the figures of its stages on top (settle_*, fs_*)."""
    d = json.load(open(out / "summary.json"))
    stage = {s["name"]: s["figures"] for s in d["stages"]}
    d.update(settle_steps=stage["in-situ"]["steps"], settle_ratio=stage["in-situ"]["unbalanced"],
             settle_moved=stage["in-situ"]["max_displacement"],
             fs_contact=stage["contact forces"]["fs"], fs_joints=stage["contact forces"]["joints"])
    return d


def _compare(s, m):
    assert m["ranks"] == 3 and s["ranks"] == 1
    assert m["iter"] == s["iter"] and m["settle_steps"] == s["settle_steps"] and m["fs_joints"] == s["fs_joints"]
    fs_rel = abs(m["fs_contact"] - s["fs_contact"]) / s["fs_contact"]
    disp = max(max(abs(a - b) for a, b in zip(s["displacement"][k], m["displacement"][k])) for k in s["displacement"])
    dmax = max(max(abs(a) for a in v) for v in s["displacement"].values())
    print("FS serial %.15g, 3 ranks %.15g (relative difference %.3g); max |displacement| %.3g m, max difference %.3g m; "
          "%d steps" % (s["fs_contact"], m["fs_contact"], fs_rel, dmax, disp, s["iter"]))
    assert sorted(s["displacement"]) == sorted(m["displacement"])
    return fs_rel, disp, dmax


@pytest.fixture(scope="module")
def sorted_runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("landslide_sorted")
    args = ["--time", "0.05", "--engines", "sorted_loop=True"]
    return tmp, _serial(tmp, args), _mpi(tmp, args)


def test_sorted_bit_for_bit(sorted_runs):
    tmp, (s, _), (m, _) = sorted_runs
    fs_rel, disp, dmax = _compare(s, m)
    assert s["iter"] > 1000 and dmax > 1e-3  # the slope has moved
    assert fs_rel <= 1e-12 and disp <= 1e-12
    assert m["settle_ratio"] == pytest.approx(s["settle_ratio"], rel=1e-12)
    # the gravity stage's largest displacement is over every rank's blocks (rank 0, holding none, said 0 m)
    assert s["settle_moved"] > 1e-4 and m["settle_moved"] == pytest.approx(s["settle_moved"], rel=1e-12)
    assert m["dt"] == s["dt"]


def test_rank0_alone_prints_and_writes(sorted_runs):
    tmp, _, (m, out) = sorted_runs
    assert out.count("Factor of safety - all methods") == 1
    # the sync engine's O.dt (the ranks' minimum) is not a script's (RbsmTimeStepper.setDt would go off)
    assert "note: RbsmTimeStepper" not in out
    assert "yade.mpy: 3 ranks; free blocks cut into 2 vertical slices" in out
    times = [l for l in out.splitlines() if l.startswith("yade.mpy: ranks at t =")]
    assert len(times) == 1 and len(set(times[0].split("=")[1].split(" s after")[0].split(","))) == 1, times
    pngs = sorted(f.name for f in (tmp / "mpi").iterdir() if f.suffix == ".png")
    assert pngs == ["landslide_0_before.png", "landslide_1_during.png", "landslide_2_during.png", "landslide_3_after.png"]
    pvd = (tmp / "mpi" / "vtk" / "landslide_blocks.pvd").read_text()
    assert pvd.count("<DataSet") == 4  # t = 0 and after each third of the dynamic stage


def test_unsorted_short_window(tmp_path):
    args = ["--time", "0.003", "--max-settle", "200"]
    (s, _), (m, _) = _serial(tmp_path, args), _mpi(tmp_path, args)
    fs_rel, disp, dmax = _compare(s, m)
    assert dmax > 1e-5
    assert fs_rel <= 1e-8 and disp <= 1e-10
