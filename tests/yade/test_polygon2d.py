"""Polygon2D in YADE, loaded through the launcher build/yade-rbsm as a user loads it.

Each test runs one yade script (asserts inside the script; a failure prints the traceback) and,
where useful, checks the reported numbers against closed forms here.
"""
import math

import pytest

from yaderun import results, run_ok, run_yade

SQUARE = "[(-1, -1), (1, -1), (1, 1), (-1, 1)]"  # side 2: area 4, J = a^4/6 = 16/6
# right triangle (0,0),(3,0),(0,3) moved to its centroid (1,1)
TRIANGLE = "[(-1, -1), (2, -1), (-1, 2)]"


def test_class_is_registered_like_a_builtin():
    r = run_ok("""
import yade.wrapper
assert 'Polygon2D' in O.childClassesNonrecursive('Shape'), O.childClassesNonrecursive('Shape')
assert yade.wrapper.Polygon2D is Polygon2D and issubclass(Polygon2D, Shape)
p = Polygon2D()
report(cls=p.__class__.__name__, dispatchIndex=p.dispIndex, vertices=list(p.vertices), area=p.area)
""")
    assert r == [{"cls": "Polygon2D", "dispatchIndex": r[0]["dispatchIndex"], "vertices": [], "area": 0.0}]
    assert r[0]["dispatchIndex"] > 0  # took an index after YADE's own shapes


def test_vertices_and_derived_quantities():
    r = run_ok("""
p = Polygon2D(vertices=%s)
sq = dict(n=len(p.vertices), area=p.area, J=p.polarMoment, R=p.circumradius, v1=tuple(p.vertices[1]))
p.vertices = %s  # setting triggers the check and the derived values again
tri = dict(n=len(p.vertices), area=p.area, J=p.polarMoment, R=p.circumradius)
report(square=sq, triangle=tri)
""" % (SQUARE, TRIANGLE))[0]
    sq, tri = r["square"], r["triangle"]
    assert sq["n"] == 4 and sq["v1"] == [1.0, -1.0]
    assert sq["area"] == pytest.approx(4.0, rel=1e-14)
    assert sq["J"] == pytest.approx(16 / 6, rel=1e-14)
    assert sq["R"] == pytest.approx(math.sqrt(2), rel=1e-14)
    # right isosceles triangle, legs a = 3: A = a^2/2, J about the centroid = a^4/18 (Ix = Iy = a^4/36)
    assert tri["n"] == 3 and tri["area"] == pytest.approx(4.5, rel=1e-14)
    assert tri["J"] == pytest.approx(81 / 18, rel=1e-13)
    assert tri["R"] == pytest.approx(math.sqrt(5), rel=1e-14)


def test_base_attributes_and_readonly_derived():
    run_ok("""
p = Polygon2D(vertices=%s, color=(0.2, 0.4, 0.6), wire=True)
assert p.color == Vector3(0.2, 0.4, 0.6) and p.wire is True and p.highlight is False
p.color = (1, 0, 0); p.wire = False; p.highlight = True
assert p.color == Vector3(1, 0, 0) and not p.wire and p.highlight
d = p.dict()
assert 'vertices' in d and 'color' in d and 'wire' in d, d.keys()
try:
    p.area = 3
    raise SystemExit('area should be read-only')
except AttributeError:
    pass
report(ok=True)
""" % SQUARE)


@pytest.mark.parametrize("vertices,what", [
    ("[(-1, -1), (-1, 1), (1, 1), (1, -1)]", "clockwise"),
    ("[(-2, -1), (2, -1), (0, -0.5), (0, 2.5)]", "non-convex"),
    ("[(-1, 0), (0, 0), (1, 0)]", "degenerate (collinear)"),
    ("[(0, 0), (2, 0), (2, 2), (0, 2)]", "off-centre"),
    ("[(-1, -1), (1, -1)]", "two vertices"),
])
def test_invalid_polygon_raises_value_error(vertices, what):
    r = run_ok("""
msgs = []
for how in ('ctor', 'setter'):
    try:
        if how == 'ctor':
            Polygon2D(vertices=%s)
        else:
            p = Polygon2D(vertices=%s); p.vertices = %s
        msgs.append(None)
    except ValueError as e:
        msgs.append(str(e))
report(msgs=msgs)
""" % (vertices, SQUARE, vertices))[0]
    assert all(m and "Polygon2D" in m for m in r["msgs"]), "%s polygon accepted or wrong message: %s" % (what, r["msgs"])


BLOCK_SCENE = """
from yade import utils
g = 9.81
mat = FrictMat(density=2000, young=1e8, label='rock')
O.materials.append(mat)

def block(vertices, pos, fixed=False):
    p = Polygon2D(vertices=vertices, color=(0.3, 0.5, 0.7))
    b = Body(shape=p, material=mat)
    b.state.pos = pos
    b.state.mass = mat.density * p.area * p.thickness
    b.state.inertia = (1, 1, mat.density * p.polarMoment * p.thickness)
    b.state.blockedDOFs = 'xyzXYZ' if fixed else 'zXY'
    return O.bodies.append(b)

base = block([(-5, -0.5), (5, -0.5), (5, 0.5), (-5, 0.5)], (0, -0.5, 0), fixed=True)
falling = block(%s, (0, 10, 0))
O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, -g, 0), damping=0)]
O.dt = 1e-3
"""


@pytest.mark.parametrize("jobs", [1, 2])
def test_free_fall_with_newton_integrator(jobs):
    r = run_ok(BLOCK_SCENE % SQUARE + """
O.run(500, True)
b = O.bodies[falling]
report(threads=O.numThreads, t=O.time, iter=O.iter, y=b.state.pos[1], x=b.state.pos[0], vy=b.state.vel[1],
       angle=b.state.ori.toAxisAngle()[1], base_y=O.bodies[base].state.pos[1], mass=b.state.mass)
""", jobs=jobs)[0]
    assert r["threads"] == jobs
    assert r["iter"] == 500 and r["t"] == pytest.approx(0.5, rel=1e-12)
    g, dt, n = 9.81, 1e-3, 500
    # NewtonIntegrator (velocity first, then position): v_n = -g n dt, y_n = y0 - g dt^2 n(n+1)/2
    assert r["vy"] == pytest.approx(-g * n * dt, rel=1e-12)
    assert r["y"] == pytest.approx(10 - g * dt * dt * n * (n + 1) / 2, rel=1e-12)
    assert abs(r["y"] - (10 - g * r["t"] ** 2 / 2)) <= g * dt * r["t"]  # the closed form 1/2 g t^2, to O(dt)
    assert r["x"] == 0 and r["angle"] == 0 and r["base_y"] == -0.5
    assert r["mass"] == pytest.approx(2000 * 4)


@pytest.mark.parametrize("ext", ["xml", "yade", "xml.bz2"])
def test_save_and_load_keep_values(ext):
    run_ok(BLOCK_SCENE % TRIANGLE + """
O.bodies.append(utils.sphere((3, 3, 0), 0.5, color=(0.9, 0.1, 0.1)))  # YADE's own shape in the same scene
O.bodies[falling].shape.wire = True
O.run(10, True)
before = [(b.shape.__class__.__name__, b.shape.dict(), b.state.pos, b.state.vel, b.state.mass, b.material.label, b.state.blockedDOFs) for b in O.bodies]
t, it = O.time, O.iter
O.save('scene.%s')
O.reset()
assert len(O.bodies) == 0
O.load('scene.%s')
assert O.iter == it and O.time == t, (O.iter, O.time)
after = [(b.shape.__class__.__name__, b.shape.dict(), b.state.pos, b.state.vel, b.state.mass, b.material.label, b.state.blockedDOFs) for b in O.bodies]
assert len(before) == len(after) == 3
for x, y in zip(before, after):
    assert x[0] == y[0] and x[2:] == y[2:], (x, y)
    for k in x[1]:
        assert x[1][k] == y[1][k], (k, x[1][k], y[1][k])
p = O.bodies[falling].shape
assert p.area == 4.5 and abs(p.polarMoment - 4.5) < 1e-12 and p.wire, (p.area, p.polarMoment)  # derived values recomputed on load
O.bodies[falling].material.density = 1234  # shared material stays shared (one object after loading)
assert O.bodies[base].material.density == 1234 and O.materials[0].density == 1234
O.run(10, True)  # and the loaded scene runs on
report(ok=True)
""" % (ext, ext))


def test_script_error_fails_the_run():
    """The helper (and so every test) sees a failing yade script as a failure."""
    p = run_yade("raise RuntimeError('expected failure')")
    assert p.returncode != 0 and "expected failure" in p.stdout + p.stderr


def test_periodic_cell_is_refused_without_a_crash():
    """Two blocks touching across a periodic cell's boundary: periodic cells are not supported. The bound functor
    names each body on stderr at the first step and stops the run after it (an exception cannot leave YADE's
    OpenMP loop; before, YADE died in std::terminate). Since issue 15 the refusal is for any periodic cell (a cell as
    thick as the blocks aborted in YADE's collider assertion), not only for contacts across its boundary."""
    p = run_yade("""
from yade_rbsm.blocks import polygon2d
mat = RbsmMat(young=1e9, poisson=0.2, density=2000, frictionAngle=0.5)
O.materials.append(mat)
O.periodic = True
O.cell.setBox(2, 2, 10)
a = O.bodies.append(polygon2d([(0.05, 0.5), (0.55, 0.5), (0.55, 1.0), (0.05, 1.0)], mat))
b = O.bodies.append(polygon2d([(1.55, 0.5), (2.0499, 0.5), (2.0499, 1.0), (1.55, 1.0)], mat))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb()], verletDist=0.01),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom()], [Ip2_RbsmMat_RbsmMat_RbsmPhys()], [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()]),
             NewtonIntegrator()]
O.dt = 1e-5
O.run(10, True)
report(iter=O.iter, contacts=O.interactions.countReal())
""", jobs=2)
    assert p.returncode == 0, p.stderr[-3000:]
    for body in (0, 1):
        assert "body #%d is in a periodic cell (O.periodic): Polygon2D blocks do not support periodic cells" % body in p.stderr, p.stderr[-3000:]
    assert results(p) == [{"iter": 1, "contacts": 0}]


def test_blocks_at_map_coordinates_from_1_mm_to_10_m():
    """Blocks drawn in UTM coordinates (x 512 345 m, y 4 212 345 m; a new user's trial 14b): the local
    vertices were the world ones less the centroid, with round-off eps x 4e6 = 1e-9 m: 0.1 m, 1 cm and
    1 mm blocks were refused at random ("the centroid must be at the origin of the body frame"), and a
    file io.export_blocks wrote of them did not import. Now every size is taken, with the closed-form area."""
    (r,) = run_ok("""
from yade_rbsm import polygon2d
m = RbsmMat()
X, Y = 512345.678, 4212345.678
out = {}
for s in [10.0, 1.0, 0.1, 0.05, 0.01, 1e-3]:
    pts = [(X, Y), (X + s, Y), (X + s, Y + 0.6 * s), (X + 0.2 * s, Y + s)]
    try:
        b = polygon2d(pts, m)
        out[repr(s)] = [b.shape.area, b.state.pos[0] - X, b.state.pos[1] - Y]
    except ValueError as e:
        out[repr(s)] = str(e)
report(**out)
""")
    for s, v in r.items():
        s = float(s)
        assert isinstance(v, list), (s, v)
        assert v[0] == pytest.approx(0.74 * s * s, rel=1e-6), (s, v)  # shoelace of (0,0) (1,0) (1,0.6) (0.2,1)
        assert 0 < v[1] < s and 0 < v[2] < s, (s, v)


def test_a_block_of_short_edges_is_warned_about():
    """Issue 34, item 8: a 10 000-sided polygon (a "disc", 0.3 mm edges) on a base sank 41 % of its diameter
    into it with overlap warnings only: a joint acts along one pair of edges, so the block rests on a 0.3 mm
    spring. polygon2d now says so when the block is made; a 64-gon (edges 4.9 % of its size) and a brick are
    not warned about. On 2c4bcaa no warning."""
    p = run_yade("""
import math, warnings
from yade_rbsm import polygon2d
mat = RbsmMat(young=1e8, density=2000)
O.materials.append(mat)
out = {}
for n in (10000, 64, 4):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        polygon2d([(0.5 * math.cos(2 * math.pi * (k + 0.5) / n), 0.5 * math.sin(2 * math.pi * (k + 0.5) / n)) for k in range(n)], mat)
    out[str(n)] = [str(x.message) for x in w]
report(**out)
""")
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    assert len(r["10000"]) == 1 and "longest edge" in r["10000"][0] and "10000 vertices" in r["10000"][0], r
    assert r["64"] == [] and r["4"] == [], r


def test_a_block_too_far_from_the_origin_for_its_size_is_warned_about():
    """Issue 34's closing pass: blocks at 1e10-2.4e12 m, where double precision resolves a position to 2e-5-2.5e-3 of
    their size, were accepted without a word and moved 2.4-44 % of their size otherwise than the same scene at the
    origin. polygon2d says so; UTM coordinates (4.2e6 m) with blocks from 1 mm up and blocks near the origin are
    not warned about."""
    p = run_yade("""
import warnings
from yade_rbsm import polygon2d
mat = RbsmMat(young=1e8, density=2000)
out = {}
for key, (x, s) in {"1e12": (1e12, 1.0), "1e10": (1e10, 1.0), "utm_1mm": (4212345.678, 1e-3), "origin": (0.0, 1e-3)}.items():
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        polygon2d([(x, x), (x + s, x), (x + s, x + s), (x, x + s)], mat)
    out[key] = [str(m.message) for m in w]
report(**out)
""")
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (r,) = results(p)
    print(r)
    for key in ("1e12", "1e10"):
        assert len(r[key]) == 1 and "resolves a position to" in r[key][0] and "near the origin" in r[key][0], r
    assert r["utm_1mm"] == [] and r["origin"] == [], r
