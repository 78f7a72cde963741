"""Strength reduction of a soil slope of plastic deformable blocks (issue 39): Griffiths & Lane's 2:1 slope (H 10 m,
γ 20 kN/m³, firm base at the toe) of c, φ (drained: c 10 kPa, φ 20°) cut into triangles (slope.triangle_slope_blocks)
or Voronoi cells, the soil's strength in the blocks, the welded joints between them the continuum's. Settles under
gravity, then runs yade_rbsm.strength_reduction on the blocks' own strength and the limit-equilibrium critical circle.
Params: cells (triangles | voronoi), spacing (m), seed, c (Pa), phi (deg), penalty, max_steps."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import emit, params

from yade_rbsm import limit_equilibrium as le
from yade_rbsm import slope
from yade_rbsm.strength_reduction import strength_reduction

p = params()
H, gamma = 10.0, 20e3
c, phi = p.get("c", 10e3), math.radians(p.get("phi", 20.0))
ground = [(0, 0), (12, 0), (12 + 2 * H, H), (52, H)]
soil = RbsmMat(young=100e6, poisson=0.3, density=gamma / 9.81, cohesion=c, frictionAngle=phi,
               tensileStrength=c / math.tan(phi) if phi > 0 else 10 * c, planeStrain=True, deformable=True, plastic=True,
               penalty=p.get("penalty", 10.0), ductile=True, label="soil")
O.materials.append(soil)
spacing = p.get("spacing", 2.0)
if p.get("cells", "triangles") == "triangles":
    sb = slope.triangle_slope_blocks(ground, 0.0, spacing=spacing)
else:
    sb = slope.voronoi_slope_blocks(ground, 0.0, spacing=spacing, seed=p.get("seed", 1), min_distance=0.5 * spacing)
model = slope.SlopeModel(sb, soil)
model.build()
settled = model.settle(progress=None)
r = strength_reduction(rtol=0.01, max_steps=p.get("max_steps", 8000), d_fail=0.1)
lim = le.critical_circle(le.Slope(ground, le.Layer(c=c / 1e3, phi=math.degrees(phi), gamma=gamma / 1e3)), x_range=(5, 40),
                         y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0, r_range=(5, 60), nr=19)
emit({"fs": r.fs, "lo": r.lo, "hi": r.hi, "bishop": lim.fs, "blocks": len(sb.free), "settled": bool(settled.figures["converged"]),
      "warnings": list(r.warnings), "text": str(r)})
