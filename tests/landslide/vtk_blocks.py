# yade script (run by test_vtk.py): two blocks stacked on a fixed base, bonded; a damped gravity
# stage, then VtkSeries writes two snapshots (after 10 steps and at the end) to argv[1]; prints the
# values the test compares with what it reads back from the files ("EXPECT key value").
import json, math, sys
from yade import O, wrapper, Vector3
import yade_rbsm as yr
from yade_rbsm import slope, vtkexport
out = sys.argv[1]
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=math.radians(30), cohesion=1e4,
                      tensileStrength=1e4)
O.materials.append(mat)
O.bodies.append([yr.polygon2d([(-3, -1), (3, -1), (3, 0), (-3, 0)], mat, fixed=True),
                 yr.polygon2d([(0, 0), (2, 0), (2, 1), (0, 1)], mat),
                 yr.polygon2d([(0, 1), (2, 1), (2, 1.8), (1, 2.2), (0, 1.8)], mat)])  # a pentagon
for b in O.bodies:
    b.state.refPos = b.state.pos
O.engines = yr.engines(damping=0.5, set_dt=False, enlarge=0.01)
O.dt = 1e-6
O.engines[2].physDispatcher.functors[0].setCohesionNow = True
O.step()
O.dt = 0.8 * yr.critical_time_step() * (1 - 1e-9)
O.bodies[2].state.vel = (0.5, 0, 0)    # a sideways kick: velocity and displacement of block 2
O.bodies[2].state.angVel = (0, 0, 0.2)
series = vtkexport.VtkSeries(out, "t")


def expect():
    b = O.bodies[2]
    return {"n_blocks": 3, "n_contacts": sum(1 for I in O.interactions if I.isReal), "time": O.time,
            "disp2": [(b.state.pos - b.state.refPos)[k] for k in (0, 1)], "vel2": [b.state.vel[0], b.state.vel[1]],
            "angvel2": b.state.angVel[2],
            "vertices2": [[(b.state.pos + b.state.ori * Vector3(v[0], v[1], 0))[k] for k in (0, 1)] for v in b.shape.vertices],
            "contacts": {"%d-%d" % (I.id1, I.id2): [I.phys.normalForce, I.phys.shearForce, I.phys.nSlipping, I.phys.nOpen,
                                                     [I.geom.p0[0], I.geom.p0[1]], [I.geom.p1[0], I.geom.p1[1]]]
                         for I in O.interactions if I.isReal}}


O.run(10, True)
series.write()  # snapshot 0: block 2 still moving (velocity, angular velocity)
exp = [expect()]
O.run(200, True)
series.write()  # snapshot 1: settled, displaced
exp.append(expect())
print("EXPECT " + json.dumps(exp))
