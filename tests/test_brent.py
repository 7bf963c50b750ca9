"""electrogrowth.brent.brentq against scipy.optimize.brentq, its slow-import twin: the same
root (the same double), after the same function calls, and the same errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.optimize

from electrogrowth.brent import brentq

EPS = np.finfo(float).eps


def _counted(f):
    calls = []

    def g(x):
        calls.append(x)
        return f(x)

    return g, calls


def _equations(rng):
    """Random smooth, steep, flat and kinked equations with a bracketed root."""
    for _ in range(300):
        r = rng.uniform(-2, 2)
        p = rng.integers(1, 8)
        s = 10 ** rng.uniform(-8, 8)
        left, right = r - rng.uniform(0.01, 3), r + rng.uniform(0.01, 3)
        yield (lambda x, r=r, p=p, s=s: s * abs(x - r) ** p * np.sign(x - r)), left, right
        yield (lambda x, r=r, s=s: math.tanh(s * (x - r)) + 1e-3 * (x - r)), left, right
        yield (lambda x, r=r: math.exp(x) - math.exp(r)), r - 5 * rng.uniform(), right
        yield (lambda x, r=r: math.cbrt(x - r) + 0.1 * (x - r) ** 3), right, left


@pytest.mark.parametrize(
    "tol", [(2e-12, 4 * EPS, 100), (1e-300, 4 * EPS, 500), (1e-6, 1e-9, 40), (1e-15, 1e-14, 8)]
)
def test_brentq_is_scipys_to_the_bit(rng, tol):
    xtol, rtol, maxiter = tol
    for f, a, b in _equations(rng):
        f1, ours_calls = _counted(f)
        f2, scipy_calls = _counted(f)
        try:
            ours = brentq(f1, a, b, xtol=xtol, rtol=rtol, maxiter=maxiter)
        except RuntimeError as exc:
            with pytest.raises(RuntimeError) as theirs:
                scipy.optimize.brentq(f2, a, b, xtol=xtol, rtol=rtol, maxiter=maxiter)
            assert str(exc) == str(theirs.value)
        else:
            theirs = scipy.optimize.brentq(f2, a, b, xtol=xtol, rtol=rtol, maxiter=maxiter)
            assert ours.hex() == float(theirs).hex()
        assert ours_calls == scipy_calls


@pytest.mark.parametrize(
    ("f", "a", "b"),
    [
        (lambda x: x * x + 1, -1.0, 1.0),  # no sign change
        (lambda x: math.nan if x > 0.3 else x - 0.5, 0.0, 1.0),  # NaN
        (lambda x: 1e-200 * x, -1.0, 2.0),  # f(a) f(b) underflows to -0
        (lambda x: x, 0.0, 1.0),  # a root at an end
        (lambda x: x - 1, 0.0, 1.0),
        # a zero denominator in the interpolation (products of values near 1e-200 underflow,
        # or two equal values of a clipped function), which C divides into inf or NaN and
        # then bisects (the port raised ZeroDivisionError)
        (lambda x: 1e-200 * (x**3 - 0.2), 0.0, 1.0),
        (lambda x: 1e-150 * math.tanh(30 * (x - 0.61)), 0.0, 1.0),
        (lambda x: min(max(x - 0.3, -0.01), 0.01), 0.0, 1.0),
    ],
)
def test_brentq_edges_are_scipys(f, a, b):
    results = []
    for solve in (brentq, scipy.optimize.brentq):
        g, calls = _counted(f)
        try:
            results.append((solve(g, a, b), calls))
        except (ValueError, RuntimeError) as exc:
            results.append((type(exc), str(exc), calls))
    assert results[0] == results[1]
