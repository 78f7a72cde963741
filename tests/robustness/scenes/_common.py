"""Shared pieces of the robustness scenes (imported inside a yade script)."""
import os
import math
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from yadescene import MARKER, emit, params  # noqa: E402,F401 (re-exported to the scenes)


def free(b):
    return b.state.blockedDOFs != "xyzXYZ"


def block_size(b):
    """Smallest side of the block's local bounding box [m] (a slender block: its thickness)."""
    xs = [v[0] for v in b.shape.vertices]
    ys = [v[1] for v in b.shape.vertices]
    return min(max(xs) - min(xs), max(ys) - min(ys))


def all_finite(O):
    for b in O.bodies:
        s = b.state
        for v in (s.pos, s.vel, s.angVel):
            if not all(math.isfinite(v[i]) for i in range(3)):
                return False
        if not all(math.isfinite(s.ori[i]) for i in range(4)):
            return False
    for b in O.bodies:
        f, t = O.forces.f(b.id), O.forces.t(b.id)
        if not all(math.isfinite(f[i]) and math.isfinite(t[i]) for i in range(3)):
            return False
    return True


def max_penetration(O):
    """(largest δn_k / smaller block size, largest δn_k [m]) over all real RBSM joints."""
    rel, ab = 0.0, 0.0
    for i in O.interactions:
        if not i.isReal or not len(i.geom.deltaN):
            continue
        d = max(i.geom.deltaN)
        if not math.isfinite(d):
            return (float("inf"), float("inf"))
        ab = max(ab, d)
        rel = max(rel, d / min(block_size(O.bodies[i.id1]), block_size(O.bodies[i.id2])))
    return rel, ab


def velocities(O):
    return {b.id: (b.state.vel[0], b.state.vel[1], b.state.angVel[2]) for b in O.bodies if free(b)}


def shadow_kinetic(O, v_before, v_after):
    """Leapfrog kinetic energy at the whole step, ½ v(n-½)·M v(n+½): with U(x_n) it is the quantity the
    central-difference scheme conserves exactly for linear springs (the plain ½ m v² at half steps
    oscillates by (ω dt/2)² of the energy, ~60 % at 0.8 × the critical step)."""
    e = 0.0
    for b in O.bodies:
        if b.id not in v_before:
            continue
        a, c = v_before[b.id], v_after[b.id]
        e += 0.5 * b.state.mass * (a[0] * c[0] + a[1] * c[1]) + 0.5 * b.state.inertia[2] * a[2] * c[2]
    return e


def kinetic_energy(O):
    e = 0.0
    for b in O.bodies:
        if free(b):
            s = b.state
            e += 0.5 * s.mass * (s.vel[0] ** 2 + s.vel[1] ** 2) + 0.5 * s.inertia[2] * s.angVel[2] ** 2
    return e


def grav_potential(O, g):
    return sum(-b.state.mass * (g[0] * b.state.pos[0] + g[1] * b.state.pos[1]) for b in O.bodies if free(b))


def elastic(O):
    return O.energy["elastPotential"] if "elastPotential" in O.energy.keys() else 0.0


def measured_step(O, g):
    """One O.step(); returns the leapfrog energy at that step: ½ v(n-½)·M v(n+½) + U(x_n) + gravity
    potential at x_n (U from the law during this step, i.e. at the positions before the update)."""
    vb = velocities(O)
    pg = grav_potential(O, g)
    O.step()
    return shadow_kinetic(O, vb, velocities(O)) + elastic(O) + pg


def body_states(O):
    out = []
    for b in O.bodies:
        s = b.state
        out.append([s.pos[0], s.pos[1], 2 * math.atan2(s.ori[2], s.ori[3]), s.vel[0], s.vel[1], s.angVel[2]])
    return out


def joint_states(O):
    out = []
    for i in O.interactions:
        if not i.isReal:
            continue
        p = i.phys
        out.append({"ids": [i.id1, i.id2], "intact": list(p.intactPoints), "slipping": list(p.slippingPoints),
                    "open": list(p.openPoints), "tau": list(p.shearTraction), "sigma": list(p.normalTraction),
                    "dn": list(i.geom.deltaN), "plast": p.plasticDissipation})
    out.sort(key=lambda j: j["ids"])
    return out


# ---- save / load / continue (test_persistence.py) -------------------------------------------------
def loop_order(O):
    """The real interactions, in the order InteractionLoop visits them (the container's order, or
    sorted by ids with InteractionLoop.loopOnSortedInteractions)."""
    real = [(i.id1, i.id2) for i in O.interactions.all(False) if i.isReal]
    loop = [e for e in O.engines if e.__class__.__name__ == "InteractionLoop"][0]
    return sorted(real) if loop.loopOnSortedInteractions else real


def state_digest(O, phys_values):
    """SHA-1 of the exact state after a step, every float as hex: each body's position, orientation,
    velocities, force and torque; each real interaction's ids and phys_values(phys) (a list of floats
    and bools); O.dt, O.time and the energies."""
    import hashlib

    h = hashlib.sha1()
    for b in O.bodies:
        s = b.state
        for v in (s.pos, s.ori, s.vel, s.angVel, O.forces.f(b.id), O.forces.t(b.id)):
            h.update(" ".join(float(v[i]).hex() for i in range(len(v))).encode())
    for i in sorted(O.interactions, key=lambda i: (i.id1, i.id2)):
        h.update(repr((i.id1, i.id2)).encode())
        h.update(" ".join(repr(x) if isinstance(x, bool) else float(x).hex() for x in phys_values(i.phys)).encode())
    h.update(" ".join(float(x).hex() for x in [O.dt, O.time] + [v for k, v in sorted(O.energy.items())]).encode())
    return h.hexdigest()


def traced_steps(O, n, phys_values):
    """n steps one by one, each recorded: 'iter' after the step, 'before' and 'after' the real
    interactions in loop order before and after the step, 'digest' the state_digest() after it."""
    steps = []
    for k in range(n):
        before = loop_order(O)
        O.step()
        steps.append({"iter": O.iter, "before": before, "after": loop_order(O), "digest": state_digest(O, phys_values)})
    return steps
