"""Running test scenes through the YADE launcher, shared by tests/physics, tests/mixed and
tests/robustness (their conftest.py: `scene_helpers(__file__)`; their test_bad_input.py:
`bad_input_tests(...)`).

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


def scene_helpers(conftest_file):
    """What the conftest.py of a test directory with a scenes/ folder provides:
    ``(SCENES, launcher, run_scene, scene)``: the folder, :func:`launcher`, :func:`run_scene` bound to
    the folder, and a pytest fixture ``scene`` returning that run_scene."""
    import functools

    import pytest

    scenes = os.path.join(os.path.dirname(os.path.abspath(conftest_file)), "scenes")
    run = functools.partial(run_scene, scenes)

    @pytest.fixture
    def scene():
        return run

    return scenes, launcher, run, scene


def bad_input_tests(run, keywords, exceptions, unchanged):
    """The two pieces of a test_bad_input.py over the scene scenes/badinput.py, which tries every
    case and returns ``{case: {"exc": [type, message] or None, ...}}``: a module fixture ``results``
    (the scene run once) and the test ``test_bad_input_rejected_scene_unchanged``, parametrized by
    case, asserting an exception of a type in *exceptions* whose message contains one of
    ``keywords[case]`` (lower case), then ``unchanged(result)`` (the scene is as before)."""
    import pytest

    @pytest.fixture(scope="module")
    def results():
        return run("badinput", {})

    @pytest.mark.parametrize("case", sorted(keywords))
    def test_bad_input_rejected_scene_unchanged(results, case):
        r = results[case]
        print(case, r)
        assert r["exc"] is not None, "accepted without an exception"
        typ, msg = r["exc"]
        assert typ in exceptions
        assert any(k in msg.lower() for k in keywords[case]), msg
        unchanged(r)

    return results, test_bad_input_rejected_scene_unchanged
