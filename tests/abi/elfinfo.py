"""Facts read from ELF shared libraries with binutils (nm, objdump, readelf).

Used by the ABI guard tests to compare the project's declarations of YADE's classes with Debian's
binary *at test time*: object sizes (from the `CreatePureCustom<Class>` factory functions that every
YADE class has: their first instructions pass the size to operator new), vtable sizes (`_ZTV`
symbol sizes) and vtable slots (the relocations inside a vtable name the function of each slot).
"""
import functools
import glob
import os
import re
import subprocess

YADE_LIB_DIR = os.environ.get("YADE_LIB_DIR", "/usr/lib/x86_64-linux-gnu/yade-double")


def run(*cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


@functools.lru_cache(maxsize=None)
def dynamic_symbols(lib):
    """{mangled name: (address, size, type letter)} of the defined dynamic symbols of lib."""
    out = {}
    for line in run("nm", "-D", "--defined-only", "-S", lib).splitlines():
        parts = line.split()
        if len(parts) == 4:
            addr, size, kind, name = parts
            out[name] = (int(addr, 16), int(size, 16), kind)
        elif len(parts) == 3:
            addr, kind, name = parts
            out[name] = (int(addr, 16), 0, kind)
    return out


def yade_libraries():
    return sorted(glob.glob(os.path.join(YADE_LIB_DIR, "lib*.so")))


def mangled_class(cls):
    return "N4yade%d%sE" % (len(cls), cls)


def find_symbol(name, libs=None):
    for lib in libs or yade_libraries():
        sym = dynamic_symbols(lib).get(name)
        if sym:
            return lib, sym
    return None, None


def object_size(cls, libs=None):
    """sizeof(yade::cls) as compiled into the binary: the operand of the first `mov $N,%edi`."""
    fn = "_ZN4yade%dCreatePureCustom%sEv" % (len("CreatePureCustom" + cls), cls)
    lib, sym = find_symbol(fn, libs)
    if not lib:
        return None
    addr = sym[0]
    dis = run("objdump", "-d", "--no-show-raw-insn", "--start-address=%#x" % addr, "--stop-address=%#x" % (addr + 48), lib)
    m = re.search(r"mov\s+\$0x([0-9a-f]+),%edi", dis)
    return int(m.group(1), 16) if m else None


def vtable_size(cls, libs=None):
    """Size in bytes of the vtable group of yade::cls (all its sub-vtables)."""
    lib, sym = find_symbol("_ZTV" + mangled_class(cls), libs)
    return sym[1] if lib else None


@functools.lru_cache(maxsize=None)
def _relocations(lib):
    """{offset: symbol name} of the relocations of lib that name a symbol, plus relative ones."""
    out = {}
    for line in run("readelf", "-rW", lib).splitlines():
        parts = line.split()
        # RELATIVE lines have 4 fields (offset, info, type, addend), symbol lines 7
        if len(parts) >= 4 and re.fullmatch(r"[0-9a-f]{8,16}", parts[0]):
            off = int(parts[0], 16)
            if parts[2].endswith("RELATIVE"):
                out[off] = ("RELATIVE", int(parts[3], 16))
            elif len(parts) >= 5:
                out[off] = (parts[4].split("@")[0], None)
    return out


@functools.lru_cache(maxsize=None)
def _defined_by_address(lib):
    out = {}
    for line in run("nm", "--defined-only", lib).splitlines():
        parts = line.split()
        if len(parts) == 3:
            out.setdefault(int(parts[0], 16), parts[2])
    return out


def vtable_slots(cls, lib):
    """The function named by every 8-byte slot of yade::cls's vtable group in lib (None: no
    relocation, e.g. offset-to-top or a pure slot)."""
    sym = dynamic_symbols(lib).get("_ZTV" + mangled_class(cls))
    if not sym:
        return None
    addr, size, _ = sym
    rel, names = _relocations(lib), _defined_by_address(lib)
    slots = []
    for off in range(addr, addr + size, 8):
        r = rel.get(off)
        if r is None:
            slots.append(None)
        elif r[0] == "RELATIVE":
            slots.append(names.get(r[1], "?%#x" % r[1]))
        else:
            slots.append(r[0])
    return slots
