"""Running test scenes through the YADE launcher, shared by tests/physics and tests/robustness.

A scene is a yade script scenes/<name>.py of the test directory. It receives its parameters as one
JSON object in argv[1] (`params()`) and prints its result as one JSON line after the marker
RBSM_RESULT (`emit()`); the test side (`run_scene`) runs it with
`yade-rbsm -j N -n -x scene.py '<json>'` and returns the decoded result, failing the test with the
scene's output when it exits non-zero or prints no result.
"""
import json
import os
import subprocess
import sys

MARKER = "RBSM_RESULT "
HERE = os.path.dirname(os.path.abspath(__file__))


# ---- inside a scene (a yade script) -------------------------------------------------------------
def params():
    """The scene's parameters: one JSON object in argv[1] (may be absent)."""
    return json.loads(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1] else {}


def emit(result):
    """Prints the result as one JSON line after the marker and flushes."""
    sys.stdout.write(MARKER + json.dumps(result) + "\n")
    sys.stdout.flush()


# ---- on the test side (pytest) ------------------------------------------------------------------
def launcher():
    """The build's yade-rbsm: $RBSM_LAUNCHER (set by ctest), else $RBSM_BUILD_DIR or build/."""
    import pytest

    exe = os.environ.get("RBSM_LAUNCHER")
    if not exe:
        build = os.environ.get("RBSM_BUILD_DIR", os.path.join(HERE, "..", "..", "build"))
        exe = os.path.join(build, "yade-rbsm")
    if not os.access(exe, os.X_OK):
        pytest.fail("launcher %s not found (build the project, or set RBSM_LAUNCHER)" % exe)
    return exe


def run_scene(scenes_dir, scene, params=None, threads=1, timeout=600, output=False, cwd=None):
    """Runs <scenes_dir>/<scene>.py and returns the dict it emitted; with output=True also the
    whole output (stdout and stderr, where YADE's and the plugin's warnings appear)."""
    import pytest

    cmd = [launcher(), "-j", str(threads), "-n", "-x", os.path.join(scenes_dir, scene + ".py"), json.dumps(params or {})]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                       universal_newlines=True, cwd=cwd or scenes_dir)
    lines = [l for l in p.stdout.splitlines() if l.startswith(MARKER)]
    if p.returncode != 0 or len(lines) != 1:
        pytest.fail("scene %s %r failed (exit %d):\n%s" % (scene, params, p.returncode, p.stdout[-4000:]))
    r = json.loads(lines[0][len(MARKER):])
    return (r, p.stdout) if output else r
