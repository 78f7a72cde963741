"""Goodman & Bray's limit equilibrium of block toppling on a stepped base (Goodman and Bray 1976; Hoek and
Bray, Rock Slope Engineering, ch. 10), for columns of rock in the frame of their joints: pure Python.

The columns stand side by side, numbered from the toe (n = 1) up the slope; column n is *width* wide,
its base at ``base[n]`` and its top at ``top[n]`` along the column axis. Gravity makes the angle *psi*
with the axis (the dip of the base planes), tilted towards the toe. From the top of the slope down,
each column passes to the one below it the force P[n-1] its equilibrium needs, from the force P[n] of
the column above: limiting friction on the column sides (phi_side) and base (phi_base), and

* toppling about its downslope base corner:
  ``P[n-1] = (P[n] (M[n] - width tan phi_side) + W/2 (y sin psi - width cos psi)) / L[n]``
* sliding on its base:
  ``P[n-1] = P[n] - W (tan phi_base cos psi - sin psi) / (1 - tan phi_base tan phi_side)``

with y = top - base, W its weight, M[n] and L[n] the heights above its base where the columns above and
below push on it (the top of the lower one of the two at each side: the corner of the shorter column
bears on the face of the taller). A column passes the larger of the two; a column stable both ways
passes nothing (P = 0). P[0] is the force the toe needs: > 0 the slope fails. The factor of safety is
the factor on tan phi (both) for which P[0] = 0, by bisection, as strength reduction reduces.
"""
import math
from dataclasses import dataclass, field
from typing import List

__all__ = ["Column", "ToppleResult", "columns", "goodman_bray", "goodman_bray_fs", "toe_side"]


@dataclass
class Column:
    base: float  # along the column axis [m]
    top: float
    width: float


@dataclass
class ToppleResult:
    P0: float  # the force the toe needs [kN/m, or the unit of unit_weight x m2]
    forces: List[float] = field(default_factory=list)  # P[n-1] passed down by column n, n = 1..N
    modes: List[str] = field(default_factory=list)  # "stable", "toppling" or "sliding", per column

    def __str__(self):
        count = {m: self.modes.count(m) for m in ("stable", "toppling", "sliding")}
        return "Goodman-Bray: P0 = %.4g (%s)" % (self.P0, ", ".join("%d %s" % (v, k) for k, v in count.items() if v))


def goodman_bray(columns, psi, phi_base, phi_side=None, unit_weight=1.0):
    """P[0] and the mode of every column (module docstring); angles in radians."""
    if phi_side is None:
        phi_side = phi_base
    cols = list(columns)
    if not cols:
        raise ValueError("goodman_bray: no columns")
    for k, c in enumerate(cols):
        if not (c.top > c.base and c.width > 0 and all(math.isfinite(v) for v in (c.base, c.top, c.width))):
            raise ValueError("goodman_bray: column %d is not a column (base %r, top %r, width %r)" % (k + 1, c.base, c.top, c.width))
    tb, ts = math.tan(phi_base), math.tan(phi_side)
    s, co = math.sin(psi), math.cos(psi)
    n = len(cols)
    P = 0.0
    forces, modes = [0.0] * n, [""] * n
    for k in range(n - 1, -1, -1):
        c = cols[k]
        y = c.top - c.base
        W = unit_weight * y * c.width
        above = cols[k + 1] if k + 1 < n else None
        below = cols[k - 1] if k > 0 else None
        M = (min(c.top, above.top) - c.base) if above else y
        L = (min(c.top, below.top) - c.base) if below else y
        # (tan phi_base tan phi_side >= 1: the side friction alone holds a column on its base: no sliding)
        p_slide = P - W * (tb * co - s) / (1 - tb * ts) if tb * ts < 1 else -math.inf
        p_topple = (P * (M - c.width * ts) + 0.5 * W * (y * s - c.width * co)) / L if L > 0 else float("inf")
        if max(p_slide, p_topple) <= 0:
            P, modes[k] = 0.0, "stable"
        elif p_topple >= p_slide:
            P, modes[k] = p_topple, "toppling"
        else:
            P, modes[k] = p_slide, "sliding"
        forces[k] = P
    return ToppleResult(P, forces, modes)


def goodman_bray_fs(columns, psi, phi_base, phi_side=None, unit_weight=1.0, rtol=1e-6):
    """The factor F on tan phi (base and sides) for which P[0] = 0, by bisection on [1e-3, 1e3]."""
    if phi_side is None:
        phi_side = phi_base

    def p0(F):
        return goodman_bray(columns, psi, math.atan(math.tan(phi_base) / F), math.atan(math.tan(phi_side) / F),
                            unit_weight).P0
    lo, hi = 1e-3, 1e3
    if p0(lo) > 0:
        raise ValueError("goodman_bray_fs: the columns fail even at %g x the friction (toppling under their own "
                         "weight, whatever the friction)" % (1 / lo))
    if p0(hi) <= 0:
        raise ValueError("goodman_bray_fs: the columns stand even at the friction / %g" % hi)
    while hi - lo > rtol * lo:
        mid = math.sqrt(lo * hi)
        if p0(mid) > 0:
            hi = mid
        else:
            lo = mid
    return math.sqrt(lo * hi)


def columns(blocks, toe=None):
    """Goodman & Bray's columns of a slope built by :func:`yade_rbsm.slope.column_blocks` (*blocks*, its
    SlopeBlocks) on a stepped ground: each free column one rectangle with a flat base and a flat top, the
    columns side by side; listed from the toe up. *toe*: "left" or "right" (default: the end where the ground
    is lower). The model's frame is the columns' (gravity tilted by psi towards the toe). ValueError naming the
    column where the blocks are not Goodman & Bray's geometry (a sloping top: give the ground as flat tops and
    risers; cross joints; a gap)."""
    slope = [b for b in blocks.blocks if not b.fixed]
    if not slope:
        raise ValueError("columns: no free blocks")
    if toe is None:
        toe = toe_side(blocks)
    if toe not in ("left", "right"):
        raise ValueError("columns: toe must be 'left' or 'right' (got %r)" % (toe,))
    by_x = {}
    for b in slope:
        xs = [v[0] for v in b.vertices]
        by_x.setdefault((min(xs), max(xs)), []).append(b)
    spans = sorted(by_x)
    out = []
    for k, (xa, xb) in enumerate(spans):
        name = "columns: column %d (x %g to %g)" % (k + 1, xa, xb)
        if len(by_x[(xa, xb)]) > 1:
            raise ValueError("%s is %d blocks: Goodman & Bray's columns are one rigid block each (no cross joints)"
                             % (name, len(by_x[(xa, xb)])))
        if k and spans[k - 1][1] != xa:  # (a cut across columns makes blocks that overlap in x, or leave gaps)
            raise ValueError("%s does not stand beside the column before it (x %g to %g): not columns side by side"
                             % (name, spans[k - 1][0], spans[k - 1][1]))
        v = by_x[(xa, xb)][0].vertices
        bottom = [y for x, y in v if y == min(yy for _, yy in v)]
        ys = sorted(set(y for _, y in v))
        if len(v) != 4 or sorted(set(x for x, _ in v)) != [xa, xb] or len(ys) != 2:
            what = "top" if len(bottom) == 2 else "base"
            raise ValueError("%s: its %s is not flat (Goodman & Bray's columns are rectangles: give the ground as flat "
                             "tops and risers, the base as steps)" % (name, what))
        out.append(Column(ys[0], ys[1], xb - xa))
    return out if toe == "left" else out[::-1]


def toe_side(blocks):
    """"left" or "right": the end of the slope's ground (SlopeBlocks.surface) that is lower; ValueError when both
    are as high."""
    ground = blocks.surface
    if ground[0][1] == ground[-1][1]:
        raise ValueError("columns: the ground is as high at both ends; say which end is the toe (toe='left' or "
                         "'right')")
    return "left" if ground[0][1] < ground[-1][1] else "right"
