"""yade_rbsm: Python side of the 2D Rigid-Bodies-Spring Model plugin for YADE.

The C++ classes (Polygon2D, RbsmMat, Ig2_Polygon2D_Polygon2D_RbsmGeom, ...) are YADE classes,
available in every yade script; this package adds the helpers a scene needs: blocks from world
polygons, the engine list, slope builders, factor of safety and limit equilibrium.
"""
from .blocks import polygon2d, polygon_properties  # noqa: F401
from .scene import engines, critical_time_step  # noqa: F401
