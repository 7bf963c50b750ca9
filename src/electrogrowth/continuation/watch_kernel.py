"""EventWatch's arithmetic (predict.py), compiled (used once numba is loaded by the compiled
kernels: a path alone does not import it).

A march extrapolates its modes' last three samples to their zeros after every sample and asks
at every step which modes are due, where the next falls due and how far it may step; in NumPy
that is 5-45 us a question even for one mode (~30 array operations and an error-state context
for the extrapolation alone), a fifth of a warm critical value. Here each is one loop over
the functions doing the same floating-point operations in the same order with NumPy's rules
(IEEE division: inf and NaN, not errors; maximum, minimum and min keep a NaN, fmin drops
one), so every answer is the NumPy route's (EventWatch's ``*_numpy`` methods) to the last bit
(tests/continuation/test_watch_kernel.py).
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
def needs(alive, due, dist, xa, x, sense):
    """EventWatch.needs: live and due at x, or predicted to have reached zero by x."""
    out = np.empty(alive.shape[0], np.bool_)
    for j in range(alive.shape[0]):
        out[j] = alive[j] and (sense * (x - due[j]) >= 0 or sense * (x - xa[j]) >= dist[j])
    return out


@nb.njit(cache=True)
def next_due(alive, due, x, sense):
    """EventWatch.next_due as (any ahead, the nearest due point beyond x)."""
    found, best = False, 0.0
    for j in range(alive.shape[0]):
        if alive[j] and sense * (due[j] - x) > 0:  # never NaN: the comparison drops it
            d = due[j]
            if not found or ((d < best) if sense > 0 else (d > best)):
                best, found = d, True
    return found, best


@nb.njit(cache=True, error_model="numpy")
def reach(alive, dist, moved, safety, finest, trust, overshoot):
    """EventWatch.reach: the least over the live functions of ``safety`` times the distance to
    the zero, or just beyond a trusted zero; inf if none is live, NaN if one's is."""
    best = np.inf
    for j in range(alive.shape[0]):
        if not alive[j]:
            continue
        d, mv = dist[j], moved[j]
        trusted = mv <= trust * _minimum(d, finest)
        past = _minimum(_maximum(2.0 * mv, overshoot * d), finest)
        v = d + past if trusted else safety * d
        if math.isnan(v):
            return v
        if v < best:
            best = v
    return best


@nb.njit(cache=True, error_model="numpy")
def settle(idx, x, sense, before, dist, moved, due, cap):
    """The end of EventWatch.record for the functions ``idx`` sampled at x: how far each
    predicted zero moved (from ``before``) and when each falls due again (half the distance
    to its zero, at most ``cap``)."""
    for i in range(idx.shape[0]):
        j = idx[i]
        moved[j] = abs(x + sense * dist[j] - before[i])
        due[j] = x + sense * _minimum(0.5 * dist[j], cap)


@nb.njit(cache=True, error_model="numpy")
def record(idx, x, g, xs, gs, sense, dist, moved, due, cap):
    """EventWatch.record of the samples g at x of the functions ``idx`` into the (3, n)
    samples xs, gs (newest first), whose distances to their zeros are ``dist``: the new
    distances, after :func:`settle`."""
    before = np.empty(idx.shape[0])
    for i in range(idx.shape[0]):
        j = idx[i]
        before[i] = xs[0, j] + sense * dist[j]  # the zero predicted before the sample
        xs[2, j], gs[2, j] = xs[1, j], gs[1, j]
        xs[1, j], gs[1, j] = xs[0, j], gs[0, j]
        xs[0, j], gs[0, j] = x, g[i]
    new = root_distances(xs, gs, sense)
    settle(idx, x, sense, before, new, moved, due, cap)
    return new


@nb.njit(cache=True)
def _maximum(a, b):
    """np.maximum of two floats: a NaN wins."""
    if math.isnan(a) or math.isnan(b):
        return math.nan
    return a if a >= b else b


@nb.njit(cache=True)
def _minimum(a, b):
    """np.minimum of two floats: a NaN wins."""
    if math.isnan(a) or math.isnan(b):
        return math.nan
    return a if a <= b else b


@nb.njit(cache=True)
def _fmin(a, b):
    """np.fmin of two floats that are not NaN (the caller replaced them)."""
    return np.fmin(a, b)
