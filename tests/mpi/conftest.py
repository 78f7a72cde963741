"""Helpers for the yade.mpy tests: a scene of scenes/ run serially (tests/support/yadescene.py), on
3 ranks by mpiexec, or from a plain run that spawns its ranks (mpy.initialize).

A scene prints one JSON line after the marker RBSM_RESULT per rank that reaches its end (or one,
gathered on rank 0, as the scene says); run_mpi returns them all, with the exit status, the whole
output and the wall time. A run that outlives its timeout (a deadlock) is ended: SIGTERM to mpiexec
(which ends its ranks), then SIGKILL to the process group, and reported as timed out.
"""
import functools
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "scenes")
SRC = os.environ.get("RBSM_SOURCE_DIR", os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
import yadescene as _scenes  # noqa: E402

MARKER = _scenes.MARKER
launcher = _scenes.launcher
run_scene = functools.partial(_scenes.run_scene, SCENES)


def mpi_env():
    """The environment of an MPI run: Open MPI refuses root unless told (CI runs as root), and
    yields the CPU while it waits (3 ranks on 2 cores would otherwise spin against each other)."""
    env = dict(os.environ)
    if os.geteuid() == 0:
        env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
        env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


class Run:
    def __init__(self, returncode, output, results, wall, timed_out):
        self.returncode, self.output, self.results, self.wall, self.timed_out = returncode, output, results, wall, timed_out

    def tail(self, n=4000):
        return self.output[-n:]


def _run(cmd, timeout, cwd):
    t0 = time.time()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
                         cwd=cwd, env=mpi_env(), start_new_session=True)
    timed_out = False
    try:
        out, _ = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        p.send_signal(signal.SIGTERM)  # mpiexec forwards it to its ranks
        try:
            out, _ = p.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            out, _ = p.communicate()
    wall = time.time() - t0
    results = [json.loads(l[l.index(MARKER) + len(MARKER):]) for l in out.splitlines() if MARKER in l]
    return Run(p.returncode, out, results, wall, timed_out)


def mpiexec():
    exe = shutil.which("mpiexec")
    if not exe:
        pytest.fail("mpiexec not found: install openmpi-bin and python3-mpi4py (scripts/setup.sh)")
    return exe


def run_mpi(script, args=(), n=3, timeout=120, cwd=None):
    """`mpiexec -n <n> --oversubscribe yade-rbsm -n -x <script> <args>`: every rank runs the script."""
    cmd = [mpiexec(), "-n", str(n), "--oversubscribe", launcher(), "-n", "-x", script] + list(args)
    return _run(cmd, timeout, cwd or SCENES)


def run_spawn(script, args=(), timeout=120, cwd=None):
    """`yade-rbsm -n -x <script> <args>` for a script that calls mpy.initialize(n) (spawns the workers)."""
    mpiexec()  # the spawn needs Open MPI's runtime too
    cmd = [launcher(), "-n", "-x", script] + list(args)
    return _run(cmd, timeout, cwd or SCENES)


def scene(name):
    return os.path.join(SCENES, name + ".py")
