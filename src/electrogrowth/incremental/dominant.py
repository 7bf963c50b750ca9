"""Where the inner face is forgotten: the dominant subspace of the frozen Stroh system.

Carried outward, the subspace of solutions that satisfy the inner-face conditions is
pulled towards the **dominant** subspace: the solutions that grow fastest with r. With
the moduli frozen at a radius, d(eta~)/dR = Q eta~ (Q = w G~, the chart-{} Stroh matrix
with S scaled by s, as in impedance.py) has eigenvalues +-nu in pairs (Q is Hamiltonian);
the four with Re nu > 0 span the growing subspace W+, the other four the decaying W-.
A perturbation of the carried subspace away from W+ shrinks like exp(-2 min |Re nu| R):
for a short wave (|(m, k r)| large) the rate is large and, a few wavelengths inside the
wall, the subspace is W+ to within rounding, whatever the inner face was. So the
impedance kernel may start a short wave's integration near the outer face, from W+
there, instead of integrating the whole wall with steps limited by stability (the stiff
part of a scan). Derivation and checks: docs/derivation-dominant.md.

Only the orientation of the subspace is not forgotten: the target is
det(M2) / sqrt(det M^T M) of the *oriented* basis carried from the inner face. Write the
incoming basis (in hat coordinates, at the start R_a of the outer segment) X = X+ + X-
with X+- = P+- X, P+ = (I + sign Q) / 2 the spectral projector. W+ is a graph over U
(strong ellipticity: no growing solution has U = 0 and S != 0 on a face, the argument of
halfspace.py), so X+ = [I; z+] A with A the U rows of X+. Carried outward, [I; z+(R)] E(R)
with dE/dR = (Q1 + Q2 z+) E, whose determinant exp(int tr(Q1 + Q2 z+)) is positive. Hence
the carried basis is [I; z+(R_s)] times a matrix of determinant sign(det A): the target
equals sign(det A) times the target of the integration started at R_s from [I; z+(R_s)].
The X- part decays like ||X- A^-1|| exp(-rate (R_s - R_a)), which the caller bounds.

Small dense kernels only (no table, no mode): impedance.py calls them with the frozen Q.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from .charts import determinant, inverse, right_divide


@nb.njit(cache=True)
def matrix_sign(Z, Zi) -> bool:
    """Z <- sign(Z) in place by Newton's iteration Z <- (mu Z + Z^-1 / mu) / 2
    (determinant scaling mu for the first 4 steps; Zi is scratch). Once a step falls below
    1e-8 |Z| convergence is quadratic and two more reach rounding level. False if the
    iteration fails (an eigenvalue on or next to the imaginary axis)."""
    n = Z.shape[0]
    extra = -1
    for it in range(80):
        if not inverse(Z, Zi):
            return False
        mu = 1.0
        if it < 4:
            dz = abs(determinant(Z))
            if dz > 0.0 and np.isfinite(dz):
                mu = dz ** (-1.0 / n)
        step, size = 0.0, 0.0
        for a in range(n):
            for b in range(n):
                new = 0.5 * (mu * Z[a, b] + Zi[a, b] / mu)
                step = max(step, abs(new - Z[a, b]))
                size = max(size, abs(new))
                Z[a, b] = new
        if not np.isfinite(step):
            return False
        if extra > 0:
            extra -= 1
        elif extra < 0 and it >= 4 and step <= 1e-8 * size:
            extra = 2
        if extra == 0:
            return True
    return False


@nb.njit(cache=True)
def attraction_rate(Q) -> float:
    """2 min |Re nu| over the eigenvalues nu of Q: the rate (per unit R) at which the
    carried subspace approaches the dominant one (0 if some nu is on the imaginary axis,
    where the incremental problem is not strongly elliptic)."""
    ev = np.linalg.eigvals(Q.astype(np.complex128))
    lo = np.inf
    for e in ev:
        lo = min(lo, abs(e.real))
    return 2.0 * lo


@nb.njit(cache=True)
def growing_projector(Q, P, Zi) -> bool:
    """P <- (I + sign Q) / 2, the projector on W+ along W- (Zi scratch)."""
    P[:, :] = Q
    if not matrix_sign(P, Zi):
        return False
    n = P.shape[0]
    for a in range(n):
        for b in range(n):
            P[a, b] = 0.5 * P[a, b] + (0.5 if a == b else 0.0)
    return True


@nb.njit(cache=True)
def dominant_impedance(P, z) -> bool:
    """z <- z+, the graph of W+ = range P over U (S = z+ U, hat coordinates): P [I; 0]
    spans W+ because W- is a graph over U too."""
    return right_divide(P[4:, :4].copy(), P[:4, :4].copy(), z)


@nb.njit(cache=True)
def split_orientation(P, X, s):
    """(sign det A, remnant) for the incoming basis X (8, 4): A the U rows of X+ = P X,
    X- = X - X+, remnant = max |B X- A^-1 B_U^-1| with the balancing B = diag(1, 1, 1,
    1/s, 1, 1, 1, s) that makes both entries of the electric pair (r Delta_r, -Phi / s)
    O(1) for a short wave (they differ by s^2 in hat coordinates); (0, inf) if A is
    singular. I + top(X-) A^-1 is similar to I + B_U top(X-) A^-1 B_U^-1, so a remnant
    below 0.1 makes det A and det(top X) agree in sign."""
    Xp = P @ X
    A = Xp[:4].copy()
    d = determinant(A)
    Ai = np.empty((4, 4))
    if d == 0.0 or not np.isfinite(d) or not inverse(A, Ai):
        return 0.0, np.inf
    C = (X - Xp) @ Ai
    for a in range(8):
        C[a, 3] *= s  # B_U^-1 on the right
    for b in range(4):
        C[3, b] /= s
        C[7, b] *= s
    return (1.0 if d > 0.0 else -1.0), np.max(np.abs(C))
