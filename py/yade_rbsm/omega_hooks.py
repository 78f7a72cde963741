"""``O.save`` that names the path and the problem (issue 34, item 12), and ``O.load`` that says why a scene
saved by another build of the plugin fails (item 11: :mod:`save_format`). YADE 2023.02a's ``Omega.save`` says
"output stream error" for a missing directory, a read-only one or a full disk, without the path, and returns
without a word, having written nothing, for a path that is a directory. Importing ``yade_rbsm`` wraps
``Omega.save``: the same call and the same files, with those cases refused (ValueError) or re-raised with the
path (OSError), before anything is half written. ``:memory:`` slots (``O.saveTmp``) pass through."""
import errno
import os

from . import save_format

_wrapped = None


def _check(path):
    """ValueError naming *path* and what is wrong with it as a place to save a scene, or None."""
    if not isinstance(path, str) or not path:
        raise ValueError("O.save: give a file name (got %r), e.g. O.save('scene.yade.gz')" % (path,))
    if "\0" in path:  # (YADE's save stops the name there: 'bad\0name.xml' wrote a file 'bad')
        raise ValueError("O.save(%r): the name holds a NUL character, which no file name can" % path)
    folder = os.path.dirname(os.path.abspath(path))
    longest = max(len(part.encode()) for part in path.split(os.sep))
    limit = os.pathconf(folder if os.path.isdir(folder) else "/", "PC_NAME_MAX")
    if longest > limit:
        raise ValueError("O.save(%r): a part of the name is %d bytes long, more than the file system allows (%d)"
                         % (path, longest, limit))
    if os.path.islink(path) and not os.path.exists(path):
        raise ValueError("O.save(%r): that is a symbolic link to %r, which does not exist" % (path, os.readlink(path)))
    if os.path.isdir(path):
        raise ValueError("O.save(%r): that is a directory; give a file name in it, e.g. %r"
                         % (path, os.path.join(path, "scene.yade.gz")))
    if not os.path.isdir(folder):
        raise ValueError("O.save(%r): the directory %r does not exist (os.makedirs(%r, exist_ok=True) first)"
                         % (path, folder, folder))
    if not os.access(folder, os.W_OK) or (os.path.exists(path) and not os.access(path, os.W_OK)):
        raise ValueError("O.save(%r): no permission to write there" % path)


def install():
    """Wrap ``yade.wrapper.Omega.save``, ``load`` and the ``dt`` setter (once per process)."""
    global _wrapped
    import yade.wrapper
    if _wrapped is not None:
        return
    _install_dt(yade.wrapper.Omega)
    original = yade.wrapper.Omega.save

    def save(self, file, quiet=False):
        if not (isinstance(file, str) and file.startswith(":memory:")):
            _check(file)
            save_format.stamp(self)  # which fields the plugin's classes have: O.load of an old file names them
        try:
            return original(self, file, quiet)
        except RuntimeError as e:
            if isinstance(file, str) and not file.startswith(":memory:"):
                raise OSError(errno.EIO, "O.save: writing the scene failed (%s): a full disk, or a file system that "
                              "refused it?" % e, file) from e
            raise
    save.__doc__ = original.__doc__
    yade.wrapper.Omega.save = save
    _wrapped = original
    load = yade.wrapper.Omega.load

    def load_naming_the_format(self, file, quiet=False):
        if isinstance(file, str) and not file.startswith(":memory:") and os.path.isfile(file):
            damaged = _unreadable(file)  # (YADE's reader can crash on a damaged gzip stream: checked first)
            if damaged:
                raise RuntimeError(damaged)
        try:
            return load(self, file, quiet)
        except RuntimeError as e:
            if not (isinstance(file, str) and os.path.isfile(file)):
                raise
            why = save_format.explain(file, e) or _damaged(file, e)
            raise RuntimeError(why) from e
    load_naming_the_format.__doc__ = load.__doc__
    yade.wrapper.Omega.load = load_naming_the_format


def _unreadable(path):
    """Why *path* cannot be a whole scene file, found without YADE (which may crash on it), or None: empty, a
    gzip stream that fails its CRC or ends early, an XML archive without its end."""
    import gzip
    import zlib
    if os.path.getsize(path) == 0:
        return "O.load(%r): the file is empty" % path
    with open(path, "rb") as f:
        head = f.read(64)
        if head[:2] != b"\x1f\x8b":
            f.seek(max(0, os.path.getsize(path) - 200))
            if head.lstrip().startswith(b"<?xml") and b"</boost_serialization>" not in f.read():
                return "O.load(%r): the XML ends before the scene does (a truncated copy?)" % path
            return None
    try:
        with gzip.open(path, "rb") as g:
            while g.read(1 << 20):
                pass
    except (OSError, EOFError, zlib.error) as e:
        return "O.load(%r): a damaged or truncated gzip file (%s)" % (path, e)
    return None


def _damaged(path, error):
    """Why YADE could not read *path*, a file :func:`_unreadable` let through (whole, not empty): YADE's own message,
    *error*, names neither the file nor the cause."""
    import gzip
    import re
    import yade.system
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    if b"yade::" not in data:
        return "O.load(%r): not a YADE scene file (no YADE class in its %d bytes; YADE: %s)" % (path, len(data), error)
    known = set(yade.system.childClasses("Serializable")) | {"Serializable"}
    unknown = sorted({n.decode() for n in re.findall(rb"yade::([A-Za-z_][A-Za-z0-9_]*)", data)} - known)
    if unknown:
        return ("O.load(%r): the file holds classes this YADE does not know: %s (a plugin not loaded, or a class renamed "
                "since the file was saved; YADE: %s)" % (path, ", ".join(unknown), error))
    return "O.load(%r): YADE could not read it (%s): a damaged file?" % (path, error)


def _install_dt(Omega):
    dt = Omega.dt

    def set_dt(self, value):
        import math
        import numbers
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
            # (NaN ran 300 steps to NaN positions without a word; None said "'<' not supported ...")
            raise ValueError("O.dt must be a finite number of seconds (> 0; < 0: the time stepper sets it), got %r" % (value,))
        if value < 0:
            from .scene import time_stepper
            stepper = time_stepper()
            if stepper is not None:  # (the step it sets from the next step on; O.dt stays meanwhile)
                stepper.setDt = True
                return
        dt.fset(self, value)
    Omega.dt = property(dt.fget, set_dt, doc=dt.__doc__)
