"""yade_rbsm.geometry and yade_rbsm.omega without YADE (issue 20): the shared plane geometry, and the
engine look-up by label with its fall-back to the class name for engine lists built by hand, on a
stand-in O (omega recognises classes by their names)."""
import importlib.util
import math
import os

import pytest

PY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "py", "yade_rbsm"))


def _load(name):
    spec = importlib.util.spec_from_file_location("rbsm_" + name, os.path.join(PY, name + ".py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


G = _load("geometry")
W = _load("omega")


# ---- geometry ---------------------------------------------------------------------------------
def test_areas_centroid_moment_of_a_square():
    sq = [(1, 1), (3, 1), (3, 3), (1, 3)]
    assert G.polygon_area(sq) == 4.0 and G.signed_area(sq) == 4.0
    assert G.polygon_area(sq[::-1]) == -4.0
    area, c, j = G.polygon_properties(sq)
    assert area == 4.0 and c == (2.0, 2.0)
    assert j == pytest.approx(2 * 2 ** 4 / 12)  # (a^2 + b^2) a b / 12
    assert G.polygon_centroid(sq) == (2.0, 2.0)
    with pytest.raises(ValueError, match="zero area"):
        G.polygon_properties([(0, 0), (1, 0), (2, 0)])


def test_distances_and_sides():
    assert G.point_segment_distance((0, 1), (-1, 0), (1, 0)) == 1.0
    assert G.point_segment_distance((3, 4), (0, 0), (0, 0)) == 5.0
    assert G.point_polyline_distance((2, 1), [(0, 0), (1, 0), (1, 5)]) == 1.0
    assert G.height_above((0.5, 2), [(0, 0), (1, 1)]) == 1.5
    assert G.interp_y([(0, 0), (2, 2), (4, 2)], 1) == 1.0 and G.interp_y([(0, 0), (2, 2)], 9) == 2
    xc, yc, r = G.circle_through((1, 0), (0, 1), (-1, 0))
    assert math.hypot(xc, yc) < 1e-15 and r == pytest.approx(1.0)


def test_cuts_keep_the_area():
    sq = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]
    pieces = G.cut_polygons([sq], [[(-1.0, 0.5), (3.0, 1.5)]])
    assert len(pieces) == 2
    assert sum(G.polygon_area(p) for p in pieces) == pytest.approx(4.0)
    assert all(G.polygon_area(p) > 0 for p in pieces)
    below, above = G.split_by_line([sq], G.Line((0, 1), (2, 1)), 1e-12)
    assert G.polygon_area(below) == G.polygon_area(above) == 2.0


@pytest.mark.parametrize("bad, words", [(None, "none given"), ([], "at least 2"), ([(0, 0), (math.nan, 1)], "NaN"),
                                        ([(1, 0), (0, 1)], "strictly increasing"), ("ab", "pairs")])
def test_polyline_checks(bad, words):
    with pytest.raises(ValueError, match=words):
        G.check_polyline(bad)


def test_z_order_keeps_neighbours_near():
    """z_order (build_scene numbers blocks with it): a permutation, points near in the plane near in the order."""
    import random
    rng = random.Random(4)
    for n, w, h in ((3000, 30.0, 10.0), (500, 1e-3, 2e-3), (200, 1e4, 1.0)):
        pts = [(rng.uniform(0, w), rng.uniform(0, h)) for _ in range(n)]
        o = G.z_order(pts)
        assert sorted(o) == list(range(n))
        step = sum(math.dist(pts[o[i]], pts[o[i + 1]]) for i in range(n - 1)) / (n - 1)
        at_random = sum(math.dist(pts[i], pts[i + 1]) for i in range(n - 1)) / (n - 1)
        assert step < 0.15 * at_random, (n, step, at_random)
    grid = [(x, y) for y in range(4) for x in range(4)]  # the Z of 2 x 2 cells, then of their quadrants
    assert [grid[i] for i in G.z_order(grid)][:4] == [(0, 0), (1, 0), (0, 1), (1, 1)]
    assert G.z_order([]) == [] and G.z_order([(2, 2)]) == [0] and G.z_order([(1, 1)] * 3) == [0, 1, 2]


def test_polygon_check_names_a_bow_tie():
    with pytest.raises(ValueError, match="not simple"):
        G.check_polygon([(0, 0), (1, 1), (1, 0), (0, 1)])


# ---- omega on a stand-in O --------------------------------------------------------------------
def _cls(name):
    """A stand-in class called *name*: attributes label (default "") and the keywords given."""
    def __init__(self, label="", **kw):
        self.label = label
        self.__dict__.update(kw)
    return type(name, (), {"__init__": __init__})


NewtonIntegrator, PyRunner, RbsmTimeStepper = _cls("NewtonIntegrator"), _cls("PyRunner"), _cls("RbsmTimeStepper")
Ip2_RbsmMat_RbsmMat_RbsmPhys, Ip2_FrictMat_FrictMat_FrictPhys = _cls("Ip2_RbsmMat_RbsmMat_RbsmPhys"), _cls("Ip2_FrictMat_FrictMat_FrictPhys")
RbsmPhys, FrictPhys, Dispatcher, InteractionLoop = _cls("RbsmPhys"), _cls("FrictPhys"), _cls("Dispatcher"), _cls("InteractionLoop")


class _O:
    def __init__(self, engines, interactions=(), bodies=()):
        self.engines, self.interactions, self.bodies = engines, list(interactions), list(bodies)


def _loop(*ip2):
    return InteractionLoop(geomDispatcher=Dispatcher(functors=[]), physDispatcher=Dispatcher(functors=list(ip2)),
                           lawDispatcher=Dispatcher(functors=[]))


def test_engines_by_label():
    n1, n2 = NewtonIntegrator(), NewtonIntegrator(label="newton")
    ip = Ip2_RbsmMat_RbsmMat_RbsmPhys(label="ip2")
    O = _O([PyRunner(), _loop(Ip2_FrictMat_FrictMat_FrictPhys(), ip), n1, n2])
    assert W.newton(O) is n2 and W.ip2(O) is ip


def test_engines_without_labels_fall_back_to_the_class():
    """A list built by hand: no labels; the first engine of the label's class."""
    n1, ts = NewtonIntegrator(), RbsmTimeStepper()
    ip = Ip2_RbsmMat_RbsmMat_RbsmPhys()
    runners = [PyRunner(), PyRunner()]
    O = _O([runners[0], _loop(Ip2_FrictMat_FrictMat_FrictPhys(), ip), ts, n1, NewtonIntegrator(), runners[1]])
    assert W.newton(O) is n1 and W.ip2(O) is ip and W.engine("timeStepper", O) is ts
    W.switch_off_pyrunners(O)
    assert all(r.dead for r in runners)
    with pytest.raises(LookupError, match="collider"):
        W.engine("collider", O)
    with pytest.raises(LookupError, match="myEngine"):
        W.engine("myEngine", O)


def test_joints_and_free_bodies():
    class I:
        def __init__(self, real, phys):
            self.isReal, self.phys = real, phys

    class B:
        def __init__(self, dofs):
            self.state = type("S", (), {"blockedDOFs": dofs})()

    inter = [I(True, RbsmPhys()), I(False, RbsmPhys()), I(True, FrictPhys()), I(True, RbsmPhys())]
    bodies = [B("zXY"), None, B("xyzXYZ"), B("")]
    O = _O([], inter, bodies)
    assert list(W.joints(O)) == [inter[0], inter[3]]
    assert W.free_bodies(O) == [bodies[0], bodies[3]]
    assert W.is_fixed(bodies[2]) and not W.is_fixed(bodies[3])
