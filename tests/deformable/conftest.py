"""Helpers for the physics tests: run a scene of scenes/ through the YADE launcher (tests/support/yadescene.py).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from yadescene import scene_helpers  # noqa: E402

SCENES, launcher, run_scene, scene = scene_helpers(__file__)
