"""The zero-distance extrapolation of EventWatch (predict.py), compiled (used once numba is
loaded by the compiled kernels: a path alone does not import it).

A march extrapolates its modes' last three samples to their zeros after every sample; in
NumPy that is ~30 array operations and an error-state context, ~45 us even for one mode, a
seventh of a warm critical value. Here one loop over the functions does the same
floating-point operations in the same order with NumPy's rules (IEEE division: inf and NaN,
not errors; maximum keeps a NaN, fmin drops one), so the distances are the NumPy route's to
the last bit (tests/continuation/test_extrapolate_kernel.py).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np


@nb.njit(cache=True, error_model="numpy")
def root_distances(x, g, sense):
    """Distance from the newest sample of each function (columns of the (3, n) samples x, g,
    newest first) to its extrapolated zero along ``sense``: the nearer of the line's zero
    (through the last two) and the parabola's first positive one (through all three), inf
    where neither lies ahead. predict.EventWatch._extrapolate_numpy, element by element."""
    n = x.shape[1]
    out = np.empty(n)
    for j in range(n):
        xa, xb, xc = x[0, j], x[1, j], x[2, j]
        ga, gb, gc = g[0, j], g[1, j], g[2, j]
        slope = (ga - gb) / (xa - xb)
        line = -ga / slope * sense if slope * sense < 0 else np.inf
        curv = ((ga - gb) / (xa - xb) - (gb - gc) / (xb - xc)) / (xa - xc)
        s_, c_ = slope * sense, curv
        disc = s_ * s_ - 4 * c_ * ga
        root = math.sqrt(_maximum(disc, 0.0))
        t = (-s_ - root) / (2 * c_)
        t2 = (-s_ + root) / (2 * c_)
        if not (t > 0 and disc >= 0):
            t = t2 if (t2 > 0 and disc >= 0) else np.inf
        out[j] = _fmin(np.inf if math.isnan(line) else line, np.inf if math.isnan(t) else t)
    return out


@nb.njit(cache=True)
def _maximum(a, b):
    """np.maximum of two floats: a NaN wins."""
    if math.isnan(a) or math.isnan(b):
        return math.nan
    return a if a >= b else b


@nb.njit(cache=True)
def _fmin(a, b):
    """np.fmin of two floats that are not NaN (the caller replaced them)."""
    return np.fmin(a, b)
