"""Stability at the extremes (issue 6, first part). Every scene runs with the time step from the
project's own estimate (yade_rbsm.engines(set_dt=True): RbsmTimeStepper sets O.dt = 0.8 × the
Gershgorin bound of the critical step) and checks:

* finite: every position, velocity, orientation, force and torque finite (checked every 10 steps);
* bounded energy: the leapfrog energy E_n = ½ v(n-½)·M v(n+½) + elastic spring energy
  (O.energy['elastPotential'], O.trackEnergy) + gravity potential never exceeds its initial value by more
  than 5 % of the energy scale (initial kinetic energy + Σ weight × block size): an unstable explicit
  step grows the energy exponentially (factors 1e6 and more within a few hundred steps), while contact
  making at a finite step and the leapfrog's O((ω dt)²) energy oscillation stay within a few per cent of
  that scale. (The plain ½ m v² at half steps oscillates by ~60 % at 0.8 × the critical step, hence the
  leapfrog product.)
* interpenetration: the largest joint overlap δn_k (RbsmGeom.deltaN) stays below 1 % of the smaller
  block's size (smallest side of its bounding box: the thickness of a slender block). Materials are
  chosen so that the static overlap under self-weight, σ (h1+h2)/E, is ~0.1 % of the block size: 1 %
  leaves the dynamic overshoot (×2) and the contrast of sizes room, while a blow-up or a block falling
  through another exceeds it by orders of magnitude.

Contact damping ξ = 0.1 in the gravity scenes: the blocks start exactly touching and settle; undamped,
the joints would chatter for the whole run at a few steps per period, which an explicit scheme at 0.8 ×
the critical step does not resolve accurately (the point of these scenes is stability, not the ringing).
ξ is kept at 0.1 because larger ratios make the stepper's dt unstable (bug 1, test_timestep.py).
The E sweep (no gravity, bonded grid with initial velocities) is undamped: there the energy is conserved
and checked within 5 %.

Default: 3000 steps per scene (~1-3 s each); RBSM_LONG=1: 30000 steps.
"""
import math

import pytest

from conftest import run_scene, rect, LONG

STEPS = 30000 if LONG else 3000
PEN_LIMIT = 0.01
ENERGY_TOL = 0.05


def check(r, label):
    e = [x[1] for x in r["energy"]]
    rise = (max(e) - e[0]) / r["escale"] if e else 0.0
    print("%s: dt %.3e s, steps %d, max δn/size %.2e, energy rise %.2e of scale %.3g J, max KE %.3g J, "
          "KE end %.3g J, joints %d" % (label, r["dt"], r["steps_done"], r["max_pen_rel"], rise, r["escale"],
                                        r["max_ke"], r["ke_end"], r["n_inter"]))
    assert r["error"] is None, r["error"]
    assert r["finite"], "NaN or inf in the state"
    assert r["steps_done"] == STEPS
    assert r["max_pen_rel"] < PEN_LIMIT
    assert rise < ENERGY_TOL, "energy grew by %.3g of its scale" % rise
    return rise


def column(sizes, mats, x0=0.0, base=True, base_w=None):
    """Blocks stacked on a fixed base: square blocks of the given sizes, centred at x0."""
    blocks = []
    if base:
        w = base_w or 3 * max(sizes)
        blocks.append({"v": rect(x0 - w / 2, -max(sizes), w, max(sizes)), "fixed": True, "mat": mats[0]})
    y = 0.0
    for s, m in zip(sizes, mats):
        blocks.append({"v": rect(x0 - s / 2, y, s, s), "mat": m})
        y += s
    return blocks


@pytest.mark.parametrize("ratio", [1e-3, 1e3])
def test_stiffness_contrast(ratio):
    """A column of 4 unit blocks alternating E and ratio × E (the softer 1e8 Pa), on a base of the first."""
    e1 = 1e8 if ratio > 1 else 1e11
    mats = [{"young": e1}, {"young": e1 * ratio}]
    blocks = column([1.0] * 4, [0, 1, 0, 1])
    r = run_scene("run", {"materials": mats, "blocks": blocks, "contact_damping": 0.1, "steps": STEPS,
                          "energy_every": 5})
    check(r, "contrast %g" % ratio)


@pytest.mark.parametrize("young", [1e3, 1e6, 1e9, 1e11])
def test_young_range_undamped(young):
    """E from 1 kPa to 100 GPa: a 3 × 3 grid of bonded unit blocks on a fixed base, no gravity, undamped,
    initial velocities of 1e-3 × the bar wave speed sqrt(E/ρ) (strain ~1e-3 at any E). The scene is the same
    in units of the wave transit time, so the measured numbers must not depend on E."""
    c = math.sqrt(young / 2000)
    blocks = [{"v": rect(-1, -1, 5, 1), "fixed": True}]
    k = 0
    for i in range(3):
        for j in range(3):
            k += 1
            blocks.append({"v": rect(i, j, 1, 1), "vel": [1e-3 * c * math.sin(k), 1e-3 * c * math.cos(3 * k)],
                           "w": 1e-3 * c * math.sin(7 * k)})
    r = run_scene("run", {"materials": [{"young": young, "cohesion": young, "tensileStrength": young}],
                          "blocks": blocks, "gravity": [0, 0], "bond": True, "steps": STEPS, "energy_every": 5})
    check(r, "E %g" % young)
    assert r["n_inter"] >= 12, "the bonded grid must stay joined"


@pytest.mark.parametrize("small", [1e-3, 0.1])
def test_sizes_ratio_1000(small):
    """Block sizes over a ratio of 1000 in one scene: a stack big (1000 × small) / medium (30 × small) /
    small on a fixed base; small = 1 mm (1 mm-1 m) and 0.1 m (0.1 m-100 m). E = 1e10 Pa (rock): the 100 m block
    loads its joint by ρ g 100 m = 2 MPa, an overlap of 0.02 % of its size."""
    s = [1000 * small, 30 * small, small]
    blocks = column(s, [0, 0, 0])
    r = run_scene("run", {"materials": [{"young": 1e10}], "blocks": blocks, "contact_damping": 0.1,
                          "steps": STEPS, "energy_every": 5})
    check(r, "sizes %g-%g m" % (small, 1000 * small))


def test_slender_blocks():
    """Aspect ratio 100: three 10 m × 0.1 m planks stacked on a fixed base, a fourth bridging two small
    supports, and a 0.1 m × 10 m column standing on the base; overlap relative to the plank thickness.
    E = 1e10 Pa: the column loads its 0.1 m foot by ρ g 10 m and its joint overlap, σ (h1+h2)/E′, is 0.1 %
    of the 0.1 m width (E = 1e9 gives 1.7 %: Kawai springs scale with the distance to the centroid, 5 m)."""
    blocks = [{"v": rect(-12, -1, 24, 1), "fixed": True}]
    for j in range(3):
        blocks.append({"v": rect(-11, 0.1 * j, 10, 0.1)})
    blocks.append({"v": rect(1, 0, 0.5, 0.5)})
    blocks.append({"v": rect(9.5, 0, 0.5, 0.5)})
    blocks.append({"v": rect(0.5, 0.5, 10, 0.1)})
    blocks.append({"v": rect(11, 0, 0.1, 10)})
    r = run_scene("run", {"materials": [{"young": 1e10}], "blocks": blocks, "contact_damping": 0.1,
                          "steps": STEPS, "energy_every": 5})
    check(r, "slender")


def test_light_and_heavy():
    """Densities 2 and 2e6 kg/m³ side by side (mass ratio 1e6): light and heavy unit blocks next to each
    other on a base, a heavy block resting on a light one and a light one on a heavy one; E = 1e10 Pa
    (the light block under the heavy one carries 2e7 Pa, an overlap of 0.4 % of its size)."""
    mats = [{"young": 1e10, "density": 2.0}, {"young": 1e10, "density": 2e6}]
    blocks = [{"v": rect(-1, -1, 8, 1), "fixed": True}]
    blocks += [{"v": rect(0, 0, 1, 1), "mat": 0}, {"v": rect(1, 0, 1, 1), "mat": 1},
               {"v": rect(3, 0, 1, 1), "mat": 0}, {"v": rect(3, 1, 1, 1), "mat": 1},
               {"v": rect(5, 0, 1, 1), "mat": 1}, {"v": rect(5, 1, 1, 1), "mat": 0}]
    r = run_scene("run", {"materials": mats, "blocks": blocks, "contact_damping": 0.1, "steps": STEPS,
                          "energy_every": 5})
    check(r, "light/heavy")
