"""Helpers for the robustness tests: run a scene of scenes/ through the YADE launcher (tests/support/yadescene.py).
RBSM_LONG=1 in the environment selects the long variants of the tests (see each file).
"""
import functools
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "scenes")
sys.path.insert(0, os.path.join(HERE, "..", "support"))
import yadescene as _scenes  # noqa: E402

launcher = _scenes.launcher
run_scene = functools.partial(_scenes.run_scene, SCENES)
LONG = os.environ.get("RBSM_LONG", "") not in ("", "0")


def rect(x0, y0, w, h):
    return [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]]
