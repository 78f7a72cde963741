"""Bug 3 reproducer: setting an existing Polygon2D's vertices to [] is accepted; the next O.step() aborts YADE
(std::terminate: the collider's Bo1 throws inside its parallel loop). Prints ACCEPTED or raised."""
from yade_rbsm import polygon2d, engines
m = RbsmMat(); O.materials.append(m)
O.bodies.append(polygon2d([(0,0),(1,0),(1,1),(0,1)], m))
O.engines = engines()
try:
    O.bodies[0].shape.vertices = []
    print("ACCEPTED, vertices now", list(O.bodies[0].shape.vertices))
except Exception as e:
    print("raised", type(e).__name__, e)
O.step()
print("stepped")
