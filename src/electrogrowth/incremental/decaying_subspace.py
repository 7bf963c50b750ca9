"""The decaying subspace of the half-space problem, compiled: the face and interface
targets of halfspace.py vectorised over wave directions psi.

The basis of the decaying solutions is M = P [0; I] with P = (I -+ sign N) / 2 the spectral
projector of the limit matrix N(psi) = sum_k w_k(psi) E_k (stroh_limit.py), sign N by
Newton's iteration (dominant.matrix_sign); the targets are determinants of M's blocks over
sqrt(det M^T M), and the ellipticity margin is read off the restriction of N to M.
"""

from __future__ import annotations

import numba
import numpy as np

from .charts import determinant, inverse
from .dominant import matrix_sign


@numba.njit(cache=True)
def _decaying_basis(E, w, inner, Z, N, Zi, M) -> bool:
    """M (8, 4) = P[:, 4:], P the projector on the decaying subspace of N = sum_k w[k] E[k]
    (left in N), from sign(N) by Newton's iteration Z <- (Z + Z^-1) / 2 (determinant
    scaling for the first 4 steps). Once a step falls below 1e-8 |Z| convergence is
    quadratic and two more reach rounding level. False if the iteration fails."""
    for a in range(8):
        for b in range(8):
            acc = 0.0
            for k in range(6):
                acc += w[k] * E[k, a, b]
            Z[a, b] = acc
            N[a, b] = acc
    if not matrix_sign(Z, Zi):
        return False
    sgn = -0.5 if inner else 0.5
    for a in range(8):
        for b in range(4):
            M[a, b] = sgn * Z[a, 4 + b] + (0.5 if a == 4 + b else 0.0)
    return True


@numba.njit(cache=True)
def _gram(M, gram, gi) -> float:
    """gram = M^T M, gi its inverse; returns det(gram), 0 if it is not invertible."""
    for a in range(4):
        for b in range(4):
            acc = 0.0
            for c in range(8):
                acc += M[c, a] * M[c, b]
            gram[a, b] = acc
    g = determinant(gram)
    if not (g > 1e-200 and inverse(gram, gi)):
        return 0.0
    return g


@numba.njit(cache=True)
def _restricted_margin(N, M, gi) -> float:
    """min |Re nu| / max |nu| over the eigenvalues nu of the restriction
    R = (M^T M)^-1 M^T N M of N to the subspace spanned by M (the other four are -nu)."""
    NM = np.empty((8, 4))
    MNM = np.empty((4, 4))
    R = np.empty((4, 4), np.complex128)
    for a in range(8):
        for b in range(4):
            acc = 0.0
            for c in range(8):
                acc += N[a, c] * M[c, b]
            NM[a, b] = acc
    for a in range(4):
        for b in range(4):
            acc = 0.0
            for c in range(8):
                acc += M[c, a] * NM[c, b]
            MNM[a, b] = acc
    for a in range(4):
        for b in range(4):
            acc = 0.0
            for c in range(4):
                acc += gi[a, c] * MNM[c, b]
            R[a, b] = acc
    ev = np.linalg.eigvals(R)
    lo, hi = np.inf, 0.0
    for e in ev:
        lo = min(lo, abs(e.real))
        hi = max(hi, abs(e))
    return lo / hi if hi > 0.0 else 0.0


@numba.njit(cache=True)
def _targets_kernel(E, w, inner, pressure, f, margin):
    """f[i] = sign(det X) det(Y - Z X) / sqrt(det M^T M), M = [X; Y] = P[:, 4:], P the
    projector on the decaying subspace of N_i = sum_k w[i, k] E[k] (:func:`_decaying_basis`),
    Z = -pressure [[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], 0] the scaled follower-pressure
    impedance (c = w[i, 1], s = w[i, 2]; Z = 0 without pressure: det Y).

    margin[i] = min |Re nu| / max |nu| over the eigenvalues nu of the restriction
    R = (M^T M)^-1 M^T N M of N to the computed subspace (the other four are -nu): where
    N has eigenvalues on the imaginary axis (loss of ellipticity) the split picks some of
    them and the margin is at rounding level. f[i] = NaN, margin[i] = 0 if the iteration
    fails."""
    Z = np.empty((8, 8))
    N = np.empty((8, 8))
    Zi = np.empty((8, 8))
    M = np.empty((8, 4))
    gram = np.empty((4, 4))
    gi = np.empty((4, 4))
    B = np.empty((4, 4))
    for i in range(w.shape[0]):
        f[i] = np.nan
        margin[i] = 0.0
        if not _decaying_basis(E, w[i], inner, Z, N, Zi, M):
            continue
        g = _gram(M, gram, gi)
        if g == 0.0:
            continue
        dx = determinant(M[:4].copy())
        for a in range(4):
            for b in range(4):
                B[a, b] = M[4 + a, b]
        if pressure != 0.0:  # B = Y - Z X, Z = -P [[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], 0]
            c, s = w[i, 1], w[i, 2]
            for b in range(4):
                B[0, b] += pressure * (c * M[1, b] + s * M[2, b])
                B[1, b] += pressure * c * M[0, b]
                B[2, b] += pressure * s * M[0, b]
        dy = determinant(B)
        f[i] = (1.0 if dx >= 0.0 else -1.0) * dy / np.sqrt(g)
        margin[i] = _restricted_margin(N, M, gi)


@numba.njit(cache=True)
def _interface_kernel(Eb, Ea, w, f, margin):
    """f[i] = sign(det X_b det X_a) det [M_b M_a] / sqrt(det(M_b^T M_b) det(M_a^T M_a))
    = det(z_b - z_a) / sqrt(det(I + z_b^T z_b) det(I + z_a^T z_a)): M_b the solutions of the
    layer below decaying as r decreases (its half-space at an outer face), M_a those of the
    layer above decaying as r increases (at an inner face). margin[i] the smaller of the two
    restricted margins."""
    Z = np.empty((8, 8))
    Nb = np.empty((8, 8))
    Na = np.empty((8, 8))
    Zi = np.empty((8, 8))
    Mb = np.empty((8, 4))
    Ma = np.empty((8, 4))
    gram = np.empty((4, 4))
    gib = np.empty((4, 4))
    gia = np.empty((4, 4))
    W = np.empty((8, 8))
    for i in range(w.shape[0]):
        f[i] = np.nan
        margin[i] = 0.0
        if not _decaying_basis(Eb, w[i], False, Z, Nb, Zi, Mb):
            continue
        if not _decaying_basis(Ea, w[i], True, Z, Na, Zi, Ma):
            continue
        gb = _gram(Mb, gram, gib)
        ga = _gram(Ma, gram, gia)
        if gb == 0.0 or ga == 0.0:
            continue
        for a in range(8):
            for b in range(4):
                W[a, b] = Mb[a, b]
                W[a, 4 + b] = Ma[a, b]
        sx = determinant(Mb[:4].copy()) * determinant(Ma[:4].copy())
        f[i] = (1.0 if sx >= 0.0 else -1.0) * determinant(W) / np.sqrt(gb * ga)
        margin[i] = min(_restricted_margin(Nb, Mb, gib), _restricted_margin(Na, Ma, gia))
