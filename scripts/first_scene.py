# A block on a 35° incline with 30° of joint friction: it slides.   build/yade-rbsm -n -x scripts/first_scene.py
from math import radians, sin, cos, tan
from yade_rbsm import polygon2d, engines
rock = RbsmMat(young=200e6, poisson=0.2, density=2403, frictionAngle=radians(30),
               cohesion=0, tensileStrength=0)                    # SI units, radians
O.materials.append(rock)
O.bodies.append(polygon2d([(-100, -1), (100, -1), (100, 0), (-100, 0)], rock, fixed=True))  # world frame, CCW
O.bodies.append(polygon2d([(0, 0), (4, 0), (4, 1), (0, 1)], rock))                           # a block on it
g = 9.81
O.engines = engines(gravity=(g * sin(radians(35)), -g * cos(radians(35)), 0), contact_damping=0.3)  # the incline
O.run(1000, True)                     # RbsmTimeStepper sets a stable O.dt (smaller for impacts)
joint = O.interactions[0, 1].phys
print(f"normal force {joint.normalForce:.0f} N, shear force {joint.shearForce:.0f} N, "
      f"slipping points {joint.slippingPoints}, block moved {O.bodies[1].state.displ()[0]:.2f} m")
m = O.bodies[1].state.mass
print(f"Coulomb: N = m g cos 35° = {m * g * cos(radians(35)):.0f} N, T = N tan 30° = {m * g * cos(radians(35)) * tan(radians(30)):.0f} N")
