"""yade_rbsm.io: RBSM block geometry in and out of YADE, in the spirit of yade.ymport / yade.export.

* :func:`export_blocks` / :func:`import_blocks`: blocks to and from a CSV text file (world-frame
  vertices, material, fixed flag, thickness, optional velocity; format in :mod:`.blocks_csv`).
* :func:`export_joints`: the state of every RBSM joint to CSV, for analysis elsewhere.
* :func:`import_dxf`: closed polylines of a DXF drawing as blocks, layers mapped to materials
  (:mod:`.dxf`, needs Debian's python3-ezdxf); :func:`export_dxf` writes blocks back.
* :func:`read_slope_dxf`: a slope drawing's outline and joint-trace layers, for
  ``slope.jointset_blocks`` (:mod:`.slope_dxf`; ``slope.jointset_blocks_dxf`` reads and cuts in one call).
* :func:`describe`: which classes a YADE save file needs and which the local YADE lacks; works
  without the plugin and without YADE (:mod:`.describe`, also a command: ``python3 describe.py f``).

Importers return lists of bodies, like ``ymport``: ``O.bodies.append(import_blocks("slope.csv"))``.
"""
from .describe import describe  # noqa: F401  (no YADE needed)
from .slope_dxf import read_slope_dxf, SlopeDrawing  # noqa: F401  (no YADE needed; ezdxf when called)

try:
    import yade.wrapper  # noqa: F401
except ImportError:  # plain python3: only describe() and the polygon checks
    pass
else:
    from .blocks_csv import export_blocks, import_blocks  # noqa: F401
    from .joints_csv import export_joints  # noqa: F401
    from .dxf import import_dxf, export_dxf  # noqa: F401
