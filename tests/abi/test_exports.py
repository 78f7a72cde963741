"""The plugin exports only its own classes' symbols, and shares YADE's class-index counters.

A plugin defines weak copies of every inline YADE function and vtable it uses; if one of them were
exported it could interpose over Debian's definition for the whole process (see the shared notes).
The patterns of the plugin's own symbols are read from pkg/rbsm/exports.map. One group is exported on
purpose: boost::serialization's registries of yade::State (DeformableState's base), so that the plugin binds to
libyade's and a scene holds one State class (with the plugin's own local copies a file mixing deformable and
rigid blocks failed to load in a new process: "unregistered class"; test_persistence_of_mixed_states).
"""
import fnmatch
import re
import subprocess

import pytest

import elfinfo
from conftest import demangle


def export_patterns(path):
    text = re.sub(r"/\*.*?\*/", "", open(path).read(), flags=re.S)
    m = re.search(r"global\s*:(.*?)(?:local\s*:|})", text, re.S)
    assert m, "no global: section in %s" % path
    pats = [p.strip() for p in m.group(1).split(";") if p.strip()]
    assert pats, "no global pattern in %s" % path
    return pats


def shared_patterns(path):
    """The exports.map patterns of YADE's own State registries (exported so as to bind to libyade's)."""
    return [p for p in export_patterns(path) if "N4yade5StateE" in p]


def test_exports_map_is_used(plugin, exports_map):
    """Every defined dynamic symbol matches a global pattern of exports.map (the version script is in effect)."""
    pats = export_patterns(exports_map)
    stray = [s for s in elfinfo.dynamic_symbols(plugin) if not any(fnmatch.fnmatchcase(s, p) for p in pats)]
    assert not stray, "libpkg_rbsm.so exports %d symbols outside %s %s, e.g.:\n  %s" % (
        len(stray), exports_map, pats, "\n  ".join(demangle(stray[:20])))


def test_every_export_mentions_a_plugin_class(plugin, exports_map):
    names = [p.strip("*") for p in export_patterns(exports_map)]
    syms = list(elfinfo.dynamic_symbols(plugin))
    dem = demangle(syms)
    shared = shared_patterns(exports_map)
    bad = [d for s, d in zip(syms, dem) if not any(n in d for n in names) and not any(fnmatch.fnmatchcase(s, p) for p in shared)]
    assert not bad, "exported symbols that name no plugin class (%s):\n  %s" % (names, "\n  ".join(bad[:20]))


def test_no_symbol_of_yade_is_exported(plugin, yade_libs, exports_map):
    """No exported symbol of the plugin is also defined by Debian's libraries (it would interpose), but State's
    serialization registries, which must be libyade's (loaded first, so the plugin's references bind to them)."""
    shared = shared_patterns(exports_map)
    ours = set(s for s in elfinfo.dynamic_symbols(plugin) if not any(fnmatch.fnmatchcase(s, p) for p in shared))
    clash = {}
    for lib in yade_libs:
        for s in ours & set(elfinfo.dynamic_symbols(lib)):
            clash.setdefault(s, lib)
    assert not clash, "libpkg_rbsm.so exports symbols that Debian's YADE defines too:\n  %s" % "\n  ".join(
        "%s (%s)" % (d, clash[s]) for s, d in zip(clash, demangle(list(clash))))


COUNTER = re.compile(r"^_ZZN4yade(\d+)(\w+?)22modifyClassIndexStaticEvE5index$")


def counters(lib, dynamic):
    cmd = ["nm", "--defined-only"] + (["-D"] if dynamic else []) + [lib]
    out = {}
    for line in subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.splitlines():
        parts = line.split()
        m = COUNTER.match(parts[-1]) if parts else None
        if m and len(m.group(2)) == int(m.group(1)):
            out[m.group(2)] = parts[-2]
    return out


def test_class_index_counters_of_yade_are_not_defined(plugin, exports_map):
    """The counters of YADE's classes (e.g. Shape's) must be Debian's shared ones: not defined in the plugin at all."""
    names = [p.strip("*") for p in export_patterns(exports_map)]
    own = [c for c in counters(plugin, dynamic=False) if not any(n in c for n in names)]
    assert not own, "libpkg_rbsm.so defines class-index counters of YADE classes (dispatch by class index would break): %s" % own


def test_plugin_class_index_counters_are_exported(plugin, exports_map):
    """The plugin's own counters are exported (unique/global), so every library sees one index per class."""
    static = counters(plugin, dynamic=False)
    dynamic = counters(plugin, dynamic=True)
    hidden = sorted(set(static) - set(dynamic))
    assert not hidden, "class-index counters of plugin classes that are not exported: %s" % hidden
