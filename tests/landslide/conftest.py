"""Helpers: load py/yade_rbsm/slope.py without YADE; run a yade script through the launcher."""
import importlib.util
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
sys.path.insert(0, os.path.join(HERE, "..", "support"))  # verification.record


def load_slope():
    spec = importlib.util.spec_from_file_location("rbsm_slope_geom", os.path.join(SRC, "py", "yade_rbsm", "slope.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def launcher():
    l = os.environ.get("RBSM_LAUNCHER") or os.path.join(os.environ.get("RBSM_BUILD_DIR", os.path.join(SRC, "build")), "yade-rbsm")
    return l


def run_yade(script, *args, cwd=None, timeout=240):
    return subprocess.run([launcher(), "-n", "-x", script, *args], cwd=cwd, capture_output=True, text=True, timeout=timeout)
