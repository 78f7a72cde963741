"""A scene loaded with O.load gets its interactions laid out in the loop's order (issue 22).

O.load allocates each interaction while it reads the body that holds it: in a loaded 10⁴-block wall the
Interaction objects follow each other at -3168 bytes (descending, between the bodies) where a freshly built
scene has them at +336 bytes, and the interaction loop ran 1.67× slower (scripts/benchmarks/loaded_scene.py).
RbsmTimeStepper re-creates them in the container's order once per engine object (MemoryOrder.hpp).

Scene: a 30 × 30 running-bond wall (900 blocks, frictional joints) run 200 steps, saved, loaded. Checked
after the first step of the loaded scene: the Interaction objects at ascending addresses in loop order (the
old code: none), the same interactions with the same geometry and physics objects (moved, not copied), in
the same container order, each found again by its ids; with InteractionLoop.loopOnSortedInteractions the run
then continues to the state of the uninterrupted run, bit for bit, at -j1 (YADE's default loop may visit a
loaded scene's joints in another order: tests/robustness/test_persistence.py); -j2 runs the same checks of
the layout. (After the first step of a loaded scene, take Interaction
objects from O.interactions again: one taken before it is the old object, which shares the geometry and
physics only until the contact ends.)
"""
import pytest

from yaderun import run_ok

SCENE = """
import re, sys
from yade_rbsm import polygon2d, engines, advance
MODE, PATH, SORTED = sys.argv[1], sys.argv[2], sys.argv[3]

def addr(o):
    return int(re.search(r"0x[0-9a-f]+", repr(o)).group(0), 16)

def ascending(objs):
    a = [addr(o) for o in objs]
    return sum(1 for i in range(len(a) - 1) if 0 < a[i + 1] - a[i] < 4096) / max(1, len(a) - 1)

def state():
    return [(b.state.pos[0].hex(), b.state.pos[1].hex(), b.state.ori[3].hex()) for b in O.bodies]

if MODE == "build":
    mat = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.6)
    O.materials.append(mat)
    n = 30
    O.bodies.append(polygon2d([(-0.2, -0.1), ((n + 1) * 0.2, -0.1), ((n + 1) * 0.2, 0), (-0.2, 0)], mat, fixed=True))
    for j in range(n):
        x0 = 0.0 if j % 2 == 0 else -0.1
        for i in range(n):
            O.bodies.append(polygon2d([(x0 + 0.2 * i, 0.1 * j), (x0 + 0.2 * i + 0.2, 0.1 * j),
                                       (x0 + 0.2 * i + 0.2, 0.1 * j + 0.1), (x0 + 0.2 * i, 0.1 * j + 0.1)], mat))
    O.engines = engines(damping=0.2, sorted_loop=SORTED)
    advance(200)
    asc_fresh = ascending([I for I in O.interactions if I.isReal])
    O.save(PATH)
    advance(100)
    report(state=state(), iter=O.iter, asc_fresh=asc_fresh)
else:
    O.load(PATH)
    real = lambda: [I for I in O.interactions if I.isReal]
    before = real()
    ids0 = [(I.id1, I.id2) for I in before]
    parts0 = [(addr(I.geom), addr(I.phys)) for I in before]
    asc0 = ascending(before)
    advance(1)
    after = real()
    found = all(O.interactions[I.id1, I.id2].id2 == I.id2 for I in after)
    # the first step may make or end a few contacts: compare the ones that were there before and after it
    kept = set(ids0) & set((I.id1, I.id2) for I in after)
    parts1 = {(I.id1, I.id2): (addr(I.geom), addr(I.phys)) for I in after}
    report(asc0=asc0, asc1=ascending(after), n=len(after), kept=len(kept), found=found,
           same_order=[k for k in ids0 if k in kept] == [(I.id1, I.id2) for I in after if (I.id1, I.id2) in kept],
           same_parts=all(parts1[k] == p for k, p in zip(ids0, parts0) if k in kept),
           per_body=sum(len(b.intrs()) for b in O.bodies))
    advance(99)
    report(state=state(), iter=O.iter)
"""


def run(mode, path, sorted_loop, jobs):
    return run_ok(SCENE.replace("sys.argv[1], sys.argv[2], sys.argv[3]", "%r, %r, %r" % (mode, path, sorted_loop)),
                  jobs=jobs)


@pytest.mark.parametrize("jobs", [1, 2])
@pytest.mark.parametrize("sorted_loop", [False, True])
def test_loaded_scene_in_loop_order(jobs, sorted_loop, tmp_path):
    path = str(tmp_path / "wall.yade.gz")
    full, = run("build", path, sorted_loop, jobs)
    moved, cont = run("load", path, sorted_loop, jobs)
    print(moved, "fresh scene:", full["asc_fresh"])
    assert moved["n"] > 1500, "the wall must hold its joints"
    assert moved["asc0"] < 0.5, "O.load no longer scatters the interactions: the test shows nothing"
    # most, not all: malloc serves some of the new objects from holes the loader left (measured 0.88; fresh 1.00)
    assert moved["asc1"] > 0.8, "the loaded scene's interactions are not in loop order after its first step"
    assert moved["kept"] > 0.95 * moved["n"] and moved["same_order"] and moved["same_parts"] and moved["found"]
    assert moved["per_body"] >= 2 * moved["n"]
    assert cont["iter"] == full["iter"] == 300
    # YADE's default loop may visit a loaded scene's joints in another order (test_persistence.py), and at -j2
    # its guided schedule hands them to the threads differently from run to run
    if sorted_loop and jobs == 1:
        assert cont["state"] == full["state"], "the continued run differs from the uninterrupted one"
