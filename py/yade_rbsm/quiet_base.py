"""A compliant base for earthquake records: Lysmer & Kuhlemeyer's (1969) viscous boundary with the record as a
stress input, FLAC's and UDEC's "quiet base".

The base blocks (the fixed blocks at the bottom of the model) are let go to translate: each keeps the static reaction it had
when the record started (so the model stands as it settled) and takes, on its faces looking down, the traction of
an elastic half-space below them carrying the record up:

    t = Z_s ((v_g − v)·s) s + Z_n ((v_g − v)·n) n,      Z_s = ρ c_s,  Z_n = ρ c_p

with v the face's velocity, v_g the ground velocity of the record (its acceleration integrated) and s, n the
face's tangent and normal. The record is taken as an outcrop motion (recorded at the surface of rock): the wave
coming up is half of it, 2 × half = v_g in FLAC's stress input 2 ρ c v_in. A wave reaching the base from above
leaves through the dashpots instead of coming back. The impedances default to the base material's plane-strain
ρ c_p and ρ c_s (from RbsmMat young, poisson, density): an elastic rock below the base.
No other body may be fixed: a side wall (the slope builders' *wall*) would hold the model while its base moves
(walls moved with the base, first tried, left a third of the base's work out of the energy balance): the model's
sides are free.
"""
import math

from .checks import number

ENERGY = "baseWork"  # O.energy: minus the work the base's tractions did on the model


def base_blocks(O, ids=None):
    """The ids of the base: *ids*, or every fixed Polygon2D block whose lowest point is at the model's bottom."""
    blocks = [b for b in O.bodies if b is not None and type(b.shape).__name__ == "Polygon2D"]
    if ids is not None:
        ids = [int(i) for i in ids]
        known = {b.id for b in blocks}
        for i in ids:
            if i not in known:
                raise ValueError("compliant base: body #%d is not a Polygon2D block of this scene" % i)
        return ids
    bottom = min(_lowest(b) for b in blocks)
    size = max(_lowest(b, top=True) for b in blocks) - bottom
    ids = [b.id for b in blocks if b.state.blockedDOFs == "xyzXYZ" and _lowest(b) < bottom + 1e-6 * size]
    if not ids:
        raise ValueError("compliant base: no fixed block at the model's bottom (y = %g): give base_ids=" % bottom)
    return ids


def _world(b):
    """The block's vertices in the drawing's frame (counter-clockwise)."""
    return [(v[0], v[1]) for v in b.shape.worldVertices(b.state.pos, b.state.ori)]


def _lowest(b, top=False):
    ys = [v[1] for v in _world(b)]
    return max(ys) if top else min(ys)


def faces_looking_down(b):
    """The block's faces whose outward normal is within 1° of −y, as pairs of vertex indices."""
    w = _world(b)
    n = len(w)
    faces = []
    for i in range(n):
        (x0, y0), (x1, y1) = w[i], w[(i + 1) % n]
        L = math.hypot(x1 - x0, y1 - y0)
        # counter-clockwise: the outward normal of edge (p0 -> p1) is (dy, -dx) / L
        if L > 0 and -(x1 - x0) / L < -math.cos(math.radians(1.0)):
            faces.append((i, (i + 1) % n))
    if not faces:
        raise ValueError("compliant base: block #%d has no face looking down (the base's dashpots act on the base "
                         "blocks' bottom faces)" % b.id)
    return faces


def impedances(O, ids):
    """(Z_n, Z_s) = (ρ c_p, ρ c_s) of the base blocks' material, plane strain."""
    m = O.bodies[ids[0]].material
    E, nu, rho = m.young, m.poisson, m.density
    G = E / (2 * (1 + nu))
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    return math.sqrt(rho * M), math.sqrt(rho * G)


def describe(O, ids, impedance=None):
    """The base kept with the scene (checked, nothing changed yet): each block's id, faces looking down and
    blockedDOFs, the impedances; its static reactions are measured at the first step (:func:`static_reaction`)."""
    if impedance is None:
        zn, zs = impedances(O, ids)
    else:
        if len(impedance) != 2:
            raise ValueError("compliant base: impedance is (rho c_p, rho c_s) [Pa s/m], got %r" % (impedance,))
        zn = number("compliant base", "impedance (normal)", impedance[0], 0, None, low_open=True)
        zs = number("compliant base", "impedance (shear)", impedance[1], 0, None, low_open=True)
    blocks = []
    for i in ids:
        b = O.bodies[i]
        if not b.state.mass > 0:
            raise ValueError("compliant base: block #%d has no mass (density %g): the base blocks move under the "
                             "record" % (i, b.material.density))
        blocks.append(dict(id=i, faces=faces_looking_down(b), blocked=b.state.blockedDOFs))
    walls = [b.id for b in O.bodies if b is not None and b.id not in ids and b.state.blockedDOFs == "xyzXYZ"]
    if walls:
        raise ValueError("compliant base: the fixed bodies %s besides the base %s would hold the model while its base "
                         "moves (side walls?): build the slope without them (the builders' wall=0) or use base='rigid'"
                         % (", ".join("#%d" % i for i in walls[:8]) + (", ..." if len(walls) > 8 else ""),
                            ", ".join("#%d" % i for i in ids)))
    return dict(blocks=blocks, zn=zn, zs=zs, reaction=None)


def let_go(O, base):
    """Frees the base blocks to translate in the plane (they were fixed). Their rotation stays held: the dashpots
    have no stiffness, and a base block rocking on them is a mode the rock below does not have (a 1 m base block
    free to rotate under a column sent back 24 % of a pulse)."""
    for d in base["blocks"]:
        O.bodies[d["id"]].state.blockedDOFs = "zXYZ"


def hold(O, base):
    """Fixes the base blocks again where they are (the record is over or taken away)."""
    for d in base["blocks"]:
        s = O.bodies[d["id"]].state
        s.vel, s.angVel = (0, 0, 0), (0, 0, 0)
        s.blockedDOFs = d["blocked"]


def static_reaction(O, base, gravity):
    """Each base block's force and torque that hold it as it stood: minus this step's contact forces and weight."""
    out = []
    for d in base["blocks"]:
        b = O.bodies[d["id"]]
        f, t = O.forces.f(b.id), O.forces.t(b.id)
        out.append([-f[0] - b.state.mass * gravity[0], -f[1] - b.state.mass * gravity[1], -t[2]])
    return out


def apply_tractions(O, base, v_ground):
    """Adds each base block's static reaction and the dashpots' traction on its faces looking down (at two Gauss
    points a face, with the torque they make: a base whose rotation a script frees is damped too); returns their
    power [W]."""
    g = 1 / math.sqrt(3)
    power = 0.0
    for d, (fx, fy, tz) in zip(base["blocks"], base["reaction"]):
        b = O.bodies[d["id"]]
        s = b.state
        power += fx * s.vel[0] + fy * s.vel[1] + tz * s.angVel[2]
        w = _world(b)
        for i, j in d["faces"]:
            (x0, y0), (x1, y1) = w[i], w[j]
            L = math.hypot(x1 - x0, y1 - y0)
            sx, sy = (x1 - x0) / L, (y1 - y0) / L
            nx, ny = sy, -sx  # outward
            a = 0.5 * L * b.shape.thickness  # each Gauss point's share of the face
            for xi in (-g, g):
                rx, ry = 0.5 * (x0 + x1 + xi * (x1 - x0)) - s.pos[0], 0.5 * (y0 + y1 + xi * (y1 - y0)) - s.pos[1]
                vx, vy = s.vel[0] - s.angVel[2] * ry, s.vel[1] + s.angVel[2] * rx
                dvx, dvy = v_ground[0] - vx, v_ground[1] - vy
                ts, tn = base["zs"] * (dvx * sx + dvy * sy), base["zn"] * (dvx * nx + dvy * ny)
                qx, qy = a * (ts * sx + tn * nx), a * (ts * sy + tn * ny)
                fx, fy, tz = fx + qx, fy + qy, tz + rx * qy - ry * qx
                power += qx * vx + qy * vy
        O.forces.addF(b.id, (fx, fy, 0))
        O.forces.addT(b.id, (0, 0, tz))
    return power
