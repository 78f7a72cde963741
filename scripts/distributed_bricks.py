# A brick slope on three MPI ranks with yade.mpy: every rank runs this script; rank 0 prints.
#   mpiexec -n 3 --oversubscribe build/yade-rbsm -n -x scripts/distributed_bricks.py
import math
from yade import mpy                   # before engines(): engines() then adds the MPI sync
# mpy.initialize(3)                    # only when started without mpiexec: spawns 2 workers running this script
import yade_rbsm as yr, yade_rbsm.mpi as rm
from yade_rbsm import slope, safety
rock = RbsmMat(young=2e8, poisson=0.2, density=2403, frictionAngle=math.radians(40), cohesion=0, tensileStrength=0)
O.materials.append(rock)
joint = [(6, 2), (17, 2 + 11 * math.tan(math.radians(35)))]           # a plane at 35° from the toe to a crack
blocks = slope.brick_blocks([(0, 2), (6, 2), (14, 12), (24, 12)], 0.0, 2.0, 1.0, joints=[joint], crack=joint[1],
                            foundation=1.0, wall=1.0)                # every rank builds the same scene
slope.build_scene(blocks, rock)
O.engines = yr.engines()               # = engines(mpi=True) since yade.mpy is imported
rm.decompose_by_x()                    # free blocks in vertical slices, one per worker; fixed blocks on rank 0
rm.distribute()                        # split now, before any joint is made (joints do not cross a split)
slope.bond_and_break(blocks)           # bond on the split scene (collective)
first = slope.settle(tol=1e-3, max_steps=5000, check=100)             # gravity, collective
rm.mpirun(500, with_merge=True)        # = mpy.mpirun + checks; rank 0 then holds the whole scene
if rm.rank() == 0:                     # post-processing on rank 0
    print(f"settled: {first}; {len(O.bodies)} bodies on rank 0 after the merge")
    print(safety.contact_fs(joint))     # the FS from the contact forces along the plane (tan 40°/tan 35° = 1.198)
