"""Shared fixtures of the ABI guard tests. ctest passes the paths through the environment
(tests/abi/CMakeLists.txt); run by hand with e.g.
    RBSM_BUILD_DIR=build /usr/bin/python3 -m pytest tests/abi
"""
import os
import subprocess

import pytest

import elfinfo

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.environ.get("RBSM_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
BUILD_DIR = os.path.abspath(os.environ.get("RBSM_BUILD_DIR", os.path.join(SOURCE_DIR, "build")))


def path_from_env(var, default):
    p = os.environ.get(var, os.path.join(BUILD_DIR, default))
    if not os.path.exists(p):
        pytest.fail("%s=%s does not exist: build the project first (cmake --build %s)" % (var, p, BUILD_DIR))
    return os.path.abspath(p)


@pytest.fixture(scope="session")
def plugin():
    return path_from_env("RBSM_PLUGIN", "pkg/rbsm/libpkg_rbsm.so")


@pytest.fixture(scope="session")
def exports_map():
    return os.environ.get("RBSM_EXPORTS_MAP", os.path.join(SOURCE_DIR, "pkg", "rbsm", "exports.map"))


@pytest.fixture(scope="session")
def yade_libs():
    """Debian's YADE libraries, without an installed copy of this project's plugins (cmake --install)."""
    ours = {"libpkg_rbsm.so", "libabi_probe.so"}
    libs = [l for l in elfinfo.yade_libraries() if os.path.basename(l) not in ours]
    if not any(os.path.basename(l) == "libyade.so" for l in libs):
        pytest.fail("Debian's yade is not installed in %s" % elfinfo.YADE_LIB_DIR)
    return libs


def demangle(names):
    """c++filt of a list of mangled names (None stays None)."""
    real = [n for n in names if n]
    if not real:
        return list(names)
    out = subprocess.run(["c++filt"], input="\n".join(real) + "\n", capture_output=True, text=True, check=True).stdout.splitlines()
    it = iter(out)
    return [next(it) if n else None for n in names]

# the launcher helper shared with tests/yade
import sys  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "yade"))
