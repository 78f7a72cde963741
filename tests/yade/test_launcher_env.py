"""build/yade-rbsm sets OMP_WAIT_POLICY=PASSIVE unless the user chose a wait policy (issue 22).

With libgomp's default, a -j2 thread spins at every barrier while its partner waits for a core another job
holds: on this 2-core machine with other work running, a 1600-block wall took 20 ms per step at -j2 against
1.2 ms at -j1, and 1.7 ms with PASSIVE (scripts/benchmarks/threads_under_load.py). The user's own
OMP_WAIT_POLICY or GOMP_SPINCOUNT is kept.
"""
import os

import pytest

from yaderun import run_ok

SCRIPT = """
import os
report(policy=os.environ.get("OMP_WAIT_POLICY"), spin=os.environ.get("GOMP_SPINCOUNT"))
"""


@pytest.mark.parametrize("given, policy", [({}, "PASSIVE"), ({"OMP_WAIT_POLICY": "ACTIVE"}, "ACTIVE"),
                                           ({"GOMP_SPINCOUNT": "300000"}, None)])
def test_wait_policy(given, policy, monkeypatch):
    for k in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT"):
        monkeypatch.delenv(k, raising=False)
    (r,) = run_ok(SCRIPT, env=given, jobs=2)
    assert r["policy"] == policy
    assert r["spin"] == given.get("GOMP_SPINCOUNT")
