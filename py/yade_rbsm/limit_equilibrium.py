"""Two-dimensional limit-equilibrium slope stability (method of slices).

Pure Python + numpy: this module does not need YADE and can be imported both
from plain Python (tests, post-processing) and from inside a yade script.

It is used to put a classical limit-equilibrium factor of safety next to the
RBSM one, as in Table 2 of the seed paper (Yagi & Takeuchi, "Application of an
explicit dynamic method for discontinuous analysis by using rigid
bodies-spring model"), which lists shear force, normal force and factor of
safety along the slip surface for RBSM and for Fellenius.

Units and conventions
---------------------
* lengths in m, unit weights ``gamma`` in kN/m^3, cohesion ``c`` and pore
  pressure ``u`` in kPa (= kN/m^2); all forces are therefore kN per metre of
  slope width (kN/m).  Any consistent unit set works (e.g. N, Pa, N/m^3) as
  long as ``gamma_w`` is given in the same set.
* angles are in degrees at the API (``phi``), radians internally.
* ``x`` is horizontal, ``y`` is vertical upwards (gravity acts in -y).
* the slope may face left or right; the direction of sliding is detected
  from the sign of the driving moment/force, so reported driving forces and
  factors of safety are always positive.

Slope description
-----------------
:class:`Slope` holds

* ``surface`` - ground surface polyline ``[(x0, y0), (x1, y1), ...]`` with
  strictly increasing ``x``; the model domain is ``x0 <= x <= xn``.
* ``layers`` - list of :class:`Layer` ordered **from the top down**.  Layer
  ``i`` occupies the material between its ``top`` polyline and the ``top`` of
  layer ``i+1`` (the last layer extends downwards without limit).  The first
  layer's ``top`` may be ``None``, meaning "the ground surface".  A top
  polyline is evaluated with constant extrapolation outside its x range and
  is clipped to the ground surface, so a boundary that "outcrops" simply
  ends there.
* pore pressure (optional, default dry): either a phreatic line
  ``phreatic`` (polyline; ``u = gamma_w * max(0, y_w(x) - y_base)``, the usual
  vertical-head approximation), or a pore-pressure ratio ``ru``
  (``u = ru * W / b``, Bishop & Morgenstern), not both.

Methods
-------
For each slice of width ``b``, base inclination ``alpha`` (positive when
the base rises in the direction opposite to sliding, i.e. when the weight
drives the slide), weight ``W``, base length ``l = b / cos(alpha)``, base
pore pressure ``u`` and base strength ``c, phi`` (layer at the middle of the
slice base):

* Fellenius / ordinary method of slices (circle or polyline, force form)::

      N' = W cos(alpha) - u l        (effective normal force on the base)
      T  = W sin(alpha)              (driving shear force)
      FS = sum(c l + N' tan(phi)) / sum(T)

  For a circle this is identical to the moment form (the radius cancels).
  The totals ``sum N'`` and ``sum T`` are returned (``normal``/``shear``).
  ``N'`` is **not** clipped at zero (textbook form), see ``Result.notes``.
* Bishop simplified (circle only)::

      FS = sum[(c b + (W - u b) tan(phi)) / m_alpha] / sum(W sin(alpha)),
      m_alpha = cos(alpha) + sin(alpha) tan(phi) / FS

  solved by fixed-point iteration starting from the Fellenius value until
  ``|FS_k+1 - FS_k| <= tol * FS_k+1`` (default ``tol = 1e-6``, at most
  ``max_iter = 200`` iterations).  ``ValueError`` is raised when
  ``m_alpha <= 0.2`` for any slice at any iterate (numerical trouble at
  the toe of steep exit circles, the usual ``m_alpha`` limit, configurable
  with ``m_alpha_min``) or when the iteration does not converge.

* Pseudo-static load (``Slope(kh=, kv=)``): each slice carries ``W (1 - kv)``
  downwards and ``kh W`` horizontally at its mid-height, in the sliding
  direction.  Fellenius: ``N' = W (1 - kv) cos(alpha) - kh W sin(alpha) - u l``,
  driving ``W (1 - kv) sin(alpha) + kh W cos(alpha)`` along a polyline's base,
  ``+ kh W (yc - y_mid) / R`` about a circle's centre; Bishop: ``W (1 - kv)``
  in the numerator and the circle's driving moment; Spencer: the same
  terms in Q below, and moment equilibrium ``sum Q cos(alpha - theta) =
  sum kh W ((yc - y_mid) / R - cos(alpha))`` (kh W acts at mid-height, not on
  the base through which Q is taken).

* Spencer (1967), circle: the interslice forces are parallel, at an
  angle theta; the resultant on each slice's sides is::

      Q = [c l / F + (W cos(alpha) - u l) tan(phi) / F - W sin(alpha)]
          / [cos(alpha - theta) (1 + tan(alpha - theta) tan(phi) / F)]

  and F, theta satisfy both force equilibrium, sum Q = 0, and moment
  equilibrium about the centre, sum Q cos(alpha - theta) = 0 (Spencer 1967,
  Geotechnique 17(1)); solved as the theta where the two F(theta) curves
  cross (scipy brentq). With phi = 0 it equals the moment FS of Fellenius
  and Bishop exactly.

Critical-circle search
----------------------
:func:`critical_circle` evaluates a deterministic rectangular grid of
centres (``nx`` x ``ny`` points spanning ``x_range`` x ``y_range``) and, for
each centre, ``nr`` radii equally spaced in ``r_range`` - or, if ``through``
is given (e.g. the toe), the single radius of the circle through that
point.  Circles that are invalid for the slope (they miss it, leave the model
domain, cut the ground more than twice, or hit ``m_alpha`` trouble) are
skipped and counted.  The minimum-FS circle (first one found in the
enumeration order on ties) is returned.  An optional ``refine`` number of
successive grid refinements around the best centre (each halving the grid
spacing) can be asked for; it is also deterministic.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Iterable, List, Optional, Sequence, Tuple

import numpy as np

__all__ = [
    "Layer",
    "Slope",
    "Circle",
    "Slices",
    "Result",
    "SearchResult",
    "fellenius_circle",
    "bishop_circle",
    "stress_circle",
    "stress_polyline",
    "StressFieldError",
    "spencer_circle",
    "fellenius_polyline",
    "circle_slices",
    "polyline_slices",
    "critical_circle",
    "results_table",
    "GAMMA_W",
]

#: unit weight of water, kN/m^3
GAMMA_W = 9.81

_REL_TOL = 1e-9  # relative geometric tolerance (scaled by the model size)


# --------------------------------------------------------------------------
# validation helpers
# --------------------------------------------------------------------------
def _finite(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {v!r}")
    return v


def _polyline(name: str, pts, min_points: int = 2) -> np.ndarray:
    try:
        a = np.asarray(pts, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a sequence of (x, y) points") from None
    if a.ndim != 2 or a.shape[1] != 2:
        raise ValueError(f"{name} must be a sequence of (x, y) points, got shape {a.shape}")
    if a.shape[0] < min_points:
        raise ValueError(f"{name} needs at least {min_points} points, got {a.shape[0]}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} contains non-finite coordinates")
    dx = np.diff(a[:, 0])
    if np.any(dx <= 0.0):
        i = int(np.argmax(dx <= 0.0))
        raise ValueError(
            f"{name} x coordinates must be strictly increasing (left to right); "
            f"point {i + 1} (x={a[i + 1, 0]}) does not follow point {i} (x={a[i, 0]})"
        )
    return a


def _interp(poly: np.ndarray, x):
    """Piecewise-linear evaluation with constant extrapolation."""
    return np.interp(x, poly[:, 0], poly[:, 1])


# --------------------------------------------------------------------------
# slope description
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Layer:
    """A soil layer (Mohr-Coulomb strength, unit weight).

    ``c`` cohesion [kPa] >= 0, ``phi`` friction angle [deg] in [0, 90),
    ``gamma`` unit weight [kN/m^3] >= 0, ``top`` polyline of the layer's top
    boundary (``None`` = the ground surface; only allowed for the first
    layer).
    """

    c: float
    phi: float
    gamma: float
    top: Optional[Sequence[Tuple[float, float]]] = None
    name: str = ""

    def __post_init__(self):
        label = f"layer {self.name!r}" if self.name else "layer"
        c = _finite(f"{label}: cohesion c", self.c)
        phi = _finite(f"{label}: friction angle phi", self.phi)
        gamma = _finite(f"{label}: unit weight gamma", self.gamma)
        if c < 0.0:
            raise ValueError(f"{label}: cohesion c must be >= 0, got {c}")
        if not (0.0 <= phi < 90.0):
            raise ValueError(f"{label}: friction angle phi must be in [0, 90) degrees, got {phi}")
        if gamma < 0.0:
            raise ValueError(f"{label}: unit weight gamma must be >= 0, got {gamma}")
        object.__setattr__(self, "c", c)
        object.__setattr__(self, "phi", phi)
        object.__setattr__(self, "gamma", gamma)
        if self.top is not None:
            object.__setattr__(self, "top", _polyline(f"{label}: top boundary", self.top))

    @property
    def tan_phi(self) -> float:
        return math.tan(math.radians(self.phi))


class Slope:
    """Ground surface + layers + optional pore pressure; see module docstring.

    Parameters
    ----------
    surface : sequence of (x, y)
        ground surface, strictly increasing x.
    layers : Layer or sequence of Layer
        ordered from the top down; the first may have ``top=None``.
    phreatic : sequence of (x, y), optional
        phreatic line (strictly increasing x); pore pressure at a point
        below it is ``gamma_w`` times the vertical distance to it.
    ru : float, optional
        pore-pressure ratio in [0, 1); ``u = ru * W / b``.
    gamma_w : float
        unit weight of water, default 9.81 kN/m^3.
    kh, kv : float, optional
        pseudo-static load: a horizontal force ``kh W`` at each slice's
        centroid in the sliding direction and ``kv W`` upwards (the
        convention of ``slope.set_seismic``); kh in [0, 1), kv in (-1, 1).
    """

    def __init__(self, surface, layers, phreatic=None, ru: float = 0.0, gamma_w: float = GAMMA_W,
                 kh: float = 0.0, kv: float = 0.0):
        self.surface = _polyline("ground surface", surface)
        if isinstance(layers, Layer):
            layers = [layers]
        layers = list(layers)
        if not layers:
            raise ValueError("at least one layer is needed")
        for i, L in enumerate(layers):
            if not isinstance(L, Layer):
                raise ValueError(f"layers[{i}] is not a Layer")
            if L.top is None and i > 0:
                raise ValueError(f"layers[{i}]: only the first layer may have top=None (ground surface)")
        self.layers: List[Layer] = layers
        self.ru = _finite("ru", ru)
        if not (0.0 <= self.ru < 1.0):
            raise ValueError(f"ru must be in [0, 1), got {self.ru}")
        self.gamma_w = _finite("gamma_w", gamma_w)
        if self.gamma_w < 0.0:
            raise ValueError(f"gamma_w must be >= 0, got {self.gamma_w}")
        self.kh, self.kv = _finite("kh", kh), _finite("kv", kv)
        if not (0.0 <= self.kh < 1.0) or not (-1.0 < self.kv < 1.0):
            raise ValueError(f"kh must be in [0, 1) and kv in (-1, 1), got kh {self.kh}, kv {self.kv}")
        self.phreatic = None if phreatic is None else _polyline("phreatic line", phreatic)
        if self.phreatic is not None and self.ru != 0.0:
            raise ValueError("give either a phreatic line or ru, not both")
        x = self.surface[:, 0]
        y = self.surface[:, 1]
        self.xmin, self.xmax = float(x[0]), float(x[-1])
        self._scale = max(float(np.ptp(x)), float(np.ptp(y)), 1.0)
        self.tol = _REL_TOL * self._scale

    # -- geometry queries ---------------------------------------------------
    def ground(self, x):
        """Ground surface elevation at x (constant beyond the ends)."""
        return _interp(self.surface, x)

    def boundaries(self, x):
        """Effective elevations ``e_i`` of the top of each layer at x.

        ``e_0`` is the ground; ``e_i = min(e_(i-1), top_i(x))`` so that the
        layers never overlap and never rise above the ground.  Layer ``i``
        occupies ``[e_(i+1), e_i]`` (the last one extends to -infinity);
        material between the ground and the first layer's top polyline (if
        it has one) belongs to the first layer.  *x* a number (floats) or an
        array (arrays, element by element: every slice of a circle at once).
        """
        e = [np.asarray(self.ground(x), dtype=float)]
        for L in self.layers[1:]:
            e.append(np.minimum(e[-1], _interp(L.top, x)))
        return [_like(x, v) for v in e]

    def layer_index(self, x, y):
        """Index in ``layers`` of the layer containing (x, y): the deepest layer whose effective top is at
        or above y (a point above the ground: the first layer); numbers or arrays, as :meth:`boundaries`."""
        k = np.zeros(np.shape(x), dtype=int)
        for i, t in enumerate(self.boundaries(x)):
            k = np.where(np.asarray(y) <= t + self.tol, i, k)
        return int(k) if np.ndim(x) == 0 else k

    def layer_at(self, x: float, y: float) -> Layer:
        """Layer containing point (x, y) (:meth:`layer_index`)."""
        return self.layers[self.layer_index(x, y)]

    def column_weight(self, x, y_base, b):
        """Weight of a vertical column of width ``b`` between ``y_base`` and
        the ground at abscissa ``x``, with the layer unit weights.  This is
        exact for a slice whose top, base and layer boundaries are straight
        across its width (midpoint rule on a trapezoid). Numbers or arrays."""
        e = self.boundaries(x) + [-math.inf]
        w = 0.0
        for i, L in enumerate(self.layers):
            w = w + L.gamma * np.maximum(0.0, e[i] - np.maximum(e[i + 1], y_base))
        return _like(x, w * b)

    def pore_pressure(self, x, y_base, w_slice, b):
        """Pore pressure at the base of a column (phreatic line, or ru times the column's weight per width,
        or 0). Numbers or arrays."""
        if self.phreatic is not None:
            return _like(x, self.gamma_w * np.maximum(0.0, _interp(self.phreatic, x) - y_base))
        if self.ru > 0.0:
            return _like(x, self.ru * np.asarray(w_slice) / b)
        return _like(x, np.zeros(np.shape(x)))


def _like(x, v):
    """v as a float when x is a number, as an array when x is one."""
    return float(v) if np.ndim(x) == 0 else np.asarray(v, dtype=float)


# --------------------------------------------------------------------------
# slip surfaces and slices
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Circle:
    """Circular slip surface: centre (xc, yc) [m] and radius R [m]."""

    xc: float
    yc: float
    R: float

    def __post_init__(self):
        for n in ("xc", "yc", "R"):
            object.__setattr__(self, n, _finite(f"circle {n}", getattr(self, n)))
        if self.R <= 0.0:
            raise ValueError(f"circle radius R must be > 0, got {self.R}")

    def lower(self, x):
        """Elevation of the lower half of the circle at x (NaN outside)."""
        d = self.R ** 2 - (np.asarray(x, dtype=float) - self.xc) ** 2
        with np.errstate(invalid="ignore"):
            return self.yc - np.sqrt(d)

    def polyline(self, n=64):
        """The lower half as *n* + 1 points [(x, y)] from left to right (to draw it)."""
        return [(self.xc + self.R * math.cos(math.pi * (1 + k / n)), self.yc + self.R * math.sin(math.pi * (1 + k / n)))
                for k in range(n + 1)]

    def __str__(self):
        return f"circle(xc={self.xc:.3f}, yc={self.yc:.3f}, R={self.R:.3f})"


@dataclass
class Slices:
    """Per-slice data (numpy arrays, one entry per slice).

    ``x`` slice mid abscissa, ``b`` width, ``alpha`` base angle [rad] (sign:
    positive = driving), ``W`` weight, ``l`` base length, ``u`` base pore
    pressure, ``c``/``tan_phi`` base strength, ``y_base`` base mid elevation,
    ``y_mid`` the column's mid-height (where a pseudo-static ``kh W`` acts),
    ``kh``/``kv`` the slope's pseudo-static coefficients.
    """

    x: np.ndarray
    b: np.ndarray
    alpha: np.ndarray
    W: np.ndarray
    l: np.ndarray
    u: np.ndarray
    c: np.ndarray
    tan_phi: np.ndarray
    y_base: np.ndarray
    x_entry: float
    x_exit: float
    direction: int  # -1: mass slides towards -x, +1: towards +x
    y_mid: np.ndarray = None
    kh: float = 0.0
    kv: float = 0.0

    @property
    def Wv(self) -> np.ndarray:
        """The vertical load W (1 - kv)."""
        return self.W * (1.0 - self.kv)

    @property
    def n(self) -> int:
        return int(self.x.size)


def _check_n(n) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise ValueError(f"number of slices must be an integer, got {n!r}")
    if n < 1:
        raise ValueError(f"number of slices must be >= 1, got {n}")
    return int(n)


def _segment_circle_roots(p0, p1, circle: Circle) -> List[float]:
    """x of intersections of segment p0-p1 with the *lower* half circle."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    fx, fy = x0 - circle.xc, y0 - circle.yc
    a = dx * dx + dy * dy
    bq = 2.0 * (fx * dx + fy * dy)
    cq = fx * fx + fy * fy - circle.R ** 2
    disc = bq * bq - 4.0 * a * cq
    if disc < 0.0:
        return []
    s = math.sqrt(disc)
    out = []
    for t in ((-bq - s) / (2 * a), (-bq + s) / (2 * a)):
        if -1e-12 <= t <= 1.0 + 1e-12:
            x = x0 + t * dx
            y = y0 + t * dy
            if y <= circle.yc + 1e-12 * max(1.0, abs(circle.yc)):
                out.append(x)
    return out


def _positive_interval(xs: List[float], f, lo: float, hi: float, tol: float, what: str):
    """Given candidate crossing abscissae of a difference function ``f``
    (ground minus slip surface) on [lo, hi], return the unique interval on
    which f > 0.  Raises ValueError if there is none or several."""
    pts = sorted(set([lo, hi] + [x for x in xs if lo - tol <= x <= hi + tol]))
    merged = [pts[0]]
    for p in pts[1:]:
        if p - merged[-1] > tol:
            merged.append(p)
        else:
            merged[-1] = max(merged[-1], min(p, hi))
    pts = [min(max(p, lo), hi) for p in merged]
    intervals = []
    for a, b in zip(pts[:-1], pts[1:]):
        if b - a <= tol:
            continue
        if f(0.5 * (a + b)) > tol:
            if intervals and abs(intervals[-1][1] - a) <= tol:
                intervals[-1] = (intervals[-1][0], b)  # tangent touch: join
            else:
                intervals.append((a, b))
    if not intervals:
        raise ValueError(f"the {what} misses the slope (it does not pass below the ground surface)")
    if len(intervals) > 1:
        raise ValueError(
            f"the {what} cuts the ground surface more than twice "
            f"({len(intervals)} separate sliding masses at x = "
            + ", ".join(f"[{a:.3f}, {b:.3f}]" for a, b in intervals)
            + ")"
        )
    return intervals[0]


def _finish_slices(slope: Slope, xm, b, ybase, alpha_geom, x_entry, x_exit, what) -> Slices:
    """Compute weights, strengths, pore pressures; fix the sliding sense."""
    # every slice at once (the critical-circle search cuts hundreds of circles into slices)
    W = slope.column_weight(xm, ybase, b)
    u = slope.pore_pressure(xm, ybase, W, b)
    k = slope.layer_index(xm, ybase)
    c = np.array([L.c for L in slope.layers])[k]
    tphi = np.array([L.tan_phi for L in slope.layers])[k]
    # alpha_geom: angle of the base rising towards +x.  A mass sliding
    # towards -x is driven by bases rising towards +x.
    drive = float(np.sum(W * np.sin(alpha_geom)))
    if abs(drive) <= 1e-12 * max(1.0, float(np.sum(W))):
        raise ValueError(f"the {what} has no driving force (sum W sin(alpha) = 0): no sliding direction")
    direction = -1 if drive > 0 else +1
    alpha = alpha_geom if direction == -1 else -alpha_geom
    l = b / np.cos(alpha)
    y_mid = 0.5 * (slope.ground(xm) + ybase)
    return Slices(xm, b, alpha, W, l, u, c, tphi, ybase, float(x_entry), float(x_exit), direction, y_mid,
                  slope.kh, slope.kv)


def circle_slices(slope: Slope, circle: Circle, n: int = 50) -> Slices:
    """Cut the mass above ``circle`` into ``n`` equal-width vertical slices.

    Raises ValueError if the circle misses the slope, leaves the x range of
    the ground surface while still below it, or cuts the ground more than
    twice.
    """
    n = _check_n(n)
    if not isinstance(circle, Circle):
        circle = Circle(*circle)
    tol = slope.tol
    g = slope.surface
    # ground above the circle at the circle's horizontal extremes would mean
    # the slip surface does not come back up through the ground
    lo = max(slope.xmin, circle.xc - circle.R)
    hi = min(slope.xmax, circle.xc + circle.R)
    if hi - lo <= tol:
        raise ValueError(f"{circle} misses the slope (no horizontal overlap with the ground surface)")
    roots: List[float] = []
    for k in range(len(g) - 1):
        roots += _segment_circle_roots(g[k], g[k + 1], circle)

    def f(x):
        return float(slope.ground(x) - circle.lower(x))

    x_entry, x_exit = _positive_interval(roots, f, lo, hi, tol, f"slip {circle}")
    for xe in (x_entry, x_exit):
        if f(xe) > 10 * tol + 1e-9 * circle.R:
            if abs(xe - slope.xmin) <= tol or abs(xe - slope.xmax) <= tol:
                raise ValueError(
                    f"{circle} leaves the ground-surface x range [{slope.xmin}, {slope.xmax}] "
                    f"below the ground (at x = {xe:.3f}): extend the ground surface"
                )
            raise ValueError(
                f"{circle} does not exit the ground surface twice "
                f"(at x = {xe:.3f} the ground is above the circle's lowest half)"
            )
    edges = np.linspace(x_entry, x_exit, n + 1)
    xm = 0.5 * (edges[:-1] + edges[1:])
    b = np.diff(edges)
    ybase = circle.lower(xm)
    s = np.clip((xm - circle.xc) / circle.R, -1.0, 1.0)
    alpha_geom = np.arcsin(s)  # base rising towards +x when x > xc
    return _finish_slices(slope, xm, b, ybase, alpha_geom, x_entry, x_exit, f"slip {circle}")


def polyline_slices(slope: Slope, surface, n: int = 50) -> Slices:
    """Slices for a polyline slip surface (strictly increasing x).

    The slip polyline must pass below the ground surface on exactly one
    interval; it is clipped to that interval (so its end points may lie on
    or above the ground).  Slice boundaries are placed at every vertex of the
    ground surface, the slip surface and the layer boundaries inside the
    interval, and the pieces are subdivided so that there are at least ``n``
    slices; each slice therefore has a straight base and a straight top.
    """
    n = _check_n(n)
    s = _polyline("slip surface", surface)
    tol = slope.tol
    lo = max(slope.xmin, float(s[0, 0]))
    hi = min(slope.xmax, float(s[-1, 0]))
    if hi - lo <= tol:
        raise ValueError("the slip surface misses the slope (no horizontal overlap with the ground surface)")
    # the difference ground - slip is piecewise linear between the union of
    # vertices: its roots are found exactly on each piece
    xs = np.unique(np.concatenate([slope.surface[:, 0], s[:, 0], [lo, hi]]))
    xs = xs[(xs >= lo) & (xs <= hi)]
    d = slope.ground(xs) - _interp(s, xs)
    roots = []
    for k in range(len(xs) - 1):
        if (d[k] > 0) != (d[k + 1] > 0) and d[k] != d[k + 1]:
            roots.append(float(xs[k] - d[k] * (xs[k + 1] - xs[k]) / (d[k + 1] - d[k])))
        if abs(d[k]) <= tol:
            roots.append(float(xs[k]))

    def f(x):
        return float(slope.ground(x) - _interp(s, x))

    x_entry, x_exit = _positive_interval(roots, f, lo, hi, tol, "slip surface")
    for xe in (x_entry, x_exit):
        if f(xe) > 10 * tol:
            raise ValueError(
                f"the slip surface does not reach the ground surface at x = {xe:.3f} "
                f"(it ends, or the ground surface ends, {f(xe):.3f} m below ground)"
            )
    brk = [slope.surface[:, 0], s[:, 0]]
    for L in slope.layers:
        if L.top is not None:
            brk.append(L.top[:, 0])
    if slope.phreatic is not None:
        brk.append(slope.phreatic[:, 0])
    bx = np.unique(np.concatenate(brk + [[x_entry, x_exit]]))
    bx = bx[(bx >= x_entry) & (bx <= x_exit)]
    # merge breakpoints closer than tol
    keep = [bx[0]]
    for v in bx[1:]:
        if v - keep[-1] > tol:
            keep.append(v)
    keep[-1] = x_exit
    bx = np.asarray(keep)
    total = x_exit - x_entry
    target = total / n
    edges = [bx[0]]
    for a, b in zip(bx[:-1], bx[1:]):
        m = max(1, int(math.ceil((b - a) / target - 1e-9)))
        edges.extend(list(np.linspace(a, b, m + 1)[1:]))
    edges = np.asarray(edges)
    xm = 0.5 * (edges[:-1] + edges[1:])
    b = np.diff(edges)
    ybase = _interp(s, xm)
    # base slope of the segment containing each slice mid point
    seg = np.clip(np.searchsorted(s[:, 0], xm) - 1, 0, len(s) - 2)
    alpha_geom = np.arctan2(s[seg + 1, 1] - s[seg, 1], s[seg + 1, 0] - s[seg, 0])
    return _finish_slices(slope, xm, b, ybase, alpha_geom, x_entry, x_exit, "slip surface")


# --------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------
@dataclass
class Result:
    """Outcome of one factor-of-safety evaluation.

    ``fs`` factor of safety; ``normal`` = sum of effective base normal
    forces N' [kN/m] (Fellenius N' = W cos(alpha) - u l; for Bishop the
    N' implied by the simplified method at convergence); ``shear`` = sum of
    driving shear forces T = W sin(alpha) [kN/m]; ``resisting`` = sum of
    available shear strength along the base [kN/m] (so fs = resisting /
    shear); ``n_slices``; ``surface`` the Circle or the slip polyline;
    ``iterations`` (0 for Fellenius); ``slices`` per-slice data.
    """

    method: str
    fs: float
    normal: float
    shear: float
    resisting: float
    n_slices: int
    surface: object
    iterations: int = 0
    slices: Optional[Slices] = field(default=None, repr=False)
    notes: str = ""
    theta: Optional[float] = None  # Spencer: the interslice forces' angle [deg]

    def row(self) -> str:
        return f"{self.method:<28s} {self.shear:12.1f} {self.normal:12.1f} {self.fs:8.3f}"

    def __str__(self):
        surf = self.surface if isinstance(self.surface, Circle) else "polyline"
        it = f", {self.iterations} iterations" if self.iterations else ""
        return (
            f"{self.method}: FS = {self.fs:.3f} (shear {self.shear:.1f} kN/m, "
            f"normal {self.normal:.1f} kN/m, {self.n_slices} slices, {surf}{it})"
        )


def results_table(rows: Iterable[Tuple[str, float, float, float]] | Iterable[Result], title: str = "") -> str:
    """Format a table like Table 2 of the seed paper.

    ``rows`` holds :class:`Result` objects and/or tuples
    ``(label, shear_kN_per_m, normal_kN_per_m, fs)``.
    """
    head = f"{'':<28s} {'Shear (kN/m)':>12s} {'Normal (kN/m)':>13s} {'FS':>8s}"
    lines = [title] if title else []
    lines += [head, "-" * len(head)]
    for r in rows:
        if isinstance(r, Result):
            lab, sh, no, fs = r.method, r.shear, r.normal, r.fs
        else:
            lab, sh, no, fs = r
        lines.append(f"{lab:<28s} {sh:12.1f} {no:13.1f} {fs:8.3f}")
    return "\n".join(lines)


def _driving(sl: Slices, circle=None) -> np.ndarray:
    """Each slice's driving force along its base (a polyline's force form), or its driving moment about the
    circle's centre divided by R: W (1 - kv) sin(alpha) + kh W cos(alpha) or + kh W (yc - y_mid) / R."""
    arm = np.cos(sl.alpha) if circle is None else (circle.yc - sl.y_mid) / circle.R
    return sl.Wv * np.sin(sl.alpha) + sl.kh * sl.W * arm


def _fellenius(sl: Slices, method: str, surface) -> Result:
    Np = sl.Wv * np.cos(sl.alpha) - sl.kh * sl.W * np.sin(sl.alpha) - sl.u * sl.l
    T = _driving(sl, surface if isinstance(surface, Circle) else None)
    res = float(np.sum(sl.c * sl.l + Np * sl.tan_phi))
    drive = float(np.sum(T))
    notes = ""
    if np.any(Np < 0):
        notes = f"{int(np.sum(Np < 0))} slice(s) with negative effective normal force (not clipped)"
    return Result(method, res / drive, float(np.sum(Np)), drive, res, sl.n, surface, 0, sl, notes)


def fellenius_circle(slope: Slope, circle, n: int = 50) -> Result:
    """Ordinary method of slices (Fellenius) for a circular slip surface.

    ``circle`` is a :class:`Circle` or a tuple ``(xc, yc, R)``.
    """
    if not isinstance(circle, Circle):
        circle = Circle(*circle)
    return _fellenius(circle_slices(slope, circle, n), "Fellenius (circle)", circle)


def fellenius_polyline(slope: Slope, surface, n: int = 50) -> Result:
    """Ordinary method of slices, force form, for a polyline slip surface
    (e.g. an RBSM slip path along block joints): FS = sum(c l + N' tan phi)
    / sum(T), N' = W cos(alpha) - u l, T = W sin(alpha)."""
    sl = polyline_slices(slope, surface, n)
    return _fellenius(sl, "Fellenius (polyline)", np.asarray(surface, dtype=float))


def bishop_circle(
    slope: Slope,
    circle,
    n: int = 50,
    tol: float = 1e-6,
    max_iter: int = 200,
    m_alpha_min: float = 0.2,
) -> Result:
    """Bishop simplified method for a circular slip surface.

    Fixed-point iteration from the Fellenius value; converged when
    ``|F_new - F| <= tol * F_new``.  Raises ValueError if any
    ``m_alpha = cos(alpha) + sin(alpha) tan(phi) / F`` drops to
    ``m_alpha_min`` or below, or if ``max_iter`` is reached.
    """
    if not isinstance(circle, Circle):
        circle = Circle(*circle)
    tol = _finite("tol", tol)
    if tol <= 0:
        raise ValueError(f"tol must be > 0, got {tol}")
    sl = circle_slices(slope, circle, n)
    f0 = _fellenius(sl, "", circle)
    F = f0.fs
    if not (F > 0):
        F = 1.0
    ca, sa = np.cos(sl.alpha), np.sin(sl.alpha)
    num0 = sl.c * sl.b + (sl.Wv - sl.u * sl.b) * sl.tan_phi
    drive = float(np.sum(_driving(sl, circle)))
    it = 0
    while True:
        it += 1
        m = ca + sa * sl.tan_phi / F
        if np.any(m <= m_alpha_min):
            k = int(np.argmin(m))
            raise ValueError(
                f"Bishop: m_alpha = {m[k]:.3f} <= {m_alpha_min} at slice {k} "
                f"(x = {sl.x[k]:.3f}, alpha = {math.degrees(sl.alpha[k]):.1f} deg) for {circle}"
            )
        F_new = float(np.sum(num0 / m)) / drive
        if not math.isfinite(F_new) or F_new <= 0:
            raise ValueError(f"Bishop iteration failed (F = {F_new}) for {circle}")
        if abs(F_new - F) <= tol * F_new:
            F = F_new
            break
        F = F_new
        if it >= max_iter:
            raise ValueError(f"Bishop iteration did not converge in {max_iter} iterations for {circle}")
    m = ca + sa * sl.tan_phi / F
    # base normal force implied by vertical equilibrium of each slice
    Np = (sl.Wv - sl.c * sl.l * sa / F - sl.u * sl.l * ca) / m
    res = F * drive
    return Result("Bishop simplified (circle)", F, float(np.sum(Np)), drive, res, sl.n, circle, it, sl)


class StressFieldError(ValueError):
    """The stress field of the stress-based method gave no stresses on a slip surface: the wrong shape (a
    mistake in the field: :func:`critical_circle` raises it) or not finite (``outside``: the surface leaves
    the field's region, e.g. runs below the blocks; :func:`critical_circle` skips the circle)."""

    def __init__(self, message, outside=False):
        super().__init__(message)
        self.outside = outside


def _stress_result(sl: Slices, stress, method: str, surface) -> Result:
    """FS of a slip surface from a stress field (Kulhawy 1969, the finite-element stress method):
    at every slice base the field's normal stress sigma_n and shear stress tau on the base,
    FS = sum (c + (sigma_n - u) tan phi) l / sum tau l (a base in tension: c alone). The normal stresses act through the centre
    of a circle, so for phi = 0 and a field in equilibrium with the weight the FS is Fellenius's and
    Bishop's exactly (moment equilibrium of the mass): whatever its horizontal stresses."""
    ag = -sl.direction * sl.alpha  # the base's angle rising towards +x
    ca, sa = np.cos(ag), np.sin(ag)
    s = np.asarray(stress(np.asarray(sl.x, dtype=float), np.asarray(sl.y_base, dtype=float)), dtype=float)
    if s.shape != (3, sl.n):
        raise StressFieldError(f"stress(x, y) must return (sxx, syy, sxy), each of the {sl.n} points' values; got shape {s.shape}")
    if not np.all(np.isfinite(s)):
        bad = int(np.argmax(~np.all(np.isfinite(s), axis=0)))
        raise StressFieldError(f"stress(x, y) is not finite at ({sl.x[bad]:.4g}, {sl.y_base[bad]:.4g}) (slice {bad}): "
                               "the surface runs outside the stress field (e.g. below the blocks)", outside=True)
    sxx, syy, sxy = s
    nx, ny = -sa, ca  # base normal, into the mass above
    tx, ty = sl.direction * ca, sl.direction * sa  # along the base, the way the mass slides
    sig_n = sxx * nx * nx + syy * ny * ny + 2 * sxy * nx * ny  # compression positive
    tau = -(tx * (sxx * nx + sxy * ny) + ty * (sxy * nx + syy * ny))  # the base's resistance to the sliding
    eff = sig_n - sl.u
    strength = sl.c + np.maximum(eff, 0.0) * sl.tan_phi
    drive = float(np.sum(tau * sl.l))
    if not drive > 1e-9 * float(np.sum((np.abs(tau) + np.abs(sig_n)) * sl.l)):  # (round-off of a field without shear)
        raise ValueError(f"the stress field holds no shear against the sliding on this {method} surface (sum tau l = {drive:.4g})")
    res = float(np.sum(strength * sl.l))
    notes = f"{int(np.sum(eff < 0))} slice base(s) in tension (no friction)" if np.any(eff < 0) else ""
    return Result(method, res / drive, float(np.sum(eff * sl.l)), drive, res, sl.n, surface, 0, sl, notes)


def stress_circle(slope: Slope, circle, stress, n: int = 50) -> Result:
    """Factor of safety of a circular slip surface from a given stress field (Kulhawy's method, as
    SIGMA/W-SLOPE/W's finite-element stress method): the stresses at each slice's base are the
    field's, not the equilibrium of the slices. *stress*: a function ``(x, y) -> (sxx, syy, sxy)``
    of arrays [kPa, compression positive, total stress: the slope's pore pressure is taken off],
    e.g. ``yade_rbsm.safety.stress_field()`` of a settled block slope. ``normal`` and ``shear`` of the
    Result are the integrals of sigma_n' and tau over the surface [kN/m]."""
    if not isinstance(circle, Circle):
        circle = Circle(*circle)
    return _stress_result(circle_slices(slope, circle, n), stress, "stress field (circle)", circle)


def stress_polyline(slope: Slope, surface, stress, n: int = 50) -> Result:
    """:func:`stress_circle` on a polyline slip surface (e.g. a path along block joints)."""
    sl = polyline_slices(slope, surface, n)
    return _stress_result(sl, stress, "stress field (polyline)", np.asarray(surface, dtype=float))


def spencer_circle(slope: Slope, circle, n: int = 50, tol: float = 1e-10) -> Result:
    """Spencer's method for a circular slip surface (see the module docstring).

    Raises ValueError if a slice's denominator ``cos(alpha - theta)(1 +
    tan(alpha - theta) tan(phi)/F)`` is <= 0 at the solution, or if the force
    and moment curves F(theta) do not cross for |theta| < 80 degrees."""
    from scipy.optimize import brentq

    if not isinstance(circle, Circle):
        circle = Circle(*circle)
    sl = circle_slices(slope, circle, n)
    a, tp = sl.alpha, sl.tan_phi
    # W (1 - kv) down and kh W in the sliding direction, resolved along and normal to each base (Fellenius's terms)
    drive = sl.Wv * np.sin(a) + sl.kh * sl.W * np.cos(a)
    resist0 = sl.c * sl.l + (sl.Wv * np.cos(a) - sl.kh * sl.W * np.sin(a) - sl.u * sl.l) * tp
    # kh W acts at mid-height, not on the base: the moment balance about the centre keeps its arm's difference
    seismic_moment = float(np.sum(sl.kh * sl.W * ((circle.yc - sl.y_mid) / circle.R - np.cos(a)))) if sl.kh else 0.0

    def q(F, th):
        d = a - th
        return (resist0 / F - drive) / (np.cos(d) * (1.0 + np.tan(d) * tp / F))

    def f_of(th, moment):
        w = np.cos(a - th) if moment else 1.0

        def g(F):
            return float(np.sum(q(F, th) * w)) - (seismic_moment if moment else 0.0)

        def valid(F):  # every slice's denominator > 0 (Bishop's m_alpha condition)
            d = a - th
            return bool(np.all(np.cos(d) * (1.0 + np.tan(d) * tp / F) > 0))

        Fs = [F for F in np.geomspace(0.02, 50.0, 120) if valid(F)]
        for F0, F1 in zip(Fs[:-1], Fs[1:]):
            if F1 < F0 * 1.1 and g(F0) * g(F1) <= 0:  # neighbours in the valid set: no pole between
                return brentq(g, F0, F1, xtol=tol, rtol=tol)
        raise ValueError(f"Spencer: no {'moment' if moment else 'force'} root F at theta = {math.degrees(th):.1f} deg")

    def diff(th):
        return f_of(th, True) - f_of(th, False)

    ths = np.radians(np.linspace(-80.0, 80.0, 161))
    vals = []
    for th in ths:
        try:
            vals.append(diff(th))
        except ValueError:
            vals.append(math.nan)
    # the root nearest theta = 0 (the physical one: interslice forces close to the mean base slope)
    roots = [k for k in range(len(ths) - 1) if math.isfinite(vals[k]) and math.isfinite(vals[k + 1])
             and vals[k] * vals[k + 1] <= 0]
    if not roots:
        raise ValueError(f"Spencer: force and moment equilibrium do not meet for |theta| < 80 deg on {circle}")
    k = min(roots, key=lambda k: abs(ths[k]))
    th = brentq(diff, ths[k], ths[k + 1], xtol=1e-12) if vals[k] != 0 else ths[k]
    F = f_of(th, True)
    d = a - th
    den = np.cos(d) * (1.0 + np.tan(d) * tp / F)
    if np.any(den <= 0):
        raise ValueError(f"Spencer: slice denominator <= 0 at theta = {math.degrees(th):.1f} deg on {circle}")
    # N' from the slice's balance normal to its base (S - drive = Q cos d along it)
    Np = (sl.Wv * np.cos(a) - sl.kh * sl.W * np.sin(a) - sl.u * sl.l) - q(F, th) * np.sin(d)
    return Result("Spencer (circle)", F, float(np.sum(Np)), float(np.sum(drive)), F * float(np.sum(drive)), sl.n, circle,
                  0, sl, notes=f"theta = {math.degrees(th):.2f} deg", theta=math.degrees(th))


# --------------------------------------------------------------------------
# critical circle search
# --------------------------------------------------------------------------
@dataclass
class SearchResult:
    """Minimum-FS circle of a grid search."""

    method: str
    best: Result
    circle: Circle
    n_tried: int
    n_valid: int
    n_skipped: int
    warnings: List[str] = field(default_factory=list)  # the minimum on the edge of the search space

    @property
    def fs(self) -> float:
        return self.best.fs

    def __str__(self):
        return (
            f"critical circle ({self.method}): FS = {self.best.fs:.3f} at {self.circle}; "
            f"{self.n_valid} of {self.n_tried} trial circles valid" + "".join("; WARNING: " + w for w in self.warnings)
        )


def _on_edges(c, ranges):
    """What of circle *c* (xc, yc, R) lies on the edge of its range or beyond it (the refinement re-grids
    around the best centre and may leave the ranges): the true minimum may be further out."""
    out = []
    for name, v, rng in ranges:
        a, b = float(rng[0]), float(rng[1])
        tol = 1e-9 * max(b - a, 1.0)
        if b > a and (v <= a + tol or v >= b - tol):
            out.append(f"the critical circle's {name} = {v:.4g} is on the edge of {name}_range ({a:g}, {b:g}) or "
                       f"beyond it: the minimum may lie further out; widen {name}_range")
    return out


def _lin(rng, k, name):
    if len(rng) != 2:
        raise ValueError(f"{name} must be a (min, max) pair")
    a, b = _finite(f"{name}[0]", rng[0]), _finite(f"{name}[1]", rng[1])
    if b < a:
        raise ValueError(f"{name} must satisfy min <= max, got {rng}")
    k = _check_n(k)
    return np.linspace(a, b, k) if k > 1 else np.array([0.5 * (a + b)])


def _depth(slope: Slope, r: Result) -> float:
    """Greatest depth of the sliding mass below the ground, at the slices' middles."""
    sl = r.slices
    return float(np.max(slope.ground(sl.x) - sl.y_base))


def _lowest(r: Result) -> float:
    """Lowest point of a circular slip surface between its entry and exit."""
    c, sl = r.surface, r.slices
    if sl.x_entry <= c.xc <= sl.x_exit:
        return c.yc - c.R
    return float(min(c.lower(sl.x_entry), c.lower(sl.x_exit)))


def critical_circle(
    slope: Slope,
    x_range,
    y_range,
    nx: int = 11,
    ny: int = 11,
    r_range=None,
    nr: int = 11,
    through=None,
    method: str = "bishop",
    n: int = 50,
    refine: int = 0,
    base: Optional[float] = None,
    stress=None,
    min_depth: float = 0.0,
    candidates=(),
) -> SearchResult:
    """Grid search for the circle of minimum FS.

    Centres: ``nx`` x ``ny`` grid on ``x_range`` x ``y_range`` (inclusive).
    Radii: either ``nr`` values on ``r_range`` (inclusive), or - when
    ``through=(x, y)`` is given - the one radius of the circle through that
    point (e.g. the toe).  ``method`` is ``"fellenius"`` or ``"bishop"``.
    ``"spencer"`` too. ``refine`` extra passes re-grid around the best centre with half the
    previous spacing (same nx, ny).  Invalid circles are skipped, and so are
    circles that dip below a firm base at elevation ``base`` (if given:
    the depth limit of Taylor's and Griffiths & Lane's D factor).
    ``method="stress"`` with ``stress=`` a stress field: :func:`stress_circle`. ``min_depth``: circles
    whose sliding mass is nowhere deeper than this are skipped (a stress field sampled at block
    centroids does not resolve a slide a block or two deep). Circles on which the field is not finite
    (outside it, e.g. below the blocks) are skipped too; a field of the wrong shape raises its
    :class:`StressFieldError`. ``candidates``: circles (:class:`Circle` or ``(xc, yc, R)``) tried
    after the grid (its refinement is the grid's alone), e.g. Bishop's critical circle for the stress
    method, whose FS over the circles is rough at the block scale: the grid alone missed it. Raises ValueError if no trial circle is valid,
    with how many were below the base, outside the field or shallower than min_depth.
    """
    meth = method.lower()
    fns = {"fellenius": fellenius_circle, "bishop": bishop_circle, "spencer": spencer_circle}
    if meth == "stress":
        if stress is None or not callable(stress):
            raise ValueError("method='stress' needs stress=, a function (x, y) -> (sxx, syy, sxy) [kPa]")
        fns["stress"] = lambda slope_, circle_, n_: stress_circle(slope_, circle_, stress, n_)
    elif stress is not None:
        raise ValueError(f"stress= is for method='stress' (got method {method!r})")
    if meth not in fns:
        raise ValueError(f"method must be 'fellenius', 'bishop', 'spencer' or 'stress', got {method!r}")
    min_depth = _finite("min_depth", min_depth)
    if min_depth < 0:
        raise ValueError(f"min_depth must be >= 0, got {min_depth}")
    fn = fns[meth]
    if (r_range is None) == (through is None):
        raise ValueError("give exactly one of r_range or through")
    if through is not None:
        tx, ty = _finite("through x", through[0]), _finite("through y", through[1])
    else:
        radii = _lin(r_range, nr, "r_range")
        if radii[0] <= 0:
            raise ValueError("radii must be > 0")
    refine = int(refine)
    if base is not None:
        base = _finite("base", base)
    xs = _lin(x_range, nx, "x_range")
    ys = _lin(y_range, ny, "y_range")
    extra = [c if isinstance(c, Circle) else Circle(*c) for c in candidates]
    best = None
    count = dict(tried=0, valid=0, below=0, outside=0, shallow=0)

    def trial(xc, yc, R, keep=True):
        """The valid result of circle (xc, yc, R), kept as the best if lower and counted (*keep*), or None."""
        nonlocal best
        tally = count if keep else dict(count)  # (a probe beyond the grid is not one of its circles)
        tally["tried"] += 1
        if R <= 0:
            return
        try:
            r = fn(slope, Circle(xc, yc, R), n)
        except StressFieldError as e:  # a field of the wrong shape fails on every circle: say so
            if not e.outside:
                raise
            tally["outside"] += 1
            return
        except ValueError:
            return
        if base is not None and _lowest(r) < base - slope.tol:
            tally["below"] += 1
            return
        if min_depth > 0 and _depth(slope, r) < min_depth:
            tally["shallow"] += 1
            return
        if not (r.fs > 0 and math.isfinite(r.fs)):
            return
        tally["valid"] += 1
        if keep and (best is None or r.fs < best.fs):
            best = r
        return r

    for level in range(refine + 1):
        for xc in xs:
            for yc in ys:
                rs = [math.hypot(xc - tx, yc - ty)] if through is not None else radii
                for R in rs:
                    trial(xc, yc, R)
        if best is None:
            break
        if level < refine:
            dx = (xs[-1] - xs[0]) / max(len(xs) - 1, 1) / 2 if len(xs) > 1 else 0.0
            dy = (ys[-1] - ys[0]) / max(len(ys) - 1, 1) / 2 if len(ys) > 1 else 0.0
            cx, cy = best.surface.xc, best.surface.yc
            hx, hy = dx * (len(xs) - 1) / 2, dy * (len(ys) - 1) / 2
            xs = np.linspace(cx - hx, cx + hx, len(xs))
            ys = np.linspace(cy - hy, cy + hy, len(ys))
    for c in extra:  # after the grid: its refinement follows the grid alone, so a candidate only ever lowers the FS
        trial(c.xc, c.yc, c.R)
    if best is None:
        why = "".join([f"; {count['below']} of them dip below the firm base y = {base}" if count["below"] else "",
                       f"; {count['outside']} run outside the stress field" if count["outside"] else "",
                       f"; {count['shallow']} are shallower than min_depth = {min_depth:g}" if count["shallow"] else ""])
        raise ValueError(f"no valid trial circle in the search space ({count['tried']} tried{why})")
    # Near an edge of the centre grid, one row of centres beyond it (all radii): a lower FS there means the
    # minimum lies outside the search space (the refinement only re-grids around the best centre).
    c, warnings = best.surface, []
    x0s, y0s = _lin(x_range, nx, "x_range"), _lin(y_range, ny, "y_range")
    for name, k, grid in (("x", 0, x0s), ("y", 1, y0s)):
        step = (grid[-1] - grid[0]) / (len(grid) - 1) if len(grid) > 1 else 0.0
        v = (c.xc, c.yc)[k]
        for edge, side in ((grid[0], -1), (grid[-1], 1)):
            if step <= 0 or abs(v - edge) > 2 * step:
                continue
            centre = [c.xc, c.yc]
            centre[k] = edge + side * step
            rs = [math.hypot(centre[0] - tx, centre[1] - ty)] if through is not None else radii
            found = [r for r in (trial(centre[0], centre[1], R, keep=False) for R in rs) if r is not None]
            low = min(found, key=lambda r: r.fs) if found else None
            if low is not None and low.fs < best.fs:
                warnings.append(f"a circle centred beyond {name}_range ({name} = {centre[k]:.4g}) has FS {low.fs:.3f} < "
                                f"{best.fs:.3f}: the minimum lies outside the search space; widen {name}_range")
    if through is None:
        warnings += _on_edges(c, [("r", c.R, r_range)])
    return SearchResult(meth, best, best.surface, count["tried"], count["valid"], count["tried"] - count["valid"],
                        warnings)
