"""The worst wave direction of a half-space, compiled: min over psi in [0, pi/2] of the signed
target s f(psi) of a face or an interface (halfspace.py), on a grid of directions and then by
a bounded minimisation between the neighbours of the lowest grid minima.

This is bifurcation.directions.worst_direction_numpy (its slow twin: a NumPy grid and
SciPy's bounded Brent minimiser, ``minimize_scalar(method="bounded")``) in one call: a
short-wave march reads a face at every state, and the twin's Python around the compiled
target (the minimiser's loop, ~40 scalar calls of the target a minimum, each through a
Python wrapper) cost as much as the target itself (~12 % of a scan whose optimum is a short
wave). The minimiser is SciPy's ``_minimize_scalar_bounded`` statement by statement (the
same floating-point operations in the same order, NumPy's rules for sign and maximum), and
the target of one direction is the kernels of decaying_subspace.py on one row of weights,
so the result is the twin's to the last bit (tests/incremental/test_direction_search.py).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .decaying_subspace import _interface_kernel, _targets_kernel
from .stroh_limit import ELLIPTICITY_TOL

HALF_PI = 0.5 * math.pi
#: f (|f| <= 1) equal to rounding: keep the exact endpoint psi (directions.ENDPOINT_SLACK)
ENDPOINT_SLACK = 1e-14
#: the bounded minimiser's evaluations at most (SciPy's maxiter, the twin's option)
MAX_EVALUATIONS = 200


@numba.njit(cache=True)
def _targets(below, above, interface, inner, pressure, w, f, margin):
    """f and margin of the face (``below``, at the ``inner`` face or not, its follower
    ``pressure``) or of the interface (``below``, ``above``) for the rows of weights w."""
    if interface:
        _interface_kernel(below, above, w, f, margin)
    else:
        _targets_kernel(below, w, inner, pressure, f, margin)


@numba.njit(cache=True)
def _signed(below, above, interface, inner, pressure, sign, x) -> float:
    """sign f(x) for one direction x, +inf where the decaying split fails or the margin is
    at most ELLIPTICITY_TOL (the twin's ``one``: target_scalar, NaN there, then inf)."""
    c, s = math.cos(x), math.sin(x)
    w = np.empty((1, 6))
    w[0, 0], w[0, 1], w[0, 2] = 1.0, c, s
    w[0, 3], w[0, 4], w[0, 5] = c * c, s * s, c * s
    f, margin = np.empty(1), np.empty(1)
    _targets(below, above, interface, inner, pressure, w, f, margin)
    v = sign * (f[0] if margin[0] > ELLIPTICITY_TOL else np.nan)
    return v if math.isfinite(v) else np.inf


@numba.njit(cache=True)
def _np_sign(x) -> float:
    """np.sign of a float (NaN stays NaN)."""
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    if x == 0.0:
        return 0.0
    return np.nan


@numba.njit(cache=True)
def _np_maximum(a, b) -> float:
    """np.maximum of two floats (a NaN wins)."""
    if math.isnan(a) or math.isnan(b):
        return np.nan
    return a if a >= b else b


@numba.njit(cache=True)
def _bounded_minimum(below, above, interface, inner, pressure, sign, x1, x2, xatol):
    """(x, f(x)): SciPy's bounded Brent minimisation (``_minimize_scalar_bounded``, maxiter
    MAX_EVALUATIONS) of :func:`_signed` on [x1, x2], statement by statement."""
    sqrt_eps = math.sqrt(2.2e-16)
    golden_mean = 0.5 * (3.0 - math.sqrt(5.0))
    a, b = x1, x2
    fulc = a + golden_mean * (b - a)
    nfc, xf = fulc, fulc
    rat = e = 0.0
    x = xf
    fx = _signed(below, above, interface, inner, pressure, sign, x)
    num = 1
    ffulc = fnfc = fx
    xm = 0.5 * (a + b)
    tol1 = sqrt_eps * abs(xf) + xatol / 3.0
    tol2 = 2.0 * tol1
    while abs(xf - xm) > (tol2 - 0.5 * (b - a)):
        golden = True
        if abs(e) > tol1:  # a parabolic fit
            golden = False
            r = (xf - nfc) * (fx - ffulc)
            q = (xf - fulc) * (fx - fnfc)
            p = (xf - fulc) * q - (xf - nfc) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            r = e
            e = rat
            if (abs(p) < abs(0.5 * q * r)) and (p > q * (a - xf)) and (p < q * (b - xf)):
                rat = (p + 0.0) / q
                x = xf + rat
                if ((x - a) < tol2) or ((b - x) < tol2):
                    si = _np_sign(xm - xf) + (1.0 if (xm - xf) == 0 else 0.0)
                    rat = tol1 * si
            else:
                golden = True
        if golden:  # a golden-section step
            if xf >= xm:
                e = a - xf
            else:
                e = b - xf
            rat = golden_mean * e
        si = _np_sign(rat) + (1.0 if rat == 0 else 0.0)
        x = xf + si * _np_maximum(abs(rat), tol1)
        fu = _signed(below, above, interface, inner, pressure, sign, x)
        num += 1
        if fu <= fx:
            if x >= xf:
                a = xf
            else:
                b = xf
            fulc, ffulc = nfc, fnfc
            nfc, fnfc = xf, fx
            xf, fx = x, fu
        else:
            if x < xf:
                a = x
            else:
                b = x
            if (fu <= fnfc) or (nfc == xf):
                fulc, ffulc = nfc, fnfc
                nfc, fnfc = x, fu
            elif (fu <= ffulc) or (fulc == xf) or (fulc == nfc):
                fulc, ffulc = x, fu
        xm = 0.5 * (a + b)
        tol1 = sqrt_eps * abs(xf) + xatol / 3.0
        tol2 = 2.0 * tol1
        if num >= MAX_EVALUATIONS:
            break
    return xf, fx


@numba.njit(cache=True)
def _lowest_minima(F, count):
    """Up to ``count`` indices of the local minima of F (F[i] <= both neighbours, an end
    against its one), lowest first, ties in index order (a stable sort, as the twin's)."""
    n = F.shape[0]
    idx = np.empty(n, np.int64)
    k = 0
    for i in range(n):
        lower = i == 0 or F[i] <= F[i - 1]
        upper = i == n - 1 or F[i] <= F[i + 1]
        if lower and upper:
            idx[k] = i
            k += 1
    for j in range(1, k):  # insertion sort: stable
        v, t = idx[j], j
        while t > 0 and F[idx[t - 1]] > F[v]:
            idx[t] = idx[t - 1]
            t -= 1
        idx[t] = v
    return idx[: min(k, count)]


@numba.njit(cache=True)
def worst_direction(below, above, interface, inner, pressure, sign, psi, w, psi_tol, below_of):
    """(min over psi of sign f, its psi) on the grid ``psi`` (weights ``w``, both endpoints
    included), refined between the neighbours of the (up to three) lowest grid minima to
    ``psi_tol`` > 0 unless the grid minimum is above ``below_of`` (psi_tol 0: the grid
    minimum alone; below_of inf: always refined; the twin refines in a second call, the
    march's sampler where the first is not above its threshold); an endpoint minimum
    kept exactly when f is flat to rounding within 1e3 psi_tol of it. (NaN, psi) at the
    first grid direction where the decaying split fails or is not strongly elliptic, or
    where the refined minimum is not finite. bifurcation.directions.worst_direction_numpy,
    compiled."""
    n = psi.shape[0]
    f, margin = np.empty(n), np.empty(n)
    _targets(below, above, interface, inner, pressure, w, f, margin)
    F = np.empty(n)
    for i in range(n):
        F[i] = sign * (f[i] if margin[i] > ELLIPTICITY_TOL else np.nan)
        if math.isnan(F[i]):
            return np.nan, psi[i]
    minima = _lowest_minima(F, 3)
    best_v, best_p = F[minima[0]], psi[minima[0]]
    if not psi_tol > 0.0 or best_v > below_of:  # the grid alone: its first lowest value
        return best_v, best_p
    for i in minima:
        lo, hi = psi[max(i - 1, 0)], psi[min(i + 1, n - 1)]
        x, v = _bounded_minimum(below, above, interface, inner, pressure, sign, lo, hi, psi_tol)
        if abs(x - 0.0) <= 1e3 * psi_tol and F[0] <= v + ENDPOINT_SLACK:
            x, v = 0.0, F[0]
        if abs(x - HALF_PI) <= 1e3 * psi_tol and F[n - 1] <= v + ENDPOINT_SLACK:
            x, v = HALF_PI, F[n - 1]
        if v < best_v:
            best_v, best_p = v, x
    if not math.isfinite(best_v):
        return np.nan, best_p
    return best_v, best_p
