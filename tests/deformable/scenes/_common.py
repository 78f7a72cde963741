"""Shared pieces of the deformable-block scenes (imported inside a yade script)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from yadescene import MARKER, emit, params  # noqa: E402,F401 (re-exported to the scenes)


def affine_fit(points, displacements):
    """Least-squares displacement gradient of u(x) = u0 + G x over the points: (G, residual rms)."""
    import numpy as np

    X = np.column_stack([np.ones(len(points)), np.asarray(points)])
    U = np.asarray(displacements)
    coef, *_ = np.linalg.lstsq(X, U, rcond=None)
    G = coef[1:].T  # G[i, j] = du_i/dx_j
    rms = float(np.sqrt(np.mean((X @ coef - U) ** 2)))
    return G, rms
