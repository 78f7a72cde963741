# A soil slope (Griffiths & Lane's 2:1 slope, c' 10 kPa, phi' 20 deg) cut into Voronoi blocks: which factor of
# safety to trust. Rigid blocks interlock, so strength reduction on them overestimates a continuum's FS;
# fos() gives Bishop's critical circle for such a slope, with the other estimates beside it.
#   build/yade-rbsm -n -x scripts/tutorial_soil_slope.py [out_dir]
import math, os, sys
from yade_rbsm import slope
from yade_rbsm import limit_equilibrium as le
out = sys.argv[1] if len(sys.argv) > 1 else "out/tutorial_soil"
os.makedirs(out, exist_ok=True)
H, c, phi, gamma = 10.0, 10e3, 20.0, 20e3                   # m, Pa, degrees, N/m3
ground = [(0, 0), (12, 0), (12 + 2 * H, H), (52, H)]        # toe at x = 12 m, a 2:1 face, a 20 m crest
soil = RbsmMat(young=100e6, poisson=0.3, density=gamma / 9.81, frictionAngle=math.radians(phi), cohesion=c,
               tensileStrength=0, ductile=True, label="soil")  # ductile: joints keep c while they slip
O.materials.append(soil)
blocks = slope.voronoi_slope_blocks(ground, 0.0, spacing=1.0, seed=1)   # a firm base at toe level (y = 0)
print(blocks)
model = slope.SlopeModel(blocks, soil)
model.build()
model.settle()                               # in-situ stress under gravity
r = model.fos()                              # the design value and the estimates beside it
print(r)
for name, e in r.estimates.items():       # strength reduction on the blocks, the contact forces, ...
    print(f"  {name}: {e['fs']}")
print(r.recommendation)
# The same slope by limit equilibrium alone (kPa, kN/m3, degrees): Bishop's critical circle above the base.
bishop = le.critical_circle(le.Slope(ground, le.Layer(c=c / 1e3, phi=phi, gamma=gamma / 1e3)), x_range=(5, 40),
                            y_range=(10, 50), nx=12, ny=12, refine=3, base=0.0, r_range=(5, 60), nr=19)
print(f"Bishop, critical circle: {bishop.fs:.3f} (Griffiths & Lane's finite elements: 1.4)")
r.to_markdown(os.path.join(out, "fos.md"))
model.report(os.path.join(out, "report.md"))
