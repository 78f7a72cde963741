"""Uniform-strain patch test: nx x ny bonded unit squares (size a), no integrator (positions imposed).
Step 1 makes the bonded contacts at zero strain; then every block gets the affine displacement
u(X) (translation only, no rotation), positions set to X + u and velocities to u/dt (the shear spring is
incremental, Δus = relative tangential velocity · dt), and one more step computes the tractions.
params: mode 'uniaxial' (u = (eps·x, 0)) or 'shear' (pure shear u = (γ/2·y, γ/2·x)), strain, planeStrain,
E, nu, nx, ny, a. Returns per interaction: ids, normal, length, normalTraction, shearTraction, kn, ks.
Param ut: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance (default 0, exact geometry)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from _common import params, emit
from yade_rbsm import polygon2d

p = params()
E, nu, a = p.get("E", 3e10), p.get("nu", 0.25), p.get("a", 1.0)
nx, ny = p.get("nx", 4), p.get("ny", 4)
mode, s = p.get("mode", "uniaxial"), p.get("strain", 1e-4)
mat = RbsmMat(young=E, poisson=nu, density=2500, planeStrain=p.get("planeStrain", True), frictionAngle=0.6,
              cohesion=1e9, tensileStrength=1e9)
O.materials.append(mat)
ref = {}
for i in range(nx):
    for j in range(ny):
        x0, y0 = 10 + i * a, 20 + j * a
        bid = O.bodies.append(polygon2d([(x0, y0), (x0 + a, y0), (x0 + a, y0 + a), (x0, y0 + a)], mat))
        ref[bid] = (x0 + a / 2, y0 + a / 2)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polygon2D_Aabb(enlarge=0.01 * a)]),
             InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom(interactionDistance=1e-6 * a, updateTolerance=p.get("ut", 0.0))],
                             [Ip2_RbsmMat_RbsmMat_RbsmPhys(setCohesionNow=True)],
                             [Law2_RbsmGeom_RbsmPhys_MohrCoulomb()])]
O.dt = 1e-3
O.step()
n0 = sum(1 for i in O.interactions if i.isReal)
for bid, (x, y) in ref.items():
    u = (s * x, 0.0) if mode == "uniaxial" else (0.5 * s * y, 0.5 * s * x)
    # displacement relative to the patch's first block corner keeps numbers small; affine anyway
    b = O.bodies[bid]
    b.state.pos = (x + u[0], y + u[1], 0)
    b.state.vel = (u[0] / O.dt, u[1] / O.dt, 0)
O.step()
out = []
for i in O.interactions:
    if not i.isReal:
        continue
    g, ph = i.geom, i.phys
    out.append({"ids": [i.id1, i.id2], "normal": [g.normal[0], g.normal[1]], "length": g.length,
                "sn": list(ph.normalTraction), "tau": list(ph.shearTraction), "kn": ph.kn, "ks": ph.ks,
                "intact": list(ph.intactPoints)})
emit({"n0": n0, "joints": out})
