"""Run a YADE script through the launcher build/yade-rbsm and collect what it reports.

A test script prints result lines ``RESULT <json>``; run_ok() returns them (decoded) and fails the
test with the whole output when yade exits non-zero (an assert or exception inside the script).
"""
import json
import os
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
BUILD_DIR = os.path.abspath(os.environ.get("RBSM_BUILD_DIR", os.path.join(SOURCE_DIR, "build")))
LAUNCHER = os.path.abspath(os.environ.get("RBSM_LAUNCHER", os.path.join(BUILD_DIR, "yade-rbsm")))

# A free 1 m block resting on a fixed 10 m base of one RbsmMat (young 1e8, density 2000, frictionAngle FRICTION),
# O.engines = engines(): the scene several scripts start from; `%`-format it with FRICTION (radians).
BLOCK_ON_BASE = """
from yade_rbsm import polygon2d, engines
rock = RbsmMat(young=1e8, density=2000, frictionAngle=%(FRICTION)g)
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], rock))
O.engines = engines()
"""

PRELUDE = """
import json as _json
def report(**kw):
    print("RESULT " + _json.dumps(kw), flush=True)
"""


def run_yade(script, jobs=None, env=None, timeout=300, workdir=None):
    """Runs `yade-rbsm -n -x [-j N] script` (script: the text of a yade script) in workdir."""
    if not os.access(LAUNCHER, os.X_OK):
        raise RuntimeError("launcher %s not found: build the project first (cmake --build %s)" % (LAUNCHER, BUILD_DIR))
    workdir = workdir or tempfile.mkdtemp(prefix="yade-rbsm-test-")
    path = os.path.join(workdir, "script.py")
    with open(path, "w") as f:
        f.write(PRELUDE + script)
    cmd = [LAUNCHER, "-n", "-x"] + (["-j", str(jobs)] if jobs else []) + [path]
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=full_env, cwd=workdir)


def results(proc):
    return [json.loads(l[len("RESULT "):]) for l in proc.stdout.splitlines() if l.startswith("RESULT ")]


def run_ok(script, **kw):
    """Runs the script, asserts a zero exit code, returns the list of reported dicts."""
    p = run_yade(script, **kw)
    assert p.returncode == 0, "yade exited with %d\n--- stdout ---\n%s\n--- stderr ---\n%s" % (p.returncode, p.stdout[-6000:], p.stderr[-6000:])
    return results(p)
