"""Joint stiffness given by the materials (RbsmMat.jointKn, jointKs) instead of Kawai's.
mode 'values': the kn, ks of joints between materials giving it or not, and of a block on a Wall.
mode 'settle': a 2 x 1 m block (thickness t) resting on a fixed base, jointKn given; damped to rest:
  returns the overlap (closed form: weight / (kn 2 m t)).
mode 'drop': a 1 m block dropped 0.2 m onto a fixed base, jointKn 100 x Kawai's, contact damping 0.1:
  the first-contact bound of RbsmTimeStepper with and without it, the highest rebound and the motion report."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
import yade_rbsm as yr
from yade_rbsm import polygon2d

p = params()
mode = p.get("mode", "values")
sq = lambda x, y, w=1.0, h=1.0: [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]
if mode == "values":
    kawai = RbsmMat(young=1e8, poisson=0.25)
    a = RbsmMat(young=1e8, poisson=0.25, jointKn=5e9, jointKs=2e9)
    b = RbsmMat(young=1e8, poisson=0.25, jointKn=3e9, jointKs=4e9)
    for m in (kawai, a, b):
        O.materials.append(m)
    ids = [O.bodies.append(polygon2d(sq(2 * k, 0), m, fixed=True)) for k, m in enumerate([kawai, a, b])]
    ids += [O.bodies.append(polygon2d(sq(2 * k, 1), m, fixed=True)) for k, m in enumerate([a, a, a])]
    w = O.bodies.append(utils.wall((0, -0.0, 0), axis=1, material=a))
    blk = O.bodies.append(polygon2d(sq(10, 0), a))
    O.engines = yr.mixed_engines(gravity=(0, 0, 0)) if hasattr(yr, "mixed_engines") else yr.engines(gravity=(0, 0, 0))
    O.dt = 1e-7
    O.step()
    def k(i, j):
        I = O.interactions[i, j]
        return [I.phys.kn, I.phys.ks]
    emit({"kawai_a": k(ids[0], ids[3]), "a_a": k(ids[1], ids[4]), "b_a": k(ids[2], ids[5]), "wall": k(w, blk),
          "saved": None})
elif mode == "settle":
    t, kn = p.get("thickness", 0.5), p.get("kn", 2e9)
    mat = RbsmMat(young=1e8, poisson=0.25, density=2000, jointKn=kn, frictionAngle=0.5)
    O.materials.append(mat)
    O.bodies.append(polygon2d([(-1, -1), (3, -1), (3, 0), (-1, 0)], mat, fixed=True, thickness=t))
    b = O.bodies.append(polygon2d(sq(0, 0, 2, 1), mat, thickness=t))
    O.engines = yr.engines(damping=0.7)
    O.dt = 1e-9
    for _ in range(200):
        yr.advance(100)
    y = O.bodies[b].state.pos[1]
    I = O.interactions[0, b]
    emit({"overlap": 0.5 - y, "weight": O.bodies[b].state.mass * 9.81, "kn": I.phys.kn, "length": I.geom.length})
else:
    out = {}
    for given in (False, True):
        O.resetThisScene()
        kawai_kn, kawai_ks = 1e8 * 0.75 / (1.25 * 0.5), 2 * 1e8 / 2.5  # E'/(h1 + h2), 2G/(h1 + h2): unit squares
        mat = RbsmMat(young=1e8, poisson=0.25, density=2000, frictionAngle=0.5, jointKn=100 * kawai_kn if given else 0,
                      jointKs=100 * kawai_ks if given else 0)
        O.materials.append(mat)
        O.bodies.append(polygon2d([(-2, -1), (3, -1), (3, 0), (-2, 0)], mat, fixed=True))
        b = O.bodies.append(polygon2d(sq(0, 0.2), mat))
        O.engines = yr.engines(contact_damping=0.1)
        O.dt = 1e-9
        yr.advance(1)
        ts = yr.time_stepper()
        first = ts.firstContactDt
        top, landed, err = 0.0, False, ""
        try:
            for _ in range(400):
                yr.advance(25)
                y = O.bodies[b].state.pos[1]
                if O.interactions.has(0, b) and O.interactions[0, b].isReal:
                    landed = True
                if landed:
                    top = max(top, y)
        except Exception as e:
            err = str(e)
        out["given" if given else "kawai"] = dict(first=first, top=top, landed=landed, err=err,
                                                    y=O.bodies[b].state.pos[1])
    emit(out)
