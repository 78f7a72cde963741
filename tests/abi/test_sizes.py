"""sizeof of every class declared in yade-interface/ against Debian's binary, read at test time.

The project's sizes come from the executable abi_print_sizes (compiled with the declarations and
the plugin's compile definitions); the binary's from the `operator new` argument in the factory
function `yade::CreatePureCustom<Class>` of Debian's libraries (elfinfo.object_size).
"""
import glob
import os
import re
import subprocess

import pytest

import elfinfo
from conftest import SOURCE_DIR, path_from_env

# Declared classes that the binary cannot measure by a factory function, and why.
NO_FACTORY = {
    "Factorable": "abstract root in YADE (no factory); its 24 bytes are the base of every measured class",
    "Serializable": "abstract in YADE (no factory); the base of every measured class",
    "Indexable": "abstract mix-in (no factory); part of Shape, State, Material, IGeom, IPhys, Bound",
    "ForceContainer": "not Factorable (no factory); a member of Scene, so Scene's size covers it and "
    "test_runtime.py reads the Scene fields after it (dt, iter, time) and the forces themselves",
    "TimingDeltas": "not Factorable; held through shared_ptr only, its size does not enter any layout",
}
# Declared names that are not YADE objects with a layout of their own (singletons, templates, helpers).
NOT_LAYOUT = {"ClassFactory", "Omega", "Functor1D", "Functor2D", "RawConstructorDispatcher", "TimingInfo", "Singleton"}


@pytest.fixture(scope="module")
def project_sizes():
    exe = path_from_env("RBSM_SIZES_EXE", "tests/abi/abi_print_sizes")
    out = subprocess.run([exe], capture_output=True, text=True, check=True).stdout
    return {name: int(size) for name, size in (line.split() for line in out.splitlines())}


def declared_classes():
    names = set()
    for h in glob.glob(os.path.join(SOURCE_DIR, "yade-interface", "**", "*.hpp"), recursive=True):
        for m in re.finditer(r"^\s*(?:class|struct)\s+(\w+)(?:\s+final)?\s*[:{]", open(h).read(), re.M):
            names.add(m.group(1))
    return sorted(names)


def test_every_declared_class_is_measured(project_sizes):
    missing = [c for c in declared_classes() if c not in project_sizes and c not in NOT_LAYOUT]
    assert not missing, "classes declared in yade-interface/ but not printed by tests/abi/print_sizes.cpp: %s (add a SIZE(...) line)" % missing


@pytest.mark.parametrize("cls", sorted(set(declared_classes()) - NOT_LAYOUT))
def test_sizeof_matches_debian(cls, project_sizes, yade_libs):
    ours = project_sizes.get(cls)
    assert ours is not None, "%s is declared but not measured by print_sizes.cpp" % cls
    theirs = elfinfo.object_size(cls, yade_libs)
    if theirs is None:
        if cls in NO_FACTORY:
            pytest.skip("%s: %s" % (cls, NO_FACTORY[cls]))
        pytest.fail("%s: no yade::CreatePureCustom%s in Debian's libraries, cannot read its size" % (cls, cls))
    assert ours == theirs, "sizeof(yade::%s): yade-interface declares %d bytes, Debian's binary has %d bytes" % (cls, ours, theirs)
