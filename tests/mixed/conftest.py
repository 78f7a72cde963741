"""Helpers for the physics tests: run a scene of scenes/ through the YADE launcher (tests/support/yadescene.py).
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


@pytest.fixture
def scene():
    return run_scene
