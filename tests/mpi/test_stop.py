"""Issue 18: a run that the plugin stops on one rank stops on every rank, within seconds, with the
message printed by the rank that found it (scenes/stop.py, 3 ranks, plain mpy.mpirun).

Before, the rank that stopped went on with the script while the others waited for it in their next
exchange: a deadlock until killed (here: the 60 s timeout).
* mixed plane states (Ip2 stops the run after the step, on rank 2): every rank stops after the same
  step as the serial run, the error printed once;
* a block moving too far in one step (RbsmTimeStepper stops the run after the step, on rank 1): same;
* a step refused by RbsmTimeStepper (O.dt above the stable step of rank 2's stiff blocks only): every
  rank raises before anything moves, rank 2 with the stepper's message, ranks 0 and 1 naming rank 2;
* an error the plugin cannot know about (a user's PyRunner raising on rank 1 only):
  yade_rbsm.mpi.mpirun ends the MPI job (MPI_Abort) instead of leaving ranks 0 and 2 waiting.
"""
import json

import pytest

from conftest import run_mpi, run_scene, run_spawn, scene

TIMEOUT = 60  # a deadlock shows as this timeout; a clean stop takes a few seconds


def _mpi(params, spawn=False, timeout=TIMEOUT):
    args = [json.dumps(dict(params, mode="spawn" if spawn else "mpi"))]
    r = run_spawn(scene("stop"), args, timeout=timeout) if spawn else run_mpi(scene("stop"), args, timeout=timeout)
    print("%s %s: exit %s, %.1f s wall%s" % ("spawned" if spawn else "mpiexec", params, r.returncode, r.wall,
                                             ", TIMED OUT" if r.timed_out else ""))
    assert not r.timed_out, "deadlock: the ranks did not all stop within %d s\n%s" % (timeout, r.tail())
    return r


@pytest.mark.parametrize("case,message", [
    ("mixed", "mix plane strain and plane stress materials"),
    ("throw", "moves by"),
])
def test_stop_after_step_on_every_rank(case, message):
    serial = run_scene("stop", {"mode": "serial", "case": case}, output=True)
    s, out_s = serial
    assert s["exc"] is None and 0 < s["iter"] < 100 and message in out_s  # the serial behaviour
    r = _mpi({"case": case})
    assert r.returncode == 0, r.tail()
    ranks = sorted(x["rank"] for x in r.results)
    assert ranks == [0, 1, 2], r.tail()
    for x in r.results:
        assert x["exc"] is None
        assert x["iter"] == s["iter"], "rank %d stopped after step %d, the serial run after %d" % (x["rank"], x["iter"], s["iter"])
        assert x["time"] == pytest.approx(s["time"], rel=1e-9)
        assert x["wall"] < 15
    assert r.output.count(message) == 1, "the error should be printed once, by the rank that found it\n" + r.tail()


def test_stop_raises_on_every_rank_through_yade_rbsm_mpirun():
    """yade_rbsm.mpi.mpirun (what run(), settle() and strength_reduction() use) raises RuntimeError on every
    rank when the plugin stops the run, as advance() does serially (a new user's trial: it returned
    normally after the one step, and settle() went on chunk after chunk, counting steps it never ran)."""
    s = run_scene("stop", {"mode": "serial", "case": "throw"})
    r = _mpi({"case": "throw", "runner": "rbsm"})
    assert r.returncode == 0, r.tail()
    assert sorted(x["rank"] for x in r.results) == [0, 1, 2], r.tail()
    for x in r.results:
        assert x["iter"] == s["iter"] and x["exc"] and "stopped at step %d" % s["iter"] in x["exc"], x


def test_refused_step_raises_on_every_rank():
    """Through yade_rbsm.mpi.mpirun (serially advance): a refusal raised in the run's first step can be lost by
    the O.run(n, True) under yade.mpy's mpirun (YADE's O.wait() returns without it when the run already ended:
    ~2 % under load, test_timestep_scenes); the wrapper raises the refusal the sync recorded."""
    s = run_scene("stop", {"mode": "serial", "case": "refuse"})
    assert s["iter"] == 0 and "exceeds the stable limit" in s["exc"]
    r = _mpi({"case": "refuse", "runner": "rbsm"})
    assert r.returncode == 0, r.tail()
    by_rank = {x["rank"]: x for x in r.results}
    assert sorted(by_rank) == [0, 1, 2], r.tail()
    assert all(x["iter"] == 0 and x["time"] == 0 and x["exc"] for x in by_rank.values())  # nothing moved
    assert "exceeds the stable limit" in by_rank[2]["exc"] and "refused on rank" not in by_rank[2]["exc"]
    for k in (0, 1):
        assert "the step was refused on rank 2; every rank stops" in by_rank[k]["exc"]
        assert "exceeds the stable limit" in by_rank[k]["exc"]
    assert all(x["wall"] < 15 for x in by_rank.values())


def test_unknown_error_on_one_rank_aborts_the_job():
    s = run_scene("stop", {"mode": "serial", "case": "user"})
    assert s["iter"] == 20 and "a user error on one rank" in s["exc"]
    r = _mpi({"case": "user", "runner": "rbsm"})
    assert r.returncode != 0
    assert "rank 1: an error ended the run on this rank only; aborting the MPI job" in r.output, r.tail()
    assert "a user error on one rank" in r.output
    assert r.wall < 30


def test_error_on_one_rank_before_the_run_aborts_the_job():
    """Issue 34, item 1: a value refused on one rank before the run (a ValueError in the script on rank 1 only)
    left the other ranks waiting for ever in the run's first exchange (rank 1 waited in MPI_Finalize): killed
    at the timeout. Now the job ends at once, exit status 1, naming the rank."""
    r = _mpi({"case": "before", "runner": "rbsm"}, timeout=TIMEOUT)
    assert r.returncode != 0
    assert "RbsmTimeStepper.safetyFactor" in r.output
    assert "rank 1: the script ended with an error; aborting the MPI job" in r.output, r.tail()
    assert r.wall < 30


def test_a_distributed_run_without_the_sync_engine_is_refused():
    """Issue 34, item 2: engines() built before yade.mpy was imported (no sync engine) and YADE's own
    mpy.mpirun drifted silently (each rank its own O.dt: master at t = 3e-6 s against 0.146 s serially). Now
    every rank's RbsmTimeStepper refuses the first step, naming the fix, and the job ends."""
    r = _mpi({"case": "nosync"}, timeout=TIMEOUT)
    assert r.returncode != 0, r.tail()
    assert "without yade_rbsm's sync engine" in r.output and "engines(mpi=True)" in r.output, r.tail()
    assert r.wall < 30



def test_a_distributed_run_with_the_sync_engine_taken_out_or_misplaced_is_refused():
    """Issue 34's closing pass: with the sync engine of engines(mpi=True) taken out, or placed before
    RbsmTimeStepper or after NewtonIntegrator, YADE's mpy.mpirun drifted silently (ranks ending at O.time 0.0003,
    0.039 and 0.048 s; or one rank integrating at 8-11 times the others' step). Each is now refused on every rank
    with what is wrong and the fix, and the job ends."""
    for case, said in (("sync_removed", "sync engine did not run"), ("sync_first", "after RbsmTimeStepper"),
                       ("sync_last", "before NewtonIntegrator")):
        r = _mpi({"case": case}, timeout=TIMEOUT)
        print(case, r.returncode, [l for l in r.output.splitlines() if "sync" in l][:3])
        assert r.returncode != 0, (case, r.tail())
        assert said in r.output and "engines(mpi=True)" in r.output, (case, r.tail())
        assert r.wall < 30
