"""The engines of an RBSM scene, in one call that stays readable and changeable."""
from yade import wrapper

__all__ = ["engines", "critical_time_step"]


def engines(gravity=(0, -9.81, 0), damping=0.0, contact_damping=0.0, nIP=2, safety=0.8, set_dt=True, interval=100, enlarge=0.0,
            verlet_dist=None, update_tolerance=0.0, mpi=None, sorted_loop=False):
    """YADE's simulation loop for RBSM blocks, to assign to O.engines (and edit if needed)::

        ForceResetter
        InsertionSortCollider([Bo1_Polygon2D_Aabb])             # candidate pairs
        InteractionLoop([Ig2_Polygon2D_Polygon2D_RbsmGeom],      # edge-to-edge contact
                        [Ip2_RbsmMat_RbsmMat_RbsmPhys],          # Kawai springs, joint strength
                        [Law2_RbsmGeom_RbsmPhys_MohrCoulomb])    # tractions, Mohr-Coulomb, tension cut-off
        RbsmTimeStepper                                          # stability limit of the explicit step
        NewtonIntegrator(gravity, damping)                       # central differences

    *damping* is NewtonIntegrator's non-viscous (Cundall) damping, for quasi-static stages;
    *contact_damping* the viscous damping ratio of the joints; *set_dt*: the time stepper sets O.dt
    to safety × critical step (True) or refuses a larger O.dt (False).
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
    Labels: collider, ig2, ip2, law, timeStepper, newton (and rbsmMpiSync).
    """
    import sys

    if mpi is None:
        mpi = "yade.mpy" in sys.modules
    collider = wrapper.InsertionSortCollider([wrapper.Bo1_Polygon2D_Aabb(enlarge=enlarge)], label="collider")
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
    stepper = wrapper.RbsmTimeStepper(safetyFactor=safety, setDt=set_dt, interval=interval, label="timeStepper")
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
        wrapper.NewtonIntegrator(gravity=gravity, damping=damping, label="newton"),
    ]


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
