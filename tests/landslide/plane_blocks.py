"""Shared set-up of the small landslide test scenes (yade scripts run with cwd = this directory):
blocks resting on a fixed block along a plane joint inclined at psi, bonded, then settled by a
damped gravity stage."""
import math

from yade import O

import yade_rbsm as yr
from yade_rbsm import slope


def plane_frame(psi):
    """Maps (x along the plane, y across it) to world coordinates for a plane inclined at psi [rad]."""
    c, s = math.cos(psi), math.sin(psi)
    return lambda x, y: (x * c - y * s, x * s + y * c)


def bonded_gravity_stage():
    """Engines (damped, O.dt set here), joints bonded at the first step, then settled; returns
    slope.settle's (converged, steps, ratio)."""
    O.engines = yr.engines(damping=0.7, set_dt=False, enlarge=0.01)
    O.dt = 1e-6
    O.engines[2].physDispatcher.functors[0].setCohesionNow = True
    O.step()
    O.dt = 0.8 * yr.critical_time_step()
    return slope.settle(tol=1e-6, max_steps=20000, check=100)
