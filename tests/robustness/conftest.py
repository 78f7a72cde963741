"""Helpers for the robustness tests: run a scene of scenes/ through the YADE launcher (as
tests/physics/conftest.py does) and parse the one JSON line it prints after the marker RBSM_RESULT.
RBSM_LONG=1 in the environment selects the long variants of the tests (see each file)."""
import json
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "scenes")
MARKER = "RBSM_RESULT "
LONG = os.environ.get("RBSM_LONG", "") not in ("", "0")


def launcher():
    exe = os.environ.get("RBSM_LAUNCHER")
    if not exe:
        build = os.environ.get("RBSM_BUILD_DIR", os.path.join(HERE, "..", "..", "build"))
        exe = os.path.join(build, "yade-rbsm")
    if not os.access(exe, os.X_OK):
        pytest.fail("launcher %s not found (build the project, or set RBSM_LAUNCHER)" % exe)
    return exe


def run_scene(scene, params=None, threads=1, timeout=600, output=False, cwd=None):
    """Runs scenes/<scene>.py with `yade -j threads -n -x scene.py '<params as JSON>'` and returns the
    dict the scene printed (one line 'RBSM_RESULT {...}'); with output=True also the whole output
    (stdout and stderr), where YADE's warnings appear."""
    cmd = [launcher(), "-j", str(threads), "-n", "-x", os.path.join(SCENES, scene + ".py"),
           json.dumps(params or {})]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                       universal_newlines=True, cwd=cwd or SCENES)
    lines = [l for l in p.stdout.splitlines() if l.startswith(MARKER)]
    if p.returncode != 0 or len(lines) != 1:
        pytest.fail("scene %s %r failed (exit %d):\n%s" % (scene, params, p.returncode, p.stdout[-4000:]))
    r = json.loads(lines[0][len(MARKER):])
    return (r, p.stdout) if output else r


def rect(x0, y0, w, h):
    return [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]]
