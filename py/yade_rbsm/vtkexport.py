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
  average stress tensor from its joints' forces, tension positive, 9 components: measure.block_stresses).
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
import math
import os
import xml.etree.ElementTree as ET

from . import omega

__all__ = ["VtkSeries", "recorder", "blocks_polydata", "contacts_polydata", "write_pvd", "write_vtp"]


def _vtk():
    from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray, vtkIntArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    return vtkPoints, vtkDoubleArray, vtkIntArray, vtkCellArray, vtkPolyData


def _array(kind, name, ncomp=1):
    a = kind()
    a.SetName(name)
    a.SetNumberOfComponents(ncomp)
    return a


def _rot2(q):
    """Rotation angle about z of a YADE Quaternion (planar motion)."""
    aa = q.toAxisAngle()
    axis, ang = aa[0], aa[1]
    return ang if axis[2] >= 0 else -ang


def blocks_polydata(O=None):
    """vtkPolyData of the Polygon2D bodies (see the module docstring)."""
    if O is None:
        from yade import O
    from yade import Vector3
    vtkPoints, vtkDoubleArray, vtkIntArray, vtkCellArray, vtkPolyData = _vtk()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    polys = vtkCellArray()
    p_disp = _array(vtkDoubleArray, "displacement", 3)
    p_vel = _array(vtkDoubleArray, "velocity", 3)
    p_id = _array(vtkIntArray, "id")
    c_id = _array(vtkIntArray, "id")
    c_disp = _array(vtkDoubleArray, "displacement", 3)
    c_dmag = _array(vtkDoubleArray, "displacementMagnitude")
    c_vel = _array(vtkDoubleArray, "velocity", 3)
    c_om = _array(vtkDoubleArray, "angularVelocity")
    c_rot = _array(vtkDoubleArray, "rotation")
    c_fix = _array(vtkIntArray, "fixed")
    c_mass = _array(vtkDoubleArray, "mass")
    c_stress = _array(vtkDoubleArray, "stress", 9)
    from .measure import block_stresses
    stresses = block_stresses(O)
    for b in O.bodies:
        if b is None or type(b.shape).__name__ != "Polygon2D":
            continue
        st = b.state
        pos, ori, rpos, rori = st.pos, st.ori, st.refPos, st.refOri
        v, w = st.vel, st.angVel
        verts = list(b.shape.vertices)
        polys.InsertNextCell(len(verts))
        for loc in verts:
            l3 = Vector3(loc[0], loc[1], 0)
            r = ori * l3
            x = pos + r
            x0 = rpos + rori * l3
            k = pts.InsertNextPoint(x[0], x[1], 0.0)
            polys.InsertCellPoint(k)
            p_disp.InsertNextTuple3(x[0] - x0[0], x[1] - x0[1], 0.0)
            p_vel.InsertNextTuple3(v[0] - w[2] * r[1], v[1] + w[2] * r[0], 0.0)
            p_id.InsertNextValue(b.id)
        d = pos - rpos
        c_id.InsertNextValue(b.id)
        c_disp.InsertNextTuple3(d[0], d[1], 0.0)
        c_dmag.InsertNextValue(math.hypot(d[0], d[1]))
        c_vel.InsertNextTuple3(v[0], v[1], 0.0)
        c_om.InsertNextValue(w[2])
        c_rot.InsertNextValue(_rot2(ori) - _rot2(rori))
        c_fix.InsertNextValue(1 if omega.is_fixed(b) else 0)
        c_mass.InsertNextValue(st.mass)
        sg = stresses[b.id]
        c_stress.InsertNextTuple([sg[i, j] for i in range(3) for j in range(3)])
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(polys)
    for a in (p_disp, p_vel, p_id):
        pd.GetPointData().AddArray(a)
    pd.GetPointData().SetActiveVectors("displacement")
    for a in (c_id, c_disp, c_dmag, c_vel, c_om, c_rot, c_fix, c_mass, c_stress):
        pd.GetCellData().AddArray(a)
    pd.GetCellData().SetActiveScalars("displacementMagnitude")
    return pd


def joint_state(ph):
    """0 intact and sticking, 1 slipping somewhere, 2 open somewhere (open wins)."""
    return 2 if ph.nOpen > 0 else (1 if ph.nSlipping > 0 else 0)


def contacts_polydata(O=None):
    """vtkPolyData of the real RBSM joints as line cells p0-p1 (see the module docstring)."""
    if O is None:
        from yade import O
    vtkPoints, vtkDoubleArray, vtkIntArray, vtkCellArray, vtkPolyData = _vtk()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    lines = vtkCellArray()
    ints = {n: _array(vtkIntArray, n) for n in ("id1", "id2", "nIntact", "nSlipping", "nOpen", "state", "broken")}
    dbls = {n: _array(vtkDoubleArray, n) for n in ("normalForce", "shearForce", "strength", "length")}
    vecs = {n: _array(vtkDoubleArray, n, 3) for n in ("normal", "force")}
    for I in omega.joints(O):
        g, ph = I.geom, I.phys
        a = pts.InsertNextPoint(g.p0[0], g.p0[1], 0.0)
        b = pts.InsertNextPoint(g.p1[0], g.p1[1], 0.0)
        lines.InsertNextCell(2)
        lines.InsertCellPoint(a)
        lines.InsertCellPoint(b)
        npts = len(list(ph.intactPoints))
        for n, v in (("id1", I.id1), ("id2", I.id2), ("nIntact", ph.nIntact), ("nSlipping", ph.nSlipping),
                     ("nOpen", ph.nOpen), ("state", joint_state(ph)), ("broken", 1 if ph.nIntact < npts else 0)):
            ints[n].InsertNextValue(int(v))
        for n, v in (("normalForce", ph.normalForce), ("shearForce", ph.shearForce), ("strength", ph.strength),
                     ("length", g.length)):
            dbls[n].InsertNextValue(float(v))
        nx, ny = g.normal[0], g.normal[1]
        tx, ty = g.tangent[0], g.tangent[1]
        vecs["normal"].InsertNextTuple3(nx, ny, 0.0)
        vecs["force"].InsertNextTuple3(ph.normalForce * nx + ph.shearForce * tx,
                                       ph.normalForce * ny + ph.shearForce * ty, 0.0)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetLines(lines)
    for a in list(ints.values()) + list(dbls.values()) + list(vecs.values()):
        pd.GetCellData().AddArray(a)
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
        parts = [("blocks", blocks_polydata)] + ([("contacts", contacts_polydata)] if self.contacts else [])
        for kind, fn in parts:
            name = "%s_%s_%04d.vtp" % (self.prefix, kind, k)
            write_vtp(fn(O), os.path.join(self.out_dir, name), self.binary)
            self.entries[kind].append((t, name))
            write_pvd(os.path.join(self.out_dir, "%s_%s.pvd" % (self.prefix, kind)), self.entries[kind])
            out.append(os.path.join(self.out_dir, name))
        self.files += out
        return out


_recorders = {}  # the series of the recorder() engines, by number (a PyRunner's command is a string)


def recorder(out_dir, prefix="rbsm", iterPeriod=0, virtPeriod=0.0, realPeriod=0.0, contacts=True, binary=True, label=""):
    """A PyRunner for ``O.engines`` that writes a :class:`VtkSeries` snapshot (blocks with their
    stresses, joints) every *iterPeriod* steps, *virtPeriod* s of simulated or *realPeriod* s of wall
    time: the RBSM counterpart of YADE's ``VTKRecorder``. ``vtkexport.series_of(engine)`` gives its
    VtkSeries (files written, .pvd paths)::

        O.engines = O.engines + [vtkexport.recorder("out/vtk", "slope", iterPeriod=500)]
    """
    from yade import wrapper
    if not (iterPeriod > 0 or virtPeriod > 0 or realPeriod > 0):
        raise ValueError("vtkexport.recorder: give iterPeriod, virtPeriod or realPeriod > 0")
    key = len(_recorders)
    _recorders[key] = VtkSeries(out_dir, prefix, contacts, binary)
    return wrapper.PyRunner(command="import yade_rbsm.vtkexport as _v; _v._recorders[%d].write()" % key, iterPeriod=int(iterPeriod),
                            virtPeriod=float(virtPeriod), realPeriod=float(realPeriod), label=label or "vtkRecorder%d" % key)


def series_of(engine):
    """The VtkSeries that a recorder() engine writes (its files, pvd paths)."""
    import re
    m = re.search(r"_recorders\[(\d+)\]", engine.command)
    if not m:
        raise ValueError("vtkexport.series_of: not an engine made by vtkexport.recorder()")
    return _recorders[int(m.group(1))]
