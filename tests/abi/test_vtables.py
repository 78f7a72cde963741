"""vtables of the plugin's classes against their YADE base classes in Debian's binary.

The plugin adds no virtual function of its own, so for every class whose vtable libpkg_rbsm.so
exports (`_ZTVN4yade...`), the vtable group must have the size of its direct base class's, and every
slot must name either the same function as the base's slot or the plugin class's own override of the
same member. A declaration that orders virtual functions differently from Debian's build puts an
override in the wrong slot: YADE then calls the wrong function through the base class.
"""
import itertools
import re

import pytest

import elfinfo
from conftest import demangle

VTABLE = re.compile(r"^_ZTVN4yade(\d+)(\w+)E$")


def plugin_classes(lib):
    out = []
    for name in elfinfo.dynamic_symbols(lib):
        m = VTABLE.match(name)
        if m and len(m.group(2)) == int(m.group(1)):
            out.append(m.group(2))
    return sorted(out)


def direct_base(cls, lib):
    """Name of the (first) direct base class of yade::cls, from its typeinfo in lib: an
    __si_class_type_info names its base at +16, a __vmi_class_type_info its first base at +24."""
    ti = elfinfo.dynamic_symbols(lib).get("_ZTI" + elfinfo.mangled_class(cls))
    assert ti, "the plugin exports the vtable of %s but not its typeinfo" % cls
    rel = elfinfo._relocations(lib)
    kind = rel.get(ti[0], (None,))[0] or ""
    at = ti[0] + (24 if "vmi_class_type_info" in kind else 16)
    base = rel.get(at)
    assert base, "no relocation naming the base typeinfo of %s" % cls
    name = base[0] if base[0] != "RELATIVE" else elfinfo._defined_by_address(lib).get(base[1], "")
    m = re.match(r"^_ZTIN4yade(\d+)(\w+)E$", name)
    assert m, "base of %s is not a yade class: %s" % (cls, name)
    return m.group(2)


def base_vtable(base, plugin, yade_libs):
    """(library, slots) of the base class's vtable: Debian's, or the plugin's if the base is a plugin class."""
    lib, _ = elfinfo.find_symbol("_ZTV" + elfinfo.mangled_class(base), yade_libs)
    if lib is None and "_ZTV" + elfinfo.mangled_class(base) in elfinfo.dynamic_symbols(plugin):
        lib = plugin
    assert lib, "no vtable of yade::%s in Debian's libraries (nor in the plugin)" % base
    return lib, elfinfo.vtable_slots(base, lib)


def pytest_generate_tests(metafunc):
    if "cls" in metafunc.fixturenames:
        import os
        from conftest import BUILD_DIR
        lib = os.environ.get("RBSM_PLUGIN", os.path.join(BUILD_DIR, "pkg/rbsm/libpkg_rbsm.so"))
        metafunc.parametrize("cls", plugin_classes(lib) if os.path.exists(lib) else ["<plugin not built>"])


def test_plugin_exports_vtables(plugin):
    assert plugin_classes(plugin), "libpkg_rbsm.so exports no yade:: vtable (expected at least Polygon2D's)"


def test_vtable_size_equals_base(cls, plugin, yade_libs):
    """size = the base's vtable size, plus one slot per override of a secondary base's virtual function."""
    base = direct_base(cls, plugin)
    lib, theirs_slots = base_vtable(base, plugin, yade_libs)
    _, extra = compare(cls, base, elfinfo.vtable_slots(cls, plugin), theirs_slots)
    ours = elfinfo.vtable_size(cls, [plugin])
    theirs = elfinfo.vtable_size(base, [lib])
    assert ours == theirs + 8 * extra, (
        "vtable of yade::%s (plugin) is %d bytes, of its base yade::%s in %s %d bytes (+%d allowed slots for overrides of "
        "secondary-base virtuals): the plugin class adds or lacks virtual functions" % (cls, ours, base, lib, theirs, extra))


def shorten(demangled):
    """Drop the padding of boost::mpl::vector (mpl_::na, ...) from a demangled name."""
    return re.sub(r"(, mpl_::na)+", ", ...", demangled) if demangled else str(demangled)


THUNK = re.compile(r"^((?:non-)?virtual thunk to |covariant return thunk to )?(.*)$")


def split_function(demangled):
    """'non-virtual thunk to yade::A<x>::f(int) const' -> ('non-virtual thunk to ', 'yade::A<x>', 'f', '(int) const').
    None if it is not a function name (typeinfo, ...)."""
    thunk, rest = THUNK.match(demangled).groups()
    depth = 0
    for i, c in enumerate(rest):
        if c in "<":
            depth += 1
        elif c in ">":
            depth -= 1
        elif c == "(" and depth == 0:
            qualified, params = rest[:i], rest[i:]
            break
    else:
        return None
    depth, cut = 0, -1
    for i, c in enumerate(qualified):
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
        elif c == ":" and depth == 0 and qualified[i:i + 2] == "::":
            cut = i
    if cut < 0:
        return None
    member = re.sub(r"\[abi:\w+\]", "", qualified[cut + 2:])
    return thunk or "", qualified[:cut], member, params


def same_member(plugin_slot, base_slot, cls, base):
    """The plugin's slot holds cls's own override of the member in the base's slot."""
    if plugin_slot is None or base_slot is None:
        return False
    if plugin_slot.startswith("typeinfo for ") or base_slot.startswith("typeinfo for "):
        return plugin_slot == "typeinfo for yade::" + cls and base_slot == "typeinfo for yade::" + base
    o, t = split_function(plugin_slot), split_function(base_slot)
    if not o or not t or o[1] != "yade::" + cls:
        return False
    name = lambda m: "~" if m.startswith("~") else m  # destructors: ~cls overrides ~base
    norm = lambda params, c: re.sub(r"\b%s\b" % re.escape(c), "@", params)
    # in a secondary vtable, a thunk to cls's override replaces the base's own function
    thunk_ok = o[0] == t[0] or (o[0] and not t[0])
    return bool(thunk_ok) and name(o[2]) == name(t[2]) and norm(o[3], cls) == norm(t[3], base)


def member_key(demangled, c):
    f = split_function(demangled) if demangled else None
    if not f:
        return None
    return ("~" if f[2].startswith("~") else f[2], re.sub(r"\b%s\b" % re.escape(c), "@", f[3]))


def groups(slots):
    """Split a vtable group into its vtables: [start, end) index ranges, each starting at the
    offset-to-top slot just before a typeinfo slot."""
    starts = [i - 1 for i, s in enumerate(slots) if s and s.startswith("_ZTI")]
    return [(a, b) for a, b in zip(starts, starts[1:] + [len(slots)])]


def compare(cls, base, ours, theirs):
    """Problems (strings) of the plugin's vtable against the base's. Besides the base's slots, the
    primary vtable of a class may only end with the class's own overrides of virtual functions of a
    secondary base (the Itanium ABI gives them a primary slot too, e.g. a functor's go(), which
    YADE's own functors have as well)."""
    d_ours, d_theirs = demangle(ours), demangle(theirs)
    g_ours, g_theirs = groups(ours), groups(theirs)
    bad = []
    if len(g_ours) != len(g_theirs):
        return ["  %s has %d vtables in its group, %s %d" % (cls, len(g_ours), base, len(g_theirs))], 0
    secondary_members = {member_key(d_theirs[i], base) for a, b in g_theirs[1:] for i in range(a, b)} - {None}
    extra = 0
    for k, ((oa, ob), (ta, tb)) in enumerate(zip(g_ours, g_theirs)):
        n_ours, n_theirs = ob - oa, tb - ta
        if k == 0 and n_ours > n_theirs:
            for j in range(oa + n_theirs, ob):
                f = split_function(d_ours[j]) if d_ours[j] else None
                if f and f[1] == "yade::" + cls and member_key(d_ours[j], cls) in secondary_members:
                    extra += 1
                else:
                    bad.append("  slot %2d: %s has  %s\n           %s has no such slot (a new virtual function?)" % (j, cls, shorten(d_ours[j]), base))
        elif n_ours != n_theirs:
            bad.append("  vtable #%d of the group: %s has %d slots, %s %d" % (k, cls, n_ours, base, n_theirs))
        for i in range(min(n_ours, n_theirs)):
            o, t = ours[oa + i], theirs[ta + i]
            if o == t or same_member(d_ours[oa + i], d_theirs[ta + i], cls, base):
                continue
            bad.append("  slot %2d: %s has  %s\n           %s has  %s" % (oa + i, cls, shorten(d_ours[oa + i]), base, shorten(d_theirs[ta + i])))
    return bad, extra


def test_vtable_slots_match_base(cls, plugin, yade_libs):
    base = direct_base(cls, plugin)
    lib, theirs = base_vtable(base, plugin, yade_libs)
    bad, _ = compare(cls, base, elfinfo.vtable_slots(cls, plugin), theirs)
    assert not bad, "vtable slots of yade::%s (plugin) differ from its base yade::%s (%s):\n%s" % (cls, base, lib, "\n".join(bad))


@pytest.mark.parametrize("dcls,base", [("Bo1_Sphere_Aabb", "BoundFunctor"), ("Ig2_Sphere_Sphere_ScGeom", "IGeomFunctor"),
                                      ("Law2_ScGeom_FrictPhys_CundallStrack", "LawFunctor"), ("Sphere", "Shape")])
def test_rules_hold_for_debians_own_classes(dcls, base, yade_libs):
    """Self-check of compare(): YADE's own derived classes satisfy the rules, and a swap of two slots is caught."""
    cls = dcls
    lc, _ = elfinfo.find_symbol("_ZTV" + elfinfo.mangled_class(cls), yade_libs)
    lb, _ = elfinfo.find_symbol("_ZTV" + elfinfo.mangled_class(base), yade_libs)
    ours, theirs = elfinfo.vtable_slots(cls, lc), elfinfo.vtable_slots(base, lb)
    bad, extra = compare(cls, base, ours, theirs)
    assert not bad, "\n".join(bad)
    assert elfinfo.vtable_size(cls, [lc]) == elfinfo.vtable_size(base, [lb]) + 8 * extra
    swapped = list(ours)
    swapped[5], swapped[6] = swapped[6], swapped[5]
    assert len(compare(cls, base, swapped, theirs)[0]) == 2
