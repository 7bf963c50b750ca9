"""The 16 coordinate charts of the Lagrangian Grassmannian in which the kernel carries the
impedance subspace (impedance.py), and the pole-free target read off any of them.

Chart J exchanges (U_j, S_j) -> (S_j, -U_j) for j in J, a symplectic swap that keeps the
Riccati form and the symmetry of z~; J = {} is the paper's impedance. The kernel leaves a
chart once an entry of z~ exceeds SWITCH (some chart always has every entry <= ~1.5) and
moves to the chart of the best-conditioned pivot. The target

    f = sign(det U~) det(z~[J', J']) / sqrt(det(I + z~^T z~)),   J' = complement of J,

is the same in every chart: det(M2) / sqrt(det(M^T M)) of the propagated basis M.

A mode family that keeps only some of the four pairs (U_j, S_j) (``keep``, bit j set: pair j
kept; incremental/targets.py) zeroes the rows and columns of the other pairs in every
chart (:func:`chart_setup`). Those pairs are decoupled from the kept ones exactly where the
family is used (torsion at m = 0, anti-plane shear at k = 0), so the kept block is the
family's own Stroh system; each left-out pair is carried as the constant z~_jj = 1
(-1 in a chart that swaps it), which multiplies the target by exactly 1/sqrt(2).
"""

from __future__ import annotations

import numba as nb
import numpy as np

SWITCH = 4.0  # leave a chart once an entry of z~ exceeds this (some chart has all <= ~1.5)


@nb.njit(cache=True)
def chart_perm(J, perm, sign):
    """eta~_a = sign[a] * eta^_{perm[a]} for chart J (bit j set: swap pair j)."""
    for j in range(4):
        if (J >> j) & 1:
            perm[j], sign[j] = 4 + j, 1.0
            perm[4 + j], sign[4 + j] = j, -1.0
        else:
            perm[j], sign[j] = j, 1.0
            perm[4 + j], sign[4 + j] = 4 + j, 1.0


@nb.njit(cache=True)
def chart_setup(J, s, keep, perm, mult):
    """G~[a, b] = G[perm[a], perm[b]] * mult[a, b]: chart J, the scaling S -> S / s and
    the pairs kept (bit j of ``keep`` set: pair (U_j, S_j) kept, else its rows and columns
    are zero)."""
    sign = np.empty(8)
    chart_perm(J, perm, sign)
    for a in range(8):
        for b in range(8):
            v = sign[a] * sign[b] * ((keep >> (perm[a] % 4)) & 1) * ((keep >> (perm[b] % 4)) & 1)
            if perm[a] < 4 and perm[b] >= 4:
                v *= s
            elif perm[a] >= 4 and perm[b] < 4:
                v /= s
            mult[a, b] = v


@nb.njit(cache=True)
def determinant(a):
    """Determinant of a small square matrix by Gaussian elimination with partial pivoting
    (``a`` is not modified)."""
    m = a.copy()
    det = 1.0
    n = a.shape[0]
    for c in range(n):
        piv = c
        for i in range(c + 1, n):
            if abs(m[i, c]) > abs(m[piv, c]):
                piv = i
        if m[piv, c] == 0.0:
            return 0.0
        if piv != c:
            for j in range(n):
                m[c, j], m[piv, j] = m[piv, j], m[c, j]
            det = -det
        det *= m[c, c]
        for i in range(c + 1, n):
            f = m[i, c] / m[c, c]
            for j in range(c, n):
                m[i, j] -= f * m[c, j]
    return det


@nb.njit(cache=True)
def inverse(A, out) -> bool:
    """out = A^-1 by Gauss-Jordan with partial pivoting; False if A is singular."""
    n = A.shape[0]
    m = A.copy()
    for i in range(n):
        for j in range(n):
            out[i, j] = 1.0 if i == j else 0.0
    for c in range(n):
        piv = c
        for i in range(c + 1, n):
            if abs(m[i, c]) > abs(m[piv, c]):
                piv = i
        if m[piv, c] == 0.0 or not np.isfinite(m[piv, c]):
            return False
        if piv != c:
            for j in range(n):
                m[c, j], m[piv, j] = m[piv, j], m[c, j]
                out[c, j], out[piv, j] = out[piv, j], out[c, j]
        d = 1.0 / m[c, c]
        for j in range(n):
            m[c, j] *= d
            out[c, j] *= d
        for i in range(n):
            if i != c and m[i, c] != 0.0:
                f = m[i, c]
                for j in range(n):
                    m[i, j] -= f * m[c, j]
                    out[i, j] -= f * out[c, j]
    return True


@nb.njit(cache=True)
def right_divide(b, a, out):
    """out = b a^-1 (4x4) by Gaussian elimination with partial pivoting on a^T; False, and
    ``out`` undefined, at a zero or non-finite pivot or a non-finite result. Unlike
    np.linalg.solve it never raises, which inside the parallel kernel would not be caught
    (the caller turns False into the NO_CHART status)."""
    n = a.shape[0]
    m = a.T.copy()  # solve a^T x = b^T: x = out^T
    x = b.T.copy()
    for c in range(n):
        piv = c
        for i in range(c + 1, n):
            if abs(m[i, c]) > abs(m[piv, c]):
                piv = i
        if not np.isfinite(m[piv, c]) or m[piv, c] == 0.0:
            return False
        if piv != c:
            for j in range(n):
                m[c, j], m[piv, j] = m[piv, j], m[c, j]
                x[c, j], x[piv, j] = x[piv, j], x[c, j]
        for i in range(c + 1, n):
            f = m[i, c] / m[c, c]
            for j in range(c, n):
                m[i, j] -= f * m[c, j]
            for j in range(n):
                x[i, j] -= f * x[c, j]
    for c in range(n - 1, -1, -1):
        for j in range(n):
            acc = x[c, j]
            for i in range(c + 1, n):
                acc -= m[c, i] * x[i, j]
            x[c, j] = acc / m[c, c]
    for i in range(n):
        for j in range(n):
            if not np.isfinite(x[j, i]):
                return False
            out[i, j] = x[j, i]
    return True


@nb.njit(cache=True)
def hat_basis(z, J):
    """The basis P_J^T [I; z~] (8, 4) of the subspace z~ of chart J in hat coordinates
    (chart {} with S scaled), with the orientation of [I; z~]."""
    X = np.zeros((8, 4))
    perm = np.empty(8, np.int64)
    sign = np.empty(8)
    chart_perm(J, perm, sign)
    for a in range(8):
        for c in range(4):
            val = (1.0 if a == c else 0.0) if a < 4 else z[a - 4, c]
            X[perm[a], c] += sign[a] * val
    return X


@nb.njit(cache=True)
def switch_chart(z, J):
    """Best chart for the subspace z~ (chart J); returns (z_new, J_new, det W1).

    W1 is the new chart's U-block of the basis P_J^T [I; z~], so det W1 is the factor by
    which det U~ changes at the switch: its sign the orientation's, its size part of the
    carried basis' growth (impedance.integrate_one's log_norm)."""
    X = hat_basis(z, J)
    perm = np.empty(8, np.int64)
    sign = np.empty(8)
    best, bestJ, bestd = np.inf, -1, 1.0
    zbest = np.zeros((4, 4))
    for Jn in range(16):
        chart_perm(Jn, perm, sign)
        W1 = np.empty((4, 4))
        W2 = np.empty((4, 4))
        for a in range(4):
            for c in range(4):
                W1[a, c] = sign[a] * X[perm[a], c]
                W2[a, c] = sign[4 + a] * X[perm[4 + a], c]
        d = determinant(W1)
        if not np.isfinite(d) or abs(d) < 1e-12:  # W1 (entries O(1)) not invertible
            continue
        zn = np.empty((4, 4))
        if not right_divide(W2, W1, zn):  # W2 W1^-1 not representable: not this chart
            continue
        size = np.max(np.abs(zn))
        if size < best:
            best, bestJ, bestd = size, Jn, d
            zbest[:, :] = zn
    return zbest, bestJ, bestd


@nb.njit(cache=True)
def chart_target(z, J, orient):
    """f = orient * det(z[J', J']) / sqrt(det(I + z^T z))."""
    idx = np.empty(4, np.int64)
    n = 0
    for j in range(4):
        if not (J >> j) & 1:
            idx[n] = j
            n += 1
    num = 1.0
    if n > 0:
        sub = np.empty((n, n))
        for a in range(n):
            for b in range(n):
                sub[a, b] = z[idx[a], idx[b]]
        num = determinant(sub)
    M = np.eye(4) + z.T @ z
    return orient * num / np.sqrt(determinant(M))


def physical_impedance(z_chart: np.ndarray, chart: int, scale: float) -> np.ndarray:
    """The paper's impedance z (S = z U) from the kernel's chart representation.

    Infinite where the subspace is not a graph over U (a pole of z), which is exactly why
    the kernel does not use it.
    """
    perm = np.empty(8, np.int64)
    sign = np.empty(8)
    chart_perm(chart, perm, sign)
    X = np.zeros((8, 4))
    Y = np.vstack([np.eye(4), z_chart])
    for a in range(8):
        X[perm[a]] += sign[a] * Y[a]
    return scale * X[4:] @ np.linalg.inv(X[:4])
