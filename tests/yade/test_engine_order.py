"""engines() and mixed_engines() keep YADE's habit that scripts rely on (issue 37): NewtonIntegrator is the
last engine and labelled 'newton', so that a script's O.engines[-1].damping = 0.2 reaches it (on b1db5ec
it went to RbsmPairCheck without a word, and the integrator kept 0), and an engine appended by the script
(a recorder, a PyRunner) runs after the positions are updated, as in YADE's own examples."""
from yaderun import run_ok

SCRIPT = r"""
from yade_rbsm import engines, mixed_engines, polygon2d
rock = RbsmMat(density=2000, young=1e8)
O.materials.append(rock)
O.bodies.append(polygon2d([(-5, -1), (5, -1), (5, 0), (-5, 0)], rock, fixed=True))
out = {}
for name, make in (("engines", engines), ("mixed", mixed_engines)):
    O.engines = make()
    last = O.engines[-1]
    err = None
    try:
        O.engines[-1].damping = 0.2
    except Exception as e:
        err = type(e).__name__
    out[name] = dict(last=type(last).__name__, label=last.label, err=err,
                     damping=[e.damping for e in O.engines if type(e).__name__ == "NewtonIntegrator"][0],
                     pairCheck=[type(e).__name__ for e in O.engines].index("RbsmPairCheck") < len(O.engines) - 1)
report(**out)
"""


def test_newton_is_last_and_labelled():
    (r,) = run_ok(SCRIPT)
    for name in ("engines", "mixed"):
        assert r[name] == dict(last="NewtonIntegrator", label="newton", err=None, damping=0.2, pairCheck=True), (name, r)
