"""RBSM blocks to and from a CSV text file (``export_blocks`` / ``import_blocks``).

The format (comma-separated, one block per row, ``#`` lines are comments)::

    # yade-rbsm blocks 1
    # material label=rock young=200000000 poisson=0.2 planeStrain=1 density=2403 frictionAngle=0.5236 cohesion=0 tensileStrength=0 ductile=0 jointKn=0 jointKs=0
    id,material,fixed,thickness,vx,vy,angVel,x1,y1,x2,y2,x3,y3,x4,y4
    0,rock,1,1,0,0,0,-100,-1,100,-1,100,0,-100,0
    1,rock,0,1,0.5,0,0,0,0,4,0,4,1,0,1

* columns are found by the header's names, in any order; ``material`` and the vertices are needed,
  the others are optional (defaults: fixed 0, thickness 1 m, velocities 0; an empty cell too);
* ``x1,y1,x2,y2,...``: the block's vertices in the world frame [m], counter-clockwise, as many as
  the block has (rows of fewer vertices leave the rest empty); the block is convex;
* ``material``: the label of an :yref:`RbsmMat`; ``# material label=... key=value ...`` lines
  define them with RbsmMat's attribute names (SI units, angles in radians) so that a file carries
  its scene; ``fixed``: 1 for a foundation or wall block (all degrees of freedom blocked);
  ``vx, vy`` [m/s] and ``angVel`` [rad/s] the velocity of the centroid and the angular velocity;
  ``id`` is the body id at export (import ignores it: bodies get new ids in file order).
"""
import csv
import math
import warnings

from yade import wrapper

from ..blocks import polygon2d
from ..omega import is_fixed

__all__ = ["export_blocks", "import_blocks", "MATERIAL_KEYS"]

SIGNATURE = "# yade-rbsm blocks 1"
# every attribute of RbsmMat but its id and label, in this order (those it gains later come after them):
# a material's joint stiffness or ductility must not come back as the default
_FIRST_KEYS = ("young", "poisson", "planeStrain", "density", "frictionAngle", "cohesion", "tensileStrength", "ductile",
               "jointKn", "jointKs")
_BOOL_KEYS = {k for k, v in wrapper.RbsmMat().dict().items() if isinstance(v, bool)}
MATERIAL_KEYS = tuple(k for k in _FIRST_KEYS if k in wrapper.RbsmMat().dict()) + tuple(sorted(
    k for k in wrapper.RbsmMat().dict() if k not in _FIRST_KEYS + ("id", "label")))
OPTIONAL = {"id": None, "fixed": 0, "thickness": 1.0, "vx": 0.0, "vy": 0.0, "angVel": 0.0}


def _num(x):
    return repr(float(x))


def _material_line(label, m):
    vals = " ".join("%s=%s" % (k, int(getattr(m, k)) if k in _BOOL_KEYS else _num(getattr(m, k))) for k in MATERIAL_KEYS)
    return "# material label=%s %s" % (label, vals)


def _key(m):
    """Identity of a material: its index in O.materials; its values for one not in O.materials (each
    access to b.material gives a new Python object, so id() cannot tell)."""
    return m.id if m.id >= 0 else tuple(sorted(m.dict().items()))


def _labels(blocks, O):
    """Label of each material used (its label, else 'mat<id>', 'unlisted<n>' for a material not in
    O.materials); two materials sharing a label are an error."""
    labels, by_label = {}, {}
    for b in blocks:
        m = b.material
        key = _key(m)
        if key in labels:
            continue
        label = m.label or ("mat%d" % m.id if m.id >= 0 else "unlisted%d" % len(labels))
        if label in by_label:
            raise ValueError("export_blocks: two different materials are labelled %r (bodies #%d and #%d): "
                             "give them distinct labels" % (label, by_label[label][1], b.id))
        if any(c in label for c in ", \"\n#="):
            raise ValueError("export_blocks: material label %r (body #%d) contains a space, comma, quote, '#' or '='" % (label, b.id))
        labels[key] = label
        by_label[label] = (m, b.id)
    return labels, by_label


def export_blocks(filename, bodies=None, O=None):
    """Writes the :yref:`Polygon2D` bodies (all of O.bodies, or the bodies/ids in *bodies*) to the CSV
    file *filename* in the format of this module, with the definition of every material they use.
    Other bodies are skipped with a warning. Returns the number of blocks written."""
    if O is None:
        from yade import O
    if bodies is None:
        bodies = [b for b in O.bodies if b is not None]
    else:
        bodies = [O.bodies[b] if isinstance(b, int) else b for b in bodies]
    blocks = [b for b in bodies if isinstance(b.shape, wrapper.Polygon2D)]
    skipped = len(bodies) - len(blocks)
    if skipped:
        warnings.warn("export_blocks: %d bodies that are not Polygon2D blocks were not written to %s" % (skipped, filename))
    odd = [b.id for b in blocks if b.state.blockedDOFs not in ("zXY", "xyzXYZ")]
    if odd:
        warnings.warn("export_blocks: bodies %s block degrees of freedom other than a free ('zXY') or fixed "
                      "('xyzXYZ') block; the file says only fixed (all blocked) or not" % odd[:10])
    labels, by_label = _labels(blocks, O)
    nmax = max((len(b.shape.vertices) for b in blocks), default=3)
    with open(filename, "w", newline="") as f:
        f.write(SIGNATURE + "\n")
        for label, (m, _) in by_label.items():
            f.write(_material_line(label, m) + "\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["id", "material", "fixed", "thickness", "vx", "vy", "angVel"]
                   + [c % (i + 1) for i in range(nmax) for c in ("x%d", "y%d")])
        for b in blocks:
            m, st = b.material, b.state
            row = [b.id, labels[_key(m)], 1 if is_fixed(b) else 0,
                   _num(b.shape.thickness), _num(st.vel[0]), _num(st.vel[1]), _num(st.angVel[2])]
            for v in b.shape.worldVertices(st.pos, st.ori):
                row += [_num(v[0]), _num(v[1])]
            w.writerow(row)
    return len(blocks)


def _parse_material(text, where):
    fields = {}
    for item in text.split():
        if "=" not in item:
            raise ValueError("%s: material definition item %r is not key=value" % (where, item))
        k, v = item.split("=", 1)
        fields[k] = v
    label = fields.pop("label", None)
    if not label:
        raise ValueError("%s: material definition without label=" % where)
    unknown = set(fields) - set(MATERIAL_KEYS)
    if unknown:
        raise ValueError("%s: material %r: unknown attribute(s) %s (known: %s)" % (where, label, ", ".join(sorted(unknown)), ", ".join(MATERIAL_KEYS)))
    kw = {}
    for k, v in fields.items():
        try:
            kw[k] = bool(int(v)) if k in _BOOL_KEYS else float(v)
        except ValueError:
            raise ValueError("%s: material %r: %s=%r is not a number" % (where, label, k, v)) from None
    return label, kw


def _resolve(label, defined, materials, O, where):
    """The RbsmMat for *label*: *materials* first, then O.materials, then the file's definition
    (appended to O.materials); a file definition differing from O.materials' material is an error."""
    if materials is not None:
        if isinstance(materials, wrapper.Material):
            return materials
        if label in materials:
            m = materials[label]
            return O.materials[m] if isinstance(m, (int, str)) else m
        raise ValueError("%s: material %r is not in the materials given (%s)" % (where, label, ", ".join(map(str, materials))))
    existing = [m for m in O.materials if m.label == label]
    if existing:
        m = existing[0]
        if label in defined:
            differ = [k for k, v in defined[label][0].items() if getattr(m, k) != v]
            if differ:
                raise ValueError("%s: material %r of the file differs from O.materials' %r in %s" % (
                    defined[label][1], label, label, ", ".join(differ)))
        return m
    if label in defined:
        m = wrapper.RbsmMat(label=label, **defined[label][0])
        O.materials.append(m)
        return m
    raise ValueError("%s: material %r is neither defined in the file ('# material label=%s ...') nor in O.materials" % (where, label, label))


def _cell(row, col, name, where, default):
    if col is None or col >= len(row) or row[col].strip() == "":
        return default
    try:
        return float(row[col])
    except ValueError:
        raise ValueError("%s: column %s: %r is not a number" % (where, name, row[col])) from None


def import_blocks(filename, materials=None, O=None):
    """Reads blocks from the CSV file *filename* (format of this module) and returns the list of
    new bodies, to be appended: ``O.bodies.append(import_blocks("slope.csv"))``.

    *materials*: None (the labels are looked up in O.materials, then in the file's ``# material``
    lines, whose materials are appended to O.materials), a dict label -> RbsmMat (or its id/label
    in O.materials), or one RbsmMat for every block. A malformed file raises ValueError naming
    the file, line and problem."""
    if O is None:
        from yade import O
    defined, header, bodies, cols = {}, None, [], {}
    with open(filename, newline="") as f:
        for lineno, row in enumerate(csv.reader(f), start=1):
            where = "%s:%d" % (filename, lineno)
            if not row or all(not c.strip() for c in row):
                continue
            if row[0].lstrip().startswith("#"):
                text = ",".join(row).lstrip()[1:].strip()
                if text.startswith("material "):
                    label, kw = _parse_material(text[len("material "):], where)
                    if label in defined:
                        raise ValueError("%s: material %r defined twice (first at %s)" % (where, label, defined[label][1]))
                    defined[label] = (kw, where)
                continue
            if header is None:
                header = [c.strip() for c in row]
                cols = {n: i for i, n in enumerate(header)}
                if "material" not in cols or "x1" not in cols or "y1" not in cols:
                    raise ValueError("%s: header must name the columns material, x1, y1, x2, y2, ... (got %s)" % (where, ",".join(header)))
                first = cols["x1"]
                expect = [c % (i + 1) for i in range((len(header) - first) // 2) for c in ("x%d", "y%d")]
                if header[first:first + len(expect)] != expect or len(header) - first != len(expect):
                    raise ValueError("%s: the vertex columns must be the last ones, x1,y1,x2,y2,... (got %s)" % (where, ",".join(header[first:])))
                unknown = set(header[:first]) - set(OPTIONAL) - {"material"}
                if unknown:
                    raise ValueError("%s: unknown column(s) %s" % (where, ", ".join(sorted(unknown))))
                continue
            first = cols["x1"]
            coords = [c.strip() for c in row[first:]]
            while coords and coords[-1] == "":
                coords.pop()
            if len(coords) % 2:
                raise ValueError("%s: odd number of vertex coordinates (%d)" % (where, len(coords)))
            try:
                pts = [(float(coords[i]), float(coords[i + 1])) for i in range(0, len(coords), 2)]
            except ValueError:
                raise ValueError("%s: a vertex coordinate is not a number (%s)" % (where, ",".join(coords))) from None
            label = row[cols["material"]].strip() if cols["material"] < len(row) else ""
            if not label:
                raise ValueError("%s: no material" % where)
            mat = _resolve(label, defined, materials, O, where)
            fixed = _cell(row, cols.get("fixed"), "fixed", where, 0)
            if fixed not in (0, 1):
                raise ValueError("%s: column fixed must be 0 or 1, got %r" % (where, row[cols["fixed"]]))
            thickness = _cell(row, cols.get("thickness"), "thickness", where, 1.0)
            vel = [_cell(row, cols.get(n), n, where, 0.0) for n in ("vx", "vy", "angVel")]
            if not all(math.isfinite(v) for v in vel):
                raise ValueError("%s: velocity is not finite" % where)
            try:
                b = polygon2d(pts, mat, thickness=thickness, fixed=bool(fixed))
            except ValueError as e:
                raise ValueError("%s: %s" % (where, e)) from None
            # a fixed block keeps its velocity too: YADE moves it kinematically (a moving wall)
            b.state.vel = (vel[0], vel[1], 0)
            b.state.angVel = (0, 0, vel[2])
            bodies.append(b)
    if header is None:
        raise ValueError("%s: no header line (material,x1,y1,...)" % filename)
    return bodies
