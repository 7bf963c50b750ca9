"""Chebyshev-Lobatto points, their differentiation matrix and the interpolation from the
interior points: the spectral building blocks of the collocation (collocation.py)."""

from __future__ import annotations

import numpy as np

from .._types import FloatArray


def chebyshev_lobatto(nodes: int) -> tuple[FloatArray, FloatArray]:
    """Chebyshev-Lobatto points x_j = cos(j pi / (nodes-1)) and the matrix of d/dx.

    Trefethen's construction (Spectral Methods in MATLAB, ch. 6) with the diagonal set by
    the negative row sum, so the matrix differentiates constants exactly.

    >>> x, Dx = chebyshev_lobatto(5)
    >>> bool(np.allclose(Dx @ x**3, 3 * x**2))
    True
    """
    N = nodes - 1
    j = np.arange(nodes)
    x = np.cos(np.pi * j / N)
    c = np.where((j == 0) | (j == N), 2.0, 1.0) * (-1.0) ** j
    dX = x[:, None] - x[None, :]
    Dx = np.outer(c, 1.0 / c) / (dX + np.eye(nodes))
    Dx -= np.diag(Dx.sum(axis=1))
    return x, Dx


def interior_interpolation(nodes: int) -> FloatArray:
    """Values at all ``nodes`` Lobatto points of the degree nodes-3 polynomial through the
    interior points x_1 .. x_{nodes-2} (the pressure space of the P_N - P_{N-2} scheme).

    Barycentric formula; the interior points are the zeros of U_{N-1}, whose barycentric
    weights are (-1)^j sin^2(j pi / N).

    >>> P = interior_interpolation(8)
    >>> x = chebyshev_lobatto(8)[0]
    >>> bool(np.allclose(P @ x[1:-1]**5, x**5))
    True
    """
    N = nodes - 1
    j = np.arange(1, N)
    x = np.cos(np.pi * np.arange(nodes) / N)
    y, w = x[1:-1], (-1.0) ** j * np.sin(np.pi * j / N) ** 2
    P = np.zeros((nodes, N - 1))
    P[1:-1] = np.eye(N - 1)
    for row in (0, N):
        c = w / (x[row] - y)
        P[row] = c / c.sum()
    return P
