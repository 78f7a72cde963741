"""Run a yade scene in the qt view under Xvfb and save a snapshot of the view (PNG).

YADE's GUI needs an X display and a terminal (its IPython prompt runs the Qt event loop): the scene
runs as `script -qfc "xvfb-run -a yade-rbsm scene.py" /dev/null`. After the scene script returns, a
thread opens nothing more: it adds a SnapshotEngine (PNG), runs one step, which saves the view, writes
the snapshot's name to <base>.done and ends yade. Pixels are read with PIL.
"""
import os
import shlex
import shutil
import subprocess
import tempfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
BUILD_DIR = os.path.abspath(os.environ.get("RBSM_BUILD_DIR", os.path.join(SOURCE_DIR, "build")))
LAUNCHER = os.path.abspath(os.environ.get("RBSM_LAUNCHER", os.path.join(BUILD_DIR, "yade-rbsm")))

SNAP = """
import os as _os, threading as _th, time as _time, traceback as _tb
from yade import qt as _qt
_qt.View()
def _snapshot():
    try:
        _time.sleep(1.0)  # the view is shown and has drawn once
        O.engines = O.engines + [SnapshotEngine(fileBase=%(base)r, iterPeriod=1, format='PNG', deadTimeout=30, ignoreErrors=False)]
        O.run(1, True)
        result = ' '.join(O.engines[-1].snapshots)
        code = 0
    except BaseException:
        result, code = _tb.format_exc(), 3
    # a file, not print(): yade's prompt holds the terminal while this thread runs
    with open(%(base)r + '.done', 'w') as f:
        f.write(result)
    _os._exit(code)
_th.Thread(target=_snapshot, daemon=True).start()
"""


def have_display_tools():
    return shutil.which("xvfb-run") and shutil.which("script") and shutil.which("xauth")


def snapshot(scene, workdir=None, timeout=120):
    """Runs the scene script text in the qt view; returns (path of the PNG snapshot, output)."""
    if not have_display_tools():
        pytest.skip("no virtual display: xvfb-run, xauth or script missing (scripts/setup.sh installs them)")
    workdir = workdir or tempfile.mkdtemp(prefix="yade-rbsm-gui-")
    base = os.path.join(workdir, "snap")
    path = os.path.join(workdir, "scene.py")
    with open(path, "w") as f:
        f.write(scene + SNAP % {"base": base})
    cmd = "xvfb-run -a -s '-screen 0 1024x768x24' %s %s" % (shlex.quote(LAUNCHER), shlex.quote(path))
    # stdin stays open (a pipe never written) while yade runs: at an end of input its prompt would quit
    log = os.path.join(workdir, "output.txt")
    with open(log, "w") as f:
        p = subprocess.Popen(["script", "-qfec", cmd, "/dev/null"], stdin=subprocess.PIPE, stdout=f, stderr=subprocess.STDOUT, cwd=workdir)
        try:
            p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
        finally:
            p.stdin.close()
    with open(log, errors="replace") as f:
        out = f.read()
    if "Xvfb failed to start" in out or "cannot open display" in out.lower():
        pytest.skip("no virtual display could be made:\n" + out[-2000:])
    done = open(base + ".done").read() if os.path.exists(base + ".done") else ""
    assert p.returncode == 0 and done.endswith(".png"), "yade in the qt view exited with %d and no snapshot\n%s\n%s" % (
        p.returncode, done, out[-6000:])
    return done, out


def load_rgb(png):
    """The snapshot as a numpy array (height, width, 3) of uint8."""
    import numpy as np
    from PIL import Image
    with Image.open(png) as im:
        assert im.format == "PNG", "%s is %s, not PNG" % (png, im.format)
        return np.asarray(im.convert("RGB"))


def mask(img, rgb, tol=40):
    """Pixels within tol (per channel, 0-255) of the colour rgb given in 0..1."""
    import numpy as np
    target = np.array([round(255 * c) for c in rgb], dtype=int)
    return (abs(img.astype(int) - target) <= tol).all(axis=2)


def bbox(m):
    """(x0, y0, x1, y1) of the True pixels, inclusive; None if there are none."""
    import numpy as np
    ys, xs = np.nonzero(m)
    if len(xs) == 0:
        return None
    return int(xs.min()), int(ys.min()), int(xs.max()), int(ys.max())
