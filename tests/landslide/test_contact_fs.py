"""Contact-force factor of safety against a hand calculation: a 2 m x 1 m block resting on a fixed
block along a plane joint inclined at psi = 20 deg, phi = 30 deg, c = 0. At equilibrium the joint
carries N = W cos(psi), T = W sin(psi) (driving, downslope), so FS = tan(phi)/tan(psi) = 1.586. The forces
are per metre of the blocks' thickness, as limit equilibrium's slices and the tables' kN/m say: a pair built
2 m thick gives the same N and T (it gave twice them, labelled kN, before). A polyline that follows the joint and
then leaves its end steeply down (a toe's exit), under the centroid of a base block reaching past the joint, reads
the same joint: the blocks' sides are judged against the joint's own line (judged by the height above the
polyline at each centroid's x, both blocks were "above" it and the joint was dropped)."""
import os

import pytest

from conftest import HERE, run_yade


@pytest.mark.parametrize("thickness,surface", [(1.0, "plane"), (2.0, "plane"), (1.0, "kink")])
def test_block_on_plane(thickness, surface):
    p = run_yade(os.path.join(HERE, "fs_two_blocks.py"), str(thickness), surface, cwd=HERE)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    line = [l for l in p.stdout.splitlines() if l.startswith("RESULT")][0].split()
    ok, n, r = line[1], int(line[2]), float(line[3])
    N, T, fs, N0, T0, fs0, nj = map(float, line[4:])
    assert ok == "True", "gravity stage did not converge (ratio %g after %d steps)" % (r, n)
    assert nj == 1
    assert N == pytest.approx(N0, rel=1e-3)
    assert T == pytest.approx(T0, rel=1e-3)
    assert fs == pytest.approx(fs0, rel=1e-3)
    shown = [l for l in p.stdout.splitlines() if l.startswith("REPR")][0]
    assert "kN/m" in shown and " kN," not in shown, shown
