"""VTK output of an RBSM scene with VTK's own Python library (Debian ``python3-vtk9``), as a time
series ParaView opens (File > Open the ``.pvd``).

:class:`VtkSeries` writes, at each call of :meth:`VtkSeries.write`, two XML PolyData files

* ``<prefix>_blocks_NNNN.vtp``: one polygon cell per :yref:`Polygon2D` body (its world vertices,
  counter-clockwise, z = 0; every block has its own points so that fields may jump between blocks).
  Point data: ``displacement`` (vertex position minus its reference position, from the body's
  ``refPos``/``refOri``) and ``velocity`` (v + ω × r) [m, m/s], ``id`` (body id of the vertex).
  Cell data: ``id`` (body id), ``displacement`` (of the centroid), ``displacementMagnitude``,
  ``velocity`` (of the centroid), ``angularVelocity`` (ω_z, rad/s), ``rotation`` (rad, since the
  reference orientation), ``fixed`` (1 for foundation/walls), ``mass``, ``stress`` (the block's
  average stress tensor from its joints' forces, tension positive, 9 components: measure.block_stresses);
  in a scene with deformable blocks also ``plasticShear`` and ``yieldMode`` (DeformableState's; 0 for rigid
  blocks).
* ``<prefix>_contacts_NNNN.vtp``: one line cell ``p0``–``p1`` per real RBSM joint. Cell data:
  ``id1``, ``id2``, ``normalForce`` (N, > 0 compression), ``shearForce`` (N, along the tangent, on
  body 2), ``strength`` (N), ``nIntact``, ``nSlipping``, ``nOpen`` (integration-point counts),
  ``state`` (0 intact and sticking, 1 slipping at some point, 2 open at some point; open wins),
  ``broken`` (1 if some point lost its cohesion), ``normal`` (unit vector from body 1 to body 2),
  ``force`` (force on body 2, N·normal + S·tangent, as a vector for glyphs), ``length``.

and rewrites ``<prefix>_blocks.pvd`` and ``<prefix>_contacts.pvd`` (VTK collection files listing
every snapshot with its time ``O.time``), so that the collection is valid after every snapshot,
also if the run is stopped.

:func:`recorder` gives the engine that YADE's ``VTKRecorder`` would be for spheres: a PyRunner for
``O.engines`` writing such a series every N steps (YADE's VTKRecorder writes no Polygon2D block, and
its contact and stress recorders would crash on RBSM joints).
"""
import os
import xml.etree.ElementTree as ET

from . import omega

__all__ = ["VtkSeries", "recorder", "series", "series_of", "blocks_polydata", "contacts_polydata", "write_pvd", "write_vtp"]


def _vtk():
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    return vtkPoints, vtkCellArray, vtkPolyData, numpy_to_vtk, numpy_to_vtkIdTypeArray


def _rot2(q):
    """Rotation angle about z of a YADE Quaternion (planar motion)."""
    aa = q.toAxisAngle()
    axis, ang = aa[0], aa[1]
    return ang if axis[2] >= 0 else -ang


def _xyz(a):
    """(n, 2) -> (n, 3) with z = 0 (VTK's points and vectors are 3D)."""
    import numpy as np
    return np.column_stack((a, np.zeros(len(a))))


def _polydata(points, sizes, connectivity, point_data, cell_data, lines=False):
    """vtkPolyData from numpy arrays: cells of *sizes* points each (polygons, or lines), data by name
    (float arrays become double, integer arrays int)."""
    import numpy as np
    vtkPoints, vtkCellArray, vtkPolyData, numpy_to_vtk, numpy_to_vtkIdTypeArray = _vtk()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(_xyz(points), dtype=np.float64), deep=True))
    cells = vtkCellArray()
    offsets = np.concatenate(([0], np.cumsum(sizes))).astype(np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(np.ascontiguousarray(connectivity, dtype=np.int64), deep=True))
    pd = vtkPolyData()
    pd.SetPoints(pts)
    (pd.SetLines if lines else pd.SetPolys)(cells)
    for data, arrays in ((pd.GetPointData(), point_data), (pd.GetCellData(), cell_data)):
        for name, a in arrays.items():
            a = np.asarray(a)
            a = np.ascontiguousarray(a, dtype=np.float64 if a.dtype.kind == "f" else np.int32)
            v = numpy_to_vtk(a, deep=True)
            v.SetName(name)
            data.AddArray(v)
    return pd


def _plastic_cells(plastic, deformable):
    """The yield of deformable blocks as cell arrays (none in a scene without them)."""
    import numpy as np
    if not deformable:
        return {}
    p = np.array(plastic, dtype=float).reshape(-1, 2)
    return {"plasticShear": p[:, 0], "yieldMode": p[:, 1].astype(np.int32)}


def blocks_polydata(O=None, table=None):
    """vtkPolyData of the Polygon2D bodies (see the module docstring); *table*: a
    measure.joint_table of the same state, if the caller has one (for the stresses)."""
    import numpy as np
    if O is None:
        from yade import O
    from .measure import block_stresses
    stresses = block_stresses(O, table)
    ids, sizes, x, x0, cell, plastic = [], [], [], [], [], []
    for b in O.bodies:
        if b is None or type(b.shape).__name__ != "Polygon2D":
            continue
        st, sh = b.state, b.shape
        pos, ori, rpos, rori, v, w = st.pos, st.ori, st.refPos, st.refOri, st.vel, st.angVel
        xs = sh.worldVertices(pos, ori)
        x += xs
        x0 += sh.worldVertices(rpos, rori)
        ids.append(b.id)
        sizes.append(len(xs))
        cell.append((pos[0], pos[1], rpos[0], rpos[1], v[0], v[1], w[2], _rot2(ori) - _rot2(rori), st.mass,
                     1 if omega.is_fixed(b) else 0))
        plastic.append((getattr(st, "plasticShear", 0.0), getattr(st, "yieldMode", 0)))
    ids, sizes = np.array(ids, dtype=np.int64), np.array(sizes, dtype=np.int64)
    x = np.array([(p[0], p[1]) for p in x], dtype=float).reshape(-1, 2)
    x0 = np.array([(p[0], p[1]) for p in x0], dtype=float).reshape(-1, 2)
    cell = np.array(cell, dtype=float).reshape(-1, 10)
    pos, d, vel, om = cell[:, 0:2], cell[:, 0:2] - cell[:, 2:4], cell[:, 4:6], cell[:, 6]
    owner = np.repeat(np.arange(len(ids)), sizes)
    r = x - pos[owner]
    pvel = vel[owner] + om[owner, None] * np.column_stack((-r[:, 1], r[:, 0]))  # v + ω ẑ × r
    sig = np.array([[stresses[i][r_, c_] for r_ in range(3) for c_ in range(3)] for i in ids], dtype=float).reshape(-1, 9)
    pd = _polydata(x, sizes, np.arange(len(x)),
                   {"displacement": _xyz(x - x0), "velocity": _xyz(pvel), "id": ids[owner]},
                   {"id": ids, "displacement": _xyz(d), "displacementMagnitude": np.hypot(d[:, 0], d[:, 1]),
                    "velocity": _xyz(vel), "angularVelocity": om, "rotation": cell[:, 7], "fixed": cell[:, 9].astype(np.int32),
                    "mass": cell[:, 8], "stress": sig,
                    **_plastic_cells(plastic, any(hasattr(b.state, "plasticShear") for b in O.bodies if b is not None))})
    pd.GetPointData().SetActiveVectors("displacement")
    pd.GetCellData().SetActiveScalars("displacementMagnitude")
    return pd


def contacts_polydata(O=None, table=None):
    """vtkPolyData of the real RBSM joints as line cells p0-p1 (see the module docstring); *table*: a
    measure.joint_table of the same state, if the caller has one."""
    import numpy as np
    if O is None:
        from yade import O
    from .measure import joint_table
    t = joint_table(O) if table is None else table
    J = len(t.id1)
    state = np.where(t.nOpen > 0, 2, np.where(t.nSlipping > 0, 1, 0))  # 0 sticking, 1 slipping, 2 open (open wins)
    force = t.normalForce[:, None] * t.normal + t.shearForce[:, None] * t.tangent
    pd = _polydata(np.column_stack((t.p0, t.p1)).reshape(-1, 2), np.full(J, 2), np.arange(2 * J), {},
                   {"id1": t.id1, "id2": t.id2, "nIntact": t.nIntact, "nSlipping": t.nSlipping, "nOpen": t.nOpen,
                    "state": state, "broken": (t.nIntact < t.nPoints).astype(np.int32),
                    "normalForce": t.normalForce, "shearForce": t.shearForce, "strength": t.strength, "length": t.length,
                    "normal": _xyz(t.normal), "force": _xyz(force)}, lines=True)
    pd.GetCellData().SetActiveScalars("normalForce")
    return pd


def write_vtp(polydata, path, binary=True):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    w = vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(polydata)
    if binary:
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToLZ4()  # 3x faster than VTK's default zlib, files 30 % larger (ParaView >= 5.5 reads it)
    else:
        w.SetDataModeToAscii()
    if w.Write() != 1:
        raise IOError("vtkXMLPolyDataWriter failed to write %s" % path)
    return path


def write_pvd(path, entries):
    """VTK collection file: *entries* ``[(time, file name relative to the .pvd), ...]``."""
    root = ET.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
    coll = ET.SubElement(root, "Collection")
    for t, f in entries:
        ET.SubElement(coll, "DataSet", timestep=repr(float(t)), group="", part="0", file=f)
    ET.ElementTree(root).write(path, xml_declaration=True, encoding="utf-8")
    return path


class VtkSeries:
    """Time series of VTK files of the blocks and contacts in *out_dir* (created if needed).

    ``series = VtkSeries("out/vtk", "landslide"); series.write()`` after each stage, or as a
    PyRunner: ``PyRunner(command="series.write()", iterPeriod=1000)`` with ``series`` a global of the
    script. ``contacts=False`` writes the blocks only. :attr:`files` lists what has been written."""

    def __init__(self, out_dir, prefix="rbsm", contacts=True, binary=True):
        self.out_dir, self.prefix, self.contacts, self.binary = out_dir, prefix, contacts, binary
        os.makedirs(out_dir, exist_ok=True)
        self.entries = {"blocks": [], "contacts": []}
        self.files = []

    @property
    def pvd(self):
        return {k: os.path.join(self.out_dir, "%s_%s.pvd" % (self.prefix, k)) for k in self.entries
                if k == "blocks" or self.contacts}

    def write(self, O=None, time=None):
        """One snapshot at O.time (or *time*); returns the paths of the .vtp files written."""
        if O is None:
            from yade import O
        t = O.time if time is None else time
        k = len(self.entries["blocks"])
        out = []
        from .measure import joint_table
        table = joint_table(O)  # one pass over the joints for the block stresses and the contacts
        parts = [("blocks", blocks_polydata)] + ([("contacts", contacts_polydata)] if self.contacts else [])
        for kind, fn in parts:
            name = "%s_%s_%04d.vtp" % (self.prefix, kind, k)
            write_vtp(fn(O, table), os.path.join(self.out_dir, name), self.binary)
            self.entries[kind].append((t, name))
            write_pvd(os.path.join(self.out_dir, "%s_%s.pvd" % (self.prefix, kind)), self.entries[kind])
            out.append(os.path.join(self.out_dir, name))
        self.files += out
        return out


def _read_pvd(path):
    """[(time, file)] of a VTK collection file; [] if there is none (or it cannot be read)."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return []
    coll = root.find("Collection")
    return [] if coll is None else [(float(d.get("timestep")), d.get("file")) for d in coll.findall("DataSet")]


_series = {}  # the series of the recorder() engines, by (directory, prefix)
_made = 0  # recorder() engines made in this process (their default labels)


def series(out_dir, prefix="rbsm", contacts=True, binary=True, resume=True):
    """The VtkSeries that recorder() engines write to *out_dir*/*prefix*: made at its first use in this
    process. Made after ``O.load`` (a restart: the engine was saved, the series lived in the process that
    saved it), it keeps the snapshots its collection files list up to ``O.time`` and numbers the next
    ones on; snapshots after ``O.time`` (from a run that went further) and those of a new run from t = 0
    are not kept. *resume* False: a new series, whatever the files say (what recorder() makes)."""
    from yade import O
    key = (os.path.abspath(out_dir), prefix)
    if key not in _series or not resume:
        s = VtkSeries(out_dir, prefix, contacts, binary)
        for kind in s.entries if resume else ():
            s.entries[kind] = [e for e in _read_pvd(os.path.join(out_dir, "%s_%s.pvd" % (prefix, kind))) if e[0] < O.time]
        if contacts and len(s.entries["contacts"]) != len(s.entries["blocks"]):
            s.entries = {"blocks": [], "contacts": []}  # not the two collections of one series: start anew
        _series[key] = s
    return _series[key]


def recorder(out_dir, prefix="rbsm", iterPeriod=0, virtPeriod=0.0, realPeriod=0.0, contacts=True, binary=True, label=""):
    """A PyRunner for ``O.engines`` that writes a :class:`VtkSeries` snapshot (blocks with their
    stresses, joints) every *iterPeriod* steps, *virtPeriod* s of simulated or *realPeriod* s of wall
    time: the RBSM counterpart of YADE's ``VTKRecorder``. ``vtkexport.series_of(engine)`` gives its
    VtkSeries (files written, .pvd paths). The engine names its series by directory and prefix, so a
    scene saved with it and loaded by another process goes on writing the same collection::

        O.engines = O.engines + [vtkexport.recorder("out/vtk", "slope", iterPeriod=500)]
    """
    from yade import wrapper
    if not (iterPeriod > 0 or virtPeriod > 0 or realPeriod > 0):
        raise ValueError("vtkexport.recorder: give iterPeriod, virtPeriod or realPeriod > 0")
    global _made
    args = (str(out_dir), str(prefix), bool(contacts), bool(binary))
    series(*args, resume=False)
    _made += 1
    return wrapper.PyRunner(command="import yade_rbsm.vtkexport as _v; _v.series(*%r).write()" % (args,),
                            iterPeriod=int(iterPeriod), virtPeriod=float(virtPeriod), realPeriod=float(realPeriod),
                            label=label or "vtkRecorder%d" % (_made - 1))


def series_of(engine):
    """The VtkSeries that a recorder() engine writes (its files, pvd paths)."""
    import ast
    import re
    m = re.search(r"_v\.series\(\*(\(.*\))\)\.write\(\)", engine.command)
    if not m:
        raise ValueError("vtkexport.series_of: not an engine made by vtkexport.recorder()")
    return series(*ast.literal_eval(m.group(1)))
