"""The qt view's functors are registered where YADE's OpenGLRenderer looks for them (no display needed).

The renderer collects every class inheriting from GlShapeFunctor / GlIGeomFunctor / GlIPhysFunctor
(Omega's class list) and dispatches by the class it renders; the options are class-wide like YADE's.
"""
from yaderun import run_ok


def test_functors_are_found_by_the_renderer_and_options_are_class_wide():
    r = run_ok("""
shape = O.childClassesNonrecursive('GlShapeFunctor')
geom = O.childClassesNonrecursive('GlIGeomFunctor')
phys = O.childClassesNonrecursive('GlIPhysFunctor')
assert issubclass(Gl1_Polygon2D, GlShapeFunctor) and issubclass(Gl1_RbsmGeom, GlIGeomFunctor) and issubclass(Gl1_RbsmPhys, GlIPhysFunctor)
Gl1_RbsmPhys.maxWidth = 7.5
Gl1_Polygon2D.outlineColor = (0.5, 0.25, 0)
report(shape='Gl1_Polygon2D' in shape, geom='Gl1_RbsmGeom' in geom, phys='Gl1_RbsmPhys' in phys,
       maxWidth=Gl1_RbsmPhys.maxWidth, outline=list(Gl1_Polygon2D.outlineColor), label=Gl1_Polygon2D(label='x').label)
""")[0]
    assert r == dict(shape=True, geom=True, phys=True, maxWidth=7.5, outline=[0.5, 0.25, 0.0], label="x")
