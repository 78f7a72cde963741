"""The simulation loop of a mixed scene: Polygon2D blocks with YADE's spheres, walls and facets."""
from yade import wrapper


def mixed_engines(gravity=(0, -9.81, 0), damping=0.0, contact_damping=0.0, nIP=2, safety=0.8, interval=100,
                  verlet_dist=None, update_tolerance=0.0, deformable=None):
    """YADE's simulation loop for blocks together with spheres, walls and facets, to assign to O.engines::

        ForceResetter
        InsertionSortCollider([Bo1_Polygon2D_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, Bo1_Facet_Aabb, Bo1_Box_Aabb])
        InteractionLoop(
            [Ig2_Polygon2D_Polygon2D_RbsmGeom, Ig2_Polygon2D_Wall_RbsmGeom, Ig2_Polygon2D_Facet_RbsmGeom,   # block edges
             Ig2_Polygon2D_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,                 # point contacts
             Ig2_Facet_Sphere_ScGeom, Ig2_Box_Sphere_ScGeom],
            [Ip2_RbsmMat_RbsmMat_RbsmPhys, Ip2_RbsmMat_FrictMat_FrictPhys, Ip2_FrictMat_FrictMat_FrictPhys],
            [Law2_RbsmGeom_RbsmPhys_MohrCoulomb,                     # block joints, also on walls and facets
             Law2_ScGeom_FrictPhys_CundallStrack(sphericalBodies=False)])   # spheres (true torques on blocks)
        RbsmTimeStepper
        RbsmPairCheck                 # blocks next to shapes no functor handles (a Box): reported, run stopped
        [BlockStrainIntegrator]       # deformable blocks only (engines(deformable=...))
        NewtonIntegrator(gravity, damping)   # last, as in YADE's scripts

    The arguments are engines()'s. The time stepper counts the block joints only (also those on walls and
    facets; sphere contacts follow YADE's own laws), so when O.bodies holds spheres O.dt is set here to
    *safety* × their P-wave step min r √(ρ/E) (YADE's PWaveTimeStep, also for spheres of RbsmMat) and the
    stepper's maxDt is that step: it sets O.dt to the blocks' stable step, never above it. Labels as engines(): collider, ig2, ip2, law, timeStepper, newton, plus
    ig2Sphere, ip2Frict, lawSphere, pairCheck. Raises ValueError for a Polygon2D without RbsmMat, or spheres of
    both RbsmMat and FrictMat (yade_rbsm.dispatch.check_materials).
    """
    from yade import O
    from .scene import _smallest_block, strain_integrator
    from .dispatch import check_materials

    check_materials()

    spheres = [b for b in O.bodies if isinstance(b.shape, wrapper.Sphere)]
    collider = wrapper.InsertionSortCollider([wrapper.Bo1_Polygon2D_Aabb(), wrapper.Bo1_Sphere_Aabb(), wrapper.Bo1_Wall_Aabb(),
                                              wrapper.Bo1_Facet_Aabb(), wrapper.Bo1_Box_Aabb()], label="collider")
    if verlet_dist is None:
        sizes = [s for s in [0.01 * _smallest_block(), 0.1 * min((b.shape.radius for b in spheres), default=0)] if s > 0]
        verlet_dist = min(sizes, default=0)
    if verlet_dist > 0:
        collider.verletDist = verlet_dist
    if spheres:
        O.dt = safety * min(b.shape.radius * (b.material.density / b.material.young) ** 0.5 for b in spheres)
    return [
        wrapper.ForceResetter(),
        collider,
        wrapper.InteractionLoop(
            [wrapper.Ig2_Polygon2D_Polygon2D_RbsmGeom(nIP=nIP, updateTolerance=update_tolerance, label="ig2"),
             wrapper.Ig2_Polygon2D_Wall_RbsmGeom(nIP=nIP), wrapper.Ig2_Polygon2D_Facet_RbsmGeom(nIP=nIP),
             wrapper.Ig2_Polygon2D_Sphere_ScGeom(label="ig2Sphere"), wrapper.Ig2_Sphere_Sphere_ScGeom(),
             wrapper.Ig2_Wall_Sphere_ScGeom(), wrapper.Ig2_Facet_Sphere_ScGeom(), wrapper.Ig2_Box_Sphere_ScGeom()],
            [wrapper.Ip2_RbsmMat_RbsmMat_RbsmPhys(label="ip2"), wrapper.Ip2_RbsmMat_FrictMat_FrictPhys(label="ip2Frict"),
             wrapper.Ip2_FrictMat_FrictMat_FrictPhys()],
            [wrapper.Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=contact_damping, label="law"),
             wrapper.Law2_ScGeom_FrictPhys_CundallStrack(sphericalBodies=False, label="lawSphere")],
        ),
        wrapper.RbsmTimeStepper(safetyFactor=safety, setDt=True, maxDt=O.dt if spheres else float("inf"), interval=interval,
                                label="timeStepper"),
        wrapper.RbsmPairCheck(label="pairCheck"),
    ] + strain_integrator(deformable) + [
        wrapper.NewtonIntegrator(gravity=gravity, damping=damping, label="newton"),  # last, as in YADE's scripts
    ]
