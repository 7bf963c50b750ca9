"""The Clenshaw recurrence of NumPy's chebval, compiled (used by chebyshev_series.py once
numba is loaded: importing a base state alone must not import it)."""

from __future__ import annotations

import numba as nb
import numpy as np


@nb.njit(cache=True)
def clenshaw(x, c):
    """sum_k c[k] T_k(x) at each point of the 1-d array x (len(c) >= 3), as numpy's chebval."""
    n, size = x.shape[0], c.shape[0]
    out = np.empty(n)
    for j in range(n):
        x2 = 2 * x[j]
        c0, c1 = c[size - 2], c[size - 1]
        for i in range(3, size + 1):
            tmp = c0
            c0 = c[size - i] - c1
            c1 = tmp + c1 * x2
        out[j] = c0 + c1 * x[j]
    return out
