"""What a new user hit in a trial of the merged plugin (session 8), each a scene in scenes/trial.py.
Before: a block on utils.wall / utils.facet under engines() fell to y = -4.66 in 1000 steps with no message
(engines()' collider bounded Polygon2D only, so the pair never existed); a block above a wall alone kept
O.dt = 1e-8 (3.1e-5 s after 3100 steps: no first contact with a rigid boundary); a block given a z velocity
fell to y = -75.9 silently (YADE keeps a blocked DOF's velocity); advance(2.7) ran 2 steps."""
import pytest

from conftest import run_scene


@pytest.mark.parametrize("boundary", ["wall", "facet"])
def test_engines_reports_a_block_on_a_wall(boundary):
    r = run_scene("trial", {"case": "engines_wall", "boundary": boundary})
    print(r)
    assert r["exc"] and "stopped at step" in r["exc"]
    assert r["iter"] <= 2 and r["y"] > 0.2


@pytest.mark.parametrize("boundary", ["wall", "facet"])
def test_block_above_a_wall_gets_a_first_contact_step(boundary):
    r = run_scene("trial", {"case": "wall_first", "boundary": boundary})
    print(r)
    assert r["exc"] is None
    assert 1e-4 < r["dt"] < 1e-2 and r["time"] > 0.01


@pytest.mark.parametrize("what", ["vel", "angVel"])
def test_out_of_plane_motion_is_refused(what):
    """Since issue 34 item 6 a block the model cannot integrate refuses the step (before, reported and the run
    stopped after it): the step is not integrated."""
    r = run_scene("trial", {"case": "z_velocity", "what": what})
    print(r)
    assert r["exc"] and "body #1 moves out of the x-y plane" in r["exc"] and "refused before integration" in r["exc"]
    assert r["iter"] <= 12 and r["y"] > 0.2


def test_advance_refuses_a_fraction():
    r = run_scene("trial", {"case": "advance_frac"})
    assert r["exc"] and "whole number" in r["exc"] and r["iter"] == 0
