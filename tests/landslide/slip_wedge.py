# yade script (run by test_circle_slip.py): a sliding wedge. Slope: toe flat y = 1 (x in [0, 3]),
# face to the crest y = 5 at x = 7, crest to x = 11; 1 m x 1 m bricks (or Voronoi blocks: argv[1])
# cut along a pre-existing joint plane from the face at (3.5, 1.5) rising at psi = 30 deg (daylights
# on the crest at x = 3.5 + 3.5/tan(psi)). Strong bonded joints (c = sigma_t = 1 MPa) everywhere except the
# plane (a crack: broken after bonding); phi = 15 deg < psi: the wedge slides. The surface of
# slipping joints is found after a short run (probe_slipping_surface, state restored) and during
# the slide; prints its polyline, the contact-force FS along it and Fellenius along it.
import json, math, sys
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import safety, slope as sl
pattern = sys.argv[1] if len(sys.argv) > 1 else "bricks"
psi, phi = math.radians(30), math.radians(15)
surface = [(0, 1), (3, 1), (7, 5), (11, 5)]
plane = [(3.5, 1.5), (3.5 + 3.5 / math.tan(psi), 5.0)]  # daylights on the face and on the crest
mat = wrapper.RbsmMat(young=200e6, poisson=0.2, density=2000, frictionAngle=phi, cohesion=1e6, tensileStrength=1e6)
O.materials.append(mat)
if pattern == "voronoi":
    sb = sl.voronoi_slope_blocks(surface, 0.0, spacing=1.0, seed=4, min_distance=0.5, cracks=[plane])
else:
    sb = sl.brick_blocks(surface, 0.0, 1.0, 1.0, cracks=[plane])
sl.build_scene(sb, mat)
O.engines = yr.engines(damping=0.0, set_dt=False, enlarge=0.01)
O.dt = 1e-6
nj, nb = sl.bond_and_break(sb)
O.dt = 0.8 * yr.critical_time_step() * (1 - 1e-9)
[e for e in O.engines if type(e).__name__ == "RbsmTimeStepper"][0].setDt = True
probe = safety.probe_slipping_surface(steps=300)
it0 = O.iter
O.run(300, True)
# Fellenius with the strength of the plane (c = 0, phi), not of the bonded blocks
found = safety.slip_surface_fs(probe, slope=safety.le_slope(surface, c=0.0, phi=phi, density=2000))
ss, fs, fel = found
print(repr(found))
print(ss)
print(safety.table2(fs, fel if not isinstance(fel, str) else None, title="sliding wedge, surface of slipping joints"))
print("RESULT " + json.dumps(dict(pattern=pattern, broken=nb, joints=nj, probe=probe.polyline, probe_iter=it0, 
                                  polyline=ss.polyline, n=len(ss.joints), fs=fs.fs, fel=getattr(fel, "fs", str(fel)),
                                  plane=plane, closed=math.tan(phi) / math.tan(psi), repr=repr(found),
                                  fs_attr=found.contact.fs)))
