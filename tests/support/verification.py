"""Figures of the closed-form and published cases, recorded by the tests that check them, for the manual's
verification page (docs/tools/verification_page.py): one JSON file per case in $RBSM_BUILD_DIR/verification
(the build directory ctest names; build/ of the checkout when a test is run by hand;
RBSM_VERIFICATION_DIR: another directory)."""
import json
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.environ.get("RBSM_SOURCE_DIR", os.path.join(HERE, "..", ".."))


def _commit():
    try:
        return subprocess.run(["git", "-C", SRC, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              timeout=10).stdout.strip() or "?"
    except OSError:
        return "?"


def record(group, case, measured, reference, source, rtol=None, tolerance=None, unit=""):
    """Records *measured* against *reference* (from *source*: a closed form, a paper) for the page's *group*.
    *rtol*: the relative tolerance the test asserts (or *tolerance*: how it is asserted, in words)."""
    directory = os.environ.get("RBSM_VERIFICATION_DIR") or os.path.join(
        os.environ.get("RBSM_BUILD_DIR", os.path.join(SRC, "build")), "verification")
    os.makedirs(directory, exist_ok=True)
    test = os.environ.get("PYTEST_CURRENT_TEST", "").split(" (")[0] or "?"
    where = os.path.relpath(os.getcwd(), SRC)  # pytest names the test from its directory (ctest's working directory)
    if not where.startswith(".."):
        test = os.path.normpath(os.path.join(where, test))
    row = dict(group=group, case=case, measured=float(measured), reference=float(reference), source=source,
               rtol=rtol, tolerance=tolerance, unit=unit, test=test, commit=_commit())
    name = re.sub(r"[^A-Za-z0-9]+", "_", f"{group}_{case}").strip("_").lower()
    with open(os.path.join(directory, name + ".json"), "w") as f:
        json.dump(row, f, indent=1)
    return row
