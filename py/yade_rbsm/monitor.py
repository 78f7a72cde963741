"""Run monitoring in YADE's idiom: a PyRunner in O.engines that records ``yade.plot`` series, and a
progress line on long runs.

::

    from yade_rbsm.monitor import Monitor
    mon = Monitor(ids=[12, 30], period=200)      # adds PyRunner(label="rbsmMonitor") to O.engines
    O.run(20000, True)
    mon.save("out/plot")                         # out/plot.png (matplotlib) + out/plot.txt (saveDataTxt)

Every *period* steps the PyRunner calls :meth:`Monitor.record`, which does ``plot.addData`` with

* ``t`` (O.time) and ``i`` (O.iter);
* ``d_<id>``: displacement magnitude |pos - refPos| of each monitored block [m], and ``dmax``, the
  largest over the monitored blocks;
* ``Ek``: kinetic energy Σ ½ m v² + ½ I ω² of the free blocks [J];
* ``unbalanced``: the unbalanced-force ratio (:func:`yade_rbsm.slope.unbalanced_ratio`: mean
  |contact force + m g| over the free blocks / mean |m g|);
* ``nSlipping``, ``nOpen``: numbers of joints slipping / open at some integration point.

``plot.plots`` gets four panels against ``t``: the displacements, ``Ek``, ``unbalanced`` and the two
joint counts. With *progress* (seconds of wall time, default 10) a line ``progress: step ...`` is
printed at most that often, with the estimated wall time left when a target (:meth:`target`) is
known. The PyRunner's command names this module and carries the Monitor's settings, so that a scene
saved with it continues after ``O.load`` in a fresh process (the Monitor is made again at its first
call there); the Monitor is also a global of ``__main__`` (``_rbsm_monitor`` by default).
"""
import math
import time

from . import omega

__all__ = ["Monitor", "kinetic_energy", "joint_counts"]

_MONITORS = {}  # PyRunner label -> the Monitor of this process


def _record(label, ids, period, progress):
    """The PyRunner's call: the Monitor of *label*, made again from its settings after O.load."""
    m = _MONITORS.get(label)
    if m is None:
        m = Monitor(ids=ids, period=period, progress=progress, label=label, install=False, reset=False)
    m.record()


def saved_monitor(O, label="rbsmMonitor"):
    """The Monitor of the recorder *label* in O.engines (a scene loaded from a file: its command, made by
    :meth:`Monitor.install`, holds the settings), or None."""
    import ast
    import re
    for e in O.engines:
        m = re.search(r"\._record\((.*)\)$", getattr(e, "command", "")) if getattr(e, "label", "") == label else None
        if m:
            label, ids, period, progress = ast.literal_eval("(%s)" % m.group(1))
            return Monitor(ids=ids, period=period, progress=progress, label=label, install=False, reset=False)
    return None


def kinetic_energy(O=None):
    if O is None:
        from yade import O
    ek = 0.0
    for b in omega.free_bodies(O):
        s = b.state
        ek += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * s.inertia[2] * s.angVel[2] ** 2
    return ek


def joint_counts(O=None):
    """(number of joints slipping somewhere, number open somewhere, number of real joints)."""
    if O is None:
        from yade import O
    ns = no = n = 0
    for I in omega.joints(O):
        n += 1
        if I.phys.nSlipping > 0:
            ns += 1
        if I.phys.nOpen > 0:
            no += 1
    return ns, no, n


class Monitor:
    def __init__(self, ids=(), period=200, progress=10.0, name="_rbsm_monitor", label="rbsmMonitor",
                 install=True, reset=True):
        from yade import plot
        self.ids = [int(i) for i in ids]
        self.period = int(period)
        self.progress = progress
        self.name, self.label = name, label
        self._last_print = time.time()
        self._t0 = time.time()
        self._target = None  # ('t' or 'i', start, end, wall0): simulated time or steps
        self.marks = []  # (t, label): stage boundaries drawn in the saved plot
        if reset:
            plot.reset()
        dnames = ["d_%d" % i for i in self.ids] + ["dmax"]
        plot.plots = {"t": tuple(dnames), "t ": ("Ek",), "t  ": ("unbalanced",), "t   ": ("nSlipping", "nOpen")}
        _MONITORS[label] = self
        if install:
            self.install()

    def install(self):
        """Register the Monitor in __main__ and put its PyRunner before NewtonIntegrator (the forces
        of the step are then complete, gravity excluded, as unbalanced_ratio expects)."""
        import __main__
        from yade import O, wrapper
        setattr(__main__, self.name, self)
        engines = [e for e in O.engines if getattr(e, "label", "") != self.label]
        # the command names this module, not a global of the script: it runs again after O.load elsewhere
        command = "__import__('yade_rbsm.monitor', fromlist=['_record'])._record(%r, %r, %d, %r)" % (
            self.label, self.ids, self.period, self.progress)
        pr = wrapper.PyRunner(command=command, iterPeriod=self.period, label=self.label)
        O.engines = omega.before_newton(engines, pr)
        return pr

    def mark(self, label):
        """Remember a stage boundary at the current O.time (a vertical line in :meth:`save`)."""
        from yade import O
        self.marks.append((O.time, label))

    def target(self, n_steps=None, time=None):
        """Announce the next stage for the progress line's estimate: *time* [s] of simulated time from now
        (the measure that holds while the time stepper changes O.dt), or *n_steps* steps."""
        from yade import O
        import time as wall
        if (n_steps is None) == (time is None):
            raise ValueError("Monitor.target: give n_steps or time")
        if time is not None:
            self._target = ("t", O.time, O.time + float(time), wall.time())
        else:
            self._target = ("i", O.iter, O.iter + int(n_steps), wall.time())

    def record(self):
        from yade import O, plot
        from .slope import unbalanced_ratio
        d = {}
        dmax = 0.0
        for i in self.ids:
            s = O.bodies[i].state
            di = (s.pos - s.refPos).norm()
            d["d_%d" % i] = di
            dmax = max(dmax, di)
        ek = kinetic_energy(O)
        ub = unbalanced_ratio()
        ns, no, n = joint_counts(O)
        plot.addData(t=O.time, i=O.iter, dmax=dmax, Ek=ek, unbalanced=ub, nSlipping=ns, nOpen=no, **d)
        now = time.time()
        if self.progress is not None and now - self._last_print >= self.progress:
            self._last_print = now
            eta = ""
            if self._target:
                kind, a, b, w0 = self._target
                x = O.time if kind == "t" else O.iter
                if b > a and x > a:
                    frac = min(1.0, (x - a) / float(b - a))  # (a stage that runs past its target: 100 %, not 226 %)
                    eta = "  %3.0f%%, about %.0f s left" % (100 * frac, (now - w0) * (1 - frac) / max(frac, 1e-9))
            print("progress: step %d  t = %.4f s  dmax %.3e m  Ek %.3e J  unbalanced %.2e  slipping %d  open %d "
                  "(of %d joints)  %.0f s wall%s" % (O.iter, O.time, dmax, ek, ub, ns, no, n, now - self._t0, eta),
                  flush=True)

    def save(self, base, title="RBSM run"):
        """``base``.txt (plot.saveDataTxt) and ``base``.png (matplotlib, 4 panels). Returns the
        paths."""
        from yade import plot
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        txt = base + ".txt"
        plot.saveDataTxt(txt)
        data = plot.data
        t = data.get("t", [])
        # fixed margins: tight_layout measured every tick label and took half of the time
        fig, axs = plt.subplots(4, 1, figsize=(8, 10), sharex=True,
                                gridspec_kw=dict(left=0.11, right=0.97, bottom=0.05, top=0.96, hspace=0.08))
        for k in ["d_%d" % i for i in self.ids] + ["dmax"]:
            if k in data:
                axs[0].plot(t, data[k], "k:" if k == "dmax" else "-", label=k, lw=2 if k == "dmax" else 1)
        axs[0].set_ylabel("displacement [m]")
        axs[0].legend(fontsize=7, ncol=4)
        axs[1].plot(t, data.get("Ek", []), "k")
        axs[1].set_ylabel("kinetic energy [J]")
        ub = [max(u, 1e-12) for u in data.get("unbalanced", [])]
        axs[2].semilogy(t, ub, "b")
        axs[2].set_ylabel("unbalanced force ratio")
        axs[3].plot(t, data.get("nSlipping", []), "r", label="slipping")
        axs[3].plot(t, data.get("nOpen", []), "g", label="open")
        axs[3].set_ylabel("joints")
        axs[3].legend(fontsize=8)
        axs[3].set_xlabel("t [s]")
        axs[0].set_title(title)
        for a in axs:
            a.grid(alpha=0.3)
            for tm, lab in self.marks:
                a.axvline(tm, color="0.5", ls="--", lw=0.8)
        for tm, lab in self.marks:
            axs[0].annotate(lab, (tm, 1), xycoords=("data", "axes fraction"), fontsize=7, ha="left", va="top",
                            rotation=90, color="0.3")
        png = base + ".png"
        fig.savefig(png, dpi=100)
        plt.close(fig)
        return png, txt
