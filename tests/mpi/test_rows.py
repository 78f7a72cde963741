"""Issue 18: a block scene under yade.mpy gives the serial run's answer, with one time step for all
ranks (scenes/rows.py: two rows of 40 blocks dropped on a base, 300 steps, joints forming across both
subdomain borders and with the base on rank 0 during the run).

* Every rank integrates with the same O.dt at every step (with engines() defaults the ranks' time
  steppers used to set their own: t = 0.0300 / 0.0811 / 0.0805 s after 300 steps).
* Positions after mergeScene equal the serial run's within 1e-10 m, started by mpiexec and by
  mpy.initialize(3) from a plain run. With InteractionLoop.loopOnSortedInteractions every block's
  joint forces are summed in the same order as serially, and the runs agree bit for bit, time steps
  included; without it the sums differ by round-off, which this violent scene amplifies to
  millimetres (-j2 against -j1 serially does the same), so the unsorted comparison uses a calm
  variant of the scene (slow blocks, no spin, contact damping 0.3).
* The same with the subdomains cut by YADE's own recursive bisection (mpy.DOMAIN_DECOMPOSITION);
  yade_rbsm.mpi.decompose_by_x is the landslide test's (scenes/rows.py has it too).
* A merged scene continues serially on rank 0 (yade_rbsm.mpi.to_serial) as the serial run does: bit
  for bit with sorted loops and a full time-step estimate at every step (interval=1; with the default
  100 the serial run's estimates fall on other steps than the merged scene's first one).
* RbsmTimeStepper's collider requests (Scene.doSort, when a rotating block's corner may leave its
  Verlet box) reach yade.mpy: the steps that request it are the serial run's (with the collider's
  fixed Verlet sweep that yade.mpy sets), and after each of them yade.mpy's collider ran on every
  rank. (The stepper used to take the boxes that yade.mpy makes at the end of a step for boxes made
  unseen and asked for a collider run at every step after the first one: 245 of 300 steps here.)
"""
import json
import os
import tempfile

import pytest

from conftest import run_mpi, run_scene, run_spawn, scene

SORTED = {"sorted": True, "interval": 1}  # (interval=1: also the serial continuation of a merged scene is bitwise)
CALM = {"vx": 0.05, "vy": 0.05, "w": 0.0, "cd": 0.3}


def _mpi(params, spawn=False):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "result.json")
        args = [json.dumps(dict(params, mode="spawn" if spawn else "mpi", out=out))]
        r = run_spawn(scene("rows"), args) if spawn else run_mpi(scene("rows"), args)
        assert not r.timed_out and r.returncode == 0 and os.path.exists(out), r.tail()
        with open(out) as f:
            return json.load(f)


@pytest.fixture(scope="module")
def serial_sorted():
    return run_scene("rows", dict(SORTED, mode="serial", mpy_collider=True))


@pytest.fixture(scope="module")
def mpi_sorted():
    return _mpi(SORTED)


@pytest.fixture(scope="module")
def mpi_default():
    return _mpi({})


def _max_diff(a, b):
    assert sorted(a["pos"]) == sorted(b["pos"])
    return max(max(abs(x - y) for x, y in zip(a["pos"][k], b["pos"][k])) for k in a["pos"])


def test_one_time_step_for_all_ranks(mpi_default):
    ranks = mpi_default["ranks"]
    print("rank times", [r["time"] for r in ranks], "final dt", [r["dt"] for r in ranks])
    assert len(ranks) == 3
    assert all(r["iter"] == 300 and len(r["dts"]) == 300 for r in ranks)
    for r in ranks[1:]:
        assert r["dts"] == ranks[0]["dts"], "the ranks integrated with different time steps"
        assert r["time"] == ranks[0]["time"]
    assert min(ranks[0]["dts"]) > 0 and max(ranks[0]["dts"]) > 1.0001 * min(ranks[0]["dts"])  # the stepper did set it


def test_positions_equal_serial_mpiexec(serial_sorted, mpi_sorted):
    d = _max_diff(serial_sorted, mpi_sorted)
    print("max |position difference| serial vs 3 ranks (mpiexec): %.3g m; joints %d, %d across ranks"
          % (d, mpi_sorted["joints"], mpi_sorted["across"]))
    assert serial_sorted["joints0"] == 0 and mpi_sorted["joints0"] == 0  # every joint formed during the run
    assert mpi_sorted["across"] >= 40  # with the base on rank 0, and the two row borders
    assert mpi_sorted["joints"] == serial_sorted["joints"]
    assert d <= 1e-10
    for r in mpi_sorted["ranks"]:
        assert r["dts"] == serial_sorted["ranks"][0]["dts"]


def test_positions_equal_serial_spawned(serial_sorted):
    spawned = _mpi(SORTED, spawn=True)
    d = _max_diff(serial_sorted, spawned)
    print("max |position difference| serial vs 3 ranks (mpy.initialize(3)): %.3g m" % d)
    assert d <= 1e-10
    assert [r["time"] for r in spawned["ranks"]] == [serial_sorted["ranks"][0]["time"]] * 3


@pytest.mark.parametrize("decomposition", ["bisection"])  # (by_x: test_landslide.py)
def test_positions_equal_serial_other_decompositions(serial_sorted, decomposition):
    dist = _mpi(dict(SORTED, decomposition=decomposition))
    d = _max_diff(serial_sorted, dist)
    print("decomposition %s: max |position difference| %.3g m, %d joints across ranks" % (decomposition, d, dist["across"]))
    assert dist["across"] >= 10
    assert d <= 1e-10


def test_merged_scene_continues_serially(serial_sorted):
    dist = _mpi(dict(SORTED, serial_after=150))
    d = _max_diff(serial_sorted, dist)
    print("150 steps on 3 ranks, merged, 150 more on rank 0 alone: max |position difference| %.3g m" % d)
    assert d <= 1e-10


def test_positions_equal_serial_unsorted_calm():
    serial = run_scene("rows", dict(CALM, mode="serial"))
    dist = _mpi(CALM)
    d = _max_diff(serial, dist)
    print("calm scene, joint forces in container order: max |position difference| %.3g m, joints %d (%d across)"
          % (d, dist["joints"], dist["across"]))
    assert dist["across"] >= 40 and dist["joints"] == serial["joints"]
    assert d <= 1e-10


def test_collider_requests_reach_mpy(serial_sorted, mpi_sorted):
    requested = sorted(set().union(*(r["sorts"] for r in mpi_sorted["ranks"])))
    print("steps where RbsmTimeStepper asked for the collider: serial %s, 3 ranks %s"
          % (serial_sorted["ranks"][0]["sorts"], requested))
    assert requested, "the scene should make the stepper ask for a collider run (rotating blocks)"
    assert requested == serial_sorted["ranks"][0]["sorts"]
    assert len(requested) < 60  # (before the fix: a request at every step after the first collide, 245 of 300)
    for r in mpi_sorted["ranks"]:
        missed = [s for s in requested if s not in r["collides"]]
        assert not missed, "yade.mpy's collider did not run after steps %s on a rank" % missed


def test_deformable_blocks_equal_serial():
    """Deformable blocks (issue 38) under yade.mpy give the serial run (sorted loops: to 1e-10 m and 1e-12 in
    strain). A joint across a border reads the strain of the neighbour's copy, which yade.mpy sends with the body.
    Hung on 09b6867 (the workers could not load a scene of DeformableState and yade.mpy's plain States:
    "unregistered class", pkg/rbsm/exports.map)."""
    params = dict(SORTED, deformable=True, steps=600, gap=2e-5)  # (their step is 1e-6 s: gaps of 20 um, to join in the run)
    serial = run_scene("rows", dict(params, mode="serial", mpy_collider=True))
    dist = _mpi(params)
    d = _max_diff(serial, dist)
    ds = max(max(abs(x - y) for x, y in zip(serial["strain"][k], dist["strain"][k])) for k in serial["strain"])
    print("deformable rows: max |position difference| %.3g m, |strain difference| %.3g; %d joints across ranks"
          % (d, ds, dist["across"]))
    assert dist["across"] >= 40
    assert max(abs(x) for s in serial["strain"].values() for x in s) > 1e-6  # the blocks did strain
    assert d <= 1e-10 and ds <= 1e-12
