# Polygon2D demo: a square RBSM block falls under gravity above a fixed base block; its height is
# printed against the closed form y(t) = y0 - g t^2 / 2. (No contact law is used here, so the block
# is stopped before it reaches the base.)
#
#   build/yade-rbsm -n -x scripts/polygon2d_demo.py      (or plain `yade` after `cmake --install`)
#
# Polygon2D is a YADE class like Sphere: no import is needed. Vertices are in the body's frame,
# counter-clockwise, centred on the centroid; area and polarMoment are derived from them.
import math

g, y0, thickness = 9.81, 6.0, 1.0
rock = FrictMat(density=2600, young=1e9, label="rock")
O.materials.append(rock)


def block(vertices, pos, fixed=False, color=(0.6, 0.5, 0.4)):
    shape = Polygon2D(vertices=vertices, thickness=thickness, color=color)
    b = Body(shape=shape, material=rock)
    b.state.pos = pos
    b.state.mass = rock.density * shape.area * shape.thickness
    b.state.inertia = (1, 1, rock.density * shape.polarMoment * shape.thickness)
    b.state.blockedDOFs = "xyzXYZ" if fixed else "zXY"  # planar motion: x, y and rotation about z
    return O.bodies.append(b)


base = block([(-3, -0.5), (3, -0.5), (3, 0.5), (-3, 0.5)], (0, -0.5, 0), fixed=True, color=(0.4, 0.4, 0.4))
falling = block([(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)], (0, y0, 0))

O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, -g, 0), damping=0)]
O.dt = 1e-4

s = O.bodies[falling].shape
print("Polygon2D block: %d vertices, area %.3f m2, polar moment %.4f m4, mass %.1f kg" % (
    len(s.vertices), s.area, s.polarMoment, O.bodies[falling].state.mass))
print("%8s %12s %12s %10s" % ("t [s]", "y [m]", "y0-gt^2/2", "error"))
worst = 0
for k in range(10):
    O.run(1000, True)
    y, t = O.bodies[falling].state.pos[1], O.time
    exact = y0 - 0.5 * g * t * t
    worst = max(worst, abs(y - exact))
    print("%8.3f %12.6f %12.6f %10.2e" % (t, y, exact, y - exact))
# the integrator is exact up to O(dt): |y - exact| = g dt t / 2
assert worst <= g * O.dt * O.time, worst
print("largest deviation from the closed form: %.2e m (time step %.0e s)" % (worst, O.dt))
