"""yade_rbsm: Python side of the 2D Rigid-Bodies-Spring Model plugin for YADE.

The C++ classes (Polygon2D, RbsmMat, Ig2_Polygon2D_Polygon2D_RbsmGeom, ...) are YADE classes,
available in every yade script; this package adds the helpers a scene needs: blocks from world
polygons, the engine list, slope builders, factor of safety and limit equilibrium.
"""
try:  # the YADE-dependent helpers; the pure-Python modules (limit_equilibrium) import without YADE
    import yade.wrapper  # noqa: F401
except ImportError:
    pass
else:
    from .blocks import polygon2d, polygon_properties  # noqa: F401
    from .scene import engines, critical_time_step, advance, time_stepper, quiet_yade_warnings  # noqa: F401
    from .mixed import mixed_engines  # noqa: F401
    from .mpi import abort_on_abnormal_exit as _abort_on_abnormal_exit

    _abort_on_abnormal_exit()  # under mpiexec: an error on one rank ends the job, not a deadlock
    from .omega_hooks import install as _install_omega_hooks

    _install_omega_hooks()  # O.save names the path and the problem; O.dt = -1 turns RbsmTimeStepper.setDt on

# submodules (import them explicitly): geometry (plane geometry, pure Python), omega (joints, free bodies,
# engines by label), slope, safety (its parts: contact_safety, slip_surface, le_bridge), snapshots, limit_equilibrium, vtkexport (VTK
# output, recorder() engine), measure (stress and fabric tensors, extrema: YADE's sphere-only utilities
# for blocks), textexport (blocks to and from text), gui (qt view, snapshots), monitor (yade.plot
# series, progress line), strength_reduction (FS by strength reduction)
