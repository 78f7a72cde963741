"""Runtime cross-check of member offsets: fields written through YADE's own Python accessors are
read through the project's declarations (the test-only engine AbiProbe in libabi_probe.so) and the
other way round. The probe is loaded through its own overlay prefix, never the launcher's default.
"""
import os

import pytest

from conftest import BUILD_DIR, path_from_env


@pytest.fixture(scope="module")
def yade():
    import yaderun
    probe = path_from_env("RBSM_PROBE", "tests/abi/libabi_probe.so")
    overlay = os.environ.get("RBSM_PROBE_OVERLAY", os.path.join(BUILD_DIR, "tests", "abi", "probe-prefix"))
    env = {"YADE_RBSM_OVERLAY": overlay, "YADE_RBSM_EXTRA_PLUGINS": probe}
    return lambda script, **kw: yaderun.run_ok(script, env=env, **kw)


def test_scene_fields(yade):
    yade("""
p = AbiProbe()
O.engines = [p]
O.dt = 1.25e-3; O.iter  # iter is read-only in Python
O.stopAtIter = 77; O.trackEnergy = True; O.tags['abi'] = 'x'
s = p.sceneInfo()
assert s['dt'] == 1.25e-3 and s['stopAtIter'] == 77 and s['trackEnergy'] is True, s
assert s['iter'] == O.iter == 0 and s['time'] == O.time == 0, s
assert s['thisIsEngine'] and s['nEngines'] == 1, s
assert 'abi=x' in s['tags'], s['tags']
O.step(); O.step(); O.step()
s = p.sceneInfo()
assert s['iter'] == O.iter == 3, (s, O.iter)
assert abs(s['time'] - O.time) < 1e-15 and abs(O.time - 3 * 1.25e-3) < 1e-15, (s, O.time)
p.setScene(dt=2.5e-4, iter=1000, time=12.5)
assert O.dt == 2.5e-4 and O.iter == 1000 and O.time == 12.5, (O.dt, O.iter, O.time)
assert p.calls == 3
report(ok=True)
""")


def test_body_and_state_fields(yade):
    yade("""
from yade import utils
p = AbiProbe()
O.materials.append(FrictMat(young=1e7, density=2650, label='sand'))
for i in range(3):
    O.bodies.append(utils.sphere((i, 0, 0), 0.5, material='sand'))
b = O.bodies[2]
b.groupMask = 5; b.shape.color = (0.1, 0.2, 0.3); b.shape.wire = True
st = b.state
st.pos = (1.5, -2.5, 3.5); st.ori = Quaternion((0, 0, 1), 0.3)
st.vel = (4, 5, 6); st.angVel = (7, 8, 9); st.angMom = (1, 2, 3)
st.mass = 12.5; st.inertia = (1, 2, 3); st.blockedDOFs = 'xyZ'
st.refPos = (9, 8, 7); st.isDamped = False; st.densityScaling = 0.5
d = p.bodyInfo(2)
assert d['id'] == 2 and d['groupMask'] == 5 and d['clumpId'] == b.clumpId and d['flags'] == b.flags, d
assert d['iterBorn'] == b.iterBorn and d['timeBorn'] == b.timeBorn, d
assert d['shapeClass'] == 'Sphere' and d['materialClass'] == 'FrictMat', d
assert d['color'] == Vector3(0.1, 0.2, 0.3) and d['wire'] is True and d['highlight'] is False, d
assert d['materialId'] == b.material.id == 0 and d['materialLabel'] == 'sand' and d['density'] == 2650, d
assert d['pos'] == Vector3(1.5, -2.5, 3.5) and d['se3pos'] == d['pos'], d
assert (d['ori'] * st.ori.conjugate()).toAxisAngle()[1] < 1e-12 and abs(d['ori'].toAxisAngle()[1] - 0.3) < 1e-12, d
assert d['vel'] == Vector3(4, 5, 6) and d['angVel'] == Vector3(7, 8, 9) and d['angMom'] == Vector3(1, 2, 3), d
assert d['mass'] == 12.5 and d['inertia'] == Vector3(1, 2, 3), d
assert d['blockedDOFs'] == 1 | 2 | 32, d['blockedDOFs']
assert d['refPos'] == Vector3(9, 8, 7) and d['isDamped'] is False and d['densityScaling'] == 0.5, d
assert d['isDynamic'] is True and d['nIntrs'] == 0, d
# the same objects: change through the pointer read in C++, see it through YADE's accessor
d['shape'].radius = 0.75; assert b.shape.radius == 0.75
d['material'].young = 3e8; assert O.materials[0].young == 3e8
# and the other way: written in C++, read through YADE's accessors
p.setState(id=1, pos=(1, 2, 3), ori=Quaternion((1, 0, 0), 0.5), vel=(-1, -2, -3), angVel=(0.1, 0.2, 0.3), mass=7.0, inertia=(4, 5, 6), blockedDOFs=63)
s1 = O.bodies[1].state
assert s1.pos == Vector3(1, 2, 3) and s1.vel == Vector3(-1, -2, -3) and s1.angVel == Vector3(0.1, 0.2, 0.3), s1.dict()
assert abs(s1.ori.toAxisAngle()[1] - 0.5) < 1e-12 and s1.mass == 7.0 and s1.inertia == Vector3(4, 5, 6), s1.dict()
assert s1.blockedDOFs == 'xyzXYZ' and not O.bodies[1].dynamic, s1.blockedDOFs
newShape = Sphere(radius=0.33); newMat = FrictMat(density=999)
p.setBody(id=0, groupMask=9, shape=newShape, material=newMat)
b0 = O.bodies[0]
assert b0.groupMask == 9 and b0.shape.radius == 0.33 and b0.material.density == 999, b0.dict()
report(ok=True)
""")


def test_interaction_fields(yade):
    yade("""
from yade import utils
p = AbiProbe()
O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((1.9, 0, 0), 1)])
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator(), p]
O.dt = 1e-6
O.step(); O.step()
i = O.interactions[0, 1]
d = p.interactionInfo(0, 1)
assert d['exists'] and d['id1'] == i.id1 == 0 and d['id2'] == i.id2 == 1, d
assert d['isReal'] is True and i.isReal, d
assert d['iterMadeReal'] == i.iterMadeReal and d['iterBorn'] == i.iterBorn, (d, i.iterMadeReal, i.iterBorn)
assert d['cellDist'] == i.cellDist, d
assert d['geomClass'] == 'ScGeom' and d['physClass'] == 'FrictPhys', d
assert d['inBody1'] is True, d
assert abs(d['geom'].penetrationDepth - i.geom.penetrationDepth) < 1e-15 and abs(i.geom.penetrationDepth - 0.1) < 1e-6, i.geom.penetrationDepth
d['phys'].kn = 123.0; assert i.phys.kn == 123.0
assert not p.interactionInfo(0, 5)['exists']
report(ok=True)
""")


def test_dem_class_fields(yade):
    """Sphere, Wall, Facet, FrictMat, ScGeom, FrictPhys (pkg/common, pkg/dem declarations, used by the
    mixed scenes of issue 17): every field read in C++ equals YADE's Python accessor."""
    yade("""
from yade import utils
p = AbiProbe()
mat = FrictMat(young=3.5e7, poisson=0.27, frictionAngle=0.41, density=2111)
O.materials.append(mat)
O.bodies.append([utils.sphere((0, 0, 0), 1, material=mat), utils.sphere((1.65, 0.1, 0), 0.8, material=mat),
                 utils.wall((0, -3, 0), axis=1, sense=-1), utils.facet([(0, 0, 5), (2, 0, 5), (0, 3, 6)])])
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator(), p]
O.bodies[1].state.vel = (0.3, -2, 0); O.bodies[1].state.angVel = (0, 0, 5)
O.dt = 1e-4
for k in range(5): O.step()
def same(a, b):
    if isinstance(b, (list, tuple)): return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b
checked = []
i = O.interactions[0, 1]
fields = [(o, p.demFields(o)) for o in [O.bodies[0].shape, O.bodies[1].shape, O.bodies[2].shape, O.bodies[3].shape, mat]]
fields += [(i.geom, p.demInteractionFields(0, 1)['geom']), (i.phys, p.demInteractionFields(0, 1)['phys'])]
for obj, d in fields:
    assert d, obj
    for k, v in d.items():
        py = getattr(obj, {'radius1': 'refR1', 'radius2': 'refR2'}.get(k, k))  # ScGeom's references to refR1, refR2
        assert same(v, py), (type(obj).__name__, k, v, py)
    checked.append(type(obj).__name__)
g = O.interactions[0, 1].geom
assert g.shearInc.norm() > 0 and g.penetrationDepth > 0, g.dict()
report(checked=checked)
""")


def test_forces_added_in_cpp_are_read_by_python(yade):
    yade("""
from yade import utils
O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((5, 0, 0), 1)])
# inside the loop, after ForceResetter, from an engine declared with the project's macros
O.engines = [ForceResetter(), AbiProbe(forceBody=0, force=(0, -9, 0.5))]
O.dt = 1e-3
O.step()
assert O.forces.f(0) == Vector3(0, -9, 0.5) and O.forces.f(1) == Vector3.Zero, (O.forces.f(0), O.forces.f(1))
assert O.engines[1].calls == 1
# called from Python; YADE's own ForceContainer keeps per-thread sums across a reset that follows a
# read from Python (the same with O.forces.addF from a PyRunner), so compare differences
p = O.engines[1]
f0, t0 = O.forces.f(1), O.forces.t(1)
p.addForce(id=1, f=(1, 2, 3), t=(4, 5, 6))
p.addForce(id=1, f=(1, 1, 1), t=(0, 0, 1))
assert O.forces.f(1) - f0 == Vector3(2, 3, 4) and O.forces.t(1) - t0 == Vector3(4, 5, 7), (O.forces.f(1), O.forces.t(1))
report(ok=True)
""")


def test_probe_sizes_agree_with_the_binary():
    """The probe was compiled with the same declarations as the sizes test: Scene's size seen in yade too."""
    import elfinfo
    import yaderun
    probe = path_from_env("RBSM_PROBE", "tests/abi/libabi_probe.so")
    overlay = os.environ.get("RBSM_PROBE_OVERLAY", os.path.join(BUILD_DIR, "tests", "abi", "probe-prefix"))
    r = yaderun.run_ok("report(**AbiProbe().sizes())", env={"YADE_RBSM_OVERLAY": overlay, "YADE_RBSM_EXTRA_PLUGINS": probe})
    assert r and r[0]["Scene"] == elfinfo.object_size("Scene"), r
