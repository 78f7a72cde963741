"""Run a yade scene in the qt view under Xvfb and save a snapshot of the view (PNG).

YADE's GUI needs an X display and a terminal (its IPython prompt runs the Qt event loop): the scene
runs through scripts/run_in_qt_view.py (its own Xvfb, yade in a pty); yade_rbsm.gui.save_view_and_exit
saves the view (SnapshotEngine, PNG) once the script has returned, writes the file's name to
<png>.done and ends yade. Pixels are read with PIL.
"""
import os
import sys
import tempfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
BUILD_DIR = os.path.abspath(os.environ.get("RBSM_BUILD_DIR", os.path.join(SOURCE_DIR, "build")))
LAUNCHER = os.path.abspath(os.environ.get("RBSM_LAUNCHER", os.path.join(BUILD_DIR, "yade-rbsm")))
sys.path.insert(0, os.path.join(SOURCE_DIR, "scripts"))
import run_in_qt_view  # noqa: E402  (scripts/run_in_qt_view.py: own Xvfb, a pty for yade's prompt)

SNAP = """
from yade_rbsm import gui as _gui
_gui.view(joints=None, geometry=None)  # the scene sets the renderer's options itself
_gui.save_view_and_exit(%(png)r, status_file=%(png)r + '.done')
"""


def snapshot(scene, workdir=None, timeout=120):
    """Runs the scene script text in the qt view; returns (path of the PNG snapshot, output)."""
    workdir = workdir or tempfile.mkdtemp(prefix="yade-rbsm-gui-")
    png = os.path.join(workdir, "snap.png")
    path = os.path.join(workdir, "scene.py")
    with open(path, "w") as f:
        f.write(scene + SNAP % {"png": png})
    code, out = run_in_qt_view.run([path], launcher=LAUNCHER, size="1024x768", timeout=timeout, cwd=workdir)
    if code == run_in_qt_view.NO_DISPLAY:
        pytest.skip("no virtual display could be made: " + out[-2000:])
    done = open(png + ".done").read() if os.path.exists(png + ".done") else ""
    assert code == 0 and done == png, "yade in the qt view exited with %d and no snapshot\n%s\n%s" % (code, done, out[-6000:])
    return png, out


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
