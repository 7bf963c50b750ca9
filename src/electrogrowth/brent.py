"""Brent's bracketed root finder, operation for operation SciPy's ``brentq``.

The base state and every critical value solve scalar equations by Brent's method (inverse
quadratic extrapolation, secant, bisection; Brent 1973, ch. 4). SciPy's ``brentq``
(C code, scipy/optimize/Zeros/brentq.c, SciPy 1.17) needs ``import scipy.optimize``, which
loads scipy.sparse, special, spatial and fft: ~0.5 s of CPU in a fresh process that uses
none of them. This is the same algorithm in Python, the same floating-point operations in
the same order, so a root is the same double after the same function calls
(tests/test_brent.py compares the two on random equations); the errors are SciPy's too
(ValueError without a sign change or at a NaN, RuntimeError after maxiter iterations), so
callers see no difference. Ported from SciPy's brentq.c (BSD 3-Clause licence, copyright
the SciPy developers), which follows Brent's ALGOL procedure ``zero``.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable

RTOL_MIN = 4 * 2.220446049250313e-16  # SciPy's smallest rtol, 4 eps


def brentq(
    f: Callable[[float], float],
    a: float,
    b: float,
    *,
    xtol: float = 2e-12,
    rtol: float = RTOL_MIN,
    maxiter: int = 100,
) -> float:
    """The root of f in [a, b] (f(a), f(b) of opposite signs or one of them 0), to
    |x - x*| <= xtol + rtol |x|, as scipy.optimize.brentq with the same arguments."""
    maxiter = operator.index(maxiter)
    if xtol <= 0:
        raise ValueError(f"xtol too small ({xtol:g} <= 0)")
    if rtol < RTOL_MIN:
        raise ValueError(f"rtol too small ({rtol:g} < {RTOL_MIN:g})")
    xpre, xcur = float(a), float(b)
    xtol, rtol = float(xtol), float(rtol)  # f sees Python floats, as SciPy's C code passes
    xblk = fblk = spre = scur = 0.0
    fpre, fcur = _value(f, xpre), _value(f, xcur)
    if fpre == 0:
        return xpre
    if fcur == 0:
        return xcur
    if _negative(fpre) == _negative(fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    for _ in range(maxiter):
        # signs compared by sign bit, not by fpre * fcur (which underflows to 0)
        if fpre != 0 and fcur != 0 and _negative(fpre) != _negative(fcur):
            # xcur and xpre bracket the root: xblk becomes the far end
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # interpolate
                stry = _quotient(-fcur * (xcur - xpre), fcur - fpre)
            else:  # extrapolate
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = _quotient(-fcur * (fblk * dblk - fpre * dpre), dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):  # good short step
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = _value(f, xcur)
    raise RuntimeError(f"Failed to converge after {maxiter} iterations.")


def _quotient(num: float, den: float) -> float:
    """num / den as C divides doubles: a zero denominator gives inf or NaN (0 / 0), not an
    exception, so the step below is not taken and Brent's method bisects (two equal values
    of f, as on a plateau of a clipped function)."""
    if den == 0.0:
        return (
            math.nan
            if num == 0.0 or math.isnan(num)
            else math.copysign(math.inf, num) * math.copysign(1.0, den)
        )
    return num / den


def _negative(x: float) -> bool:
    return math.copysign(1.0, x) < 0


def _value(f, x: float) -> float:
    fx = float(f(x))
    if math.isnan(fx):
        raise ValueError(f"The function value at x={x} is NaN; solver cannot continue.")
    return fx
