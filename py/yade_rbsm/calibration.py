"""Micro-macro calibration of Voronoi RBSM joints by virtual biaxial tests.

Rigid Voronoi blocks sliding on Mohr-Coulomb joints interlock and dilate: a band of blocks has a
larger friction angle and cohesion than its joints (on a 2:1 slope with the soil's c', phi' on the
joints, strength reduction gave FS 2.43 against Bishop's 1.38). The established remedy in
Voronoi-block DEM is to give the joints the strength that makes the *assembly* have the soil's:

* :func:`biaxial_test` builds a rectangular sample of the same tessellation (Voronoi cells of the
  same spacing and ``min_distance``) between rough rigid platens, confines its sides with a
  pressure sigma3 (forces on the boundary edges), and shortens it at a constant strain rate until
  the axial stress peaks: the peak sigma1.
* :func:`calibrate` runs it at several confinements for a grid of joint strengths (tan phi_j x c_j,
  ductile joints), fits the Mohr-Coulomb envelope ``sigma1 = Kp sigma3 + 2 c sqrt(Kp)`` to each, and
  returns a :class:`Calibration`: the table joint -> assembly and its inverse,
  :meth:`Calibration.joint_strength` (the joint c_j, tan phi_j that give an assembly c', tan phi',
  linear interpolation on the triangulated table). The table is cached as JSON.

What was measured (docs/slope_factor_of_safety.md): the assembly's friction angle does not go below
about 30 degrees even with frictionless joints (the zig-zag of the block faces along any band), and
brittle joints (RbsmMat.ductile False) lose their cohesion before the peak, so the assembly's
cohesion does not depend on theirs; ductile joints carry it (c about 2.6-3.7 c_j).

* :func:`simple_shear_test` shears a long sample (24 x 6 cells) between glued rigid platens under a
  constant normal stress: what a horizontal band of the tessellation carries. With the biaxially
  calibrated joints of the 45 degree slope (c' 10 kPa, phi' 40 deg) the peak is 14-18 % below the
  soil's at sigma_n = 100 kPa (free ends; a 48 x 6 sample: 1-5 %); see docs/slope_factor_of_safety.md.

The model is rate independent and has no length scale but the block size (the joint stiffness is
E'/(h1 + h2)), so the table holds for any spacing with the same ``min_distance`` ratio and the same
ratio of confinement to E; the confinements are given as fractions of a stress scale (gamma H of the
slope). :func:`yade_rbsm.strength_reduction.strength_reduction` takes the calibration and reduces
the *assembly's* strength: at trial F the joints get ``joint_strength(c'/F, tan phi'/F)``.

The tests run in the current YADE scene, which is saved before and restored after
(``O.saveTmp``/``O.loadTmp``), so :func:`calibrate` may be called from a slope script at any time.
"""
import hashlib
import json
import math
import os
import time
from dataclasses import asdict, dataclass, field
from typing import List, Optional, Sequence

from .checks import count, number

__all__ = ["BiaxialResult", "Calibration", "ShearResult", "biaxial_test", "calibrate", "fit_coulomb", "fit_mohr_coulomb",
           "simple_shear_test"]


@dataclass
class BiaxialResult:
    sigma3: float  # confinement [Pa]
    peak: float  # peak axial stress sigma1 [Pa]
    strain_at_peak: float
    steps: int
    wall: float
    blocks: int
    peaked: bool  # False: max_strain reached with the stress still rising (peak = the largest value)
    curve: List[tuple] = field(default_factory=list, repr=False)  # (axial strain, sigma1 [Pa]) every 50 steps
    residual: Optional[float] = None  # mean sigma1 over the last quarter of the strain range (residual=True)


def _line(x, y, who, pairs, xs):
    """Least-squares line y = a x + b: (a, b). ValueError for fewer than two pairs or equal x."""
    n = len(x)
    if n < 2 or len(y) != n:
        raise ValueError("%s: need at least two %s" % (who, pairs))
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((v - mx) ** 2 for v in x)
    if sxx <= 0:
        raise ValueError("%s: the %s must differ" % (who, xs))
    a = sum((u - mx) * (v - my) for u, v in zip(x, y)) / sxx
    return a, my - a * mx


def fit_mohr_coulomb(sigma3, sigma1):
    """Least-squares line sigma1 = Kp sigma3 + q through the peaks; returns (c, phi [rad], Kp, q,
    largest relative misfit of sigma1). ValueError for fewer than two confinements or Kp <= 1."""
    kp, q = _line(sigma3, sigma1, "fit_mohr_coulomb", "(sigma3, sigma1) pairs", "confinements")
    if not kp > 1:
        raise ValueError("fit_mohr_coulomb: slope Kp = %.4g <= 1 (no friction), peaks %r" % (kp, list(sigma1)))
    phi = math.asin((kp - 1) / (kp + 1))
    c = q / (2 * math.sqrt(kp))
    misfit = max(abs(kp * x + q - y) / abs(y) for x, y in zip(sigma3, sigma1))
    return c, phi, kp, q, misfit


def _rectangle(w, h):
    return [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]


def _side_loads(verts, pos, p, w, tol, thickness):
    """Force and moment (about the block's centroid *pos*) of pressure *p* on the block's edges on
    x = 0 (pushing +x) and x = w (pushing -x)."""
    fx = mz = 0.0
    n = len(verts)
    for k in range(n):
        a, b = verts[k], verts[(k + 1) % n]
        for x0, sign in ((0.0, 1.0), (w, -1.0)):
            if abs(a[0] - x0) <= tol and abs(b[0] - x0) <= tol:
                f = sign * p * abs(b[1] - a[1]) * thickness
                ym = 0.5 * (a[1] + b[1])
                fx += f
                mz += -(ym - pos[1]) * f  # r x F, F along x
    return fx, mz


def _sample(W, H, side_pressure, top_force, young, poisson, density, joint_cohesion, joint_tan_phi, tensile_strength,
            ductile, spacing, seed, min_distance, thickness):
    """The scene of the virtual tests, reset: a W x H Voronoi sample (cells of *spacing*) between a fixed
    bottom platen and a top platen free to move vertically only and pushed down by *top_force*, the
    *side_pressure* on the blocks that form its sides (permanent forces), the joints made intact (rough
    platens). Returns (ids of the blocks, id of the bottom platen, id of the top one)."""
    from yade import O, Vector3, wrapper
    from .blocks import polygon2d
    from .scene import advance, engines
    from .voronoi import voronoi_tessellation
    from . import omega
    O.resetThisScene()
    mat = wrapper.RbsmMat(young=young, poisson=poisson, density=density, frictionAngle=math.atan(joint_tan_phi),
                          cohesion=joint_cohesion, tensileStrength=tensile_strength, ductile=bool(ductile))
    O.materials.append(mat)
    t = voronoi_tessellation(_rectangle(W, H), spacing=spacing, seed=seed, min_distance=min_distance * spacing)
    ids = O.bodies.append([polygon2d(v, mat, thickness=thickness) for v in t.blocks])
    e = spacing
    bottom = O.bodies.append(polygon2d([(-e, -e), (W + e, -e), (W + e, 0), (-e, 0)], mat, thickness=thickness,
                                       fixed=True))
    top = O.bodies.append(polygon2d([(-e, H), (W + e, H), (W + e, H + e), (-e, H + e)], mat, thickness=thickness))
    O.bodies[top].state.blockedDOFs = "xzXYZ"
    if side_pressure > 0:
        tol = 1e-9 * H
        for i, v in zip(ids, t.blocks):
            fx, mz = _side_loads(v, O.bodies[i].state.pos, side_pressure, W, tol, thickness)
            if fx != 0 or mz != 0:
                O.forces.setPermF(i, Vector3(fx, 0, 0))
                O.forces.setPermT(i, Vector3(0, 0, mz))
    O.forces.setPermF(top, Vector3(0, -top_force, 0))
    O.engines = engines(gravity=(0, 0, 0), damping=0.7, set_dt=True, enlarge=0.01)
    O.dt = 1e-9
    omega.ip2(O).setCohesionNow = True  # rough platens, intact joints
    advance(1)
    omega.ip2(O).setCohesionNow = False
    return ids, bottom, top


def _consolidate(platen, H):
    """Runs until the top platen (its State) stops (at most 20000 steps); returns the steps run."""
    from .scene import advance
    y_prev, steps = platen.pos[1], 0
    for _ in range(100):
        advance(200)
        steps += 200
        y = platen.pos[1]
        if abs(y - y_prev) < 1e-7 * H:
            break
        y_prev = y
    return steps


def biaxial_test(sigma3, joint_cohesion, joint_tan_phi, young, poisson, spacing=1.0, seed=1, width_blocks=8,
                 aspect=2.0, min_distance=0.5, tensile_strength=None, density=2000.0, strain_per_step=1e-6,
                 max_strain=0.03, drop=0.85, thickness=1.0, ductile=True, residual=False):
    """One plane-strain biaxial test of a Voronoi sample (see the module docstring) in the current
    scene (it is reset). Returns a :class:`BiaxialResult`. *tensile_strength* of the joints
    defaults to c_j / tan phi_j (0 without cohesion). *ductile*: RbsmMat.ductile of the joints
    (True: the cohesion survives slip, as in the continuum the calibration aims at). *residual*:
    run to *max_strain* whatever the peak and report the mean axial stress of its last quarter
    (the strength after the interlocking is lost). The side pressure acts horizontally on the
    blocks that form the sides at the start (permanent forces: a membrane that follows them), the
    platens are rough (bonded), the top one is driven at *strain_per_step* of the height per step."""
    from yade import O, Vector3
    from .scene import advance
    who = "biaxial_test"
    sigma3 = number(who, "sigma3", sigma3, 0)
    joint_cohesion = number(who, "joint_cohesion", joint_cohesion, 0)
    joint_tan_phi = number(who, "joint_tan_phi", joint_tan_phi, 0, low_open=True)
    spacing = number(who, "spacing", spacing, 0, low_open=True)
    width_blocks = count(who, "width_blocks", width_blocks)
    strain_per_step = number(who, "strain_per_step", strain_per_step, 0, 0.01, low_open=True)
    max_strain = number(who, "max_strain", max_strain, 0, 1, low_open=True)
    if tensile_strength is None:
        tensile_strength = joint_cohesion / joint_tan_phi
    w0 = time.time()
    W = width_blocks * spacing
    H = aspect * W
    ids, _, top = _sample(W, H, sigma3, sigma3 * W * thickness, young, poisson, density, joint_cohesion, joint_tan_phi,
                          tensile_strength, ductile, spacing, seed, min_distance, thickness)
    steps = 1 + _consolidate(O.bodies[top].state, H)  # isotropic stage
    # axial stage: the top platen driven down at a constant strain rate
    O.forces.setPermF(top, Vector3(0, 0, 0))
    st = O.bodies[top].state
    st.blockedDOFs = "xyzXYZ"
    y0 = st.pos[1]
    area = W * thickness
    peak, eps_peak, peaked = -math.inf, 0.0, False
    curve = []
    while True:
        st.vel = Vector3(0, -strain_per_step * H / O.dt, 0)
        advance(50)
        steps += 50
        s1 = O.forces.f(top)[1] / area
        eps = (y0 - st.pos[1]) / H
        curve.append((eps, s1))
        if s1 > peak:
            peak, eps_peak = s1, eps
        elif not residual and s1 < drop * peak and peak > sigma3:
            peaked = True
            break
        if eps > max_strain:
            break
    res = None
    if residual:
        tail = [v for e, v in curve if e >= 0.75 * max_strain]
        res = sum(tail) / len(tail) if tail else None
    return BiaxialResult(sigma3, peak, eps_peak, steps, time.time() - w0, len(ids), peaked, curve, res)


@dataclass
class ShearResult:
    sigma_n: float  # normal stress on the top platen [Pa]
    peak: float  # peak shear stress tau [Pa]
    disp_at_peak: float  # horizontal displacement of the top platen at the peak, / sample height
    large: float  # mean tau over the last quarter of the displacement range [Pa]
    dilation: float  # rise of the top platen during shearing, / sample height
    steps: int
    wall: float
    blocks: int
    curve: List[tuple] = field(default_factory=list, repr=False)  # (disp / H, tau, rise / H, tau_mid, sigma_mid)
    peak_mid: float = math.nan  # peak of tau_mid: the shear stress on the platens' middle halves (no end effect) [Pa]
    sigma_mid_at_peak: float = math.nan  # the normal stress on the platens' middle halves at that peak [Pa]
    large_mid: float = math.nan  # mean tau_mid over the last quarter of the displacement range [Pa]
    sigma_mid_large: float = math.nan  # mean sigma_mid over the last quarter [Pa]


def fit_coulomb(sigma_n, tau):
    """Least-squares line tau = c + sigma_n tan phi; returns (c, phi [rad]). ValueError for fewer
    than two distinct normal stresses."""
    t, c = _line(sigma_n, tau, "fit_coulomb", "(sigma_n, tau) pairs", "normal stresses")
    return c, math.atan(t)


def simple_shear_test(sigma_n, joint_cohesion, joint_tan_phi, young, poisson, spacing=1.0, seed=1, length_blocks=24,
                      height_blocks=6, min_distance=0.5, tensile_strength=None, density=2000.0, disp_per_step=1e-6,
                      max_disp=0.08, thickness=1.0, ductile=True, end_pressure=0.0, verbose=False):
    """One direct (simple) shear test of a long Voronoi sample in the current scene (it is reset):
    the mobilised strength of a horizontal band of the tessellation, to compare with the biaxial
    peak of :func:`biaxial_test`. The sample, *length_blocks* x *height_blocks* cells of *spacing*,
    lies between two rigid platens glued to it (the block-platen joints made unbreakable: with the
    joints' strength the sample slides on a platen instead of shearing); the bottom one is fixed, the top one carries a
    permanent downward force *sigma_n* x length x *thickness* and is free vertically only. After
    consolidation (until the top platen stops) the top platen is driven horizontally at
    *disp_per_step* of the sample height per step to *max_disp* of the height, the normal force
    kept. tau = the horizontal force on the top platen / (length x thickness). The sample's ends
    are free (*end_pressure* 0; a pressure on them acts like biaxial_test's side pressure): the
    length of 4 heights keeps their effect small, but they are unconfined. Returns a
    :class:`ShearResult` (peak tau, and *large*: the mean tau over the last quarter of the
    displacement range). *tensile_strength* of the joints defaults to c_j / tan phi_j."""
    from yade import O, Vector3
    from .scene import advance
    who = "simple_shear_test"
    sigma_n = number(who, "sigma_n", sigma_n, 0, low_open=True)
    joint_cohesion = number(who, "joint_cohesion", joint_cohesion, 0)
    joint_tan_phi = number(who, "joint_tan_phi", joint_tan_phi, 0, low_open=True)
    young = number(who, "young", young, 0, low_open=True)
    spacing = number(who, "spacing", spacing, 0, low_open=True)
    length_blocks = count(who, "length_blocks", length_blocks)
    height_blocks = count(who, "height_blocks", height_blocks)
    disp_per_step = number(who, "disp_per_step", disp_per_step, 0, 0.01, low_open=True)
    max_disp = number(who, "max_disp", max_disp, 0, 1, low_open=True)
    end_pressure = number(who, "end_pressure", end_pressure, 0)
    if tensile_strength is None:
        tensile_strength = joint_cohesion / joint_tan_phi
    w0 = time.time()
    L = length_blocks * spacing
    H = height_blocks * spacing
    area = L * thickness
    ids, bottom, top = _sample(L, H, end_pressure, sigma_n * area, young, poisson, density, joint_cohesion, joint_tan_phi,
                               tensile_strength, ductile, spacing, seed, min_distance, thickness)
    st = O.bodies[top].state
    # glued platens: the block-platen joints would otherwise have the joints' strength, and a straight
    # interface with no interlocking is where the sample would slip (tau ~ c_j + sigma_n tan phi_j)
    glue = 1e3 * max(sigma_n, joint_cohesion, tensile_strength)
    for I in O.interactions:
        if I.isReal and (I.id1 in (bottom, top) or I.id2 in (bottom, top)):
            I.phys.cohesion, I.phys.tanPhi, I.phys.tensileStrength = glue, 10.0, glue
    steps = 1 + _consolidate(st, H)
    x0, y0 = st.pos[0], st.pos[1]
    peak, d_peak = -math.inf, 0.0
    peak_mid, sig_mid_peak = -math.inf, math.nan
    curve = []

    def middle():
        """(tau, sigma) carried by the joints of both platens whose midpoints lie in the middle half
        of the platen (the free ends' effect left out); the force on body 2 of a joint is
        normalForce n + shearForce t."""
        fx = fy = 0.0
        for pid, shift, sign in ((top, st.pos[0] - x0, 1.0), (bottom, 0.0, -1.0)):
            for I in O.interactions.withBody(pid):
                if not I.isReal:
                    continue
                g, ph = I.geom, I.phys
                if not 0.25 * L <= 0.5 * (g.p0[0] + g.p1[0]) - shift <= 0.75 * L:
                    continue
                tx, ty = (g.p1[0] - g.p0[0]) / g.length, (g.p1[1] - g.p0[1]) / g.length
                s = 1.0 if I.id2 == pid else -1.0  # force on the platen
                fx += sign * s * (ph.normalForce * g.normal[0] + ph.shearForce * tx)
                fy += sign * s * (ph.normalForce * g.normal[1] + ph.shearForce * ty)
        a = 2 * 0.5 * L * thickness  # two platens, half the length each
        return -fx / a, fy / a

    while True:
        st.vel = Vector3(disp_per_step * H / O.dt, st.vel[1], 0)
        advance(50)
        steps += 50
        tau = -O.forces.f(top)[0] / area
        d = (st.pos[0] - x0) / H
        tm, sm = middle()
        curve.append((d, tau, (st.pos[1] - y0) / H, tm, sm))
        if tau > peak:
            peak, d_peak = tau, d
        if tm > peak_mid:
            peak_mid, sig_mid_peak = tm, sm
        if verbose and len(curve) % 200 == 0:
            print("  simple shear sigma_n %.4g: disp %.4f H, tau %.5g Pa, rise %.5f H" % (sigma_n, d, tau, curve[-1][2]),
                  flush=True)
        if d > max_disp:
            break
    tail = [c for c in curve if c[0] >= 0.75 * max_disp]
    mean = lambda k: sum(c[k] for c in tail) / len(tail)
    return ShearResult(sigma_n, peak, d_peak, mean(1), curve[-1][2], steps, time.time() - w0, len(ids), curve,
                       peak_mid, sig_mid_peak, mean(3), mean(4))


@dataclass
class Calibration:
    """Joint -> assembly strength table of one tessellation (see the module docstring)."""
    params: dict
    rows: List[dict] = field(default_factory=list)  # tan_phi_j, c_j, phi_macro (deg), c_macro, misfit, tests

    def joint_strength(self, cohesion, tan_phi):
        """(c_j, tan phi_j): the joint strength for which the assembly has cohesion *cohesion* [Pa]
        and friction coefficient *tan_phi*: linear interpolation on the Delaunay triangulation of
        the assembly strengths of the table (scipy); ValueError outside the calibrated range."""
        from scipy.interpolate import LinearNDInterpolator
        cs = self.params["cohesion"]
        pts = [(r["c_macro"] / cs, math.tan(math.radians(r["phi_macro"]))) for r in self.rows]
        vals = [(r["c_j"], r["tan_phi_j"]) for r in self.rows]
        f = LinearNDInterpolator(pts, vals)
        v = [float(x) for x in f([(cohesion / cs, tan_phi)]).reshape(-1)]
        if not all(math.isfinite(x) for x in v):
            weakest = min(pts, key=lambda p: p[1])
            if tan_phi < weakest[1]:
                raise ValueError("calibration: the assembly tan phi = %.4g asked for is outside the calibrated assemblies and "
                                 "below the weakest one (tan phi %.4g, phi %.1f deg, with the joints' smallest friction): "
                                 "rigid Voronoi blocks interlock, and no joint strength makes the assembly that weak "
                                 "(docs/slope_factor_of_safety.md)" % (tan_phi, weakest[1],
                                                                        math.degrees(math.atan(weakest[1]))))
            lo_c, hi_c = min(p[0] for p in pts), max(p[0] for p in pts)
            ok = [x for x in (lo_c + (hi_c - lo_c) * k / 200 for k in range(201))
                  if all(math.isfinite(y) for y in f([(x, tan_phi)]).reshape(-1))]
            where = (("at tan phi %.4g the calibrated assemblies reach c %.4g..%.4g Pa" % (tan_phi, ok[0] * cs, ok[-1] * cs))
                     if ok else ("tan phi %.4g is outside the calibrated %.4g..%.4g" % (tan_phi, min(p[1] for p in pts),
                                                                                   max(p[1] for p in pts))))
            raise ValueError("calibration: no joint strength gives the assembly c = %.5g Pa, tan phi = %.4g (%s): widen "
                             "cohesion_factors or joint_friction_angles" % (cohesion, tan_phi, where))
        return float(v[0]), float(v[1])

    def report(self):
        p = self.params
        lines = ["Calibration of Voronoi RBSM joints by biaxial tests (%d x %g blocks wide, aspect %g, seeds %s, "
                 "min_distance %g, confinements %s x %.4g Pa, E = %.4g Pa, nu = %g)"
                 % (p["width_blocks"], p["spacing"], p["aspect"], p["seeds"], p["min_distance"],
                    p["confinements"], p["stress"], p["young"], p["poisson"]),
                 "%10s %12s | %10s %12s %8s %9s" % ("tan phi_j", "c_j [Pa]", "phi [deg]", "c [Pa]", "c/c_j",
                                                   "misfit")]
        for r in sorted(self.rows, key=lambda r: (r["tan_phi_j"], r["c_j"])):
            lines.append("%10.4f %12.5g | %10.3f %12.5g %8.3f %8.1f%%" % (
                r["tan_phi_j"], r["c_j"], r["phi_macro"], r["c_macro"], r["c_macro"] / r["c_j"] if r["c_j"] else math.nan,
                100 * r["misfit"]))
        return "\n".join(lines)

    def save(self, path):
        with open(path, "w") as f:
            json.dump(asdict(self), f, indent=1)

    @classmethod
    def load(cls, path):
        with open(path) as f:
            d = json.load(f)
        return cls(d["params"], d["rows"])


def _cache_path(params, cache):
    if cache is False:
        return None
    key = hashlib.sha1(json.dumps(params, sort_keys=True).encode()).hexdigest()[:16]
    d = cache if isinstance(cache, str) else os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.join(os.path.expanduser("~"), ".cache")), "yade_rbsm")
    os.makedirs(d, exist_ok=True)
    return os.path.join(d, "calibration-%s.json" % key)


def calibrate(cohesion, friction_angle, young, poisson, stress, spacing=1.0, min_distance=0.5, seeds=(1,),
              width_blocks=8, aspect=2.0, confinements=(0.05, 0.15, 0.3),
              joint_friction_angles=(0.5, 5.0, 10.0, 15.0, 20.0, 25.0), cohesion_factors=(0.0, 0.25, 0.5, 1.0),
              density=2000.0, strain_per_step=1e-6, cache=None, verbose=True, strength="peak", max_strain=0.03):
    """Calibrate joints so that a Voronoi assembly has the soil's *cohesion* [Pa] and
    *friction_angle* [rad] and the reduced strengths c/F, tan phi/F of strength reduction (see the
    module docstring). *stress*: the stress scale of the problem (gamma H of a slope) [Pa]; the
    confinements are *confinements* x *stress*. The joints tried: friction angles
    *joint_friction_angles* [deg], c_j = *cohesion_factors* x the soil's (every pair), ductile, tensile strength the soil's
    c/tan phi; the peaks of the *seeds* are averaged. *cache*: a directory (default
    ~/.cache/yade_rbsm), or False. Returns a :class:`Calibration` (``.report()`` prints the fitted
    envelopes). *strength*: "peak" (the peak axial stress) or "residual" (the mean of the last quarter
    of a test run to *max_strain*)."""
    from yade import O
    who = "calibrate"
    cohesion = number(who, "cohesion", cohesion, 0, low_open=True)
    friction_angle = number(who, "friction_angle", friction_angle, 0, math.pi / 2, low_open=True, high_open=True)
    stress = number(who, "stress", stress, 0, low_open=True)
    tan_phi_joint = [math.tan(math.radians(number(who, "joint_friction_angles[%d]" % k, f, 0, 90, low_open=True,
                                                  high_open=True))) for k, f in enumerate(joint_friction_angles)]
    cohesion_factors = [number(who, "cohesion_factors[%d]" % k, f, 0) for k, f in enumerate(cohesion_factors)]
    if len(tan_phi_joint) * len(cohesion_factors) < 3:
        raise ValueError("calibrate: the grid needs at least 3 joint strengths")
    seeds = [int(s) for s in seeds]
    if not seeds:
        raise ValueError("calibrate: give at least one tessellation seed")
    confinements = [number(who, "confinements[%d]" % k, f, 0) for k, f in enumerate(confinements)]
    if len(set(confinements)) < 2:
        raise ValueError("calibrate: give at least two different confinements (a Mohr-Coulomb envelope needs two points)")
    strain_per_step = number(who, "strain_per_step", strain_per_step, 0, 0.01, low_open=True)
    tp = math.tan(friction_angle)
    tensile = cohesion / tp
    params = dict(cohesion=cohesion, friction_angle=friction_angle, young=young, poisson=poisson, stress=stress,
                  spacing=spacing, min_distance=min_distance, seeds=seeds, width_blocks=width_blocks, aspect=aspect,
                  confinements=list(confinements), joint_friction_angles=list(joint_friction_angles),
                  cohesion_factors=cohesion_factors,
                  density=density, strain_per_step=strain_per_step, version=2)
    if strength not in ("peak", "residual"):
        raise ValueError("calibrate: strength must be 'peak' or 'residual', got %r" % (strength,))
    if strength != "peak":
        params.update(strength=strength, max_strain=max_strain)
    path = _cache_path(params, cache)
    if path and os.path.exists(path):
        cal = Calibration.load(path)
        if verbose:
            print("calibration from the cache %s" % path)
        return cal
    mark = "rbsm_calibration_user_scene"
    saved = len(O.bodies) > 0 or len(O.engines) > 0
    if saved:
        O.saveTmp(mark)
    cal = Calibration(params)
    try:
        for tj, cj in ((t, cohesion * b) for t in tan_phi_joint for b in cohesion_factors):
            s3, s1 = [], []
            for f in confinements:
                peaks = [biaxial_test(f * stress, cj, tj, young, poisson, spacing, seed=s, width_blocks=width_blocks,
                                      aspect=aspect, min_distance=min_distance, density=density,
                                      strain_per_step=strain_per_step, tensile_strength=tensile,
                                      ductile=True, residual=strength == "residual", max_strain=max_strain)
                         for s in seeds]
                s3.append(f * stress)
                s1.append(sum(p.peak if strength == "peak" else p.residual for p in peaks) / len(peaks))
                if verbose:
                    print("  biaxial: tan phi_j %.4f, c_j %.5g Pa, sigma3 %.5g Pa: %s sigma1 %s Pa (%s)" % (
                        tj, cj, f * stress, strength, " ".join("%.5g" % (p.peak if strength == "peak" else p.residual)
                                                               for p in peaks),
                        ", ".join("%d steps %.1f s%s" % (p.steps, p.wall, "" if p.peaked else " NO PEAK")
                                  for p in peaks)), flush=True)
            try:
                c, phi, kp, q, misfit = fit_mohr_coulomb(s3, s1)
            except ValueError as e:  # e.g. a residual state with (nearly) frictionless joints: no envelope
                if verbose:
                    print("  left out of the table: tan phi_j %.4f, c_j %.5g Pa: %s" % (tj, cj, e), flush=True)
                continue
            if c < 0:  # a curved envelope's negative intercept: no Mohr-Coulomb soil to map to
                if verbose:
                    print("  left out of the table: tan phi_j %.4f, c_j %.5g Pa: fitted cohesion %.4g Pa < 0 (phi %.1f deg)"
                          % (tj, cj, c, math.degrees(phi)), flush=True)
                continue
            cal.rows.append(dict(tan_phi_j=tj, c_j=cj, phi_macro=math.degrees(phi), c_macro=c, misfit=misfit,
                                 sigma3=s3, sigma1=s1))
    finally:
        if saved:
            O.loadTmp(mark)
        else:
            O.resetThisScene()
    if len(cal.rows) < 3:
        raise ValueError("calibrate: only %d of the joint strengths gave a Mohr-Coulomb envelope (at least 3 are needed "
                         "to interpolate); not cached" % len(cal.rows))
    if path:
        cal.save(path)
    if verbose:
        print(cal.report())
    return cal
