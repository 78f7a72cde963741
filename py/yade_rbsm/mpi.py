"""Distributed RBSM runs with YADE's own MPI domain decomposition, ``yade.mpy``.

yade.mpy splits a scene by ``Body.subdomain``: rank 0 (the master) keeps the bodies of subdomain 0
(typically the fixed ones) and collects the forces on them; each worker rank k integrates the blocks
of subdomain k, holding copies of its neighbours' blocks near its borders, which it receives after
every step. What RBSM needs on top of that, and this module adds:

* one time step for every rank: ``RbsmTimeStepper`` on a worker bounds the step of the blocks that
  rank owns (they have all their joints there), and the sync engine (:func:`sync_engine`, placed
  right after the stepper by ``engines(mpi=True)``) sets ``O.dt`` on every rank to the minimum of the
  ranks' steps (``RbsmTimeStepper.stepDt``), before NewtonIntegrator: one MPI_Allreduce of three
  numbers per step;
* a run that stops on one rank stops on all: the same reduction carries ``O.stopAtIter`` (a block
  reported for moving too far, mixed plane states: the plugin stops the run after the step on the
  rank that found it, and every rank then stops after the same step) and a step refused by
  ``RbsmTimeStepper`` (``deferErrors``: the refusal is kept on its rank, and every rank raises
  ``RuntimeError`` before NewtonIntegrator, with the message of the rank that found it);
* :func:`decompose_by_x`: subdomains as vertical slices holding equal numbers of blocks;
* :func:`mpirun`: ``yade.mpy.mpirun`` that checks the above and, when an error that no other rank
  knows about leaves the run on one rank (a Python error in a user's PyRunner, ...), aborts the MPI
  job (MPI_Abort) instead of leaving the other ranks waiting for it;
* :func:`rank_states`, :func:`to_serial`: per-rank time and step; the merged scene made serial;
* a script that ends with an error on one rank under ``mpiexec`` (a value refused before the run on that
  rank alone) aborts the MPI job (:func:`abort_on_abnormal_exit`, set when the package is imported).

Usage (the same script runs on every rank: ``mpiexec -n 3 yade-rbsm -n -x script.py``, or started
plainly with ``mpy.initialize(3)`` at the top, which spawns the workers running the same script)::

    from yade import mpy
    import yade_rbsm as yr, yade_rbsm.mpi as rm
    ... build the blocks ...
    O.engines = yr.engines(mpi=True)   # default when yade.mpy is imported before engines()
    rm.decompose_by_x()                # or mpy.DOMAIN_DECOMPOSITION = True (YADE's bisection)
    rm.distribute()                    # split before any joint is made (bonding, settling: see distribute)
    rm.mpirun(1000, with_merge=True)   # then on rank 0: the whole scene, for post-processing
"""
import math
import sys

SYNC_LABEL = "rbsmMpiSync"
SYNC_COMMAND = "__import__('yade_rbsm.mpi').mpi.sync()"

_refused = None  # (rank that refused, message raised here) of the last refusal sync() raised on every rank
_alone = False  # to_serial() was called: this rank (0) goes on without the others
_exit_check = False  # abort_on_abnormal_exit() registered


def _O():
    from yade import O

    return O


def _mpy():
    """yade.mpy if it is imported and the scene is split over more than one rank, else None."""
    mp = sys.modules.get("yade.mpy")
    if mp is None or mp.comm is None or not mp.numThreads or mp.numThreads < 2:
        return None
    if not getattr(_O(), "splitted", False):
        return None
    return mp


def is_split():
    """Whether the scene is split over yade.mpy's ranks now (between the first mpirun and a merge)."""
    return _mpy() is not None


def _stepper(engines):
    for e in engines:
        if type(e).__name__ == "RbsmTimeStepper":
            return e
    return None


def sync_engine():
    """The PyRunner that follows RbsmTimeStepper in a distributed run (label ``rbsmMpiSync``): every
    step it calls :func:`sync`. Outside a split scene it only raises a refusal the stepper kept."""
    from yade import wrapper

    return wrapper.PyRunner(iterPeriod=1, initRun=True, command=SYNC_COMMAND, label=SYNC_LABEL)


def sync():
    """One time step and one stopping decision for every rank; runs after RbsmTimeStepper and before
    NewtonIntegrator (the sync engine calls it every step).

    Each rank contributes the step its RbsmTimeStepper chose (``stepDt``, inf with setDt=False or
    when it owns no block), its ``O.stopAtIter`` if the run is to stop earlier than planned, and
    whether its stepper refused the step (``error``); one MPI_Allreduce(MIN) of the three. O.dt
    becomes the smallest step (unless none bounds it), O.stopAtIter the earliest stop; a refusal on
    any rank raises RuntimeError on every rank (its message on the rank that found it, "refused on
    rank k: message" on the others) before anything moves."""
    global _refused
    O = _O()
    ts = _stepper(O.engines)
    err = ts.error if ts is not None else ""
    mp = _mpy()
    if ts is not None:
        ts.syncedAt = O.iter  # (the stepper of a split scene checks that this ran in every step)
        if mp is not None:
            _check_sync_place(O.engines, ts)
    if mp is None:  # serial: the stepper's own behaviour
        if err:
            ts.error = ""
            _refused = (0, err)
            raise RuntimeError(err)
        return
    import numpy as np

    inf = math.inf
    local = np.array([ts.stepDt if (ts is not None and ts.setDt and not err) else inf,
                      float(O.stopAtIter) if O.stopAtIter > O.iter else inf,
                      -1.0 if err else 0.0])
    glob = np.empty(3)
    mp.comm.Allreduce(local, glob, op=mp.MPI.MIN)
    if math.isfinite(glob[0]):
        O.dt = float(glob[0])
        if ts is not None and ts.setDt:
            ts.dtSet = O.dt  # the ranks' step, not a script's (RbsmTimeStepper.setDt)
    if glob[2] < 0:  # a refusal somewhere: every rank stops here, before NewtonIntegrator
        msgs = mp.comm.allgather(err)
        if ts is not None:
            ts.error = ""
        rank = next(r for r, m in enumerate(msgs) if m)
        _refused = (rank, err or "yade-rbsm: the step was refused on rank %d; every rank stops: %s" % (rank, msgs[rank]))
        raise RuntimeError(_refused[1])
    if math.isfinite(glob[1]) and int(glob[1]) != O.stopAtIter:
        O.stopAtIter = int(glob[1])


def _check_sync_place(engines, ts):
    """The sync engine between RbsmTimeStepper (whose step it shares) and NewtonIntegrator (which takes it):
    before the stepper it shared the last step's, after Newton the ranks had already moved by their own (one
    rank integrated at 8-11 times the others' step). Every rank has the same list: each raises the same."""
    names = [(getattr(e, "label", ""), type(e).__name__) for e in engines]
    here = next(i for i, (label, _) in enumerate(names) if label == SYNC_LABEL)
    stepper = engines.index(ts)
    newton = next((i for i, (_, kind) in enumerate(names) if kind == "NewtonIntegrator"), len(engines))
    if not stepper < here < newton:
        raise RuntimeError("yade_rbsm.mpi: the sync engine (label %r) is at place %d of O.engines, but must come right "
                           "after RbsmTimeStepper (place %d) and before NewtonIntegrator (place %d): the ranks would not "
                           "share one O.dt. Build the engines with yade_rbsm.engines(mpi=True) (or yade_rbsm.mpi.with_sync)"
                           % (SYNC_LABEL, here, stepper, newton))


def _abort_if_ended_early():
    """At interpreter exit of a process that yade started in MPI mode: if MPI is still running, the script did
    not end the way yade ends an MPI run (workers released by rank 0, then MPI_Finalize): it raised (yade -x
    exits with status 1) or called sys.exit. The other ranks would wait for it for ever (this one too, in
    MPI_Finalize's fence): abort the job instead."""
    mp = sys.modules.get("yade.mpy")
    if mp is None or mp.MPI.Is_finalized() or not mp.numThreads or mp.numThreads < 2:
        return
    sys.stdout.flush()
    sys.stderr.write("yade-rbsm: rank %d: the script ended with an error; aborting the MPI job so that the other "
                     "ranks do not wait for it (its traceback is above)\n" % mp.rank)
    sys.stderr.flush()
    mp.MPI.COMM_WORLD.Abort(1)


def abort_on_abnormal_exit():
    """Registers the exit check above once, in a process that yade runs in MPI mode (under ``mpiexec``, or a
    worker spawned by ``mpy.initialize``); nothing elsewhere. mpi4py finalizes MPI after Python's exit
    handlers, so the check runs while MPI is up."""
    global _exit_check
    import os

    if _exit_check or os.getenv("OMPI_COMM_WORLD_RANK") is None:
        return
    import atexit

    atexit.register(_abort_if_ended_early)
    _exit_check = True


def with_sync(engines):
    """A copy of the engine list with the sync engine right after RbsmTimeStepper and the stepper's
    deferErrors set (no change if it is there already). ValueError without a RbsmTimeStepper."""
    engines = list(engines)
    ts = _stepper(engines)
    if ts is None:
        raise ValueError("yade_rbsm.mpi: O.engines has no RbsmTimeStepper (use yade_rbsm.engines(mpi=True))")
    i = engines.index(ts)
    nxt = engines[i + 1] if i + 1 < len(engines) else None
    if not (type(nxt).__name__ == "PyRunner" and nxt.command == SYNC_COMMAND):
        engines.insert(i + 1, sync_engine())
    ts.deferErrors = True
    return engines


def decompose_by_x(workers=None, fixed_to_master=True):
    """Assigns the Polygon2D blocks to the workers as vertical slices: sorted by the x of their
    centroid (then y, then id), cut into ``workers`` runs of equal numbers of blocks, worker k
    (Body.subdomain = k, 1 ≤ k ≤ workers) getting the k-th from the left. Fixed blocks go to the
    master (subdomain 0) with ``fixed_to_master`` (they only collect forces there), else with the
    free ones. Other bodies are left as they are. ``workers`` defaults to yade.mpy's ranks − 1.
    Returns the list of the x ranges [(xmin, xmax)] of the slices' centroids.
    Call it on every rank before the first mpirun (every rank builds the same scene), or only on
    rank 0 (its scene is the one yade.mpy sends to the workers)."""
    O = _O()
    if workers is None:
        mp = sys.modules.get("yade.mpy")
        if mp is None or not mp.numThreads:
            raise ValueError("yade_rbsm.mpi.decompose_by_x: give workers= (yade.mpy is not initialised)")
        workers = mp.numThreads - 1
    if not (isinstance(workers, int) and workers >= 1):
        raise ValueError("yade_rbsm.mpi.decompose_by_x: workers must be an integer >= 1 (got %r)" % (workers,))
    blocks = []
    for b in O.bodies:
        if b is None or type(b.shape).__name__ != "Polygon2D":
            continue
        if fixed_to_master and b.state.blockedDOFs == "xyzXYZ":
            b.subdomain = 0
            continue
        blocks.append((b.state.pos[0], b.state.pos[1], b.id))
    blocks.sort()
    if len(blocks) < workers:
        raise ValueError("yade_rbsm.mpi.decompose_by_x: %d blocks for %d workers" % (len(blocks), workers))
    ranges = []
    for k in range(workers):
        part = blocks[k * len(blocks) // workers:(k + 1) * len(blocks) // workers]
        for x, y, i in part:
            O.bodies[i].subdomain = k + 1
        ranges.append((part[0][0], part[-1][0]))
    return ranges


def start(ranks=0, quiet_workers=True):
    """Collective: a distributed run of the calling script with yade.mpy. Under ``mpiexec -n N`` (or in a
    worker yade.mpy spawned) the job's N ranks, and *ranks* must be 0 or N; started plainly, *ranks* (>= 2)
    ranks: rank 0 spawns ranks - 1 workers running the same script (yade.mpy's ``initialize``). Waiting
    ranks yield the CPU (3 ranks on 2 cores), and with *quiet_workers* only rank 0 prints (errors still
    show: yade.mpy sends stderr to the terminal). Returns yade.mpy."""
    import os
    os.environ.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    from yade import mpy as mp
    if not isinstance(ranks, int) or isinstance(ranks, bool) or ranks < 0:
        raise ValueError("yade_rbsm.mpi.start: ranks must be an integer >= 0 (got %r)" % (ranks,))
    if mp.numThreads is None or mp.numThreads < 2:  # not under mpiexec, not a spawned worker
        if ranks < 2:
            raise ValueError("yade_rbsm.mpi.start: give ranks >= 2 (got %d), or start the script with mpiexec -n N" % ranks)
        mp.initialize(ranks)
    elif ranks not in (0, mp.numThreads):
        raise ValueError("yade_rbsm.mpi.start: ranks = %d but the job has %d MPI ranks" % (ranks, mp.numThreads))
    if quiet_workers and mp.rank != 0:
        sys.stdout = open(os.devnull, "w")
    return mp


def mpirun(steps, with_merge=False):
    """``yade.mpy.mpirun(steps, withMerge=with_merge)`` for an RBSM scene: before the first split it
    puts the sync engine after RbsmTimeStepper if ``O.engines`` lacks it (:func:`with_sync`); a
    refused step raises RuntimeError on every rank (see :func:`sync`); any other error that leaves
    the run on this rank alone is printed and ends the MPI job (MPI_Abort, exit status 1): the other
    ranks would otherwise wait for this one forever; a run the plugin stops early (a report on any rank:
    every rank stops after the same step) raises RuntimeError on every rank, as :func:`yade_rbsm.advance`
    does serially. Without yade.mpy's ranks (one process) it is ``O.run(steps, True)``."""
    global _refused
    from yade import mpy as mp

    _prepare_split()
    _refused = None
    end = _O().iter + int(steps)
    try:
        mp.mpirun(steps, withMerge=with_merge)
    except Exception:
        if _refused is not None or mp.comm is None or not mp.numThreads or mp.numThreads < 2:
            raise  # every rank raises the same refusal (or there are no other ranks)
        import traceback

        sys.stdout.flush()
        sys.stderr.write("yade-rbsm: rank %d: an error ended the run on this rank only; aborting the MPI job "
                         "so that the other ranks do not wait for it:\n%s" % (mp.rank, traceback.format_exc()))
        sys.stderr.flush()
        mp.comm.Abort(1)
    if _refused is not None:  # raised in the run's first step, lost by YADE's O.wait() (the run ended before it)
        raise RuntimeError(_refused[1])
    if _O().iter < end:  # stopped early: a report of the plugin on some rank (the sync stops every rank there)
        raise RuntimeError("yade-rbsm: the run was stopped at step %d by an error of the plugin, printed on stderr "
                           "by the rank that found it (as yade_rbsm.advance raises serially)" % _O().iter)


def distributed():
    """yade.mpy if it is imported with more than one rank (under mpiexec, or after
    ``mpy.initialize(n)``), else None: then :func:`run` runs distributed. None on rank 0 after
    :func:`to_serial` (the workers have left: a stage there, ``settle``, waited for them forever)."""
    if _alone:
        return None
    mp = sys.modules.get("yade.mpy")
    if mp is None or mp.comm is None or not mp.numThreads or mp.numThreads < 2:
        return None
    return mp


def check_one_subdomain(where):
    """Outside yade.mpy's ranks (serially, or on rank 0 after :func:`to_serial`): ValueError if a body is
    not in subdomain 0. YADE's NewtonIntegrator moves only the bodies of Scene.subdomain, so the blocks
    of a scene merged from the ranks and saved without to_serial stayed frozen when the file was run
    serially, silently (a new user's settle "did not converge", ratio 1.79, nothing moving)."""
    if distributed() is not None:
        return
    O = _O()
    n = sum(1 for b in O.bodies if b is not None and b.subdomain != 0)
    if n:
        raise ValueError("%s: %d bodies are in yade.mpy subdomains other than 0 (a scene merged from the ranks and saved "
                         "without to_serial?): NewtonIntegrator would not move them; call yade_rbsm.mpi.to_serial() "
                         "first" % (where, n))


def rank():
    """This process's yade.mpy rank (0 without yade.mpy)."""
    mp = distributed()
    return mp.rank if mp is not None else 0


def run(steps, with_merge=False):
    """``steps`` steps of the scene: :func:`mpirun` when distributed, else :func:`yade_rbsm.advance`
    (no idle waits). The helpers that run stages (``slope.settle``) go through it, so the same script
    runs serially and under yade.mpy (every rank calls it)."""
    if distributed() is None:
        from .scene import advance

        advance(steps)
    else:
        mpirun(steps, with_merge=with_merge)


def merge():
    """Collective: ``yade.mpy.mergeScene()`` if the scene is split (rank 0 then holds every block and
    joint, for post-processing: factor of safety, snapshots, VTK). A later :func:`run` splits it
    again (changes made to the merged scene on rank 0 do not reach the workers)."""
    mp = _mpy()
    if mp is not None:
        mp.mergeScene()


def owned(b):
    """Whether this rank integrates body ``b`` (always outside a split scene)."""
    return _mpy() is None or b.subdomain == _O()._sceneObj.subdomain


def counted_here(I):
    """For counting joints over a split scene without counting twice: a joint between blocks of
    subdomains a and b is computed on the workers a and b (both hold it) and counted on max(a, b)
    only (so a joint with a fixed block of the master, subdomain 0, on its worker). Always true
    outside a split scene."""
    if _mpy() is None:
        return True
    O = _O()
    b1, b2 = O.bodies[I.id1], O.bodies[I.id2]
    return b1 is not None and b2 is not None and max(b1.subdomain, b2.subdomain) == O._sceneObj.subdomain


def _allreduce(mp, values, op):
    """The element-wise MPI reduction *op* of a list of floats over the ranks of *mp* (the list itself
    without one)."""
    if mp is None:
        return list(values)
    import numpy as np

    local = np.array(values, dtype=float)
    out = np.empty_like(local)
    mp.comm.Allreduce(local, out, op=op(mp))
    return [float(v) for v in out]


def allreduce_min(values):
    """Collective when the scene is split: the element-wise minimum over the ranks (the list itself
    otherwise)."""
    return _allreduce(_mpy(), values, lambda mp: mp.MPI.MIN)


def allreduce_sum(values):
    """Collective when distributed: the element-wise sum over the ranks of a list of floats
    (the list itself serially)."""
    return _allreduce(distributed(), values, lambda mp: mp.MPI.SUM)


def joints_across():
    """Number of real RBSM joints whose two blocks are in different subdomains (Body.subdomain)."""
    O = _O()
    n = 0
    for I in O.interactions:
        if not I.isReal or type(I.phys).__name__ != "RbsmPhys":
            continue
        b1, b2 = O.bodies[I.id1], O.bodies[I.id2]
        if b1 is not None and b2 is not None and b1.subdomain != b2.subdomain:
            n += 1
    return n


def _prepare_split():
    """Before the first split: the sync engine, and no joint across subdomains (see distribute)."""
    O = _O()
    if getattr(O, "splittedOnce", False):
        if not any(type(e).__name__ == "PyRunner" and e.command == SYNC_COMMAND for e in O.engines):
            raise RuntimeError("yade_rbsm.mpi: the scene was split without the sync engine; "
                               "build O.engines with yade_rbsm.engines(mpi=True) before the first mpirun")
        return
    O.engines = with_sync(O.engines)
    n = joints_across()
    if n:
        raise ValueError(
            "yade_rbsm.mpi: %d RBSM joints connect blocks of different subdomains. yade.mpy does not carry joints "
            "across subdomain borders when it splits a scene: it erases each rank's copies of the other ranks' "
            "blocks and sends them again without their joints, which are then made anew (unbonded, without their "
            "slip, opening and shear history). Split the scene before the joints are made: assign the subdomains "
            "and call yade_rbsm.mpi.distribute() (or run the first steps with yade_rbsm.mpi.mpirun) before "
            "bonding (Ip2.setCohesionNow, yade_rbsm.slope.bond_and_break) or settling." % n)


def distribute():
    """Collective: splits the scene over yade.mpy's ranks now, without running a step (what the first
    mpirun does first): every rank keeps its blocks and copies of its neighbours' near its borders.
    Checks first that the sync engine is there (inserted if not) and that no RBSM joint connects blocks
    of different subdomains (ValueError: yade.mpy would make such joints anew, losing their bond and
    history; so bond, break and settle after this call). No-op serially or when already split."""
    mp = distributed()
    if mp is None or getattr(_O(), "splitted", False):
        return
    _prepare_split()
    mp.splitScene()


def rank_states():
    """[(O.time, O.iter, O.dt)] of every rank, in rank order (collective: call it on every rank)."""
    O = _O()
    mine = (O.time, O.iter, O.dt)
    mp = sys.modules.get("yade.mpy")
    if mp is None or mp.comm is None or not mp.numThreads or mp.numThreads < 2:
        return [mine]
    return mp.comm.allgather(mine)


def to_serial():
    """On rank 0 after ``mergeScene`` (``mpirun(..., with_merge=True)``): makes the merged scene an
    ordinary serial one, for a stage run with O.run on the master alone (strength reduction, a probe):
    every body back to subdomain 0 (YADE's NewtonIntegrator moves only the bodies of
    Scene.subdomain, 0 outside yade.mpy) and the Subdomain bodies that yade.mpy inserted erased.
    Afterwards this scene cannot be split again (build a new one for another distributed run).
    Rank 0's RbsmTimeStepper only knew the blocks of rank 0: its next run is a full estimate of the
    merged scene (RbsmTimeStepper.checkNextStep()), so the next step is bounded by every joint. (A
    serial run makes its full estimates every ``interval`` steps from step 0 and adds the joints made
    in between, so the two continue with slightly different steps unless interval=1, when the
    continuation is the serial run bit for bit with sorted loops: tests/mpi/test_rows.py.)
    Reading the merged scene (positions, contact forces, factor of safety, snapshots, VTK) needs
    none of this."""
    global _alone
    O = _O()
    _alone = True  # run(), settle() and the other helpers go on serially here
    for b in list(O.bodies):
        if b is None:
            continue
        if type(b.shape).__name__ == "Subdomain":
            O.bodies.erase(b.id)
        else:
            b.subdomain = 0
    O._sceneObj.subdomain = 0
    O.splitted = False
    for e in O.engines:
        if type(e).__name__ == "RbsmTimeStepper":
            e.checkNextStep()
