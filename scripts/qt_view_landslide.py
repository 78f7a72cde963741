"""The landslide example in YADE's qt view: blocks coloured by displacement, joints by state.

Makes the picture out/qt_view/landslide_qt_view.png (--out; docs/ keeps the manual's copy), on a virtual
display (Xvfb):

    /usr/bin/python3 scripts/run_in_qt_view.py scripts/qt_view_landslide.py

The slope of scripts/landslide_slope.py (bricks 2 m x 1 m, joint plane at 35 deg from the toe, tension
crack behind the crest; E = 200 MPa, phi = 30 deg, c = 0) is bonded, the crack broken, and released
without a gravity stage for --time s, so that the wedge starts to slide: joints along the plane slip
(red) or open (yellow), the others are broken and closed (blue: c = 0 and no tensile strength leave
no joint intact, green). Blocks: light grey at rest to dark grey for the most displaced.
On a desktop, `build/yade-rbsm scripts/qt_view_landslide.py --stay` keeps the view open instead.
"""
import argparse
import math
import os
import sys

from yade import O, wrapper

import yade_rbsm as yr
from yade_rbsm import gui, omega, slope as sl

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
# yade runs a script in its own globals: __file__ is yade's launcher, sys.argv[0] this script
ap.add_argument("--out", default=os.path.join("out", "qt_view", "landslide_qt_view.png"))  # docs/ has the tracked copy
ap.add_argument("--time", type=float, default=0.4, help="simulated time after the release [s]")
ap.add_argument("--stay", action="store_true", help="keep the view open (no picture, no exit)")
args = ap.parse_args(sys.argv[1:])

yr.quiet_yade_warnings()  # one warning per joint that separates

surface = [(0.0, 2.0), (6.0, 2.0), (14.0, 12.0), (24.0, 12.0)]
psi = math.radians(35.0)
xcrack = 17.0
ycrack = 2.0 + (xcrack - 6.0) * math.tan(psi)
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=0.0,
                      tensileStrength=0.0, planeStrain=True, label="rock")
O.materials.append(mat)
sb = sl.brick_blocks(surface, 0.0, 2.0, 1.0, joints=[[(6.0, 2.0), (xcrack, ycrack)]], crack=(xcrack, ycrack),
                     foundation=1.0, wall=1.0)
sl.build_scene(sb, mat)
O.engines = yr.engines(gravity=(0, -9.81, 0), set_dt=False, enlarge=0.01)
O.dt = 1e-6  # the bonding step
sl.bond_and_break(sb)
O.dt = 0.8 * yr.critical_time_step() * (1 - 1e-9)
omega.engine("timeStepper").setDt = True  # follows the joints as they change
t0 = O.time
while O.time - t0 < args.time * (1 - 1e-9):  # by simulated time: the stepper shortens O.dt as joints open
    O.run(max(1, min(200, int((args.time - (O.time - t0)) / O.dt) + 1)), True)

# blocks coloured by displacement, light grey at rest to dark grey for the most displaced (the joints'
# colours stay apart from them), the fixed blocks tan
free = [b for b in omega.free_bodies() if isinstance(b.shape, wrapper.Polygon2D)]
dmax = max((b.state.pos - b.state.refPos).norm() for b in free) or 1.0
for b in O.bodies:
    g = 0.85 - 0.55 * (b.state.pos - b.state.refPos).norm() / dmax
    b.shape.color = (0.8, 0.72, 0.55) if b not in free else (g, g, g)
print("t = %.2f s: largest displacement %.3f m" % (O.time, dmax))

gui.view(joints=True, size=(1100, 600))
if not args.stay:
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    gui.save_view_and_exit(args.out, delay=2.0)
