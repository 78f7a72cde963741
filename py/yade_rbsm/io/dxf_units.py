"""The length unit of a DXF drawing, and ezdxf itself (pure Python, no YADE): shared by the block
importer (:mod:`.dxf`) and the slope-drawing reader (:mod:`.slope_dxf`)."""

import warnings

__all__ = ["drawing_scale", "read_drawing", "warn_if_unitless_and_huge"]

# $INSUNITS codes of lengths a slope is drawn in -> metres, and the names units= takes
_INSUNITS = {0: ("unitless, taken as metres", 1.0), 1: ("in", 0.0254), 2: ("ft", 0.3048), 4: ("mm", 1e-3),
             5: ("cm", 1e-2), 6: ("m", 1.0), 7: ("km", 1e3), 10: ("yd", 0.9144), 14: ("dm", 0.1)}
_UNITS = {name: m for code, (name, m) in _INSUNITS.items() if code}


def drawing_scale(doc, units, filename):
    """Metres per drawing unit of the ezdxf document *doc*: from *units* if given, else $INSUNITS."""
    if units is not None:
        if units not in _UNITS:
            raise ValueError("%s: units=%r is not a length this reader knows (%s)" % (filename, units, ", ".join(sorted(_UNITS))))
        return _UNITS[units]
    code = doc.header.get("$INSUNITS", 0)
    if code not in _INSUNITS:
        raise ValueError("%s: the drawing's units, $INSUNITS = %r, are no length a slope is drawn in (known: %s); "
                         "give units= if the numbers are in one of %s" % (
                             filename, code, ", ".join("%d %s" % (k, v[0]) for k, v in sorted(_INSUNITS.items())),
                             ", ".join(sorted(_UNITS))))
    return _INSUNITS[code][1]


# A drawing without units is read in metres; one wider or taller than this [m] is rather in millimetres.
_IMPLAUSIBLE_EXTENT = 5000.0


def warn_if_unitless_and_huge(doc, units, filename, points, who):
    """A warning (naming *who*, the reader) for a drawing without units ($INSUNITS 0, no *units*) whose *points*, read
    in metres, are kilometres across: a slope drawn in millimetres and read so is a million times too large (and
    too heavy) without it."""
    if units is not None or doc.header.get("$INSUNITS", 0) != 0 or not points:
        return
    w = max(p[0] for p in points) - min(p[0] for p in points)
    h = max(p[1] for p in points) - min(p[1] for p in points)
    if max(w, h) > _IMPLAUSIBLE_EXTENT:
        warnings.warn("%s: %s: the drawing has no units ($INSUNITS 0) and is read in metres: it is %.4g m by %.4g m "
                      "across; if it is drawn in millimetres, give units='mm'" % (who, filename, w, h))


def read_drawing(filename, units=None):
    """(ezdxf document, metres per drawing unit) of the DXF *filename*; ValueError naming the file when it
    cannot be read or is no DXF, or its units are no length (:func:`drawing_scale`)."""
    ezdxf = _ezdxf()
    try:
        doc = ezdxf.readfile(filename)
    except IOError as e:
        raise ValueError("%s: cannot read the file (%s)" % (filename, e)) from None
    except ezdxf.DXFStructureError as e:
        raise ValueError("%s: not a valid DXF file (%s)" % (filename, e)) from None
    return doc, drawing_scale(doc, units, filename)


def _ezdxf():
    try:
        import ezdxf
    except ImportError:
        raise ImportError("yade_rbsm.io: DXF needs ezdxf (Debian: apt-get install python3-ezdxf)") from None
    return ezdxf
