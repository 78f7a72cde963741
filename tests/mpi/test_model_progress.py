"""Issue 37: "a progress bar on every long stage, also under yade.mpy from rank 0". Serially the Monitor's
PyRunner prints it; under yade.mpy SlopeModel.run ran without one (the example's 7 silent minutes): rank 0 now
prints it between its runs, by the stage's simulated time, never above 100 %, and the workers print none
(scenes/model_progress.py, 3 ranks; progress=0: a line after every run). On 3092515 no line at all."""
import re

from conftest import run_mpi, scene


def test_progress_of_a_distributed_dynamic_stage():
    r = run_mpi(scene("model_progress"), timeout=180)
    assert not r.timed_out and r.returncode == 0, r.tail()
    shown = [eval(m.group(1)) for m in re.finditer(r"^RESULT (\[.*\])$", r.output, re.M)]
    workers = [int(m.group(1)) for m in re.finditer(r"RESULT-WORKER \d+ (\d+)", r.output)]
    assert len(shown) == 1 and workers == [0, 0], r.tail()
    (pct,) = shown
    assert len(pct) >= 2 and pct == sorted(pct) and pct[-1] <= 100 and pct[-1] >= 90, pct
