"""The engines of an RBSM scene, in one call that stays readable and changeable."""
from yade import wrapper

from .checks import count, number

__all__ = ["engines", "critical_time_step", "advance", "time_stepper"]


def engines(gravity=(0, -9.81, 0), damping=0.0, contact_damping=0.0, nIP=2, safety=0.8, impact_safety=0.25, set_dt=True, interval=100, enlarge=0.0,
            verlet_dist=None, update_tolerance=0.0, mpi=None, sorted_loop=False, deformable=None):
    """YADE's simulation loop for RBSM blocks, to assign to O.engines (and edit if needed)::

        ForceResetter
        InsertionSortCollider([Bo1_Polygon2D_Aabb])             # candidate pairs
        InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom],      # edge-to-edge contact
                        [Ip2_RbsmMat_RbsmMat_RbsmPhys],          # Kawai springs, joint strength
                        [Law2_RbsmGeom_RbsmPhys_MohrCoulomb])    # tractions, Mohr-Coulomb, tension cut-off
        RbsmTimeStepper                                          # stability limit of the explicit step
        RbsmPairCheck                                            # no silent pass-through
        [BlockStrainIntegrator]                                  # deformable blocks only (RbsmMat.deformable)
        NewtonIntegrator(gravity, damping)                       # central differences, last (label newton)

    *damping* is NewtonIntegrator's non-viscous (Cundall) damping, for quasi-static stages;
    *contact_damping* the viscous damping ratio of the joints; *set_dt*: the time stepper sets O.dt
    to safety × critical step (True) or refuses a larger O.dt (False). *impact_safety*: the fraction
    of the critical step set while contacts can open and close (frictional joints and first contacts,
    undamped stages: RbsmTimeStepper.impactSafety; = safety for the step of earlier versions).
    *update_tolerance*: Ig2_Polygon2D_Polygon2D_RbsmGeom.updateTolerance, 0 for the exact contact
    geometry at every step, e.g. 1e-4 to follow closed joints as material points between exact
    updates (faster, overlap error O(tol²·size); docs/benchmarks.md measures the trade).
    *verlet_dist*: the collider's verletDist [m]; by default 1 % of the smallest block already in
    O.bodies (YADE's automatic value is for spheres and becomes 0 without them, which re-sorts the
    bounds at every step: 9 % of the step of a brick wall, docs/benchmarks.md).
    *mpi*: for distributed runs under yade.mpy (True by default when yade.mpy is imported): the
    PyRunner ``rbsmMpiSync`` follows RbsmTimeStepper (its ``deferErrors`` set), so that every rank
    integrates with the same O.dt (the minimum of the ranks' stable steps) and a run stopped or a
    step refused on one rank stops every rank (yade_rbsm.mpi). Serially it changes nothing.
    *sorted_loop*: InteractionLoop.loopOnSortedInteractions, the joints of a block summed in the order
    of their ids: a serial run (-j1) and a yade.mpy run (one thread per rank) then give the same
    numbers bit for bit (and so does a run continued after a save/load), at the cost of a sort every
    step; otherwise the sums follow the container's order and the runs differ by round-off, which
    a chaotic or slipping scene amplifies.
    *deformable*: put BlockStrainIntegrator (label strainIntegrator) before NewtonIntegrator, which integrates
    the strain of deformable blocks (RbsmMat.deformable, DeformableState); None (default): if a material in
    O.materials or of a body in O.bodies is deformable, so a rigid scene's list is as before (a deformable
    block without it is refused by RbsmTimeStepper at its first step, naming the body).
    Labels: collider, ig2, ip2, law, timeStepper, pairCheck (RbsmPairCheck: reports blocks next to shapes that
    no functor handles), rbsmMpiSync, strainIntegrator, and newton: NewtonIntegrator is last, YADE's habit (``O.engines[-1].damping``,
    engines appended after it see the step's positions). A Polygon2D body without RbsmMat in O.bodies raises ValueError.
    Periodic cells (O.periodic) are not supported: ValueError.
    """
    import sys

    from yade import O
    from .dispatch import check_materials
    if mpi is None:
        mpi = "yade.mpy" in sys.modules
    if O.periodic:
        raise ValueError("engines: O.periodic is set, and Polygon2D blocks do not support periodic cells")
    try:
        gravity = tuple(number("engines", "gravity[%d]" % k, gravity[k]) for k in range(3))
    except (TypeError, IndexError):
        raise ValueError("engines: gravity must be 3 finite numbers (got %r)" % (gravity,)) from None
    damping = number("engines", "damping", damping, 0, 1, high_open=True)
    contact_damping = number("engines", "contact_damping", contact_damping, 0)
    nIP = count("engines", "nIP", nIP)
    safety = number("engines", "safety", safety, 0, 1, low_open=True)
    impact_safety = number("engines", "impact_safety", impact_safety, 0, 1, low_open=True)
    interval = count("engines", "interval", interval)
    enlarge = number("engines", "enlarge", enlarge, 0)
    update_tolerance = number("engines", "update_tolerance", update_tolerance, 0, 0.1, high_open=True)
    if verlet_dist is not None:
        verlet_dist = number("engines", "verlet_dist", verlet_dist, 0)
    check_materials()  # a block without RbsmMat: ValueError now, not an abort in the loop
    # YADE's own shapes are bounded too, so that a block next to a wall, facet, sphere or box is a pair
    # RbsmPairCheck reports (this list has no functor for them: use mixed_engines()) instead of a
    # silent pass-through; without their bounds the collider never pairs them.
    collider = wrapper.InsertionSortCollider([wrapper.Bo1_Polygon2D_Aabb(enlarge=enlarge), wrapper.Bo1_Sphere_Aabb(),
                                              wrapper.Bo1_Wall_Aabb(), wrapper.Bo1_Facet_Aabb(), wrapper.Bo1_Box_Aabb()],
                                             label="collider")
    if verlet_dist is None:
        verlet_dist = 0.01 * _smallest_block()
    if verlet_dist > 0:
        collider.verletDist = verlet_dist
    loop = wrapper.InteractionLoop(
        [wrapper.Ig2_Polygon2D_Polygon2D_RbsmGeom(nIP=nIP, updateTolerance=update_tolerance, label="ig2")],
        [wrapper.Ip2_RbsmMat_RbsmMat_RbsmPhys(label="ip2")],
        [wrapper.Law2_RbsmGeom_RbsmPhys_MohrCoulomb(dampingRatio=contact_damping, label="law")],
    )
    if sorted_loop:
        loop.loopOnSortedInteractions = True
    stepper = wrapper.RbsmTimeStepper(safetyFactor=safety, impactSafety=impact_safety, setDt=set_dt, interval=interval,
                                      label="timeStepper")
    strain = strain_integrator(deformable)
    sync = []
    if mpi:
        from .mpi import sync_engine


        stepper.deferErrors = True
        sync = [sync_engine()]
    return [
        wrapper.ForceResetter(),
        collider,
        loop,
        stepper,
    ] + sync + [
        wrapper.RbsmPairCheck(label="pairCheck"),  # blocks next to shapes no functor handles: reported, run stopped
    ] + strain + [
        wrapper.NewtonIntegrator(gravity=gravity, damping=damping, label="newton"),  # last, as in YADE's scripts
    ]


def strain_integrator(deformable=None):
    """[BlockStrainIntegrator(label="strainIntegrator")] for a scene with deformable blocks, else []:
    *deformable* True or False, or None to look at O.materials and the materials of O.bodies."""
    from yade import O

    if deformable is None:
        mats = list(O.materials) + [b.material for b in O.bodies if b is not None and b.material is not None]
        deformable = any(getattr(m, "deformable", False) for m in mats)
    return [wrapper.BlockStrainIntegrator(label="strainIntegrator")] if deformable else []


def _smallest_block():
    """Smallest circumradius of the Polygon2D blocks in O.bodies [m] (0 if there are none)."""
    from yade import O

    sizes = [b.shape.circumradius for b in O.bodies if isinstance(b.shape, wrapper.Polygon2D) and b.shape.circumradius > 0]
    return min(sizes) if sizes else 0.0


def critical_time_step():
    """Critical time step [s] of the scene as it is now, as RbsmTimeStepper bounds it: the smaller of
    the joints' step and the first contacts' step (the stiffest joint each free block can form),
    divided by √(1 + NewtonIntegrator.damping) of O.engines. ``O.dt = 0.8 * critical_time_step()``
    is the step RbsmTimeStepper allows at its default safety 0.8 (inf: no two blocks can meet).
    RbsmTimeStepper().estimate() gives the joints' undamped step alone. Collective on a scene split
    by yade.mpy (the minimum over the ranks: call it on every rank)."""
    from . import mpi

    limit = wrapper.RbsmTimeStepper(safetyFactor=1).limit()
    return mpi.allreduce_min([limit])[0] if mpi.is_split() else limit


def advance(n):
    """Runs *n* steps in the calling thread and returns when they are done, like ``O.run(n, True)``
    but without its idle waits: ``O.run(n, True)`` polls the background run every 40 ms (YADE's
    ``O.wait()``), so a helper that checks the scene every few steps spent most of its time asleep
    (docs/benchmarks.md, "Idle waits"). Raises RuntimeError when a step is stopped by a report of the
    plugin (a block moving too far in one step, a pair of bodies it cannot handle: the message is on
    stderr), where ``O.run`` would have returned early and the caller gone on. Unlike ``O.run`` it does not
    stop for ``O.pause()`` or ``O.stopAtTime``, and a PyRunner that sets ``O.stopAtIter`` to the next step is
    taken as such a report (the plugin stops a run that way): helpers that run through it (``settle``,
    ``strength_reduction``) check their own conditions between chunks instead."""
    from yade import O

    if isinstance(n, bool) or not float(n).is_integer():
        raise ValueError("advance(n): n must be a whole number of steps (got %r)" % (n,))
    n = int(n)
    if n < 0:
        raise ValueError("advance(n): n must be >= 0 (got %d)" % n)
    O.stopAtIter = -1  # a report during a step sets it to the next step (rbsm_report::stopAfterThisStep)
    step = O.step
    for _ in range(n):
        step()
        if O.stopAtIter == O.iter:
            O.stopAtIter = -1
            raise RuntimeError("yade-rbsm: the run was stopped at step %d by an error of the plugin, printed on stderr "
                               "(each kind is printed 5 times per process at most)" % O.iter)


def time_stepper():
    """The RbsmTimeStepper of O.engines (by its label ``timeStepper`` from engines(), else by type),
    or None."""
    from . import omega

    try:
        return omega.engine("timeStepper")
    except LookupError:
        return None


def quiet_yade_warnings():
    """Keep only the errors of YADE's InteractionLoop and InsertionSortCollider: they warn "IGeomFunctor
    returned false on existing interaction!" each time a joint separates (thousands of lines in a
    landslide) and about verletDist in a scene without spheres."""
    from yade import log
    for name in ("InteractionLoop", "InsertionSortCollider"):
        log.setLevel(name, log.ERROR)
