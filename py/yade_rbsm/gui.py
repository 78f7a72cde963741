"""The qt view of an RBSM scene: open it, and save a snapshot of it from a script.

YADE's qt view draws the blocks (Gl1_Polygon2D, in each shape's colour) and, with the renderer's
``intrPhys``, the joints coloured by state (Gl1_RbsmPhys). The GUI runs only while yade's prompt
runs (its Qt loop): a script that wants a picture and then to end, e.g. under Xvfb::

    script -qfc "xvfb-run -a build/yade-rbsm myscene.py" /dev/null     # myscene.py ends with:
    from yade_rbsm import gui
    gui.view(joints=True)
    gui.save_view_and_exit("scene.png")

(``script`` gives yade the terminal its prompt needs; without ``-x``, so that the prompt starts.)
"""
import os
import threading
import time
import traceback

from yade import O, wrapper


def view(joints=True, geometry=False, size=None):
    """Opens the qt view (yade.qt.View) with the joints drawn by state (renderer's intrPhys) and
    optionally their geometry (intrGeom: contact segment and normal); None leaves the renderer's
    setting as it is. *size*: (width, height) of the view in pixels (the scene is centred in it).
    Returns the view."""
    from yade import qt
    r = qt.Renderer()
    if joints is not None:
        r.intrPhys = bool(joints)
    if geometry is not None:
        r.intrGeom = bool(geometry)
    v = qt.View()
    if size is not None:
        v.screenSize = tuple(int(n) for n in size)
        v.center()
    return v


def color_blocks(field="plasticShear", vmax=None, cmap="magma", O=O):
    """Colours every free Polygon2D block in the qt view by *field* ("plasticShear": the band of plastic
    deformable blocks; "displacement" since refPos), through matplotlib's *cmap* from 0 to *vmax* (default the
    largest value); fixed blocks keep their colour. Returns vmax. To follow a run, a PyRunner:
    ``PyRunner(command="import yade_rbsm.gui; yade_rbsm.gui.color_blocks()", iterPeriod=200)``."""
    from matplotlib import colormaps
    from . import omega
    from .snapshots import block_values
    values = block_values(field, O)
    free = {i: v for i, v in values.items() if not omega.is_fixed(O.bodies[i])}
    top = vmax if vmax is not None else max(max(free.values(), default=0.0), 1e-12)
    colors = colormaps[cmap]
    for i, v in free.items():
        r, g, b, _ = colors(min(1.0, max(0.0, v / top)))
        O.bodies[i].shape.color = (r, g, b)
    return top


def _compress(png):
    """Qt writes uncompressed PNGs (2 MB for 1100 x 600); PIL, if there, makes them ~100 times smaller."""
    try:
        from PIL import Image
    except ImportError:
        return
    with Image.open(png) as im:
        im = im.convert("RGB")
    im.save(png, optimize=True)


def save_view_and_exit(path, delay=1.0, timeout=30, status_file=None):
    """After the script returns (the view then draws), saves the view as a PNG at *path* and ends
    yade. Works in a thread: it waits *delay* s, adds a SnapshotEngine (format PNG) to O.engines and
    runs one step, which saves the next frame; YADE's snapshots are taken by an engine. Writes the
    path (or the error) to *status_file* if given, and exits with 0 (saved) or 3."""
    path = os.path.abspath(path)
    # checked now: a snapshot that cannot be written makes the view open a modal error box and hang
    if not (os.path.isdir(os.path.dirname(path)) and os.access(os.path.dirname(path), os.W_OK)):
        raise ValueError("save_view_and_exit: cannot write %s (no such directory, or not writable)" % path)
    base = os.path.splitext(path)[0] + ".snapshot-"

    def work():
        try:
            time.sleep(delay)
            for attempt in (1, 2):  # once seen under heavy load: a first snapshot that never came
                eng = wrapper.SnapshotEngine(fileBase=base, iterPeriod=1, initRun=True, format="PNG", deadTimeout=timeout,
                                             ignoreErrors=attempt == 1)
                O.engines = O.engines + [eng]
                O.run(1, True)
                O.engines = O.engines[:-1]
                if eng.snapshots:
                    break
            if not eng.snapshots:
                raise RuntimeError("SnapshotEngine saved nothing (no view?)")
            os.replace(eng.snapshots[-1], path)
            _compress(path)
            result, code = path, 0
        except BaseException:
            result, code = traceback.format_exc(), 3
        # straight to the file descriptors: yade's prompt holds Python's stdout while this thread runs
        if code:
            os.write(2, ("yade_rbsm.gui.save_view_and_exit: no snapshot saved\n" + result).encode())
        if status_file:
            with open(status_file, "w") as f:
                f.write(result)
        os._exit(code)

    threading.Thread(target=work, daemon=True).start()
