"""Runs sphinx-build inside YADE, so that autodoc imports yade_rbsm as a scene script does.
    build/yade-rbsm -n -x docs/tools/sphinx_in_yade.py <sphinx-build arguments>"""
import sys

from sphinx.cmd.build import main

status = main(sys.argv[1:])
if status:
    # YADE's -x ends the process with status 0 after the script: an exception carries the failure out.
    raise SystemExit(f"sphinx-build failed (status {status})")
