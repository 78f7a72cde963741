"""What a saved scene says about the plugin that wrote it (issue 34, item 11).

YADE's archives have no class versions: a scene saved before a field was added to one of the plugin's classes
fails to load with "input stream error" or "XML start/end tag mismatch", naming nothing. ``O.save`` (wrapped by
:mod:`omega_hooks` once ``yade_rbsm`` is imported) writes, in ``O.tags``, the format: the saved attributes of
every plugin class at that time. When ``O.load`` fails, :func:`explain` reads that record back from the file's
raw bytes (XML or binary, plain, gzip or bzip2) and names the classes and fields that differ from this build's,
and the commit that wrote the file; for a file saved before the record existed it compares an XML file's
elements directly.
"""
import html
import json
import os
import re
import subprocess

TAG = "yade_rbsm.format"
_MARK = '{"yade_rbsm_format"'


_COMMIT = None


def _commit():
    """The checkout's commit (once per process), or "installed" for the Debian package."""
    global _COMMIT
    if _COMMIT is None:
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        try:
            out = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                                 timeout=5)
            _COMMIT = out.stdout.strip() or "installed"
        except (OSError, subprocess.SubprocessError):
            _COMMIT = "installed"
    return _COMMIT


_FIELDS = None


def _saved(cls, name):
    """An attribute the archive holds: not flagged noSave (YADE's Attr::noSave = 1, shown as :yattrflags:)."""
    m = re.search(r":yattrflags:`(\d+)`", getattr(getattr(cls, name, None), "__doc__", "") or "")
    return not (m and int(m.group(1)) & 1)


def fields():
    """{class: [saved attribute, ...]} of the plugin's classes in this build."""
    global _FIELDS
    if _FIELDS is None:
        import yade.wrapper as w
        from .io.describe import RBSM_CLASSES
        _FIELDS = {c: sorted(k for k in getattr(w, c)().dict() if _saved(getattr(w, c), k))
                   for c in sorted(RBSM_CLASSES) if hasattr(w, c)}
    return _FIELDS


def stamp(O):
    """Writes this build's format into O.tags (before O.save)."""
    O.tags[TAG] = json.dumps(dict(yade_rbsm_format=1, commit=_commit(), fields=fields()), separators=(",", ":"))


def _raw_text(path):
    from .io.describe import _open
    stream, _ = _open(path)
    with stream:
        data = stream.read()
    return data.decode("latin-1")


def recorded(path):
    """The format record of a save file (dict), or None when the file has none."""
    text = _raw_text(path)
    at = text.find(_MARK)
    if at < 0:
        at = text.find(html.escape(_MARK))
        if at < 0:
            return None
        text, at = html.unescape(text[at:at + 200000]), 0
    try:
        return json.JSONDecoder().raw_decode(text[at:])[0]
    except ValueError:
        return None


def _xml_fields(text):
    """{class: set of child element names} of the plugin's classes in an XML archive (no record needed)."""
    from .io.describe import RBSM_CLASSES
    out = {}
    for m in re.finditer(r'<(\w+) class_id="\d+" class_name="yade::(\w+)"[^>]*>(.*?)</\1>', text, re.S):
        if m.group(2) in RBSM_CLASSES and m.group(2) not in out:
            out[m.group(2)] = set(re.findall(r"^\t*<(\w+)[ >]", m.group(3), re.M)) - {"px", "item", "count",
                                                                                    "item_version", "first", "second"}
    return out


def explain(path, error):
    """A message naming why *path* fails to load in this build, or None when it is not the plugin's format."""
    try:
        rec = recorded(path)
    except OSError:
        return None
    now = fields()
    if rec is not None:
        then = rec.get("fields", {})
        diffs = []
        for cls in sorted(set(then) | set(now)):
            lacks = sorted(set(now.get(cls, ())) - set(then.get(cls, ())))
            extra = sorted(set(then.get(cls, ())) - set(now.get(cls, ())))
            if lacks:
                diffs.append("%s lacks %s (added since)" % (cls, ", ".join(lacks)))
            if extra:
                diffs.append("%s has %s (removed since)" % (cls, ", ".join(extra)))
        if not diffs:
            return None
        return ("O.load(%r): %s. The file was saved by yade-rbsm %s, whose classes had other fields than this build's: "
                "%s. Load it with the build that saved it (git checkout %s), or rebuild the scene with this one."
                % (path, error, rec.get("commit", "?"), "; ".join(diffs), rec.get("commit", "?")))
    text = _raw_text(path)
    if "yade::" not in text or not any(c in text for c in now):
        return None
    found = _xml_fields(text) if text.lstrip().startswith("<?xml") else {}
    diffs = ["%s lacks %s" % (c, ", ".join(sorted(set(now[c]) - f))) for c, f in sorted(found.items())
             if c in now and set(now[c]) - f]
    return ("O.load(%r): %s. The file was saved by a yade-rbsm build older than its format record (before 2026-11-28)%s. "
            "Load it with the build that saved it, or rebuild the scene with this one."
            % (path, error, (": " + "; ".join(diffs)) if diffs else ", whose classes had other fields than this build's"))
