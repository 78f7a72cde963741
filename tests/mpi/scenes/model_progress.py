# slope.SlopeModel under yade.mpy (mpiexec -n 3): the dynamic stage's progress line comes from rank 0, by the
# stage's simulated time (never above 100 %). RESULT on rank 0: the progress percentages printed.
import math
import re
import sys

from yade import O

from yade_rbsm import mpi as rmpi, slope as sl

mp = rmpi.start(0, quiet_workers=False)
rock = RbsmMat(young=2e8, poisson=0.2, density=2403, frictionAngle=math.radians(30), cohesion=0, tensileStrength=0)
O.materials.append(rock)
sb = sl.brick_blocks([(0, 0.8), (2.4, 0.8), (5.6, 4.8), (9.6, 4.8)], 0.0, 2.0, 1.0, foundation=0.4, wall=0.4)
m = sl.SlopeModel(sb, rock)
m.build(distribute=True)
m.settle(tol=1e-3, max_steps=400, density_scaling=False, hold_friction=5.0)
import io
import contextlib
buf = io.StringIO()
with contextlib.redirect_stdout(buf):
    m.run(0.1, progress=0.0)
lines = [l for l in buf.getvalue().splitlines() if l.startswith("progress:")]
if mp.rank == 0:
    sys.stdout.write(buf.getvalue())
    print("RESULT %s" % [float(re.search(r", +([0-9.]+)%", l).group(1)) for l in lines])
else:
    print("RESULT-WORKER %d %d" % (mp.rank, len(lines)))
