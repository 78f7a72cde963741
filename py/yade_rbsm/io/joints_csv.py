"""The state of every RBSM joint to CSV (``export_joints``), for analysis elsewhere (a spreadsheet,
pandas: ``read_csv(f, comment="#")``).

One row per real joint (``points=False``), columns::

    id1,id2            the two bodies (normal from 1 to 2)
    p0x,p0y,p1x,p1y    ends of the contact segment [m]; nx,ny its unit normal; length [m]
    d0,d1              normal overlap at p0 and p1 [m] (> 0 penetration)
    normalForce        [N] (> 0 compression); shearForce [N] along the tangent (-ny, nx), on body 2
    strength           shear strength at the current normal stress [N]
    kn,ks              spring stiffnesses per unit area [Pa/m]; cohesion [Pa], tanPhi, tensileStrength [Pa]
    nIP,nIntact,nSlipping,nOpen   integration points: all, intact, slipping, open
    state              0 intact and sticking, 1 slipping somewhere, 2 open somewhere (open wins)
    plasticDissipation [J]

or one row per integration point (``points=True``): ``id1,id2,k,x,y,weight,deltaN,normalTraction,
shearTraction,intact,slipping,open`` (tractions in Pa, > 0 compression). The first line, a comment,
gives ``iter`` and ``time`` of the scene.
"""
import csv

from yade import wrapper

__all__ = ["export_joints", "JOINT_COLUMNS", "POINT_COLUMNS"]

JOINT_COLUMNS = ("id1", "id2", "p0x", "p0y", "p1x", "p1y", "nx", "ny", "length", "d0", "d1", "normalForce",
                 "shearForce", "strength", "kn", "ks", "cohesion", "tanPhi", "tensileStrength", "nIP", "nIntact",
                 "nSlipping", "nOpen", "state", "plasticDissipation")
POINT_COLUMNS = ("id1", "id2", "k", "x", "y", "weight", "deltaN", "normalTraction", "shearTraction",
                 "intact", "slipping", "open")


def _joint_row(I):
    g, ph = I.geom, I.phys
    state = 2 if ph.nOpen > 0 else (1 if ph.nSlipping > 0 else 0)
    vals = (I.id1, I.id2, g.p0[0], g.p0[1], g.p1[0], g.p1[1], g.normal[0], g.normal[1], g.length, g.d0, g.d1,
            ph.normalForce, ph.shearForce, ph.strength, ph.kn, ph.ks, ph.cohesion, ph.tanPhi, ph.tensileStrength,
            g.nIP, ph.nIntact, ph.nSlipping, ph.nOpen, state, ph.plasticDissipation)
    return [v if isinstance(v, int) else repr(float(v)) for v in vals]


def _point_rows(I):
    g, ph = I.geom, I.phys
    cols = (g.weights, g.deltaN, ph.normalTraction, ph.shearTraction, ph.intactPoints, ph.slippingPoints, ph.openPoints)
    for k, (w, dn, sn, tau, intact, slip, op) in enumerate(zip(*cols)):
        x = g.point(k)
        yield [I.id1, I.id2, k, repr(float(x[0])), repr(float(x[1])), repr(float(w)), repr(float(dn)),
               repr(float(sn)), repr(float(tau)), int(intact), int(slip), int(op)]


def export_joints(filename, points=False, O=None):
    """Writes the real RBSM joints of the scene (RbsmGeom + RbsmPhys interactions) to the CSV file
    *filename*, one row per joint or, with *points*, per integration point (columns in the module
    docstring). Returns the number of joints written."""
    if O is None:
        from yade import O
    joints = [I for I in O.interactions if I.isReal and isinstance(I.phys, wrapper.RbsmPhys)
              and isinstance(I.geom, wrapper.RbsmGeom)]
    with open(filename, "w", newline="") as f:
        f.write("# yade-rbsm joints 1, iter=%d time=%r\n" % (O.iter, float(O.time)))
        w = csv.writer(f, lineterminator="\n")
        w.writerow(POINT_COLUMNS if points else JOINT_COLUMNS)
        for I in joints:
            if points:
                w.writerows(_point_rows(I))
            else:
                w.writerow(_joint_row(I))
    return len(joints)
