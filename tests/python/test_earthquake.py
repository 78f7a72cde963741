"""yade_rbsm.earthquake without YADE (issue 40): a ground-acceleration Record (checked input, interpolation, CSV,
units), and Newmark's rigid sliding block against closed forms: a rectangular pulse (sliding while the pulse
lasts, then decelerating at the yield acceleration: d = T² a (a − a_y) / (2 a_y)), the plane's factor
cos(φ − ψ)/cos φ and yield acceleration g tan(φ − ψ), nothing below a_y, and the direction conventions."""
import math

import pytest

from yade_rbsm import earthquake as eq


def pulse(a, T):
    return eq.Record([0, 1e-9, T, T + 1e-9, T + 5], [0, a, a, 0, 0], units="m/s2")


def test_rectangular_pulse_closed_form():
    """(to 1e-4: the pulse's edges fall inside an integration step, a millionth of the span)"""
    a, T, ay = 3.0, 0.5, 1.0
    r = eq.newmark(pulse(a, T), ky=ay / eq.G, direction=1, face=-1, extra=2)
    assert r.displacement == pytest.approx(0.5 * T * T * a * (a - ay) / ay, rel=1e-4)
    assert r.velocity[-1] == 0


def test_plane_factor_and_yield_acceleration():
    a, T, psi, phi = 4.0, 0.3, 25.0, 35.0
    r = eq.newmark(pulse(a, T), psi=psi, phi=phi, direction=1, face=-1, extra=2)
    ay = eq.G * math.tan(math.radians(phi - psi))
    f = math.cos(math.radians(phi - psi)) / math.cos(math.radians(phi))
    # accelerates at (a - ay) f for T, decelerates at ay f: d = (a - ay) f T² a / (2 ay)
    assert r.ay == pytest.approx(ay) and r.displacement == pytest.approx((a - ay) * f * T * T * a / (2 * ay), rel=1e-4)


def test_below_yield_and_the_other_way_nothing_slides():
    assert eq.newmark(pulse(0.9, 1.0), ky=1.0 / eq.G, direction=1, face=-1).displacement == 0
    # the same pulse pushes into the slope when the ground accelerates the other way (or the face looks to +x)
    assert eq.newmark(pulse(3.0, 0.5), ky=1.0 / eq.G, direction=1, face=1).displacement == 0
    assert eq.newmark(pulse(3.0, 0.5), ky=1.0 / eq.G, direction=-1, face=1).displacement > 0


def test_record_interpolates_and_is_zero_outside():
    r = eq.Record([0.0, 1.0, 2.0], [0.0, 0.5, -0.5], units="g")
    assert r.at(0.5) == pytest.approx(0.25 * eq.G) and r.at(1.5) == pytest.approx(0.0)
    assert r.at(-1) == 0 and r.at(3) == 0 and r.pga == pytest.approx(0.5 * eq.G)
    s = eq.Record.sine(0.2, 2.0, 1.5)
    assert s.duration == pytest.approx(1.5) and s.at(0.125) == pytest.approx(0.2 * eq.G, rel=1e-3)
    assert "PGA 0.2 g" in repr(s)
    again = eq.Record.from_json(s.to_json())
    assert again.t == s.t and again.a == s.a


def test_csv_record(tmp_path):
    p = tmp_path / "kobe.csv"
    p.write_text("# a comment\ntime,acc\n0,0\n0.01,0.1\n0.02,-0.05\n")
    r = eq.Record.from_csv(str(p), time="time", acceleration="acc")
    assert r.a[1] == pytest.approx(0.1 * eq.G)
    with pytest.raises(ValueError, match="columns 't' and 'a'"):
        eq.Record.from_csv(str(p))


@pytest.mark.parametrize("t,a,units,match", [
    ([0, 1, 1], [0, 1, 2], "g", "times must increase"),
    ([0, 1], [0, float("nan")], "g", "row 1 is not a finite number"),
    ([0], [0], "g", "at least two"),
    ([0, 1], [0, 1], "gal", "units must be"),
])
def test_bad_records_are_refused_naming_the_problem(t, a, units, match):
    with pytest.raises(ValueError, match=match):
        eq.Record(t, a, units=units, name="bad")


def test_newmark_needs_its_yield():
    with pytest.raises(ValueError, match="give ky, or psi and phi"):
        eq.newmark(pulse(1, 1))


def _wedge_fs(kh, psi=30.0, phi=40.0):
    p, f = math.radians(psi), math.radians(phi)
    return (math.cos(p) - kh * math.sin(p)) * math.tan(f) / (math.sin(p) + kh * math.cos(p))


def test_yield_coefficient_of_a_wedge_is_tan_phi_minus_psi():
    """The root finder SlopeModel.yield_acceleration uses, on the wedge's closed form FS(kh): tan(phi - psi) to 1e-6
    from the two measured trials nearest it; the same when every trial past k_y slides (FS 0: no FS there)."""
    trials = []
    assert eq.yield_coefficient(_wedge_fs, trials=trials) == pytest.approx(math.tan(math.radians(10)), rel=1e-3)
    assert 3 <= len(trials) <= 12
    slid = eq.yield_coefficient(lambda k: _wedge_fs(k) if _wedge_fs(k) >= 1 else 0.0)
    assert slid == pytest.approx(math.tan(math.radians(10)), rel=0.01)


def test_yield_coefficient_ends():
    assert eq.yield_coefficient(lambda k: 0.9) == 0.0  # fails statically
    with pytest.raises(ValueError, match="no yield below it"):
        eq.yield_coefficient(lambda k: 2.0, kh_max=0.5)


def test_record_velocity_is_the_exact_integral_of_its_acceleration():
    """Record.velocity (the compliant base's ground velocity): the integral of at()'s piecewise-linear acceleration,
    exact; checked against scipy's quad over the samples and, for a sine, the closed form A/(2 pi f) (1 - cos 2 pi f t) to the
    sampling's accuracy; 0 before the record, constant after it."""
    import math
    import random
    rng = random.Random(3)
    t = sorted(rng.uniform(0, 5) for _ in range(40))
    r = eq.Record(t, [rng.uniform(-3, 3) for _ in t])
    from scipy.integrate import quad
    for time in [rng.uniform(t[0], t[-1]) for _ in range(20)]:
        ref, _ = quad(r.at, t[0], time, points=[x for x in t if t[0] < x < time], limit=400, epsabs=1e-12, epsrel=1e-12)
        assert r.velocity(time) == pytest.approx(ref, abs=1e-9 * (1 + abs(ref)))
    assert r.velocity(t[0] - 1) == 0 and r.velocity(t[-1] + 1) == r.velocity(t[-1])
    s = eq.Record.sine(0.1, 5.0, 0.2, units="g")
    for time in (0.03, 0.1, 0.17):
        closed = 0.1 * eq.G / (2 * math.pi * 5.0) * (1 - math.cos(2 * math.pi * 5.0 * time))
        assert s.velocity(time) == pytest.approx(closed, rel=1e-4)
