# Water and an earthquake on a rock slope: Hoek & Bray's plane failure (a 60 deg face 12 m high, a bedding
# dipping 30 deg with c 20 kPa, phi 30 deg, a vertical tension crack), its factor of safety dry, with water
# in the crack and the bedding, under a pseudo-static acceleration kh g, and its yield acceleration, each
# against Hoek & Bray's closed form.
#   build/yade-rbsm -n -x scripts/tutorial_water_earthquake.py [out_dir]
import math, os, sys
from yade_rbsm import slope
out = sys.argv[1] if len(sys.argv) > 1 else "out/tutorial_loads"
os.makedirs(out, exist_ok=True)
psi, phi, c, rho, gw = math.radians(30), math.radians(30), 20e3, 2600.0, 9810.0
toe, crest, daylight, crack = (10, 0), (10 + 12 / math.tan(math.radians(60)), 12), (10 + 3 / math.tan(math.radians(60)), 3), 22
base = (crack, daylight[1] + (crack - daylight[0]) * math.tan(psi))       # where the bedding meets the crack
rock = RbsmMat(young=2e8, poisson=0.2, density=rho, frictionAngle=math.radians(45), cohesion=5e6,
               tensileStrength=2e6, ductile=True, label="rock")
O.materials.append(rock)
bedding = slope.Trace([daylight, base], cohesion=c, friction_angle=30, ductile=True, name="bedding")
tension_crack = slope.Trace([base, (crack, 12)], friction_angle=20, ductile=True, name="tension crack")
blocks = slope.jointset_blocks([(0, 0), toe, crest, (35, 12)], base=-4, traces=[bedding, tension_crack])
model = slope.SlopeModel(blocks, rock)
model.build(enlarge=0.01)
model.settle()
model.give_joint_sets()                     # the traces' own strength
wedge = [daylight, base, (crack, 12), crest]
W = rho * 9.81 * 0.5 * abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(wedge, wedge[1:] + wedge[:1])))  # N/m
A = (crack - daylight[0]) / math.cos(psi)   # bedding length [m]


def hoek_bray(U=0.0, V=0.0, kh=0.0):        # Hoek & Bray's plane failure: water forces U on the plane, V in the crack
    return ((c * A + (W * (math.cos(psi) - kh * math.sin(psi)) - U - V * math.sin(psi)) * math.tan(phi))
            / (W * (math.sin(psi) + kh * math.cos(psi)) + V * math.cos(psi)))


dry = model.fos()
zw = 2.0                                    # water 2 m up the crack and along the bedding to the daylight point
model.set_water([daylight, (base[0], base[1] + zw)])   # the joints of the sets and traces: bedding and crack
wet = model.fos()
model.set_water(None)                       # dry again
model.set_seismic(0.1, towards=-1)          # kh = 0.1, out of the face (the face looks to -x)
quake = model.fos()
for name, r, closed in (("dry", dry, hoek_bray()), ("water, zw 2 m", wet, hoek_bray(U=0.5 * gw * zw * A, V=0.5 * gw * zw ** 2)),
                        ("kh 0.1", quake, hoek_bray(kh=0.1))):
    print(f"{name:14s} FS {r.fs:.3f} by {r.method}, Hoek & Bray {closed:.3f} ({100 * (r.fs / closed - 1):+.1f} %)")
model.set_seismic(0)                        # static again; the yield acceleration: kh at FS = 1
ky = model.yield_acceleration(towards=-1)
lo, hi = 0.0, 1.0                           # Hoek & Bray's kh at FS = 1, by bisection
for _ in range(50):
    lo, hi = ((lo + hi) / 2, hi) if hoek_bray(kh=(lo + hi) / 2) > 1 else (lo, (lo + hi) / 2)
print(f"yield acceleration k_y {ky:.4f}, Hoek & Bray {lo:.4f} ({100 * (ky / lo - 1):+.1f} %)")
model.report(os.path.join(out, "report.md"))
