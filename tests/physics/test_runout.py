"""Incline to flat: damping that adds no friction (issue 35, item 2).

A block L × L/2 (L 0.05–0.4 m) slides 10 m down a 30° incline (φ 20°) onto a flat. Its speed near the
kink must be the closed form sqrt(2 g s (sin ψ − tan φ cos ψ)) within 0.5 % whatever the contact damping
ratio ξ (0, 0.3, 1), also when the block is placed touching the incline and bounces on its springs. On the flat, with the landing damped (ξ 0.3, 1), the runout lies between the
point-mass answers, 2.38 m (the normal velocity stopped by a Coulomb impulse) and 3.81 m (lost without
friction), is not shorter with more damping (less rebound, less normal impulse, less friction), and
changes by less than 5 % from ξ 0.3 to 1: the dashpot damps the springs and adds no friction. Before, its
normal force entered the Coulomb cap and the per-point caps let the landing slip point by point: the 0.2 m
block ran out 2.99 m at ξ 0.3 and 3.38 m at ξ 1 (12 %; the issue's 2.96 and 3.40 m). What is left, up to
4 %, is the restitution the damping sets (a point mass would change by 19 %), not a numerical friction.
(Undamped, ξ = 0, the landing is elastic and the block bounces on: a runout for a restitution of 1,
outside these bounds by nature, so only its arrival is checked.)
Every run's energy balance closes (issue 35, item 3): O.energy.total() stays within 1 % of the work of gravity
(kinetic, gravity work, spring energy, friction, released spring energy, dashpots).
"""
from math import radians, sin, cos, tan, sqrt

import pytest

from conftest import run_scene
from verification import record

G, PSI, PHI, SLIDE = 9.81, radians(30), radians(20), 10.0
V = sqrt(2 * G * SLIDE * (sin(PSI) - tan(PHI) * cos(PSI)))
LOW = (V * (cos(PSI) - tan(PHI) * sin(PSI))) ** 2 / (2 * G * tan(PHI))  # 2.38 m
HIGH = (V * cos(PSI)) ** 2 / (2 * G * tan(PHI))  # 3.81 m


@pytest.mark.parametrize("L", [0.05, 0.1, 0.2, 0.4])
def test_runout_between_point_mass_answers(L):
    r = {xi: run_scene("runout", {"L": L, "H": L / 2, "xi": xi, "kink_only": xi == 0}) for xi in (0, 0.3, 1)}
    # placed touching the incline, as a user places a block: it bounces on its springs on the way down
    touching = {xi: run_scene("runout", {"L": L, "H": L / 2, "xi": xi, "kink_only": True, "start": "touching"}) for xi in (0, 1)}
    for xi, x in r.items():
        print("L %g xi %g: speed near the kink %.6f m/s (closed form %.6f, %+.4f %%), runout %.4f m (bounds %.3f..%.3f), %d steps"
              % (L, xi, x["v_kink"], x["v_closed"], 100 * (x["v_kink"] / x["v_closed"] - 1), x["runout"], LOW, HIGH, x["steps"]))
    for xi, x in r.items():
        print("L %g xi %g: energy balance off by %.3g J = %.4f %% of the work of gravity; %s"
              % (L, xi, x["drift"], 100 * x["drift"] / x["grav_work"], {k: round(v, 3) for k, v in x["energy"].items()}))
    for xi, x in touching.items():
        print("L %g xi %g, placed touching: speed near the kink %.6f m/s (%+.4f %%)" % (L, xi, x["v_kink"], 100 * (x["v_kink"] / x["v_closed"] - 1)))
        assert x["v_kink"] == pytest.approx(x["v_closed"], rel=0.005), "touching, xi %g" % xi
    record("Blocks and joints", "a %g m block sliding down an incline: speed at the kink" % L, r[0.3]["v_kink"],
           r[0.3]["v_closed"], "the point mass's energy balance", rtol=0.005, unit="m/s")
    for xi, x in r.items():
        assert x["v_kink"] == pytest.approx(x["v_closed"], rel=0.005), "xi %g" % xi
        assert abs(x["drift"]) < 0.01 * x["grav_work"], "xi %g" % xi
    for xi in (0.3, 1):
        assert r[xi]["stopped"] and LOW < r[xi]["runout"] < HIGH, "xi %g" % xi
    assert r[0.3]["runout"] <= r[1]["runout"] < 1.05 * r[0.3]["runout"]
