"""Helpers of the documentation tests: the repository, the launcher, the fenced code blocks of a Markdown file."""
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
BUILD = os.environ.get("RBSM_BUILD_DIR", os.path.join(SRC, "build"))
MANUAL = os.path.join(SRC, "docs", "manual")


def launcher():
    return os.environ.get("RBSM_LAUNCHER", os.path.join(BUILD, "yade-rbsm"))


def python_blocks(path):
    """The ```python blocks of a Markdown file, as (line number, code)."""
    text = open(path, encoding="utf-8").read()
    return [(text[:m.start()].count("\n") + 1, m.group(1)) for m in re.finditer(r"^```python\n(.*?)^```", text, re.S | re.M)]


def run_block(code, cwd, timeout=600):
    """Runs a code block verbatim as a YADE script in *cwd*; returns the CompletedProcess."""
    script = os.path.join(cwd, "block.py")
    with open(script, "w", encoding="utf-8") as f:
        f.write(code)
    return subprocess.run([launcher(), "-n", "-x", script], cwd=cwd, capture_output=True, text=True, timeout=timeout)


def manual_pages():
    return sorted(os.path.join(d, f) for d, _, fs in os.walk(MANUAL) for f in fs if f.endswith(".md"))
