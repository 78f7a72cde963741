"""The README's "continue serially on rank 0": a row of bricks bonded and settled over 3 ranks, merged,
then rank 0 calls to_serial() and settles again alone (a new user's trial: settle went through
yade_rbsm.mpi.run, which called yade.mpy's mpirun on rank 0 alone and waited for the workers, which had
left: a hang); strength_reduction on the split scene is refused on every rank. Every rank prints its result;
rank 0 its second settle's (converged, steps, ratio)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), "..", "..", "support"))
from yadescene import emit  # noqa: E402
from yade import mpy as mp  # noqa: E402,F401
from yade import O, wrapper  # noqa: E402
import yade_rbsm as yr  # noqa: E402
import yade_rbsm.mpi as rm  # noqa: E402
from yade_rbsm import slope as sl  # noqa: E402

rock = wrapper.RbsmMat(young=1e9, poisson=0.25, density=2600, frictionAngle=0.7, cohesion=5e6, tensileStrength=2e6)
O.materials.append(rock)
sb = sl.brick_blocks([(0.0, 3.0), (20.0, 3.0)], 0.0, 2.0, 1.0)
sl.build_scene(sb, rock)
O.engines = yr.engines()
rm.decompose_by_x()
rm.distribute()
sl.bond_and_break(sb)
first = sl.settle(tol=1e-3, max_steps=2000, check=100)
try:  # on the split scene: refused on every rank (it hung: O.loadTmp failed on the workers, rank 0 waited)
    from yade_rbsm.strength_reduction import strength_reduction
    strength_reduction(max_steps=500, verbose=False)
    refused = ""
except ValueError as e:
    refused = str(e)
rm.merge()
out = {"rank": rm.rank(), "first": list(first), "sr_refused": refused}
if rm.rank() == 0:
    rm.to_serial()
    out["second"] = list(sl.settle(tol=1e-4, max_steps=2000, check=100))
    out["iter"] = O.iter
emit(out)
