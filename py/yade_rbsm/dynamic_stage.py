"""What a dynamic stage (:meth:`SlopeModel.run`) writes as it goes: a line and a PNG after each of its
parts, a VTK series of the blocks and joints, and the balance of ``O.energy`` at its end. Everything
here reads the whole scene: rank 0 of a yade.mpy run calls it on the merged scene."""
import os
import time


class DynamicOutputs:
    """*ids*: the free blocks; *snapshots*: a path prefix for the PNGs (None: none), *slip* a polyline
    drawn on them; *vtk*: a directory for the VTK series (None: none), written every *vtk_every* s of
    simulated time by a :func:`vtkexport.recorder` engine (serial runs) or else after each part;
    *energy*: track O.energy and report its balance."""

    def __init__(self, ids, snapshots=None, slip=None, vtk=None, vtk_every=None, energy=False):
        from yade import O
        from . import mpi, omega, vtkexport
        self.ids, self.prefix, self.slip, self.energy = ids, snapshots, slip, energy
        self.master, self.split = mpi.rank() == 0, mpi.distributed() is not None
        self.t0, self.balance0, self.series, self.recorder = O.time, None, None, None
        if snapshots:
            os.makedirs(os.path.dirname(snapshots) or ".", exist_ok=True)
            if self.master:
                self._png("%s_0_before.png" % snapshots, "before the dynamic stage, t = 0")
        if vtk:
            name = os.path.basename(snapshots) if snapshots else "slope"
            if vtk_every and not self.split:  # (split: a recorder would write each rank's part of the scene)
                self.recorder = vtkexport.recorder(vtk, name, virtPeriod=vtk_every, label="vtkRecorder")
                self.recorder.virtLast = O.time  # (the first snapshot is written here, at t = 0)
                O.engines = omega.before_newton(list(O.engines), self.recorder)
                self.series = vtkexport.series_of(self.recorder)
            else:
                self.series = vtkexport.series(vtk, name, resume=False)
            if self.master:
                self.series.write()
        if energy:
            O.trackEnergy = True  # (the forces and the motion are the same with it)

    def _png(self, path, title):
        from yade import O
        from .snapshots import snapshot
        snapshot(path, title, O=O, slip=self.slip)

    def started(self):
        """After the stage's first run: the energy balance counts from here (O.energy's terms are set)."""
        from yade import O
        if self.energy and self.balance0 is None:
            self.balance0 = dict(O.energy.items())

    def chunk(self, k, n, t, w0):
        """Part *k* of *n* ended at *t* s into the stage: its line, its PNG, a VTK snapshot (when no
        recorder writes them). Returns the figures of the scene now."""
        from yade import O
        from .monitor import joint_counts
        d = [(O.bodies[i].state.pos - O.bodies[i].state.refPos).norm() for i in self.ids]
        dmax = max(d, default=0.0)
        nslip, nopen, _ = joint_counts(O)
        print("  dynamic stage: t = %.3f s  max displacement %.3f m  slipping joints %d  open joints %d  (%.1f s wall)"
              % (t, dmax, nslip, nopen, time.time() - w0), flush=True)
        if self.prefix:
            self._png("%s_%d_%s.png" % (self.prefix, k + 1, "during" if k < n - 1 else "after"),
                      "dynamic stage, t = %.2f s" % t)
        if self.series is not None and self.recorder is None:
            self.series.write()
        return dict(max_displacement=dmax, mean_displacement=sum(d) / len(d) if d else 0.0,
                    slipping=nslip, open=nopen)

    def finish(self):
        """The energy balance (printed), the last VTK snapshot; the recorder leaves O.engines. Returns figures."""
        from yade import O
        figures = {}
        if self.balance0 is not None:
            # each term's change over the stage (elastPotential is a state, the others sums since trackEnergy):
            # they add up to the total's change, the error
            change = {k: v - self.balance0.get(k, 0.0) for k, v in O.energy.items()}
            work, off = -change.get("gravWork", 0.0), sum(change.values())
            terms = ", ".join("%s %.4g" % kv for kv in sorted(change.items()))
            stored = abs(self.balance0.get("elastPotential", 0.0))
            if abs(work) >= 0.1 * max(stored, max(map(abs, change.values()), default=0.0)):
                error = 100 * off / work
                print("  energy balance of the dynamic stage (changes of O.energy's terms, J/m): %s; off by %.3g %% of the "
                      "work of gravity" % (terms, error), flush=True)
            else:  # a stage where little moves: a percentage of its tiny work of gravity would read as an error
                error = 100 * off / max(stored, abs(work), 1e-300)
                print("  energy balance of the dynamic stage (changes of O.energy's terms, J/m): %s; off by %.3g J, %.3g %% "
                      "of the elastic energy stored at its start (the work of gravity, %.3g J, is too small to judge it by)"
                      % (terms, off, error, work), flush=True)
            figures["energy_error_percent"] = error
        if self.recorder is not None:
            O.engines = [e for e in O.engines if getattr(e, "label", "") != "vtkRecorder"]  # (O.engines: new wrappers)
        if self.series is not None and self.master:
            if self.series.entries["blocks"][-1][0] < O.time:
                self.series.write()  # the last state
            figures["vtk"] = sorted(self.series.pvd.values())
            figures["vtk_snapshots"] = len(self.series.entries["blocks"])
        return figures
