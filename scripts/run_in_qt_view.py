#!/usr/bin/python3
"""Runs a yade script with the qt view on a virtual display (Xvfb) and waits until yade ends.

    /usr/bin/python3 scripts/run_in_qt_view.py [--size 1280x1024] [--timeout 300] script.py [script args]

YADE's GUI needs an X display and a terminal: its IPython prompt runs the Qt event loop, and at an
end of input it would quit. This starts its own Xvfb (unless --display is given), runs
`build/yade-rbsm script.py` in a pseudo-terminal (util-linux `script`) whose input stays open, and
stops Xvfb afterwards. The script must end yade itself, e.g. with yade_rbsm.gui.save_view_and_exit.
Exit code: yade's; 77 if no virtual display could be made (Xvfb missing or failing to start).
"""
import argparse
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_LAUNCHER = os.path.join(HERE, "..", "build", "yade-rbsm")
NO_DISPLAY = 77


def start_xvfb(size):
    """(process, ':N') of a new Xvfb on a free display, or (None, reason)."""
    if not shutil.which("Xvfb"):
        return None, "Xvfb is not installed (apt-get install xvfb; scripts/setup.sh)"
    r, w = os.pipe()
    p = subprocess.Popen(["Xvfb", "-displayfd", str(w), "-screen", "0", size + "x24", "-nolisten", "tcp"],
                         pass_fds=(w,), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.close(w)
    with os.fdopen(r) as f:
        number = f.readline().strip()  # Xvfb writes the display number once it accepts clients
    if not number:
        err = p.communicate(timeout=10)[1].decode(errors="replace") if p.poll() is not None else ""
        p.kill()
        return None, "Xvfb failed to start: " + err[-1000:]
    return p, ":" + number


def run(script_args, launcher=DEFAULT_LAUNCHER, size="1280x1024", timeout=300, display=None, log=None, cwd=None):
    """Runs yade (launcher) with script_args in the qt view; returns (exit code, output text)."""
    if not shutil.which("script"):
        return NO_DISPLAY, "util-linux `script` is missing"
    xvfb = None
    if display is None:
        xvfb, display = start_xvfb(size)
        if xvfb is None:
            return NO_DISPLAY, display
    env = dict(os.environ, DISPLAY=display)
    env.pop("XAUTHORITY", None)
    cmd = " ".join(shlex.quote(a) for a in [os.path.abspath(launcher)] + list(script_args))
    try:
        out = open(log, "w+") if log else tempfile.TemporaryFile("w+")
        # stdin: a pipe that is never written nor closed while yade runs (an end of input quits its prompt)
        p = subprocess.Popen(["script", "-qfec", cmd, "/dev/null"], stdin=subprocess.PIPE, stdout=out, stderr=subprocess.STDOUT,
                             env=env, cwd=cwd)
        try:
            code = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            p.kill()  # the pty closes: yade gets SIGHUP
            p.wait()
            code = 124
        p.stdin.close()
        out.seek(0)
        text = out.read()
        out.close()
        return code, text
    finally:
        if xvfb is not None:
            xvfb.terminate()
            try:
                xvfb.wait(timeout=10)
            except subprocess.TimeoutExpired:
                xvfb.kill()
                xvfb.wait()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--launcher", default=DEFAULT_LAUNCHER)
    ap.add_argument("--size", default="1280x1024", help="screen of the virtual display")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--display", default=None, help="use this X display instead of a new Xvfb")
    ap.add_argument("script", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    code, text = run(a.script, a.launcher, a.size, a.timeout, a.display)
    sys.stdout.write(text)
    return code


if __name__ == "__main__":
    sys.exit(main())
