"""Measures of an RBSM packing that YADE's own utilities compute for spheres only.

YADE's ``utils.getStress()``, ``bodyStressTensors()``, ``fabricTensor()``, ``aabbExtrema()`` and
``porosity()`` read sphere radii and sphere contacts (static casts in YADE's C++): on blocks they
give NaN or garbage. Their RBSM equivalents, from the joints' tractions at their integration points:

* :func:`block_stresses` - the average stress tensor of each block, σ_b = (1/V_b) Σ x ⊗ f over the
  forces f the joints (and, in a mixed scene, YADE's sphere contacts) apply to it at points x
  (relative to its centroid; V_b = area × thickness);
* :func:`stress` - the average stress of a set of blocks (default: the free blocks), the volume
  average of σ_b (Love-Weber: internal joints contribute (c1 − c2) ⊗ f, the branch vector form);
* :func:`fabric_tensor` - (1/N) Σ n ⊗ n over the joints (optionally weighted by their length);
* :func:`aabb_extrema` - the corners of the box around the blocks' world vertices;
* :func:`porosity` - 1 − (area of the blocks) / (area of a region, default the box).

Stresses follow YADE's sign convention (tension positive, compression negative) and are 3×3
(``Matrix3``), the x-y block filled; the stress of a block in equilibrium is symmetric. Body forces
(gravity) act inside the blocks and are not part of the sum (as in YADE's Love-Weber stress).
"""
import math
import types

from . import omega

__all__ = ["joint_point_forces", "joint_table", "block_stresses", "stress", "fabric_tensor", "aabb_extrema", "porosity"]


def _O(O):
    if O is None:
        from yade import O
    return O


def _blocks(O, ids=None):
    from yade import wrapper
    bodies = [b for b in O.bodies if b is not None and isinstance(b.shape, wrapper.Polygon2D)]
    if ids is None:
        return bodies
    want = set(ids)
    return [b for b in bodies if b.id in want]


def _rbsm_joints(O):
    for I in omega.joints(O):
        if type(I.geom).__name__ == "RbsmGeom":
            yield I


def joint_point_forces(I):
    """[(x, y, fx, fy)]: world position of each integration point of joint I and the force [N] that the
    joint applies there to body 2 (body 1 gets the opposite): (σn_k n + τ_k t) w_k ℓ thickness."""
    g, ph = I.geom, I.phys
    n, t = g.normal, g.tangent
    out = []
    for k, (w, sn, tau) in enumerate(zip(g.weights, ph.normalTraction, ph.shearTraction)):
        a = w * g.length * g.thickness
        p = g.point(k)
        out.append((p[0], p[1], (sn * n[0] + tau * t[0]) * a, (sn * n[1] + tau * t[1]) * a))
    return out


def joint_table(O=None):
    """The real RBSM joints in one pass over O.interactions, as numpy arrays (what exports and averages
    over many joints read; one Python loop instead of one per measure). Per joint (length J):
    ``id1``, ``id2``, ``p0``, ``p1``, ``normal``, ``tangent`` (J×2), ``length``, ``thickness``,
    ``normalForce``, ``shearForce``, ``strength``, ``nIntact``, ``nSlipping``, ``nOpen``, ``nPoints``;
    per integration point (length P): ``joint`` (index of its joint), ``x`` (P×2, world position),
    ``force`` (P×2, on body 2: (σn n + τ t) w ℓ thickness, as :func:`joint_point_forces`)."""
    import numpy as np
    O = _O(O)
    ids, segs, scal, counts, pts = [], [], [], [], []
    for I in _rbsm_joints(O):
        g, ph = I.geom, I.phys
        p0, p1, n = g.p0, g.p1, g.normal
        ids.append((I.id1, I.id2))
        segs.append((p0[0], p0[1], p1[0], p1[1], n[0], n[1]))
        scal.append((g.length, g.thickness, ph.normalForce, ph.shearForce, ph.strength))
        sn, tau = ph.normalTraction, ph.shearTraction
        counts.append((ph.nIntact, ph.nSlipping, ph.nOpen, len(sn)))
        pts.append((g.positions, g.weights, sn, tau))
    J = len(ids)
    ids = np.array(ids, dtype=np.int64).reshape(J, 2)
    segs = np.array(segs, dtype=float).reshape(J, 6)
    scal = np.array(scal, dtype=float).reshape(J, 5)
    counts = np.array(counts, dtype=np.int64).reshape(J, 4)
    t = types.SimpleNamespace(id1=ids[:, 0], id2=ids[:, 1], p0=segs[:, 0:2], p1=segs[:, 2:4], normal=segs[:, 4:6],
                              length=scal[:, 0], thickness=scal[:, 1], normalForce=scal[:, 2], shearForce=scal[:, 3],
                              strength=scal[:, 4], nIntact=counts[:, 0], nSlipping=counts[:, 1], nOpen=counts[:, 2],
                              nPoints=counts[:, 3])
    t.tangent = np.column_stack((-t.normal[:, 1], t.normal[:, 0]))  # YADE's t = (-n.y, n.x)
    t.joint = np.repeat(np.arange(J), t.nPoints)
    flat = [np.fromiter((v for p in pts for v in p[k]), dtype=float, count=len(t.joint)) for k in range(4)]
    s, w, sn, tau = flat
    j = t.joint
    t.x = t.p0[j] + s[:, None] * (t.p1[j] - t.p0[j])
    a = w * t.length[j] * t.thickness[j]
    t.force = (sn[:, None] * t.normal[j] + tau[:, None] * t.tangent[j]) * a[:, None]
    return t


def _moments(O, table=None):
    """Per body id, the 2×2 sums [[Σ x fx, Σ x fy], [Σ y fx, Σ y fy]] of the joint (and sphere contact)
    forces on the block, x relative to its centroid (numpy array indexed by body id; 0 without contacts)."""
    import numpy as np
    t = joint_table(O) if table is None else table
    nb = len(O.bodies)
    c = np.zeros((nb, 2))
    spheres = False
    for b in O.bodies:
        if b is not None:
            c[b.id] = (b.state.pos[0], b.state.pos[1])
            spheres = spheres or type(b.shape).__name__ == "Sphere"
    M = np.zeros((nb, 2, 2))
    for body, sign in ((t.id1, -1.0), (t.id2, 1.0)):
        bid = body[t.joint]
        r = t.x - c[bid]
        np.add.at(M, bid, sign * r[:, :, None] * t.force[:, None, :])
    if spheres:  # YADE's point contacts of spheres on blocks (mixed scenes), only where there are spheres
        for bid, x, f in _sphere_contact_forces(O):
            M[bid] += np.outer(np.subtract(x, c[bid]), f)
    return M


def _sphere_contact_forces(O):
    """(block id, contact point, force on the block) of each real ScGeom contact of a Polygon2D block
    (Law2_ScGeom_FrictPhys_CundallStrack applies -(Fn + Fs) to body 1 and Fn + Fs to body 2 at
    ScGeom.contactPoint; x-y components)."""
    for I in O.interactions:
        if not I.isReal or type(I.geom).__name__ != "ScGeom":
            continue
        f = I.phys.normalForce + I.phys.shearForce
        x = I.geom.contactPoint
        for bid, sign in ((I.id1, -1.0), (I.id2, 1.0)):
            if type(O.bodies[bid].shape).__name__ == "Polygon2D":
                yield bid, (x[0], x[1]), (sign * f[0], sign * f[1])


def _matrix3(m, scale):
    from yade import Matrix3
    return Matrix3(m[0][0] * scale, m[1][0] * scale, 0, m[0][1] * scale, m[1][1] * scale, 0, 0, 0, 0)


def block_stresses(O=None, table=None):
    """{body id: Matrix3} average stress of every Polygon2D block [Pa], σ[i][j] = (1/V) Σ f_i x_j
    (symmetric in equilibrium); the RBSM counterpart of YADE's ``bodyStressTensors()``. A deformable
    block (DeformableState) gives its own stress D(ε − εᵖ) instead (DeformableState.stress, the same at rest:
    its strain equation is V σ = sym Σ x ⊗ f). *table*: a :func:`joint_table` of the same state, if the
    caller has one."""
    from yade import Matrix3
    O = _O(O)
    M = _moments(O, table)
    out = {}
    for b in _blocks(O):
        s = getattr(b.state, "stress", None)
        if s is not None:
            out[b.id] = Matrix3(s[0], s[2], 0, s[2], s[1], 0, 0, 0, 0)
            continue
        v = b.shape.area * b.shape.thickness
        out[b.id] = _matrix3(M[b.id], 1.0 / v)
    return out


def stress(ids=None, volume=None, O=None):
    """Average stress tensor [Pa] of the blocks *ids* (default: every block that is not fixed):
    (1/V) Σ_b V_b σ_b, V = *volume* or the blocks' volume (area × thickness); the RBSM counterpart
    of YADE's ``utils.getStress()``."""
    O = _O(O)
    blocks = _blocks(O, ids)
    if ids is None:
        blocks = [b for b in blocks if not omega.is_fixed(b)]
    if not blocks:
        raise ValueError("measure.stress: no Polygon2D block among %s" % ("the free bodies" if ids is None else "ids %r" % (list(ids),)))
    M = _moments(O)
    tot = sum((M[b.id] for b in blocks), start=M[0] * 0.0)
    v = volume if volume is not None else sum(b.shape.area * b.shape.thickness for b in blocks)
    if not (v > 0):
        raise ValueError("measure.stress: volume must be > 0 (got %r)" % (v,))
    return _matrix3(tot, 1.0 / v)


def fabric_tensor(weighted=False, O=None):
    """(1/N) Σ n ⊗ n over the real RBSM joints (Matrix3, trace 1), or weighted by joint length
    (Σ ℓ n ⊗ n / Σ ℓ); the RBSM counterpart of YADE's ``utils.fabricTensor()``. Zero without joints."""
    O = _O(O)
    s, tot = [[0.0, 0.0], [0.0, 0.0]], 0.0
    for I in _rbsm_joints(O):
        n, w = I.geom.normal, (I.geom.length if weighted else 1.0)
        for i in range(2):
            for j in range(2):
                s[i][j] += w * n[i] * n[j]
        tot += w
    return _matrix3(s, 1.0 / tot if tot > 0 else 0.0)


def aabb_extrema(O=None):
    """((xmin, ymin, zmin), (xmax, ymax, zmax)) of the blocks' world vertices (z: ± half the
    thickness); the RBSM counterpart of YADE's ``aabbExtrema()``."""
    from yade import Vector3
    O = _O(O)
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    for b in _blocks(O):
        for v in b.shape.worldVertices(b.state.pos, b.state.ori):
            for k in range(2):
                lo[k], hi[k] = min(lo[k], v[k]), max(hi[k], v[k])
        h = 0.5 * b.shape.thickness
        lo[2], hi[2] = min(lo[2], b.state.pos[2] - h), max(hi[2], b.state.pos[2] + h)
    if lo[0] == math.inf:
        raise ValueError("measure.aabb_extrema: no Polygon2D block in the scene")
    return Vector3(*lo), Vector3(*hi)


def porosity(area=None, ids=None, O=None):
    """1 − (area of the blocks *ids*, default all) / *area* (default: the x-y box of aabb_extrema);
    the RBSM counterpart of YADE's ``porosity()``."""
    O = _O(O)
    blocks = _blocks(O, ids)
    if area is None:
        lo, hi = aabb_extrema(O)
        area = (hi[0] - lo[0]) * (hi[1] - lo[1])
    if not (area > 0):
        raise ValueError("measure.porosity: area must be > 0 (got %r)" % (area,))
    return 1.0 - sum(b.shape.area for b in blocks) / area
