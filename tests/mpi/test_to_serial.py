"""After merge() and to_serial(), rank 0 goes on alone as a serial scene (README, yade.mpy): a stage run
there (settle, which goes through yade_rbsm.mpi.run) runs serially (scenes/to_serial.py, 3 ranks). Before:
it called yade.mpy's mpirun on rank 0 alone and waited for the workers forever (here: the timeout).
strength_reduction on the split scene is refused on every rank."""
from conftest import run_mpi, scene


def test_settle_on_rank0_after_to_serial():
    r = run_mpi(scene("to_serial"), timeout=120)
    assert not r.timed_out, "rank 0 waited for the workers after to_serial\n" + r.tail()
    assert r.returncode == 0, r.tail()
    by_rank = {x["rank"]: x for x in r.results}
    assert sorted(by_rank) == [0, 1, 2], r.tail()
    assert by_rank[0]["second"][0] is True and by_rank[0]["second"][2] < 1e-4, by_rank[0]


def test_strength_reduction_of_a_split_scene_is_refused_on_every_rank():
    """Before: O.loadTmp failed on the workers ("shared materials not preserved") and rank 0 waited for them."""
    r = run_mpi(scene("to_serial"), timeout=120)
    assert not r.timed_out and r.returncode == 0, r.tail()
    assert sorted(x["rank"] for x in r.results) == [0, 1, 2], r.tail()
    assert all("to_serial" in x["sr_refused"] for x in r.results), r.results
