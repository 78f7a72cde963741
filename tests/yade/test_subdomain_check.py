"""Blocks in a yade.mpy subdomain other than 0 in a serial run: YADE's NewtonIntegrator moves only the bodies of
Scene.subdomain (0 outside yade.mpy), so they stay frozen. A new user's trial saved a scene merged from 3 ranks
without to_serial and ran it serially: settle "did not converge" (ratio 1.79, nothing moved) and
strength_reduction blamed the reference state. Both now say what is wrong and what to call; after
yade_rbsm.mpi.to_serial() the same scene settles."""
from yaderun import run_ok


def test_settle_and_strength_reduction_refuse_blocks_of_other_subdomains():
    r = run_ok("""
from yade import O, wrapper
import yade_rbsm as yr, yade_rbsm.mpi as rm
from yade_rbsm import polygon2d, slope as sl
from yade_rbsm.strength_reduction import strength_reduction
rock = wrapper.RbsmMat(young=1e8, poisson=0.2, density=2000, frictionAngle=0.6)
O.materials.append(rock)
O.bodies.append(polygon2d([(-1, -1), (4, -1), (4, 0), (-1, 0)], rock, fixed=True))
ids = [O.bodies.append(polygon2d([(i, 0), (i + 1, 0), (i + 1, 1), (i, 1)], rock)) for i in range(3)]
O.engines = yr.engines()
for i in ids[1:]:
    O.bodies[i].subdomain = 2  # as a merged scene saved without to_serial has them
msgs = []
for f in (lambda: sl.settle(tol=1e-4, max_steps=2000), lambda: strength_reduction(verbose=False)):
    try:
        f()
        msgs.append("")
    except ValueError as e:
        msgs.append(str(e))
rm.to_serial()
ok = sl.settle(tol=1e-4, max_steps=20000)
report(msgs=msgs, settled=ok[0], y=[O.bodies[i].state.pos[1] for i in ids])
""")[0]
    assert all("2 bodies are in yade.mpy subdomains other than 0" in m and "to_serial" in m for m in r["msgs"]), r
    assert r["settled"] is True, r
