# Sphinx configuration of the yade-rbsm manual. Built by scripts/build_docs.sh, which copies docs/ into
# build/docs/src, generates the class reference and the verification page there, and runs Sphinx inside YADE
# (so autodoc imports yade_rbsm as a script does).
import os
import subprocess

project = "yade-rbsm"
author = "yade-rbsm developers"
copyright = "the yade-rbsm developers, GPL-2.0-or-later"
try:
    release = subprocess.run(["git", "-C", os.environ.get("RBSM_SOURCE_DIR", "."), "describe", "--always", "--dirty"],
                             capture_output=True, text=True).stdout.strip() or "unknown"
except OSError:
    release = "unknown"

extensions = ["myst_parser", "sphinx.ext.autodoc"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_enable_extensions = ["colon_fence"]   # formulas are written in Unicode: no MathJax, no CDN
myst_heading_anchors = 3
exclude_patterns = ["_build"]
root_doc = "index"

autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False}

html_theme = "sphinx_rtd_theme"
html_title = "yade-rbsm manual"
html_static_path = ["_static"]
html_css_files = ["wide.css"]


# The package's docstrings are written for help() in YADE's console: plain text with YADE's :yref: role,
# |x| for magnitudes and bullet lists without a blank line before them. Read them as reST here.
import re  # noqa: E402


def _plain_text_as_rest(app, what, name, obj, options, lines):
    out = []
    for line in lines:
        line = re.sub(r":yref:`([^`]*)`", r"``\1``", line)
        parts = re.split(r"(``[^`]*``)", line)  # leave literals alone
        line = "".join(p if p.startswith("``") else p.replace("|", r"\|") for p in parts)
        if re.match(r"\s*[*-] ", line) and out and out[-1].strip() and not re.match(r"\s*[*-] ", out[-1]):
            out.append("")
        out.append(line)
    lines[:] = out


def setup(app):
    app.connect("autodoc-process-docstring", _plain_text_as_rest)
