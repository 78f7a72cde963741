"""Factor of safety from the RBSM contact forces along a slip surface (seed paper, Table 2).

:func:`contact_fs` selects the real RBSM joints whose contact segment (``geom.p0``–``geom.p1``)
lies on a slip polyline (both ends within *tol* of it) and whose two blocks are on opposite sides
of it (centroids above / below). For each such joint, with the block *above* the surface taken as
the sliding one:

* normal force ``N_j = phys.normalForce`` (> 0 compression);
* the shear force the lower block exerts on the upper one is ``±phys.shearForce·t`` (``+`` if the
  upper block is body 2: the law's shear force is the force on body 2 along the tangent); the
  driving shear is its opposite projected on the downslope direction ``d`` (unit tangent of the
  joint pointing the way the polyline descends), ``T_j = -(F_shear on upper)·d``;
* strength ``c_j·ℓ_j·thickness`` over the intact points (``phys.cohesion``, tributary
  ``w_k·ℓ``) plus ``N_j·tanφ_j`` (``phys.tanPhi``).

``FS = Σ(c ℓ t + N tanφ) / |Σ T|``. Forces are returned in kN (per metre of thickness for
thickness 1), ready to print next to :func:`limit_equilibrium.fellenius_polyline`.

:func:`contact_fs_circle` does the same along a circle ``(xc, yc, R)``: the joints whose contact
segment midpoint lies within ``band`` of the circle (``|dist - R| <= band``) and whose blocks are
on opposite sides (centroid inside / outside); the sliding block is the one inside; the driving
direction ``d`` at a joint is the circle's tangent in the sense of the rotation of the sliding mass
(clockwise if the weights of the blocks inside the circle have their centroid right of the centre,
i.e. ``Σ m (x - xc) > 0``, as in Fellenius' driving moment).

:func:`slipping_surface` finds the surface of slipping joints: the real joints with at least
``min_slipping`` slipping integration points (``phys.nSlipping``) are linked when their contact
segments share an end (within *tol*); the largest connected set (by length) is the surface,
returned as a polyline: the shortest path (by length) through its joints and the gaps between
them from its end point of least x to its end point of greatest x (x made strictly increasing), with
the joints along that path.
Joints are linked when their contact segments come within *tol* of each other (default half the
median length of the scene's joints: a sliding block's contact may cover only part of its edge); point contacts
(length < 1 % of the median) are left out.
:func:`slip_surface_fs` evaluates :func:`contact_fs` along it and, given the ground polyline and
the material, Fellenius along it (the ends of the polyline that lie below the ground are extended
to the ground along their end segments, or vertically like a tension crack if the end segment
does not rise to the ground, for the slices).

Modules: contact_safety (contact FS along a polyline or circle), slip_surface (the surface of
slipping joints and its FS), le_bridge (limit equilibrium on the block slope, the tables, the blocks'
stresses as a field for the stress-based FS), geometry
(polylines, circles); every name is importable from here.

Bad input (an empty or NaN polyline, a polyline or circle that meets no joint of the scene: "misses
the slope", a non-positive band) raises ValueError naming the problem.
"""
from .contact_safety import ContactFS, contact_fs, contact_fs_circle  # noqa: F401
from .geometry import check_polyline, circle_through, point_polyline_distance  # noqa: F401
from .le_bridge import StressField, fs_table, le_slope, limit_equilibrium_summary, stress_field, table2  # noqa: F401
from .slip_surface import SlipSurface, SlipSurfaceFS, probe_slipping_surface, slip_surface_fs, slipping_surface  # noqa: F401

__all__ = ["ContactFS", "contact_fs", "contact_fs_circle", "SlipSurface", "SlipSurfaceFS", "slipping_surface", "slip_surface_fs",
           "point_polyline_distance", "table2", "le_slope", "circle_through", "limit_equilibrium_summary",
           "fs_table", "check_polyline", "probe_slipping_surface", "stress_field", "StressField"]
