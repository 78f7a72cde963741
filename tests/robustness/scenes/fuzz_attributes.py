"""Random attribute assignments on a running RBSM scene (issue 15): params {"rounds", "steps", "seed"}.
Each round sets one checked attribute of the material, a block's shape or an engine to a value drawn
from good and bad ones, through one path (assignment, updateAttrs, a constructor, or a saved file
edited and loaded with O.load), then runs a few steps. Emits every refusal that was not a ValueError
naming the attribute, every bad value that was accepted, and whether the state stayed finite."""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit, all_finite  # noqa: E402
from yade_rbsm import polygon2d, engines  # noqa: E402

P = params()
rnd = random.Random(P.get("seed", 1))
nan, inf = float("nan"), float("inf")
tmp = P["tmp"]


def build():
    O.resetThisScene()
    m = RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.6, cohesion=1e4, tensileStrength=1e3, label="rock")
    O.materials.append(m)
    O.bodies.append(polygon2d([(-6, -1), (6, -1), (6, 0), (-6, 0)], m, fixed=True))
    for k in range(5):
        for j in range(2):
            O.bodies.append(polygon2d([(-2.5 + k, j), (-1.5 + k, j), (-1.5 + k, j + 1), (-2.5 + k, j + 1)], m))
    O.engines = engines(contact_damping=0.1, interval=1)


build()
O.step()

# attribute -> (valid(value), values to draw from); valid() says what the model must accept
REAL = [nan, inf, -inf, -1.0, 0.0, 1e-3, 0.1, 0.3, 0.49, 0.5, 0.9, 1.0, 1.5, 3.0, 1e6, 1e8, 1e10]
ATTRS = {
    "mat": {
        "young": (lambda v: math.isfinite(v) and v > 0, REAL),
        "poisson": (lambda v: -1 < v < 0.5, REAL),
        "density": (lambda v: math.isfinite(v) and v > 0, REAL),
        "frictionAngle": (lambda v: 0 <= v < math.pi / 2, REAL),
        "cohesion": (lambda v: math.isfinite(v) and v >= 0, REAL),
        "tensileStrength": (lambda v: math.isfinite(v) and v >= 0, REAL),
    },
    "shape": {
        "thickness": (lambda v: math.isfinite(v) and v > 0, REAL),
        "vertices": (None, None),  # drawn by shape_vertices()
    },
    "ig2": {
        "nIP": (lambda v: 1 <= v <= 8, [0, 1, 2, 3, 8, 9, -1]),
        "interactionDistance": (lambda v: math.isfinite(v) and v >= 0, REAL),
        "hysteresis": (lambda v: math.isfinite(v) and v >= 0, REAL),
        "updateTolerance": (lambda v: 0 <= v <= 1e-3, REAL + [1e-4, 1e-3, 1e-2]),
    },
    "law": {"dampingRatio": (lambda v: math.isfinite(v) and v >= 0, REAL)},
    "ts": {"safetyFactor": (lambda v: 0 < v <= 1, REAL), "interval": (lambda v: v >= 1, [0, 1, 5, -3])},
    "bo1": {"enlarge": (lambda v: math.isfinite(v) and v >= 0, REAL)},
}


def shape_vertices():
    """A square no larger than the block (shrinking keeps neighbours apart), or a bad polygon."""
    s = rnd.uniform(0.3, 0.5)
    good = [(-s, -s), (s, -s), (s, s), (-s, s)]
    return rnd.choice([(True, good), (False, good[::-1]), (False, [(x + 0.2, y) for x, y in good]),
                       (False, [(-s, -s), (s, s), (s, -s), (-s, s)]), (False, []), (False, [(0, 0), (1, 0)]),
                       (False, [(-s, -s), (s, -s), (s, s), (s, s), (-s, s)]), (False, [(nan, 0), (1, 0), (0, 1)])])


def target(kind):
    if kind == "mat":
        return O.materials[0]
    if kind == "shape":
        return O.bodies[rnd.randrange(1, len(O.bodies))].shape
    loop = O.engines[2]
    return {"ig2": loop.geomDispatcher.functors[0], "law": loop.lawDispatcher.functors[0], "ts": O.engines[3],
            "bo1": O.engines[1].boundDispatcher.functors[0]}[kind]


def constructor(obj, name, value):
    kw = {"vertices": obj.vertices} if kind_of(obj) == "shape" else {}  # (a polygon needs its vertices)
    kw[name] = value
    type(obj)(**kw)  # a new object, checked like the others; the scene keeps the old one


def kind_of(obj):
    return "shape" if type(obj).__name__ == "Polygon2D" else "other"


def through_file(name, value):
    """Save the scene, write the value into the file (only for the material, the first one in the
    file), load it: a bad value must be refused naming the attribute (YADE then leaves an empty
    scene: the saved good one is loaded back)."""
    good = os.path.join(tmp, "good.xml")
    bad = os.path.join(tmp, "edited.xml")
    O.save(good)
    text = open(good).read()
    tag = "<%s>" % name
    i = text.index(tag) + len(tag)
    j = text.index("</%s>" % name, i)
    open(bad, "w").write(text[:i] + repr(float(value)) + text[j:])
    try:
        O.load(bad)
    except Exception:
        O.load(good)
        raise


wrong, accepted_bad, refused_good, rounds = [], [], [], 0
paths = {"assign": 0, "updateAttrs": 0, "constructor": 0, "O.load": 0}
for r in range(P.get("rounds", 300)):
    kind = rnd.choice(sorted(ATTRS))
    name = rnd.choice(sorted(ATTRS[kind]))
    obj = target(kind)
    if name == "vertices":
        ok, value = shape_vertices()
    else:
        valid, pool = ATTRS[kind][name]
        value = rnd.choice(pool)
        ok = valid(value)
    path = rnd.choice(["assign", "updateAttrs", "constructor"] + (["O.load"] if kind == "mat" else []))
    paths[path] += 1
    before = obj.dict()[name] if path != "O.load" else None
    try:
        if path == "assign":
            setattr(obj, name, value)
        elif path == "updateAttrs":
            obj.updateAttrs({name: value})
        elif path == "constructor":
            constructor(obj, name, value)
        else:
            through_file(name, value)
        if not ok:
            accepted_bad.append([kind, name, repr(value), path])
    except Exception as e:  # noqa: BLE001
        if not (type(e).__name__ == "ValueError" and name in str(e)):
            wrong.append([kind, name, repr(value), path, type(e).__name__, str(e)])
        elif ok:
            refused_good.append([kind, name, repr(value), path, str(e)])
        if path in ("assign", "updateAttrs") and repr(obj.dict()[name]) != repr(before):
            wrong.append([kind, name, repr(value), path, "old value not kept", repr(obj.dict()[name])])
    O.run(P.get("steps", 10), True)
    rounds += 1
    if not all_finite(O):
        break
emit({"rounds": rounds, "iter": O.iter, "finite": all_finite(O), "wrong": wrong[:20], "accepted_bad": accepted_bad[:20],
      "refused_good": refused_good[:20], "paths": paths})
