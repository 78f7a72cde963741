# The homogeneous c'-phi' slopes of issue 21 (docs/slope_factor_of_safety.md), shared by
# scripts/slope_fs_study.py (RBSM), scripts/fe_stress_fs.py (finite elements), scripts/slope_stress_fs_table.py
# and the tests' slope scenes: H = 10 m, gamma = 20 kN/m3, a firm base at toe level (y = 0), the face rising from
# x = 12 m, a 20 m crest. Plain Python; plastic_soil() alone needs YADE.
import math

H = 10.0  # m
GAMMA = 20.0  # kN/m3
# name: face angle [deg], c' [kPa], phi' [deg], label (c'/gamma H)
SLOPES = {
    "20": (20.0, 5.0, 20.0, "20°, c′/γH 0.025, φ′ 20°"),
    "gl": (math.degrees(math.atan(0.5)), 10.0, 20.0, "26.6° (2:1), 0.05, 20° (Griffiths & Lane)"),
    "30": (30.0, 20.0, 25.0, "30°, 0.1, 25°"),
    "45": (45.0, 10.0, 40.0, "45°, 0.05, 40°"),
}
# Undrained (phi = 0): Griffiths & Lane's 2:1 slope with c_u / gamma H = 0.25 on a firm base at the toe (Taylor's
# depth factor D = 1); kept apart from SLOPES, which the drained tables iterate over.
UNDRAINED = {
    "taylor": (math.degrees(math.atan(0.5)), 50.0, 0.0, "26.6° (2:1), c_u/γH 0.25, φ 0 (Taylor, D = 1)"),
}


def case(name):
    """(face angle [deg], c' [kPa], phi' [deg], label) of a drained or undrained slope."""
    return SLOPES[name] if name in SLOPES else UNDRAINED[name]


def face_length(name):
    """Horizontal length of the face [m]."""
    return H / math.tan(math.radians(case(name)[0]))


def ground(name):
    """The ground polyline (for limit_equilibrium.Slope and the builders)."""
    L = face_length(name)
    return [(0, 0), (12, 0), (12 + L, H), (32 + L, H)]


def search(name):
    """critical_circle's grid (centres over the face, circles above the base)."""
    return dict(x_range=(5, 20 + face_length(name)), y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0,
                r_range=(5, 60), nr=19)


def soil(name):
    """The limit_equilibrium.Slope of the slope (kPa, kN/m3, degrees)."""
    from yade_rbsm import limit_equilibrium as le
    beta, c, phi, _ = case(name)
    return le.Slope(ground(name), le.Layer(c=c, phi=phi, gamma=GAMMA))


def plastic_soil(name, penalty=10.0, young=100e6, poisson=0.3, label=""):
    """The slope's soil as plastic deformable blocks (issue 39; SI units): its c', phi' in the blocks, plane strain,
    welded joints of RbsmMat.penalty, ductile; the tension cut-off at the Mohr-Coulomb apex c'/tan phi' (undrained:
    10 c_u, beyond any tension the slope reaches)."""
    from yade import wrapper
    _, c_kpa, phi_deg, _ = case(name)
    c, phi = c_kpa * 1e3, math.radians(phi_deg)
    return wrapper.RbsmMat(young=young, poisson=poisson, density=GAMMA * 1e3 / 9.81, frictionAngle=phi, cohesion=c,
                           tensileStrength=c / math.tan(phi) if phi > 0 else 10 * c, planeStrain=True, deformable=True,
                           plastic=True, penalty=penalty, ductile=True, label=label)
