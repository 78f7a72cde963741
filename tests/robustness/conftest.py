"""Helpers for the robustness tests: run a scene of scenes/ through the YADE launcher (tests/support/yadescene.py).
RBSM_LONG=1 in the environment selects the long variants of the tests (see each file).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from yadescene import scene_helpers  # noqa: E402

SCENES, launcher, run_scene, scene = scene_helpers(__file__)
LONG = os.environ.get("RBSM_LONG", "") not in ("", "0")


def rect(x0, y0, w, h):
    return [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]]
