"""The per-point values of a joint, as Python sees them: RbsmGeom samples the linear relative motion of the
two rigid blocks at the Gauss points, RbsmPhys keeps the state of each point inline (no per-point arrays).

Scene: two unit squares, the upper one pushed into the lower by a uniform overlap δ and moving with a known
velocity (vx, vy) and spin ω; one step (no integrator, so the blocks stay put) makes the contact and applies
the law. Closed forms: the overlap is uniform, δn_k = δ; the relative velocity at a point x of the contact is
that of the upper block's material point, (vx − ω (y − yc), vy + ω (x − xc)), the lower block being fixed;
σn_k = kn δ, and the first shear increment is elastic, τ_k = −ks Δus_k.
"""
import math

import pytest

from yaderun import results, run_ok, run_yade

SCENE = """
from yade_rbsm import polygon2d
mat = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=math.radians(30))
O.materials.append(mat)
d = 1e-4
lower = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], mat, fixed=True))
upper = O.bodies.append(polygon2d([(0, 1 - d), (1, 1 - d), (1, 2 - d), (0, 2 - d)], mat))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(nIP=%d)], [Ip2_RbsmMat_RbsmMat_RbsmPhys()],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()])]
O.dt = 1e-5
b = O.bodies[upper]
b.state.vel = (0.3, -0.2, 0)
b.state.angVel = (0, 0, 0.5)
O.step()
i = O.interactions[lower, upper]
g, p = i.geom, i.phys
"""


@pytest.mark.parametrize("nip", [2, 3])
def test_points_sample_the_rigid_relative_motion(nip):
    r = run_ok("import math\n" + SCENE % nip + """
pts = [tuple(g.point(k)) for k in range(g.nIP)]
report(nIP=g.nIP, s=list(g.positions), w=list(g.weights), dn=list(g.deltaN), vn=list(g.normalVelocity),
       vs=list(g.shearVelocity), dus=list(g.shearIncrement), dt=O.dt, pts=pts, n=tuple(g.normal), t=tuple(g.tangent),
       c2=tuple(b.state.pos), kn=p.kn, sn=list(p.normalTraction), tau=list(p.shearTraction), ks=p.ks,
       flags=[list(p.intactPoints), list(p.slippingPoints), list(p.openPoints)])
""")[0]
    assert r["nIP"] == nip and len(r["s"]) == nip and sum(r["w"]) == pytest.approx(1, abs=1e-15)
    d, vx, vy, w = 1e-4, 0.3, -0.2, 0.5
    nx, ny = r["n"]
    assert (nx, ny) == pytest.approx((0, 1), abs=1e-15)  # from the lower block (1) to the upper one (2)
    for k in range(nip):
        x, y = r["pts"][k]
        assert r["dn"][k] == pytest.approx(d, rel=1e-9)
        # upper block's material point velocity, the lower block is fixed
        ux, uy = vx - w * (y - r["c2"][1]), vy + w * (x - r["c2"][0])
        assert r["vn"][k] == pytest.approx(-(ux * nx + uy * ny), rel=1e-12)
        assert r["vs"][k] == pytest.approx(ux * r["t"][0] + uy * r["t"][1], rel=1e-12)
        assert r["dus"][k] == pytest.approx(r["vs"][k] * r["dt"], rel=1e-15)
        assert r["sn"][k] == pytest.approx(r["kn"] * d, rel=1e-9)
        assert r["tau"][k] == pytest.approx(-r["ks"] * r["dus"][k], rel=1e-9)  # first increment, elastic
    assert r["flags"] == [[False] * nip, [False] * nip, [False] * nip]  # cohesionless, sticking, closed


def test_shear_traction_is_settable_per_point_and_checked():
    run_ok("import math\n" + SCENE % 2 + """
p.shearTraction = [1.5, -2.5]
assert list(p.shearTraction) == [1.5, -2.5], p.shearTraction
for bad, what in (([1.0], 'one value per integration point'), ([1.0, float('nan')], 'not finite')):
    try:
        p.shearTraction = bad
        raise SystemExit('accepted %r' % (bad,))
    except ValueError as e:
        assert what in str(e), e
assert list(p.shearTraction) == [1.5, -2.5]  # a refused value leaves the joint as it was
q = RbsmPhys(kn=1, shearTraction=[3.0, 4.0, 5.0])  # the constructor takes them too
assert list(q.shearTraction) == [3, 4, 5] and q.nIntact == 3 and list(q.normalTraction) == [0, 0, 0]
try:
    RbsmPhys(shearTraction=[1.0, 2.0], normalTraction=[1.0])
    raise SystemExit('accepted per-point values of different lengths')
except ValueError as e:
    assert 'differ in length' in str(e), e
report(ok=True)
""")


@pytest.mark.parametrize("ext", ["xml", "yade"])
def test_points_survive_save_and_load(ext):
    r = run_ok("import math\n" + SCENE % 3 + """
p.shearTraction = [0.5, -0.25, 0.125]
p.breakJoint()
before = (list(p.shearTraction), list(p.normalTraction), list(p.intactPoints), g.nIP, list(g.positions))
O.save('joint.%s'); O.reset(); O.load('joint.%s')
i = O.interactions[lower, upper]
after = (list(i.phys.shearTraction), list(i.phys.normalTraction), list(i.phys.intactPoints), i.geom.nIP, list(i.geom.positions))
report(before=before, after=after)
""" % (ext, ext))[0]
    assert r["after"] == r["before"]
    assert r["after"][2] == [False] * 3 and r["after"][0] == [0.5, -0.25, 0.125]


def test_phys_with_another_number_of_points_is_refused_by_name():
    """An RbsmPhys set by hand with 3 points on a 2-point contact: the law names the interaction and both counts on
    stderr and removes the interaction (an exception cannot leave YADE's OpenMP loop); the blocks still touch, so
    the contact is made again with Ip2's 2-point joint. No crash, no reading past the points."""
    p = run_yade("import math\n" + SCENE % 2 + """
i.phys = RbsmPhys(kn=p.kn, ks=p.ks, tanPhi=p.tanPhi, shearTraction=[0.0, 0.0, 0.0])
O.step()
O.step()
j = O.interactions[lower, upper]
report(real=j.isReal, n=len(j.phys.shearTraction), kn=j.phys.kn)
""")
    assert p.returncode == 0, p.stderr[-3000:]
    assert "interaction #0+#1: RbsmPhys has 3 integration points, its RbsmGeom 2" in p.stderr, p.stderr[-3000:]
    r = results(p)[0]
    assert r["real"] and r["n"] == 2 and r["kn"] > 0


def test_mixed_plane_states_stop_the_run_without_a_crash():
    """A plane-strain block touching a plane-stress one: no joint stiffness follows from two plane states. Ip2 names
    the bodies on stderr, gives the joint no stiffness for that step and stops the run after it (before, a throw
    inside YADE's OpenMP loop ended YADE in std::terminate)."""
    p = run_yade("""
from yade_rbsm import polygon2d
strain = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=0.5, planeStrain=True)
stress = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=0.5, planeStrain=False)
O.materials.append(strain); O.materials.append(stress)
lower = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], strain, fixed=True))
upper = O.bodies.append(polygon2d([(0, 1 - 1e-4), (1, 1 - 1e-4), (1, 2 - 1e-4), (0, 2 - 1e-4)], stress))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()], verletDist=0.01),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()], [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
             NewtonIntegrator(gravity=(0, -9.81, 0))]
O.dt = 1e-5
O.run(10, True)
i = O.interactions[lower, upper]
report(iter=O.iter, kn=i.phys.kn, fy=O.forces.f(upper)[1])
""", jobs=2)
    assert p.returncode == 0, p.stderr[-3000:]
    assert "bodies #0 and #1 mix plane strain and plane stress materials (RbsmMat.planeStrain); the run stops after step 0" in p.stderr, p.stderr[-3000:]
    assert results(p) == [{"iter": 1, "kn": 0.0, "fy": 0.0}]
