"""Strength reduction of a soil slope of plastic deformable blocks (issue 39): one of scripts/reference_slopes.py's
slopes ("gl": Griffiths & Lane's 2:1 slope, H 10 m, γ 20 kN/m³, c 10 kPa, φ 20°, firm base at the toe; "taylor": the
same slope undrained, φ 0, c_u/γH 0.25) cut into triangles (slope.triangle_slope_blocks) or Voronoi cells, the soil's
strength in the blocks (reference_slopes.plastic_soil), the welded joints between them the continuum's. Settles under
gravity, then runs yade_rbsm.strength_reduction on the blocks' own strength and the limit-equilibrium critical circle
(the reference search). The band: the plastic shear the failed end's trial gained, the share of it (mass-weighted)
in blocks within 1.5 spacings of the critical circle ("band"), against those blocks' share of the mass
("band_mass"); png: a path prefix for strength reduction's drawings (the circle dashed on them).
Params: slope (gl | taylor), cells (triangles | voronoi), spacing (m), seed, penalty, weldYields, max_steps, png."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "scripts"))  # the reference slopes, shared with the studies
from _common import emit, params
from reference_slopes import ground, plastic_soil, search, soil as soil_of

from yade_rbsm import limit_equilibrium as le
from yade_rbsm import slope
from yade_rbsm.strength_reduction import strength_reduction

p = params()
name = p.get("slope", "gl")
soil = plastic_soil(name, penalty=p.get("penalty", 10.0), label="soil")
soil.weldYields = p.get("weldYields", False)
O.materials.append(soil)
spacing = p.get("spacing", 2.0)
if p.get("cells", "triangles") == "triangles":
    sb = slope.triangle_slope_blocks(ground(name), 0.0, spacing=spacing, seed=p.get("seed"))
else:
    sb = slope.voronoi_slope_blocks(ground(name), 0.0, spacing=spacing, seed=p.get("seed", 1), min_distance=0.5 * spacing)
model = slope.SlopeModel(sb, soil)
model.build()
settled = model.settle(progress=None)
lim = le.critical_circle(soil_of(name), **search(name))
r = strength_reduction(rtol=0.01, max_steps=p.get("max_steps", 8000), d_fail=0.1, png=p.get("png"),
                       png_line=lim.circle.polyline())
gain = [t for t in r.trials if t.F == r.hi][0].plastic_gain
near = {i for i in gain if abs((O.bodies[i].state.pos - Vector3(lim.circle.xc, lim.circle.yc, 0)).norm() - lim.circle.R)
        < 1.5 * spacing}
mass = {i: O.bodies[i].state.mass for i in gain}
total = sum(mass[i] * max(g, 0.0) for i, g in gain.items()) or 1.0
emit({"fs": r.fs, "lo": r.lo, "hi": r.hi, "bishop": lim.fs, "blocks": len(sb.free), "settled": bool(settled.figures["converged"]),
      "warnings": list(r.warnings), "text": str(r),
      "band": sum(mass[i] * max(gain[i], 0.0) for i in near) / total,
      "band_mass": sum(mass[i] for i in near) / sum(mass.values())})
