"""The unbalanced-force ratio under density scaling (issue 22; a new user's trial, 14b).

RbsmTimeStepper.densityScaling leaves (F + m g)/s - m g in O.forces for a block scaled by s (its force
and weight divided before NewtonIntegrator adds the weight): unbalanced_ratio read that as it was, so a
scaled block's residual counted 1/s of its own. settle(density_scaling=True) then "converged" after 100
steps with six 2 cm pebbles still in the air above 1 m blocks (scaled 115 x, each reported at 0.0087 of
its weight), and strength reduction of a tilted slab on a 35 deg base (tan 35 / tan 25 = 1.5016) gave
1.5075 scaled against 1.4985 plain.
"""
import pytest

from yaderun import run_ok

PEBBLES = """
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import polygon2d
from yade_rbsm.slope import settle
rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2500, frictionAngle=0.6)
O.materials.append(rock)
O.bodies.append(polygon2d([(-1, -1), (12, -1), (12, 0), (-1, 0)], rock, fixed=True))
for k in range(6):
    O.bodies.append(polygon2d([(2 * k, 0), (2 * k + 1, 0), (2 * k + 1, 1), (2 * k, 1)], rock))
pebbles = [O.bodies.append(polygon2d([(2 * k + 0.4, 1.001), (2 * k + 0.42, 1.001), (2 * k + 0.42, 1.021), (2 * k + 0.4, 1.021)], rock))
           for k in range(6)]
O.engines = yr.engines()
ok, steps, ratio = settle(tol=1e-4, max_steps=20000, check=100, density_scaling=DS)
landed = sum(1 for i in pebbles if any(I.isReal for I in O.interactions.withBody(i)))
report(ok=ok, steps=steps, ratio=ratio, landed=landed, scaled=sum(1 for s in yr.time_stepper().massScale if s > 1))
"""


@pytest.mark.parametrize("ds", [False, True])
def test_settle_with_density_scaling_waits_for_the_pebbles_to_land(ds):
    (r,) = run_ok(PEBBLES.replace("DS", str(ds)))
    assert r["ok"] and r["landed"] == 6, r  # scaled: converged at step 100 with no pebble down


SLAB = """
import math, random
from yade import O, wrapper
import yade_rbsm as yr
from yade_rbsm import polygon2d
from yade_rbsm.slope import settle
from yade_rbsm.voronoi import voronoi_blocks
from yade_rbsm.strength_reduction import strength_reduction
# a 6 x 2 m bonded Voronoi slab (a cluster of small cells: blocks 0.04-1.3 m) on a flat base, gravity
# tilted 25 deg; the base joint c = 0, phi = 35 deg, the slab's joints never fail: FS = tan 35 / tan 25
rng = random.Random(2)
sites = [(rng.uniform(0, 6), rng.uniform(0, 2)) for _ in range(25)]
sites += [(rng.uniform(4.5, 4.8), rng.uniform(0.1, 0.4)) for _ in range(25)]
rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2500, frictionAngle=math.radians(45), cohesion=2e6, tensileStrength=2e6)
base = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2500, frictionAngle=math.radians(35))
O.materials.append(rock); O.materials.append(base)
O.bodies.append(polygon2d([(-2, -1), (30, -1), (30, 0), (-2, 0)], base, fixed=True))
for v in voronoi_blocks([(0, 0), (6, 0), (6, 2), (0, 2)], sites=sites):
    O.bodies.append(polygon2d(v, rock))
psi = math.radians(25)
O.engines = yr.engines(gravity=(9.81 * math.sin(psi), -9.81 * math.cos(psi), 0))
yr.omega.ip2(O).setCohesionNow = True
O.step()
yr.omega.ip2(O).setCohesionNow = False
settle(tol=1e-5, max_steps=100000, check=100, density_scaling=DS)
r = strength_reduction(start=1.2, grow=1.2, rtol=0.01, tol=1e-4, density_scaling=DS, verbose=False, max_steps=20000)
report(fs=r.fs, lo=r.lo, hi=r.hi, exact=math.tan(math.radians(35)) / math.tan(psi))
"""


def test_strength_reduction_with_density_scaling_gives_the_plain_fs():
    (plain,) = run_ok(SLAB.replace("DS", "False"), timeout=600)
    (scaled,) = run_ok(SLAB.replace("DS", "True"), timeout=600)
    # the bracket holds the exact FS: a trial above it must fail (scaled, F = 1.503 passed: 1.5075 [1.5030, 1.5120])
    assert plain["lo"] < plain["exact"] < plain["hi"], plain
    assert scaled["lo"] < scaled["exact"] < scaled["hi"], (scaled, plain)
    assert scaled["fs"] == pytest.approx(plain["fs"], rel=0.005), (scaled, plain)
