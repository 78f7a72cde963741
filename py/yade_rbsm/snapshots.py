"""PNG snapshots of an RBSM scene (matplotlib, Agg): blocks coloured by displacement magnitude
(|pos - refPos|) or by the plastic shear of plastic deformable blocks (the band of a mechanism), fixed blocks
grey, failed joints red (slipping somewhere, ductile joints with their cohesion too, or broken and open), like
the seed paper's Fig. 5-6."""
import math

from . import omega

__all__ = ["block_polygons", "snapshot"]


def block_polygons(O=None):
    """[(id, world vertices, displacement magnitude, fixed)] for every Polygon2D body."""
    if O is None:
        from yade import O
    from yade import Vector3
    out = []
    for b in O.bodies:
        if b is None or type(b.shape).__name__ != "Polygon2D":
            continue
        pos, ori = b.state.pos, b.state.ori
        pts = []
        for v in b.shape.vertices:
            w = ori * Vector3(v[0], v[1], 0)
            pts.append((pos[0] + w[0], pos[1] + w[1]))
        d = (pos - b.state.refPos).norm()
        out.append((b.id, pts, d, omega.is_fixed(b)))
    return out


def failed_joints(O=None, min_share=0.05):
    """The segments of the joints at their strength (slipping somewhere, ductile joints too) or broken open; not
    those shorter than *min_share* x the distance between their blocks' centroids across them, h1 + h2 (a corner
    touching a face: a triangle mesh has two to eight a block, and they slip while the mesh deforms), nor those with
    no strength at all (a smooth wall or footing slips by design: it cannot fail)."""
    if O is None:
        from yade import O
    segs = []
    for I in omega.joints(O):
        ph, g = I.phys, I.geom
        if g.length < min_share * (g.h1 + g.h2) or (ph.tanPhi == 0 and ph.cohesion == 0 and ph.tensileStrength == 0):
            continue
        if ph.nSlipping > 0 or (ph.nIntact == 0 and ph.nOpen > 0):  # at its strength (ductile too), or broken open
            segs.append([(g.p0[0], g.p0[1]), (g.p1[0], g.p1[1])])
    return segs


FIELDS = {"displacement": "displacement [m]", "plasticShear": "plastic shear strain [-]"}


def block_values(field, O=None):
    """{body id: value} of *field* for every Polygon2D body: "displacement" (|pos − refPos| [m]) or
    "plasticShear" (DeformableState.plasticShear, 0 for rigid blocks)."""
    if O is None:
        from yade import O
    if field not in FIELDS:
        raise ValueError("unknown field %r: one of %s" % (field, ", ".join(sorted(FIELDS))))
    out = {}
    for b in O.bodies:
        if b is None or type(b.shape).__name__ != "Polygon2D":
            continue
        out[b.id] = (b.state.pos - b.state.refPos).norm() if field == "displacement" else getattr(b.state, "plasticShear", 0.0)
    return out


def snapshot(path, title="", vmax=None, O=None, slip=None, dpi=110, field="displacement", values=None, label=None):
    """Write a PNG of the scene to *path*; *slip*: optional polyline drawn dashed; *field*: what colours the
    free blocks, "displacement" or "plasticShear" (block_values), or *values* ({body id: value}, the colour bar
    named *label*). Returns path."""
    if O is None:
        from yade import O
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection, LineCollection

    polys = block_polygons(O)
    free = [p for p in polys if not p[3]]
    fixed = [p for p in polys if p[3]]
    if values is None and field != "displacement":
        values = block_values(field, O)
    disp = [p[2] if values is None else values.get(p[0], 0.0) for p in free]
    vmax = vmax if vmax is not None else max(max(disp, default=0.0), 1e-6)
    # fixed margins instead of tight_layout, which measured every tick label and took half of the time
    fig, ax = plt.subplots(figsize=(9, 5), gridspec_kw=dict(left=0.07, right=0.94, bottom=0.1, top=0.93))
    if fixed:
        ax.add_collection(PolyCollection([p[1] for p in fixed], facecolors="0.8", edgecolors="0.4", linewidths=0.5))
    pc = PolyCollection([p[1] for p in free], array=disp, cmap="viridis", edgecolors="k", linewidths=0.3)
    pc.set_clim(0, vmax)
    ax.add_collection(pc)
    segs = failed_joints(O)
    if segs:
        ax.add_collection(LineCollection(segs, colors="red", linewidths=1.5))
    if slip is not None:
        ax.plot([p[0] for p in slip], [p[1] for p in slip], "w--", lw=1)
    xs = [x for p in polys for x, _ in p[1]]
    ys = [y for p in polys for _, y in p[1]]
    if xs:
        ax.set_xlim(min(xs) - 0.5, max(xs) + 0.5)
        ax.set_ylim(min(ys) - 0.5, max(ys) + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.colorbar(pc, ax=ax, label=label or FIELDS[field], shrink=0.8, fraction=0.05, pad=0.02)
    ax.set_title(title + ("  (red: failed joints, %d)" % len(segs)))
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path
