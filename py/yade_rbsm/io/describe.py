"""Which classes a YADE save file needs, and which of them the local YADE lacks.

A scene saved with a plugin (``O.save``) names, in its archive, every class that YADE must create
from its name when loading: the concrete class behind each polymorphic pointer (shapes, materials,
engines, functors, contact geometry and physics). A YADE that lacks one of them stops with
``RuntimeError: unregistered class`` and does not say which; :func:`describe` does. Classes reached
through a pointer of their exact type (``State``, ``NewtonIntegrator`` inside a collider ...) are
not named in an archive, and every YADE has them.

Readable formats, told apart by their first bytes (not by the file name): YADE's XML archives
(``.xml``) and its binary archives (``.yade``, ``.bin``), each plain, gzip'ed (``.gz``) or
bzip2'ed (``.bz2``). XML names classes in ``class_name="..."`` attributes; a binary archive holds
each name once as a length-prefixed string, found by a scan for ``yade::`` names whose 8-byte
length prefix matches (a heuristic: another string of the scene looking exactly like a class key
would be listed too).

The module is stand-alone (standard library only) so that a collaborator without the plugin can run
it, from YADE or from plain python3::

    yade -n -x describe.py scene.yade.gz      # the local YADE's classes from the running yade
    python3 describe.py scene.xml.bz2         # asks `yade` (on PATH, or $YADE) for its classes

Exit status: 0 when the local YADE has every class, 1 when some are missing, 2 on a bad file.
"""
import bz2
import gzip
import os
import re
import subprocess
import sys
import tempfile

__all__ = ["describe", "SaveFileInfo", "classes_in", "local_yade_classes", "RBSM_CLASSES"]

# The classes of the yade-rbsm plugin (tests/io checks this list against the built plugin).
RBSM_CLASSES = frozenset((
    "Polygon2D", "Bo1_Polygon2D_Aabb", "RbsmMat", "RbsmGeom", "RbsmPhys", "Ig2_Polygon2D_Polygon2D_RbsmGeom",
    "Ip2_RbsmMat_RbsmMat_RbsmPhys", "Law2_RbsmGeom_RbsmPhys_MohrCoulomb", "RbsmTimeStepper",
    # the qt view's functors (issue 16)
    "Gl1_Polygon2D", "Gl1_RbsmGeom", "Gl1_RbsmPhys",
    # mixed scenes: blocks with spheres, walls and facets (issue 17)
    "Ig2_Polygon2D_Sphere_ScGeom", "Ip2_RbsmMat_FrictMat_FrictPhys", "Ig2_Polygon2D_Wall_RbsmGeom",
    "Ig2_Polygon2D_Facet_RbsmGeom", "RbsmPairCheck",
    # deformable blocks (issue 38)
    "DeformableState", "BlockStrainIntegrator",
    # blocks in open water (issue 40)
    "OpenWaterPressure"))

_XML_CLASS = re.compile(rb'class_name="([^"]+)"')
_BINARY_KEY = re.compile(rb"yade::[A-Za-z_][A-Za-z0-9_]*")
_BINARY_SIGNATURE = b"\x16" + b"\0" * 7 + b"serialization::archive"
_CHUNK = 1 << 24


def _open(path):
    """(binary stream of the decompressed file, compression name or None)."""
    with open(path, "rb") as f:
        magic = f.read(3)
    if magic[:2] == b"\x1f\x8b":
        return gzip.open(path, "rb"), "gzip"
    if magic == b"BZh":
        return bz2.open(path, "rb"), "bzip2"
    return open(path, "rb"), None


def _scan(stream, first):
    """Class names in an archive's body (XML attributes or length-prefixed binary keys)."""
    xml = first.lstrip().startswith(b"<?xml") or b"<boost_serialization" in first
    if not xml and not first.startswith(_BINARY_SIGNATURE):
        return None, set()
    names, tail, data = set(), b"", first
    while data:
        buf = tail + data
        if xml:
            names.update(m.group(1).decode("ascii", "replace") for m in _XML_CLASS.finditer(buf))
        else:
            for m in _BINARY_KEY.finditer(buf):
                n = len(m.group())
                if m.start() >= 8 and buf[m.start() - 8:m.start()] == n.to_bytes(8, "little"):
                    names.add(m.group().decode("ascii"))
        tail = buf[-512:]  # a name cut by a chunk boundary is found in the next round
        data = stream.read(_CHUNK)
    return ("xml" if xml else "binary"), names


def classes_in(path):
    """(format 'xml' or 'binary', compression or None, set of class names such as 'yade::Polygon2D').
    Raises ValueError naming the file if it is not a YADE save file."""
    try:
        stream, compression = _open(path)
        with stream:
            first = stream.read(_CHUNK)
            fmt, names = _scan(stream, first)
    except (OSError, EOFError) as e:  # also a corrupt gzip/bzip2 stream
        raise ValueError("%s: cannot read it as a YADE save file (%s)" % (path, e)) from None
    if fmt is None:
        raise ValueError("%s: not a YADE save file (neither a boost XML nor a boost binary archive%s)"
                         % (path, ", after %s decompression" % compression if compression else ""))
    return fmt, compression, names


def _strip(name):
    return name[len("yade::"):] if name.startswith("yade::") else name


_LIST_SCRIPT = "import yade.system\nprint('YADE-CLASSES ' + ' '.join(sorted(yade.system.childClasses('Serializable'))))\n"


def local_yade_classes(yade=None):
    """Names of the Serializable classes the local YADE knows (without namespace). Inside a running
    yade: from that yade; otherwise from running `yade` ($YADE, or *yade*) once. None when no YADE
    can be asked."""
    if "yade.system" in sys.modules or "yade.wrapper" in sys.modules:
        import yade.system
        return set(yade.system.childClasses("Serializable")) | {"Serializable"}
    exe = yade or os.environ.get("YADE", "yade")
    with tempfile.TemporaryDirectory(prefix="yade-describe-") as tmp:
        script = os.path.join(tmp, "list_classes.py")
        with open(script, "w") as f:
            f.write(_LIST_SCRIPT)
        try:
            p = subprocess.run([exe, "-n", "-x", script], capture_output=True, text=True, timeout=300, cwd=tmp)
        except (OSError, subprocess.TimeoutExpired):
            return None
    for line in p.stdout.splitlines():
        if line.startswith("YADE-CLASSES "):
            return set(line.split()[1:]) | {"Serializable"}
    return None


class SaveFileInfo:
    """What :func:`describe` found: ``path``, ``format`` ('xml' or 'binary'), ``compression``
    (None, 'gzip', 'bzip2'), ``classes`` (sorted names without the ``yade::`` namespace),
    ``missing`` (those the local YADE lacks; None if no YADE could be asked), ``rbsm`` (those
    yade-rbsm provides). ``str()`` gives a short report."""

    def __init__(self, path, fmt, compression, classes, missing):
        self.path, self.format, self.compression = path, fmt, compression
        self.classes, self.missing = classes, missing
        self.rbsm = sorted(set(classes) & RBSM_CLASSES)

    def __repr__(self):
        return "SaveFileInfo(%r, format=%r, compression=%r, classes=%r, missing=%r)" % (
            self.path, self.format, self.compression, self.classes, self.missing)

    def __str__(self):
        kind = "%s archive%s" % (self.format, ", %s-compressed" % self.compression if self.compression else "")
        lines = ["%s: YADE %s naming %d classes:" % (self.path, kind, len(self.classes)),
                 "  " + ", ".join(self.classes)]
        if self.missing is None:
            lines.append("could not ask a local YADE which of them it has (is `yade` installed?)")
        elif not self.missing:
            lines.append("the local YADE has all of them: O.load() should work")
        else:
            lines.append("the local YADE lacks %d of them (O.load() would stop with 'unregistered class'):" % len(self.missing))
            lines.append("  " + ", ".join(self.missing))
            gap = sorted(set(self.missing) & RBSM_CLASSES)
            if gap:
                lines.append("%s %s from the yade-rbsm plugin: install its Debian package (apt-get install "
                             "./yade-rbsm_*.deb) or run the scene with yade-rbsm" % (", ".join(gap), "is" if len(gap) == 1 else "are"))
        return "\n".join(lines)


def describe(path, known=None):
    """Reads the YADE save file *path* and returns a :class:`SaveFileInfo`: the classes it needs and
    which the local YADE lacks (``print(describe("scene.yade.gz"))``). *known*: the class names to
    check against instead of asking the local YADE (see :func:`local_yade_classes`). Raises
    ValueError naming the file for a missing file or one that is not a YADE save file."""
    if not os.path.isfile(path):
        raise ValueError("%s: no such file" % path)
    fmt, compression, names = classes_in(path)
    classes = sorted(_strip(n) for n in names)
    if known is None:
        known = local_yade_classes()
    missing = None if known is None else sorted(c for c in classes if c not in set(known))
    return SaveFileInfo(path, fmt, compression, classes, missing)


def main(argv):
    if len(argv) < 1 or argv[0] in ("-h", "--help"):
        print(__doc__.strip().split("\n\n")[0] + "\n\nusage: describe.py SAVE_FILE [SAVE_FILE ...]\n"
              "       describe.py --list-local   (the classes of the local YADE)")
        return 2
    if argv[0] == "--list-local":
        known = local_yade_classes()
        print("YADE-CLASSES " + " ".join(sorted(known)) if known is not None else "describe: no YADE to ask")
        return 0 if known is not None else 2
    status = 0
    for path in argv:
        try:
            info = describe(path)
        except ValueError as e:
            print("describe: %s" % e, file=sys.stderr)
            status = 2
            continue
        print(info)
        if info.missing:
            status = max(status, 1)
    return status


if __name__ == "__main__":
    status = main(sys.argv[1:])
    if "yade.wrapper" in sys.modules:  # inside `yade -x`: sys.exit would be caught; leave with the status
        sys.stdout.flush()
        os._exit(status)
    sys.exit(status)
