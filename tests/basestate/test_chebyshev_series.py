"""The base states' Chebyshev series equal NumPy's bit for bit (basestate/chebyshev_series.py)."""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import chebyshev as cheb

from electrogrowth.basestate import clenshaw_kernel  # loads numba: the compiled route
from electrogrowth.basestate.chebyshev_series import ChebyshevSeries, _compiled, chebinterpolate


def test_the_compiled_route_is_taken_once_numba_is_loaded():
    assert _compiled() is clenshaw_kernel.clenshaw


@pytest.mark.parametrize("seed", range(50))
def test_series_values_equal_numpys(seed):
    rng = np.random.default_rng(seed)
    size = int(rng.integers(1, 90))
    coef = rng.normal(size=size) * np.exp(-rng.uniform(0, 1) * np.arange(size))
    a = rng.uniform(0.5, 3.0)
    domain = [a, a + rng.uniform(1e-3, 3.0)]
    x = rng.uniform(*domain, size=int(rng.integers(1, 70)))
    if seed % 5 == 0:
        x = x[::2]  # not contiguous
    fast, slow = ChebyshevSeries(coef, domain=domain), cheb.Chebyshev(coef, domain=domain)
    assert fast(x).tobytes() == slow(x).tobytes()
    lo = domain[0]
    assert fast.integ(lbnd=lo)(x).tobytes() == slow.integ(lbnd=lo)(x).tobytes()
    assert isinstance(fast.integ(lbnd=lo), ChebyshevSeries)
    assert fast(float(x[0])) == slow(float(x[0]))  # a scalar: NumPy's own route


@pytest.mark.parametrize("deg", [16, 32, 64, 128])
def test_interpolation_equals_numpys(deg):
    rng = np.random.default_rng(deg)
    scales = rng.uniform(0.5, 5.0, size=4)

    def f(x):
        return np.stack([np.exp(s * x) * np.cos(3 * s * x) for s in scales], axis=-1)

    assert chebinterpolate(f, deg).tobytes() == cheb.chebinterpolate(f, deg).tobytes()
    assert chebinterpolate(np.sin, deg).tobytes() == cheb.chebinterpolate(np.sin, deg).tobytes()
