# -*- coding: utf-8 -*-
"""Benchmark cases, one YADE process per call (run by scripts/benchmarks/run_all.py).

    yade-rbsm -j1 -n -x scripts/benchmarks/cases.py '{"case": "incline", "method": "polyhedra", ...}'

Prints one line "BENCH_RESULT {json}". Methods: rbsm (Polygon2D blocks), spheres (one sphere per block, or a
hexagonal sphere stack for the wall), clumps (a block = a clump of spheres filling it), polyhedra (YADE
Polyhedra prisms, extruded 1 m out of plane, held in the plane with blockedDOFs 'zXY').
Every method runs at its own stable time step:
  rbsm      RbsmTimeStepper (setDt, safety 0.8 unless given);
  spheres, clumps  0.5·PWaveTimeStep();
  polyhedra no time stepper in YADE: dt = 0.5·sqrt(m_min / k), k = E·ℓ_max·t the stiffness of the volumetric law
            (F = kn·V, kn ≤ E) for a full face ℓ_max × t in contact (documented estimate).
All scenes are planar in the x-y plane, gravity along -y (tilted by ψ for the incline: g = g(sinψ, -cosψ)).
"""
import json
import math
import os
import sys
import time

from yade import O, utils, wrapper, Vector3, Quaternion

from yade_rbsm.blocks import polygon2d
from yade_rbsm.scene import engines as rbsm_engines

P = json.loads(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1] else {}
G = 9.81
E = P.get("E", 1e8)
RHO = 2000.0
T_OUT = 1.0  # out-of-plane thickness [m] (RBSM thickness, Polyhedra extrusion)


def vm_hwm_mb():
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024.0
    return float("nan")


def emit(res):
    res["vmhwm_mb"] = vm_hwm_mb()
    sys.stdout.write("BENCH_RESULT " + json.dumps(res) + "\n")
    sys.stdout.flush()


# --------------------------------------------------------------------------------------------- builders
class Method:
    """Materials, blocks, ground and engines of one method."""

    def __init__(self, name, phi, nIP=2, safety=0.8, contact_damping=0.3, verlet=None, interval=100, update_tol=0.0):
        self.name, self.phi, self.update_tol = name, phi, update_tol
        self.nIP, self.safety, self.cdamp, self.verlet, self.interval = nIP, safety, contact_damping, verlet, interval
        if name == "rbsm":
            self.mat = wrapper.RbsmMat(young=E, poisson=0.2, density=RHO, frictionAngle=phi, cohesion=0, tensileStrength=0)
        elif name in ("spheres", "clumps"):
            self.mat = wrapper.FrictMat(young=E, poisson=0.2, density=RHO, frictionAngle=phi)
        elif name == "polyhedra":
            self.mat = wrapper.PolyhedraMat(young=E, poisson=0.2, density=RHO, frictionAngle=phi)
        elif name == "pp":  # PotentialParticle: stiffness from Ip2_FrictMat_FrictMat_KnKsPhys
            self.mat = wrapper.FrictMat(young=-1, poisson=-1, density=RHO, frictionAngle=phi)
        else:
            raise ValueError(name)
        O.materials.append(self.mat)
        self.lmax = 0.0

    # a rectangular block [x0,x1]x[y0,y1]; returns the id of the body that moves (clump id for clumps)
    def block(self, x0, y0, x1, y1, fixed=False, dsphere=None):
        m = self.name
        self.lmax = max(self.lmax, x1 - x0, y1 - y0)
        if m == "rbsm":
            return O.bodies.append(polygon2d([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], self.mat, fixed=fixed))
        if m == "polyhedra":
            v = [Vector3(x, y, z) for z in (-T_OUT / 2, T_OUT / 2) for (x, y) in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
            b = utils.polyhedron(v, fixed=fixed, material=self.mat)
            if not fixed:
                b.state.blockedDOFs = "zXY"
            return O.bodies.append(b)
        if m == "pp":  # PotentialParticle box (rounded by r = 10 % of the thin side), 1 m out of plane
            w, h = x1 - x0, y1 - y0
            r = 0.1 * min(w, h)
            b = wrapper.Body()
            b.aspherical = True
            hx, hy, hz = w / 2, h / 2, T_OUT / 2
            ext = math.sqrt(hx * hx + hy * hy + hz * hz)
            b.shape = wrapper.PotentialParticle(
                k=P.get("pp_k", 0.05), r=r, R=ext, a=[1, -1, 0, 0, 0, 0], b=[0, 0, 1, -1, 0, 0], c=[0, 0, 0, 0, 1, -1],
                d=[hx - r, hx - r, hy - r, hy - r, hz - r, hz - r], isBoundary=False, AabbMinMax=True,
                fixedNormal=False, minAabb=Vector3(ext, ext, ext), maxAabb=Vector3(ext, ext, ext),
                minAabbRotated=Vector3(ext, ext, ext), maxAabbRotated=Vector3(ext, ext, ext), id=len(O.bodies))
            V = w * h * T_OUT
            inert = Vector3(V * (h * h + T_OUT ** 2) / 12, V * (w * w + T_OUT ** 2) / 12, V * (w * w + h * h) / 12)
            utils._commonBodySetup(b, V, inert, material=self.mat, pos=(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0), fixed=fixed)
            b.state.pos = (0.5 * (x0 + x1), 0.5 * (y0 + y1), 0)
            if not fixed:
                b.state.blockedDOFs = "zXY"
            self.lmax = max(self.lmax, w, h)
            self.amax = max(getattr(self, "amax", 0.0), max(w, h) * T_OUT)
            return O.bodies.append(b)
        if m == "spheres":  # one sphere of the block's height (a block cannot be represented otherwise)
            r = 0.5 * min(x1 - x0, y1 - y0)
            b = utils.sphere((0.5 * (x0 + x1), y0 + r, 0), r, material=self.mat, fixed=fixed)
            if not fixed:
                b.state.blockedDOFs = "zXY"
            return O.bodies.append(b)
        if m == "clumps":  # grid of spheres filling the block, clumped
            w, h = x1 - x0, y1 - y0
            d = dsphere or min(w, h) / max(1, round(min(w, h) / (0.25 * min(w, h))))  # 4 across the thin side
            nx, ny = max(1, int(round(w / d))), max(1, int(round(h / d)))
            dx, dy = w / nx, h / ny
            r = 0.5 * min(dx, dy)
            sph = [utils.sphere((x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy, 0), r, material=self.mat)
                   for i in range(nx) for j in range(ny)]
            if len(sph) == 1:
                sph[0].state.blockedDOFs = "zXY"
                return O.bodies.append(sph[0])
            cid, _ = O.bodies.appendClumped(sph)
            O.bodies[cid].state.blockedDOFs = "zXY"
            return cid
        raise ValueError(m)

    def ground(self, x0, x1):
        """Fixed ground with its top at y = 0."""
        if self.name in ("spheres", "clumps"):
            return O.bodies.append(utils.wall(0, axis=1, sense=0, material=self.mat))
        return self.block(x0, -1.0, x1, 0.0, fixed=True)

    def engines(self, gravity=(0, -G, 0), damping=0.0):
        m = self.name
        if m == "pp":
            # kn per unit contact area, like RBSM's kn = E'/(h1+h2) for blocks of height ~1 m: E/1 m
            kn = E / 1.0
            O.engines = [
                wrapper.ForceResetter(),
                wrapper.InsertionSortCollider([wrapper.PotentialParticle2AABB()], label="collider"),
                wrapper.InteractionLoop([wrapper.Ig2_PP_PP_ScGeom(twoDimension=False, calContactArea=True, areaStep=5)],
                                        [wrapper.Ip2_FrictMat_FrictMat_KnKsPhys(kn_i=kn, ks_i=kn / 2, Knormal=kn, Kshear=kn / 2,
                                                                                useFaceProperties=False, viscousDamping=0.0)],
                                        [wrapper.Law2_SCG_KnKsPhys_KnKsLaw(neverErase=False)]),
                wrapper.NewtonIntegrator(gravity=gravity, damping=damping, exactAsphericalRot=True, label="newton"),
            ]
            if self.verlet is not None:
                O.engines[1].verletDist = self.verlet
            # no time stepper for PotentialParticle: dt = 0.5·sqrt(m_min / (kn·A_max)), A_max the largest face
            mmin = min(b.state.mass for b in O.bodies if b.dynamic)
            O.dt = 0.5 * math.sqrt(mmin / (kn * self.amax))
            return
        if m == "rbsm":
            eng = rbsm_engines(gravity=gravity, damping=damping, contact_damping=self.cdamp, nIP=self.nIP,
                               safety=self.safety, set_dt=True, interval=self.interval, update_tolerance=self.update_tol)
            if self.verlet is not None:
                eng[1].verletDist = self.verlet
            O.engines = eng
            O.dt = 1e-7  # RbsmTimeStepper sets it at the first step with joints
            return
        if m in ("spheres", "clumps"):
            O.engines = [
                wrapper.ForceResetter(),
                wrapper.InsertionSortCollider([wrapper.Bo1_Sphere_Aabb(), wrapper.Bo1_Wall_Aabb()], label="collider"),
                wrapper.InteractionLoop([wrapper.Ig2_Sphere_Sphere_ScGeom(), wrapper.Ig2_Wall_Sphere_ScGeom()],
                                        [wrapper.Ip2_FrictMat_FrictMat_FrictPhys()],
                                        [wrapper.Law2_ScGeom_FrictPhys_CundallStrack()]),
                wrapper.NewtonIntegrator(gravity=gravity, damping=damping, label="newton"),
            ]
            if self.verlet is not None:
                O.engines[1].verletDist = self.verlet
            O.dt = 0.5 * utils.PWaveTimeStep()
            return
        if m == "polyhedra":
            O.engines = [
                wrapper.ForceResetter(),
                wrapper.InsertionSortCollider([wrapper.Bo1_Polyhedra_Aabb()], label="collider"),
                wrapper.InteractionLoop([wrapper.Ig2_Polyhedra_Polyhedra_PolyhedraGeom()],
                                        [wrapper.Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                                        [wrapper.Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
                wrapper.NewtonIntegrator(gravity=gravity, damping=damping, label="newton"),
            ]
            if self.verlet is not None:
                O.engines[1].verletDist = self.verlet
            mmin = min(b.state.mass for b in O.bodies if b.dynamic)
            k = E * self.lmax * T_OUT
            O.dt = 0.5 * math.sqrt(mmin / k)
            return

    def newton(self):
        return [e for e in O.engines if isinstance(e, wrapper.NewtonIntegrator)][0]


def first_step():
    """One step (RBSM: the time stepper sets O.dt there)."""
    O.step()


def run_time(t):
    n = max(1, int(math.ceil(t / O.dt)))
    O.run(n, True)
    return n


def timed(nsteps, chunk=None, each=None):
    """Run nsteps with O.timingEnabled; returns cost figures. each(): called every chunk steps."""
    for e in O.engines:
        e.execTime = 0
    O.timingEnabled = True
    t0 = time.perf_counter()
    done = 0
    chunk = chunk or nsteps
    while done < nsteps:
        k = min(chunk, nsteps - done)
        O.run(k, True)
        done += k
        if each:
            each()
    wall = time.perf_counter() - t0
    O.timingEnabled = False
    eng = {}
    for e in O.engines:
        key = e.label or e.__class__.__name__
        eng[key] = eng.get(key, 0.0) + e.execTime * 1e-9 / nsteps
    return {"steps": nsteps, "wall_per_step": wall / nsteps, "exec_per_step": sum(eng.values()), "engines": eng}


# --------------------------------------------------------------------------------------------- tracking
class Tracker:
    """Downslope bottom corner and rotation of a body relative to its state at reset()."""

    def __init__(self, bid, corner):
        self.b = O.bodies[bid]
        self.c0 = Vector3(corner[0], corner[1], 0)
        self.reset()

    def reset(self):
        s = self.b.state
        self.p0, self.q0 = Vector3(s.pos), Quaternion(s.ori)
        self.c0 = Vector3(self.c0)

    def rel(self):
        s = self.b.state
        return s.ori * self.q0.conjugate()

    def corner(self):
        return self.b.state.pos + self.rel() * (self.c0 - self.p0)


def quat_z(q):
    # minieigen Quaternion: indices [0..3] = x, y, z, w
    return 2 * math.atan2(q[2], q[3])


def lsq_slope(t, v):
    n = len(t)
    mt, mv = sum(t) / n, sum(v) / n
    den = sum((a - mt) ** 2 for a in t)
    return sum((a - mt) * (b - mv) for a, b in zip(t, v)) / den if den > 0 else float("nan")


def contacts_real():
    return O.interactions.countReal()


# --------------------------------------------------------------------------------------------- problems
def setup_block(method, b, h, phi, **kw):
    O.reset()
    m = Method(method, phi, **kw)
    gid = m.ground(-50, 50)
    bid = m.block(-b / 2, 0.0, b / 2, h)
    m.engines(gravity=(0, -G, 0), damping=0.5)
    return m, gid, bid


def settle(m, t=0.2):
    first_step()
    run_time(t)
    m.newton().damping = 0.0


def incline(method, psi_deg=35.0, phi_deg=30.0, b=2.0, h=0.5, T=0.6, **kw):
    """(a) block sliding on an incline: a = g(sinψ - cosψ tanφ)."""
    psi, phi = math.radians(psi_deg), math.radians(phi_deg)
    m, gid, bid = setup_block(method, b, h, phi, **kw)
    settle(m)
    m.newton().gravity = (G * math.sin(psi), -G * math.cos(psi), 0)
    body = O.bodies[bid]
    ts, vs = [], []
    n = int(math.ceil(T / O.dt))

    def sample():
        if O.time - t_start > 0.5 * T:
            ts.append(O.time)
            vs.append(body.state.vel[0])
    t_start = O.time
    cost = timed(n, chunk=max(1, n // 200), each=sample)
    a = lsq_slope(ts, vs)
    a_cf = G * (math.sin(psi) - math.cos(psi) * math.tan(phi))
    return {"a": a, "a_cf": a_cf, "err": abs(a / a_cf - 1), "dt": O.dt, "steps_per_s": 1.0 / O.dt, "cost": cost,
            "contacts": contacts_real()}


def topple_one(method, psi_deg, phi_deg, b, h, T=1.0, **kw):
    """(b) one (b/h, ψ) case: slides? topples? Returns the observed and the closed-form regime."""
    psi, phi = math.radians(psi_deg), math.radians(phi_deg)
    m, gid, bid = setup_block(method, b, h, phi, **kw)
    settle(m)
    tr = Tracker(bid, (b / 2, 0.0))
    m.newton().gravity = (G * math.sin(psi), -G * math.cos(psi), 0)
    # run until the block has rotated by 10° (the regime is decided at the onset, before a toppled block
    # lands and slides on) or T has passed
    n, chunk = 0, 20
    while n * O.dt < T and abs(quat_z(tr.rel())) < math.radians(10):
        O.run(chunk, True)
        n += chunk
    rot = quat_z(tr.rel())
    slip = tr.corner()[0] - tr.c0[0]
    # closed form (rigid block, Hoek & Bray): slides if tanψ > tanφ; a block at rest topples if b/h < tanψ; a
    # sliding block carries the friction force N·tanφ at its base, so it topples only if b/h < tanφ
    slides_cf = math.tan(psi) > math.tan(phi)
    topples_cf = b / h < (math.tan(phi) if slides_cf else math.tan(psi))
    # observed: toppled = rotated by more than 5°; slid = the downslope bottom corner (the pivot of a
    # toppling block, which stays in place while the block pivots) moved more than 1 % of b along the slope
    # (the stable blocks' elastic shear and settling stay below 0.3 %)
    toppled = abs(rot) > math.radians(5)
    slid = slip > 0.01 * b
    return {"psi": psi_deg, "phi": phi_deg, "b_over_h": b / h, "rot_deg": math.degrees(rot), "corner_slip": slip,
            "slides_cf": slides_cf, "topples_cf": topples_cf, "slides": slid, "topples": toppled,
            "ok": (slid == slides_cf) and (toppled == topples_cf), "steps": n, "dt": O.dt}


TOPPLE_CASES = [  # ψ, φ, b, h: stable, sliding, toppling, sliding and toppling, sliding only although b/h < tanψ
    (25.0, 35.0, 1.0, 1.0), (45.0, 35.0, 1.5, 1.0), (25.0, 35.0, 0.3, 1.0), (60.0, 35.0, 0.5, 1.0),
    (45.0, 35.0, 0.9, 1.0)]


def topple(method, **kw):
    out = [topple_one(method, *c, **kw) for c in P.get("topple_cases", TOPPLE_CASES)]
    return {"cases": out, "n_ok": sum(c["ok"] for c in out), "n": len(out)}


def safety_factor(method, psi_deg=20.0, phi_deg=30.0, b=2.0, h=0.5, T=0.6, **kw):
    """(c) single-joint factor of safety at rest on an incline: FS = tanφ/tanψ from the contact forces,
    FS_num = Σ N tanφ / |Σ S| over the block's contacts with the ground (after settling, Newton damping 0.5)."""
    psi, phi = math.radians(psi_deg), math.radians(phi_deg)
    O.reset()
    m = Method(method, phi, **kw)
    gid = m.ground(-50, 50)
    bid = m.block(-b / 2, 0.0, b / 2, h)
    m.engines(gravity=(G * math.sin(psi), -G * math.cos(psi), 0), damping=0.5)
    first_step()
    run_time(T)
    N, S = 0.0, Vector3(0, 0, 0)
    for i in O.interactions:
        if not i.isReal:
            continue
        ph = i.phys
        if method == "rbsm":
            N += ph.normalForce
            S += Vector3(i.geom.tangent[0], i.geom.tangent[1], 0) * ph.shearForce
        else:
            N += ph.normalForce.norm()
            S += ph.shearForce
    fs = N * math.tan(phi) / S.norm() if S.norm() > 0 else float("inf")
    fs_cf = math.tan(phi) / math.tan(psi)
    return {"fs": fs, "fs_cf": fs_cf, "err": abs(fs / fs_cf - 1), "dt": O.dt}


def patch(method, strain=1e-4, nu=0.25, **kw):
    """(d) uniform-strain patch (RBSM only): 3x3 bonded unit squares, affine uniaxial strain, σ vs E'ε."""
    if method != "rbsm":
        return {"na": "no bonded elastic continuum representation with a closed-form stiffness"}
    O.reset()
    mat = wrapper.RbsmMat(young=E, poisson=nu, density=RHO, frictionAngle=0.6, cohesion=1e9, tensileStrength=1e9)
    O.materials.append(mat)
    ref = {}
    for i in range(3):
        for j in range(3):
            x0, y0 = i, j
            ref[O.bodies.append(polygon2d([(x0, y0), (x0 + 1, y0), (x0 + 1, y0 + 1), (x0, y0 + 1)], mat))] = (x0 + .5, y0 + .5)
    O.engines = [wrapper.ForceResetter(), wrapper.InsertionSortCollider([wrapper.Bo1_Polygon2D_Aabb(enlarge=0.01)]),
                 wrapper.InteractionLoop([wrapper.Ig2_Polygon2D_Polygon2D_RbsmGeom(interactionDistance=1e-6, nIP=kw.get("nIP", 2))],
                                         [wrapper.Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=True)],
                                         [wrapper.Law2_RbsmGeom_RbsmPhys_MohrCoulomb()])]
    O.dt = 1e-3
    O.step()
    for bid, (x, y) in ref.items():
        b = O.bodies[bid]
        b.state.pos = (x + strain * x, y, 0)
        b.state.vel = (strain * x / O.dt, 0, 0)
    O.step()
    Ep = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    errs = []
    for i in O.interactions:
        if i.isReal and abs(i.geom.normal[0]) > 0.5:
            for sn in i.phys.normalTraction:
                errs.append(abs(-sn / (Ep * strain) - 1) if sn < 0 else abs(sn / (Ep * strain) + 1))
    # tension: normal traction < 0 (opening)
    return {"err": max(errs) if errs else float("nan"), "n": len(errs)}


# --------------------------------------------------------------------------------------------- wall scene
BW, BH = 0.2, 0.1


def build_wall(method, nx, ny, phi=0.6, **kw):
    """Wall of ny courses of nx bricks BW x BH in running bond (half bricks at the ends of odd courses) on a fixed base (spheres: hexagonal stack of spheres of radius
    BH/2 with the same number of rows and a similar number of bodies, between side walls)."""
    O.reset()
    m = Method(method, phi, **kw)
    if method == "spheres":  # same number of bodies: ny rows of nx / nx-1 spheres (diameter BH)
        R = BH / 2
        O.bodies.append(utils.wall(0, axis=1, sense=1, material=m.mat))
        O.bodies.append(utils.wall(0, axis=0, sense=1, material=m.mat))
        O.bodies.append(utils.wall(2 * R * nx, axis=0, sense=-1, material=m.mat))
        dy = 3 ** 0.5 * R
        for k in range(ny):
            odd = k % 2
            for i in range(nx - odd):
                b = utils.sphere((R + 2 * R * i + odd * R, R + k * dy, 0), R, material=m.mat)
                b.state.blockedDOFs = "zXY"
                O.bodies.append(b)
    else:
        x0, x1 = -BW, (nx + 1) * BW
        m.ground(x0, x1) if method != "clumps" else O.bodies.append(utils.wall(0, axis=1, sense=1, material=m.mat))
        for j in range(ny):
            y0, y1 = j * BH, (j + 1) * BH
            # running bond: odd courses start and end with a half brick, so that no brick overhangs (an end
            # brick overhanging by half its length is balanced on its tipping point and topples)
            xs = [i * BW for i in range(nx + 1)] if j % 2 == 0 else [0.0] + [(i + 0.5) * BW for i in range(nx)] + [nx * BW]
            for xa, xb in zip(xs[:-1], xs[1:]):
                m.block(xa, y0, xb, y1, dsphere=BH)
    m.engines(gravity=(0, -G, 0), damping=0.2)
    return m


def max_penetration(method):
    """Largest interpenetration depth [m] over the real contacts."""
    worst = 0.0
    for i in O.interactions:
        if not i.isReal:
            continue
        g = i.geom
        if method == "rbsm":
            d = max(g.deltaN) if len(g.deltaN) else 0.0
        elif method == "polyhedra":
            d = g.equivalentPenetrationDepth
        elif method == "pp":
            d = g.penetrationDepth
        else:
            d = g.penetrationDepth
        worst = max(worst, d)
    return worst


def wall(method, nx=20, ny=20, settle_steps=20, steps=50, **kw):
    t0 = time.perf_counter()
    m = build_wall(method, nx, ny, **kw)
    build_s = time.perf_counter() - t0
    nb = sum(1 for b in O.bodies if not b.isClumpMember)
    first_step()
    if settle_steps > 1:
        O.run(settle_steps - 1, True)
    cost = timed(steps, chunk=steps)
    nc = contacts_real()
    res = {"bodies": nb, "contacts": nc, "interactions": len(O.interactions), "dt": O.dt, "cost": cost,
           "build_s": build_s, "threads": int(getattr(O, "numThreads", 1)), "time": O.time}
    res["us_per_contact_step"] = cost["exec_per_step"] * 1e6 / max(nc, 1)
    res["il_us_per_contact_step"] = cost["engines"].get("InteractionLoop", 0.0) * 1e6 / max(nc, 1)
    res["sim_s_per_wall_s"] = O.dt / cost["exec_per_step"]
    res["max_pen_rel"] = max_penetration(method) / BH
    res["contacts_per_block"] = nc / max(nb, 1)
    return res


def wall_sim(method, nx=50, ny=50, T=0.05, max_steps=2000, **kw):
    """Realistic scene: a wall of a few thousand bricks settling for T simulated seconds (or max_steps):
    cost, contacts formed, worst interpenetration, lowest brick's drop."""
    m = build_wall(method, nx, ny, **kw)
    nb = sum(1 for b in O.bodies if not b.isClumpMember)
    y0 = {b.id: b.state.pos[1] for b in O.bodies if b.dynamic and not b.isClumpMember}
    first_step()
    n = min(max_steps, max(1, int(math.ceil(T / O.dt))))
    cost = timed(n, chunk=n)
    nc = contacts_real()
    drop = max(y0[i] - O.bodies[i].state.pos[1] for i in y0)
    return {"bodies": nb, "contacts": nc, "contacts_per_block": nc / max(nb, 1), "dt": O.dt, "steps": n,
            "sim_time": O.time, "cost": cost, "max_pen_rel": max_penetration(method) / BH,
            "max_drop_rel": drop / BH, "us_per_contact_step": cost["exec_per_step"] * 1e6 / max(nc, 1),
            "sim_s_per_wall_s": O.dt / cost["exec_per_step"]}


def main():
    case, method = P.get("case"), P.get("method", "rbsm")
    kw = {k: P[k] for k in ("nIP", "safety", "contact_damping", "verlet", "interval", "update_tol") if k in P}
    t0 = time.perf_counter()
    if case == "incline":
        r = incline(method, **{k: P[k] for k in ("psi_deg", "phi_deg", "T") if k in P}, **kw)
    elif case == "topple":
        r = topple(method, **kw)
    elif case == "fs":
        r = safety_factor(method, **kw)
    elif case == "patch":
        r = patch(method, **kw)
    elif case == "wall":
        r = wall(method, **{k: P[k] for k in ("nx", "ny", "settle_steps", "steps") if k in P}, **kw)
    elif case == "wall_sim":
        r = wall_sim(method, **{k: P[k] for k in ("nx", "ny", "T", "max_steps") if k in P}, **kw)
    elif case == "all_small":  # (a)-(d) in one process
        r = {"incline": incline(method, **kw), "topple": topple(method, **kw), "fs": safety_factor(method, **kw),
             "patch": patch(method, **kw)}
    else:
        raise SystemExit("unknown case %r" % case)
    r.update({"case": case, "method": method, "params": P, "run_s": time.perf_counter() - t0})
    emit(r)


main()
