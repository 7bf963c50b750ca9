"""The base states' Chebyshev series: interpolated and evaluated as NumPy does, faster.

The base states keep sigma_rr (and the layered state its antiderivatives) as
``numpy.polynomial.Chebyshev`` series, and a march evaluates them at the Chebyshev table's
radii at every step: NumPy's ``chebval`` runs the recurrence as one array operation per
coefficient (~40 us for 33 coefficients at 17 radii, a tenth of a layered critical value).
:class:`ChebyshevSeries` is that class with ``__call__`` compiled for one-dimensional float
arrays: the same mapping of the domain (NumPy's own), then per point the same recurrence,

    c0, c1 = c[-2], c[-1];  c0, c1 = c[-i] - c1, c0 + 2 x c1  (i = 3 .. len(c));  c0 + c1 x,

the same operations in the same order without fused multiply-adds, so the values equal
NumPy's bit for bit (tests/basestate/test_chebyshev_series.py). Anything else (scalars, other
shapes, short series), and any evaluation before numba is loaded by the compiled kernels, is
NumPy's own.

:func:`chebinterpolate` is NumPy's, with the nodes and the Vandermonde matrix of each degree
remembered instead of rebuilt at every call (a base state interpolates three to six
integrands; the same arrays, the same product, the same coefficients).
"""

from __future__ import annotations

import functools
import sys

import numpy as np
from numpy.polynomial import chebyshev as cheb
from numpy.polynomial import polyutils as pu


class ChebyshevSeries(cheb.Chebyshev):
    """``numpy.polynomial.Chebyshev`` whose values at 1-d float arrays are compiled."""

    def __call__(self, arg):
        if (
            isinstance(arg, np.ndarray)
            and arg.ndim == 1
            and arg.dtype == np.float64
            and self.coef.dtype == np.float64
            and self.coef.ndim == 1
            and len(self.coef) >= 3
        ):
            clenshaw = _compiled()
            if clenshaw is not None:
                return clenshaw(pu.mapdomain(arg, self.domain, self.window), self.coef)
        return super().__call__(arg)


def _compiled():
    """The compiled recurrence (clenshaw_kernel.py) once the compiled kernels have loaded
    numba, else None: a base state alone (the ``state`` command) never imports numba, and
    NumPy's evaluation gives the same bits."""
    if "numba" not in sys.modules:
        return None
    from .clenshaw_kernel import clenshaw

    return clenshaw


@functools.lru_cache(maxsize=16)
def _nodes_and_vandermonde(deg: int) -> tuple[np.ndarray, np.ndarray]:
    """NumPy's chebpts1(deg + 1) and chebvander there, read-only."""
    x = cheb.chebpts1(deg + 1)
    m = cheb.chebvander(x, deg)
    x.setflags(write=False)
    m.setflags(write=False)
    return x, m


def chebinterpolate(func, deg: int) -> np.ndarray:
    """``numpy.polynomial.chebyshev.chebinterpolate(func, deg)``: the coefficients of the
    interpolant of func (vectorised, values on the last axis) at the deg + 1 Chebyshev points
    of the first kind, by the same arithmetic."""
    order = deg + 1
    x, m = _nodes_and_vandermonde(deg)
    c = np.dot(m.T, func(x))
    c[0] /= order
    c[1:] /= 0.5 * order
    return c
