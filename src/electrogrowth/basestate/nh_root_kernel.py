"""The root of (NH-6) for lambda_i, compiled (used by neo_hookean.nh_lambda_i once numba is
loaded: importing a base state alone must not import it).

Every base state of the paper's tube solves (NH-6), (Vbar / Vbar_inf)^2 = ratio^2 in
y = (lambda_i0 / lambda_i)^2, by Brent's method: ~8 evaluations, ~8 us in Python, a tenth of
the Python left in a warm critical value (a march solves ~20 states). Here the same
iteration runs in one compiled call: :func:`nh_root` is brent.brentq operation for operation
(itself SciPy's brentq.c) on neo_hookean.nh_square, with the same C library's log1p and sinh, so
the root is the same double (tests/basestate/test_nh_root_kernel.py, on random tubes).
"""

from __future__ import annotations

import math

import numba as nb


@nb.njit(cache=True)
def _nh_square(y, k):
    """neo_hookean.nh_square (with nh_traction), the same operations in the same order."""
    kappa = k * (1.0 - y) / (1.0 + k * y)
    traction = 0.5 * (math.log1p(kappa) + y * kappa)
    s = 0.5 * math.log1p(k * y)
    damp = s / math.sinh(s) if s > 0.0 else 1.0
    return 2.0 * traction / math.log1p(k) * damp * damp


@nb.njit(cache=True)
def _negative(x):
    return math.copysign(1.0, x) < 0


@nb.njit(cache=True)
def nh_root(k, target, xtol, rtol, maxiter):
    """(y, ok): the root of nh_square(y, k) - target on [0, 1] by brent.brentq(f, 0, 1,
    xtol=xtol, rtol=rtol, maxiter=maxiter); ok False where brentq would raise (a NaN, no
    sign change, no convergence): the caller then runs brentq itself for its error."""
    xpre, xcur = 0.0, 1.0
    xblk = fblk = spre = scur = 0.0
    fpre = _nh_square(xpre, k) - target
    fcur = _nh_square(xcur, k) - target
    if math.isnan(fpre) or math.isnan(fcur):
        return math.nan, False
    if fpre == 0:
        return xpre, True
    if fcur == 0:
        return xcur, True
    if _negative(fpre) == _negative(fcur):
        return math.nan, False
    for _ in range(maxiter):
        if fpre != 0 and fcur != 0 and _negative(fpre) != _negative(fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur, True
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # interpolate
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # extrapolate
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):  # good short step
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = _nh_square(xcur, k) - target
        if math.isnan(fcur):
            return math.nan, False
    return math.nan, False
