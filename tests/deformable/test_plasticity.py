"""Plastic deformable blocks (issue 39): RbsmMat.plastic holds a block's stress D(ε − εᵖ) within Mohr-Coulomb with a
tension cut-off by FLAC's explicit return map (pkg/rbsm/kernel/BlockPlasticity.hpp, its unit tests in
tests/unit/test_block_plasticity.cpp). A plate of Voronoi blocks in plane-strain uniaxial compression between
frictionless platens carries the material's strength, 2c cos φ/(1 − sin φ), whatever the blocks; ψ = 0 keeps its
plastic area, ψ = φ dilates it by the flow rule; the yield is in O.energy (plastDissip) and the balance closes;
every way of setting the attributes works and a saved scene keeps the plastic state. Fails on ac21977 (no
RbsmMat.plastic); the plate also failed there with the attribute added until the contact geometry followed welded
joints as material points and found other contacts on the strained shapes (20227e2): at 0.6 % plastic strain the
undeformed shapes drew apart, 118 of 265 welded joints were lost and the plateau fell 7-17 % below 2c. Welded joints of
yielded blocks become cracks at RbsmMat.weldBreakStrain; strength reduction of plastic blocks finds the closed form."""
import math
import os
import sys

import pytest

from conftest import run_scene
from verification import record

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "yade"))
from yaderun import run_ok  # noqa: E402


def plateau(r):
    """The mean of the nominal stress over the last 40 % of the loading (after yield)."""
    tail = r["curve"][int(0.6 * len(r["curve"])):]
    return sum(f for _, f in tail) / len(tail)


@pytest.mark.parametrize("phi,seed", [(0, 1), (0, 2), (30, 3)], ids=["tresca-seed1", "tresca-seed2", "mc30-seed3"])
def test_plate_carries_the_material_strength(phi, seed):
    c = 1e5
    r = run_scene("compression", {"n": 100, "seed": seed, "c": c, "phi": phi, "sigmaT": c, "steps": 60000, "strain": 0.006})
    q = 2 * c * math.cos(math.radians(phi)) / (1 - math.sin(math.radians(phi)))
    print("phi %g seed %d: plateau %.4g (%+.2f %% of %.4g), blocks' mean sxx %+.2f %%, %d/%d yielded, welded %s, plastic area %.1e"
          % (phi, seed, plateau(r), 100 * (plateau(r) / q - 1), q, 100 * (-r["mean_stress"][0] / q - 1), r["yielded"], r["n"],
             r["welded"], r["plastic_area"]))
    record("Plastic blocks", "plate of 100 plastic Voronoi blocks in uniaxial compression (φ %g°, seed %d): strength" % (phi, seed),
           plateau(r), q, "2c cos φ / (1 − sin φ)", rtol=0.02, unit="Pa")
    assert plateau(r) == pytest.approx(q, rel=0.02)
    assert -r["mean_stress"][0] == pytest.approx(q, rel=0.02)
    assert r["yielded"] == r["n"]  # a uniform stress: every block at the surface
    assert r["welded"][1] == r["welded"][0]  # no welded joint lost to the geometry
    assert abs(r["plastic_area"]) < 1e-9  # ψ = 0: plastic flow keeps the area
    assert r["energy"]["plastDissip"] > 0.3 * r["energy"]["strainElastic"]


def test_plate_strength_holds_at_large_strain():
    """To 6 % plastic strain: the welded joints are followed as the material points they are (frozen), and the
    blocks meet on their strained shapes. With the joints clipped on the undeformed shapes (as in ac21977) the
    undeformed polygons overlapped and parted, the joints turned, and the plate carried 2.5 MPa = 12 × 2c at 9 %."""
    c = 1e5
    r = run_scene("compression", {"n": 100, "seed": 4, "c": c, "phi": 0, "sigmaT": c, "steps": 100000, "strain": 0.06})
    print("Tresca to 6 %%: plateau %+.2f %%, blocks' mean sxx %+.2f %%, plastic shear %.3f, welded %s"
          % (100 * (plateau(r) / (2 * c) - 1), 100 * (-r["mean_stress"][0] / (2 * c) - 1), r["plastic_shear"], r["welded"]))
    assert r["plastic_shear"] > 0.05
    assert -r["mean_stress"][0] == pytest.approx(2 * c, rel=0.03)
    assert plateau(r) == pytest.approx(2 * c, rel=0.06)  # (the platen's force: the loading's inertia in it)
    assert r["welded"][1] == r["welded"][0]


def test_associated_flow_dilates_and_elastic_blocks_do_not_yield():
    c, phi = 1e5, 30
    dil = run_scene("compression", {"n": 100, "seed": 1, "c": c, "phi": phi, "psi": phi, "sigmaT": c, "steps": 60000, "strain": 0.006})
    ela = run_scene("compression", {"n": 100, "seed": 1, "c": c, "phi": phi, "plastic": False, "steps": 20000, "strain": 0.006})
    q = 2 * c * math.cos(math.radians(phi)) / (1 - math.sin(math.radians(phi)))
    s = math.sin(math.radians(phi))
    # plastic strain rates (ε1ᵖ, ε3ᵖ) ∝ (1 + sin ψ, −(1 − sin ψ)): the area grows by sin ψ of the plastic shear
    print("psi = phi: plateau %+.2f %%, plastic area %.3e = %.4f of the plastic shear (sin psi %.4f); elastic blocks: %.4g at the end (q %.4g)"
          % (100 * (plateau(dil) / q - 1), dil["plastic_area"], dil["plastic_area"] / dil["plastic_shear"], s, ela["last"], q))
    assert dil["plastic_area"] == pytest.approx(s * dil["plastic_shear"], rel=0.01)
    assert plateau(dil) == pytest.approx(q, rel=0.03)
    assert ela["yielded"] == 0 and ela["last"] > 1.5 * q
    assert "plastDissip" not in ela["energy"] or ela["energy"]["plastDissip"] == 0


def test_welded_joints_of_yielded_blocks_become_cracks():
    """RbsmMat.weldBreakStrain: a welded joint whose two blocks have both accumulated that much plastic shear becomes
    a Mohr-Coulomb joint of the material (brittle here: its cohesion goes at the first slip, φ = 0), so the failed
    plate comes apart and its load falls, where with welded joints it holds 2c (test above)."""
    c = 1e5
    r = run_scene("compression", {"n": 100, "seed": 1, "c": c, "phi": 0, "sigmaT": c, "steps": 80000, "strain": 0.02, "weldBreak": 0.01})
    print("weldBreakStrain 0.01: peak %.4g (2c %.4g), last %.4g, welded %s" % (r["peak"], 2 * c, r["last"], r["welded"]))
    assert r["peak"] == pytest.approx(2 * c, rel=0.1)  # the continuum's strength until the cracks form
    assert r["welded"][1] < 0.6 * r["welded"][0]
    assert r["last"] < 0.1 * 2 * c


def reduced_strength(c, phi, F):
    """2c' cos φ'/(1 − sin φ') of c' = c/F, tan φ' = tan φ/F: the plate's strength at the factor F."""
    p = math.atan(math.tan(phi) / F)
    return 2 * c / F * math.cos(p) / (1 - math.sin(p))


@pytest.mark.parametrize("phi", [0, 20])
def test_strength_reduction_of_plastic_blocks_finds_the_closed_form(phi):
    """A plate under a constant end load q between frictionless platens: strength reduction (c/F, tan φ/F on the
    blocks) must fail it where its reduced strength falls to q. Not a slope, so it
    checks the blocks' part alone: every joint of the plate is welded."""
    c, expected = 1e5, 1.5
    q = reduced_strength(c, math.radians(phi), expected)  # the load the plate carries at F = 1.5 exactly
    # (reducing c alone would give another F for phi > 0: 1.5 needs c and tan(phi) reduced together)
    r = run_scene("srm_plate", {"c": c, "phi": phi, "q": q, "rtol": 0.01})
    print("phi %g: strength reduction FS %.4f against %.4f (%+.2f %%): %s" % (phi, r["fs"], expected, 100 * (r["fs"] / expected - 1), r["text"]))
    assert r["warnings"] == []
    assert r["fs"] == pytest.approx(expected, rel=0.02)


def test_energy_balance_closes_with_yielding_blocks():
    """Undamped plate of welded blocks with random velocities and strain rates, blocks weak enough to yield: the
    yield takes about a third of the initial energy, and the balance with plastDissip closes as for elastic blocks."""
    r = run_scene("energy", {"size": 4.0, "seed": 1, "v": 0.04, "steps": 4000, "safety": 0.05, "plastic": [2000, 0.3, 0.1]})
    print("plastic blocks: plastDissip %.3g of the initial energy, balance worst %.2e drift %+.2e"
          % (r["energies"]["plastDissip"] / r["e0"], r["worst"], r["drift"]))
    assert r["energies"]["plastDissip"] > 0.2 * r["e0"]
    assert r["worst"] < 0.01 and abs(r["drift"]) < 2e-3


def test_energy_balance_closes_with_yielding_welds():
    """The same plate with RbsmMat.weldYields: its welds slip at the blocks' strength too (plastDissip about 0.77 of
    the initial energy, 0.37 with elastic welds). The balance's drift is the explicit return's error of the step,
    first order: -3.6e-3 at the test above's step, -1.8e-3 at half of it, -0.9e-3 at a quarter."""
    plastic = {"size": 4.0, "seed": 1, "v": 0.04, "steps": 4000, "safety": 0.05, "plastic": [2000, 0.3, 0.1]}
    elastic = run_scene("energy", plastic)
    coarse = run_scene("energy", dict(plastic, weldYields=True))
    fine = run_scene("energy", dict(plastic, weldYields=True, safety=0.025, steps=8000))
    for r in (coarse, fine):
        print("yielding welds, dt %.3g: plastDissip %.3g of the initial energy (elastic welds %.3g), balance worst %.2e "
              "drift %+.2e" % (r["dt"], r["energies"]["plastDissip"] / r["e0"], elastic["energies"]["plastDissip"] / elastic["e0"],
                               r["worst"], r["drift"]))
    assert coarse["energies"]["plastDissip"] > 1.5 * elastic["energies"]["plastDissip"]  # the welds took part
    assert abs(fine["drift"]) < 0.6 * abs(coarse["drift"])  # the step's error: it goes with the step
    assert fine["worst"] < 0.01 and abs(fine["drift"]) < 2e-3


SETTING = r"""
import os
import yade_rbsm
from yade_rbsm import polygon2d, omega
out = {}
soil = RbsmMat(young=1e8, density=2000, deformable=True, plastic=True, dilatancy=0.1, cohesion=1e3, frictionAngle=0.3, label="soil")
O.materials.append(soil)
m = RbsmMat()
m.plastic = True
m.dilatancy = 0.2
m2 = RbsmMat()
m2.updateAttrs({"plastic": True, "dilatancy": 0.25})
out["ways"] = [soil.plastic, soil.dilatancy, m.plastic, m.dilatancy, m2.plastic, m2.dilatancy, RbsmMat().plastic, RbsmMat().dilatancy]
out["refused"] = []
for bad in (-0.1, 1.6, float("nan")):
    try:
        RbsmMat(dilatancy=bad)
    except ValueError as e:
        out["refused"].append(str(e))
m.weldBreakStrain = 0.02
out["weldBreak"] = [RbsmMat(weldBreakStrain=0.05).weldBreakStrain, m.weldBreakStrain, RbsmMat().weldBreakStrain]
for bad in (-1e-3, float("inf")):
    try:
        m.weldBreakStrain = bad
    except ValueError as e:
        out["refused"].append(str(e))
m.weldYields = True
m2.updateAttrs({"weldYields": True})
out["weldYields"] = [RbsmMat(weldYields=True).weldYields, m.weldYields, m2.weldYields, RbsmMat().weldYields]
s = DeformableState(plasticStrain=(1e-3, -1e-3, 0), plasticShear=2e-3)
out["state_ctor"] = [list(s.plasticStrain), s.plasticShear]
try:
    s.yieldMode = 1
except AttributeError as e:
    out["readonly"] = str(e)
a = O.bodies.append(polygon2d([(0, 0), (1, 0), (1, 1), (0, 1)], soil))
b = O.bodies.append(polygon2d([(1, 0), (2, 0), (2, 1), (1, 1)], soil))
strong = RbsmMat(young=1e8, density=2000, deformable=True, plastic=True, cohesion=1e3, weldYields=True, label="strong")
stiff = RbsmMat(young=1e8, density=2000, deformable=True, cohesion=1e3, weldYields=True, label="elastic")  # not plastic
O.materials.append(strong)
O.materials.append(stiff)
pairs = [(a, b)]
for mats, x in (((strong, strong), 5), ((strong, soil), 8), ((stiff, stiff), 11)):
    pairs.append(tuple(O.bodies.append(polygon2d([(x + i, 0), (x + i + 1, 0), (x + i + 1, 1), (x + i, 1)], mt)) for i, mt in enumerate(mats)))
O.engines = yade_rbsm.engines(gravity=(0, 0, 0))
omega.ip2(O).setCohesionNow = True
O.step()
out["weld_yields"] = [[O.interactions[i, j].phys.welded, O.interactions[i, j].phys.weldYields] for i, j in pairs]
# the joint's strength Σ (c + max(σn, 0) tan φ) a_k as the law reports it: finite for a weld that yields
out["weld_strength"] = [O.interactions[i, j].phys.strength for i, j in pairs[:2]]
I = O.interactions[pairs[1]]
out["weld_strength_expected"] = sum((I.phys.cohesion + max(sn, 0) * I.phys.tanPhi) * w * I.geom.length * I.geom.thickness
                                    for sn, w in zip(I.phys.normalTraction, I.geom.weights))
O.bodies[a].state.strain = (-0.01, 0, 0)  # far beyond the strength: the next step returns it
O.bodies[b].state.updateAttrs({"plasticStrain": (1e-4, 0, 0)})
out["updated"] = list(O.bodies[b].state.plasticStrain)
O.step()
sa = O.bodies[a].state
import math
sx, sy, sxy = sa.stress
mean, radius = (sx + sy) / 2, math.hypot((sx - sy) / 2, sxy)
f = radius + mean * math.sin(soil.frictionAngle) - soil.cohesion * math.cos(soil.frictionAngle)
out["after"] = [sa.yieldMode, sa.plasticShear, list(sa.plasticStrain), list(O.bodies[b].state.plasticStrain), f]
from yade_rbsm import gui
from yade_rbsm.snapshots import snapshot
top = gui.color_blocks()  # the band in the qt view: brightest where the plastic shear is largest
out["colors"] = [top, list(O.bodies[a].shape.color), list(O.bodies[b].shape.color), max(sa.plasticShear, O.bodies[b].state.plasticShear)]
out["png"] = os.path.getsize(snapshot("band.png", field="plasticShear"))
try:
    gui.color_blocks("strain")
except ValueError as e:
    out["bad_field"] = str(e)
O.save("plastic.yade.gz")
O.save("plastic.xml")
report(**out)
"""

LOAD = r"""
out = {}
for f in ("plastic.yade.gz", "plastic.xml"):
    O.load(f)
    sa = O.bodies[0].state
    out[f] = [sa.yieldMode, sa.plasticShear, list(sa.plasticStrain), O.materials[0].plastic, O.materials[0].dilatancy,
              O.materials["strong"].weldYields, O.interactions[2, 3].phys.weldYields]
report(**out)
"""


def test_setting_and_saving_plastic_blocks(tmp_path):
    (r,) = run_ok(SETTING, workdir=str(tmp_path))
    assert r["ways"] == [True, 0.1, True, 0.2, True, 0.25, False, 0.0]
    assert len(r["refused"]) == 5 and all("dilatancy" in m and "[0, pi/2)" in m for m in r["refused"][:3])
    assert all("weldBreakStrain" in m and ">= 0" in m for m in r["refused"][3:])
    assert r["weldBreak"] == [0.05, 0.02, 0.0]
    assert r["weldYields"] == [True, True, True, False]
    # welded as built; the welds yield only between two plastic materials that both ask for it
    assert r["weld_yields"] == [[True, False], [True, True], [True, False], [True, False]]
    elastic_weld, yielding_weld = r["weld_strength"]
    assert elastic_weld == float("inf") and yielding_weld == pytest.approx(r["weld_strength_expected"], rel=1e-12)
    assert r["state_ctor"] == [[1e-3, -1e-3, 0], 2e-3]
    assert "readonly" in r  # yieldMode is the integrator's to set
    mode, shear, eps_p, other, f = r["after"]
    assert mode in (1, 2, 3) and shear > 0 and eps_p != [0, 0, 0]
    assert f <= 1e-9 * 1e3  # the stress after the step is on or inside Mohr-Coulomb
    assert r["updated"] == [1e-4, 0, 0] and other != [1e-4, 0, 0]  # set by updateAttrs; then b yields too
    top, color_a, color_b, largest = r["colors"]
    assert top == largest and color_a != color_b  # coloured by plastic shear, from 0 to the largest
    assert r["png"] > 10000 and "strain" in r["bad_field"] and "plasticShear" in r["bad_field"]
    (l,) = run_ok(LOAD, workdir=str(tmp_path))
    for f in ("plastic.yade.gz", "plastic.xml"):
        assert l[f][:3] == [mode, shear, eps_p] and l[f][3:] == [True, 0.1, True, True]
