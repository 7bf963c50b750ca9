"""The compiled Clenshaw recurrence equals NumPy's chebval bit for bit (basestate/clenshaw.py)."""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import chebyshev as cheb

from electrogrowth.basestate.clenshaw import ChebyshevSeries


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
