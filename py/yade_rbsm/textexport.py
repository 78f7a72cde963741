"""Blocks to and from a text file: the RBSM counterpart of YADE's ``export.text`` / ``ymport.text``
(which write and read spheres only; on blocks export.text writes its header and nothing else).

One line per Polygon2D body, after a ``#format`` line::

    id  x  y  angle  thickness  n  x1 y1 ... xn yn

(centroid [m], rotation about z [rad], thickness [m], then the n world vertices, counter-clockwise).
:func:`read` returns what :func:`yade_rbsm.polygon2d` needs to make the blocks again. Like YADE's
text format it carries no material and no velocity: ``yade_rbsm.io.export_blocks`` writes a file that
carries every RbsmMat attribute, the fixed flags and the velocities.
"""
FORMAT = "id_x_y_angle_thickness_n_vertices"


def text(filename, comment="", O=None):
    """Writes the Polygon2D bodies of the scene to *filename*; returns how many were written."""
    if O is None:
        from yade import O
    from yade import wrapper
    lines = ["#format " + FORMAT] + (["# " + c for c in comment.split("\n")] if comment else [])
    for b in O.bodies:
        if b is None or not isinstance(b.shape, wrapper.Polygon2D):
            continue
        axis, angle = b.state.ori.toAxisAngle()
        angle = angle if axis[2] >= 0 else -angle  # planar: a rotation about +z or -z
        verts = b.shape.worldVertices(b.state.pos, b.state.ori)
        lines.append(" ".join(["%d" % b.id] + ["%.17g" % v for v in (b.state.pos[0], b.state.pos[1], angle, b.shape.thickness)]
                              + ["%d" % len(verts)] + ["%.17g" % c for v in verts for c in (v[0], v[1])]))
    with open(filename, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(lines) - 1 - (len(comment.split("\n")) if comment else 0)


def read(filename):
    """[(id, [(x, y), ...] world vertices, thickness)] from a file written by :func:`text`."""
    out = []
    with open(filename) as f:
        first = f.readline().split()
        if first[:2] != ["#format", FORMAT]:
            raise ValueError("%s: not a block file (first line must be '#format %s')" % (filename, FORMAT))
        for n, line in enumerate(f, 2):
            if not line.strip() or line.startswith("#"):
                continue
            w = line.split()
            try:
                k = int(w[5])
                xy = [float(v) for v in w[6:6 + 2 * k]]
                if len(xy) != 2 * k:
                    raise ValueError
                out.append((int(w[0]), list(zip(xy[0::2], xy[1::2])), float(w[4])))
            except (ValueError, IndexError):
                raise ValueError("%s:%d: expected 'id x y angle thickness n x1 y1 ... xn yn'" % (filename, n)) from None
    return out
