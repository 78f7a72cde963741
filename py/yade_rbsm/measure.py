"""Measures of an RBSM packing that YADE's own utilities compute for spheres only.

YADE's ``utils.getStress()``, ``bodyStressTensors()``, ``fabricTensor()``, ``aabbExtrema()`` and
``porosity()`` read sphere radii and sphere contacts (static casts in YADE's C++): on blocks they
give NaN or garbage. Their RBSM equivalents, from the joints' tractions at their integration points:

* :func:`block_stresses` - the average stress tensor of each block, σ_b = (1/V_b) Σ x ⊗ f over the
  forces f the joints apply to it at points x (relative to its centroid; V_b = area × thickness);
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

from . import omega

__all__ = ["joint_point_forces", "block_stresses", "stress", "fabric_tensor", "aabb_extrema", "porosity"]


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


def _moments(O):
    """{body id: [[Σ x fx, Σ x fy], [Σ y fx, Σ y fy]]} of the joint forces on each block, x relative to its centroid."""
    M = {}
    for I in _rbsm_joints(O):
        c1, c2 = O.bodies[I.id1].state.pos, O.bodies[I.id2].state.pos
        for x, y, fx, fy in joint_point_forces(I):
            for bid, c, s in ((I.id1, c1, -1.0), (I.id2, c2, 1.0)):
                m = M.setdefault(bid, [[0.0, 0.0], [0.0, 0.0]])
                rx, ry = x - c[0], y - c[1]
                m[0][0] += s * rx * fx
                m[0][1] += s * rx * fy
                m[1][0] += s * ry * fx
                m[1][1] += s * ry * fy
    return M


def _matrix3(m, scale):
    from yade import Matrix3
    return Matrix3(m[0][0] * scale, m[1][0] * scale, 0, m[0][1] * scale, m[1][1] * scale, 0, 0, 0, 0)


def block_stresses(O=None):
    """{body id: Matrix3} average stress of every Polygon2D block [Pa], σ[i][j] = (1/V) Σ f_i x_j
    (symmetric in equilibrium); the RBSM counterpart of YADE's ``bodyStressTensors()``."""
    O = _O(O)
    M = _moments(O)
    out = {}
    for b in _blocks(O):
        v = b.shape.area * b.shape.thickness
        out[b.id] = _matrix3(M.get(b.id, [[0.0, 0.0], [0.0, 0.0]]), 1.0 / v)
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
    tot = [[0.0, 0.0], [0.0, 0.0]]
    for b in blocks:
        m = M.get(b.id)
        if m:
            for i in range(2):
                for j in range(2):
                    tot[i][j] += m[i][j]
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
