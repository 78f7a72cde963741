"""What reads a deformable block's stress (issue 38): measure.block_stresses, the VTK output (vtkexport's
"stress" cell array) and the stress-based factor of safety's field (le_bridge.stress_field) all give the
block's own D·ε (DeformableState.stress), and in a settled column of Voronoi blocks under its weight on a
frictionless base that is the closed form σyy = −ρ g (H − y), σxx = 0 (rms within 5 % of ρ g H).
A guard, not a fix: it passes on 1984eeb; a reader that took the joints' Love-Weber average instead (equal at
rest to about 1e-6) fails its 1e-12 comparison."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "yade"))
from yaderun import run_ok  # noqa: E402

SCRIPT = r"""
import math
import numpy as np
import yade_rbsm
from yade_rbsm import polygon2d, omega, measure, vtkexport, le_bridge
from yade_rbsm.voronoi import voronoi_blocks
from vtk.util.numpy_support import vtk_to_numpy
W = H = 4.0
rho, g = 2000.0, 10.0
soil = RbsmMat(young=1e8, poisson=0.3, density=rho, deformable=True, cohesion=1e9, tensileStrength=1e9, frictionAngle=0.5)
base = RbsmMat(young=1e8, poisson=0.3, density=rho, frictionAngle=0)
O.materials.append(soil); O.materials.append(base)
ids = [O.bodies.append(polygon2d(b, soil)) for b in voronoi_blocks([(0, 0), (W, 0), (W, H), (0, H)], n=60, seed=3, min_distance=0.15)]
O.bodies.append(polygon2d([(-1, -1), (W + 1, -1), (W + 1, 0), (-1, 0)], base, fixed=True))
O.engines = yade_rbsm.engines(gravity=(0, -g, 0), damping=0.5)
omega.engine("timeStepper", O).densityScaling = True
omega.ip2(O).setCohesionNow = True
O.step()
last = None
while O.iter < 200000:
    O.run(2000, True)
    y = sum(O.bodies[i].state.pos[1] for i in ids)
    if last is not None and abs(y - last) < 1e-10 * abs(y):
        break
    last = y
own = {i: list(O.bodies[i].state.stress) for i in ids}
S = measure.block_stresses(O)
pd = vtkexport.blocks_polydata(O)
cells = pd.GetCellData()
vid = list(vtk_to_numpy(cells.GetArray("id")))
vsig = vtk_to_numpy(cells.GetArray("stress"))
F = le_bridge.stress_field(O)
out = {"iter": O.iter, "rows": []}
for i in ids:
    c = O.bodies[i].state.pos
    k = vid.index(i)
    out["rows"].append({"y": c[1], "own": own[i], "measure": [S[i][0][0], S[i][1][1], S[i][0][1]],
                        "vtk": [float(vsig[k][0]), float(vsig[k][4]), float(vsig[k][1])],
                        "field_kPa": list(F(c[0], c[1]))})
report(**out)
"""


def test_block_stress_readers_give_the_blocks_own_stress(tmp_path):
    (r,) = run_ok(SCRIPT, workdir=str(tmp_path))
    rho_g_h = 2000.0 * 10.0 * 4.0
    err_yy, err_xx = [], []
    for row in r["rows"]:
        own = row["own"]
        assert row["measure"] == pytest.approx(own, rel=1e-12, abs=1e-9)
        assert row["vtk"] == pytest.approx(own, rel=1e-12, abs=1e-9)
        # the field: kPa, compression positive (limit_equilibrium's convention), at the block's own centroid
        assert row["field_kPa"][0] == pytest.approx(-own[0] / 1e3, rel=1e-6, abs=1e-6)
        assert row["field_kPa"][1] == pytest.approx(-own[1] / 1e3, rel=1e-6, abs=1e-6)
        err_yy.append((own[1] + 2000.0 * 10.0 * (4.0 - row["y"])) / rho_g_h)
        err_xx.append(own[0] / rho_g_h)
    rms = lambda e: (sum(x * x for x in e) / len(e)) ** 0.5
    print("column of %d deformable blocks, %d steps: syy rms error %.2f %%, sxx rms %.2f %% of rho g H"
          % (len(r["rows"]), r["iter"], 100 * rms(err_yy), 100 * rms(err_xx)))
    assert rms(err_yy) < 0.05 and rms(err_xx) < 0.05
