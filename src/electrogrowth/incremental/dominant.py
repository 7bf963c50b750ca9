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
incoming basis (in hat coordinates, at the start R_a of a segment) X = X+ + X-
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
    """2 min |Re nu| over the eigenvalues nu of the Hamiltonian Q: the rate (per unit R) at
    which the carried subspace approaches the dominant one (0 to rounding if some nu is on
    the imaginary axis, where the incremental problem is not strongly elliptic).

    The nu come in pairs +-nu, so the four mu = nu^2 are each a double eigenvalue of Q^2
    and the roots of a quartic. Its coefficients follow from the traces of the powers of
    S = Q^2 - c I (Newton's identities), c the mean of the mu: a short wave's mu cluster
    about c, and without the shift the identities would cancel. Its roots are the
    eigenvalues of the 4x4 companion matrix, and Re nu = Re sqrt(mu). Two 8x8 products
    and a 4x4 eigenproblem (~6 us) instead of the 8x8 complex one (~20 us, three per short
    wave's plan); the two agree to ~1e-7 where the mu nearly coincide
    (docs/derivation-dominant.md, tests/incremental/test_dominant.py).
    """
    S = _product(Q, Q)
    c = np.trace(S) / 8.0
    for a in range(8):
        S[a, a] -= c
    S2 = _product(S, S)
    t3 = t4 = 0.0
    for a in range(8):
        for b in range(8):
            t3 += S2[a, b] * S[b, a]
            t4 += S2[a, b] * S2[b, a]
    p2, p3, p4 = 0.5 * np.trace(S2), 0.5 * t3, 0.5 * t4  # power sums of mu - c (p1 = 0)
    e2, e3 = -0.5 * p2, p3 / 3.0  # elementary symmetric functions (e1 = 0)
    e4 = (0.5 * p2 * p2 - p4) / 4.0
    if not (np.isfinite(c) and np.isfinite(e2) and np.isfinite(e3) and np.isfinite(e4)):
        return 0.0
    companion = np.zeros((4, 4), np.complex128)  # of x^4 + e2 x^2 - e3 x + e4
    companion[0, 1], companion[0, 2], companion[0, 3] = -e2, e3, -e4
    for a in range(3):
        companion[a + 1, a] = 1.0
    lo = np.inf
    for x in np.linalg.eigvals(companion):
        lo = min(lo, abs(np.sqrt(x + c).real))
    return 2.0 * lo


@nb.njit(cache=True)
def _product(X, Y):
    """X Y of two small square matrices, in loops (numba's @ calls BLAS: slower at 8x8)."""
    n = X.shape[0]
    out = np.empty((n, n))
    for a in range(n):
        for b in range(n):
            acc = 0.0
            for q in range(n):
                acc += X[a, q] * Y[q, b]
            out[a, b] = acc
    return out


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
def hold_left_out(P, keep) -> None:
    """P <- the projector of a mode family's block (bit j of ``keep`` set: pair j kept).

    A family leaves pairs out because they decouple (their entries in Q carry a factor
    k r = 0 or m = 0), so Q and its sign are block-diagonal. A left-out pair is carried
    unchanged on its constant subspace U_j = S~_j (z~_jj = 1, impedance._start), which is
    not W+: its block of P becomes the projector on that line, [[1, 1], [1, 1]] / 2, so
    the carried basis lies in the new range there exactly (no remnant), its U row gives
    det A the factor 1, and the dominant impedance keeps z~_jj = 1, z~_ji = 0."""
    for j in range(4):
        if not (keep >> j) & 1:
            for a in range(8):
                P[j, a] = P[4 + j, a] = P[a, j] = P[a, 4 + j] = 0.0
            P[j, j] = P[j, 4 + j] = P[4 + j, j] = P[4 + j, 4 + j] = 0.5


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


@nb.njit(cache=True)
def split_sizes(P, X, s):
    """(sign det A, log|det A|, rho) for the incoming basis X (8, 4), A the U rows of
    X+ = P X: rho = max |B X- B_U^-1| / max |B_U A B_U^-1| (B as in
    :func:`split_orientation`), the remnant relative to the *size* of A, not to its
    inverse. It stays finite where det A = 0 (at a root of a mode of the inner face,
    where :func:`split_orientation`'s remnant is infinite); it cannot fall below the
    O(1 / |(m, k r)|) by which the frozen W+ differs from the true dominant subspace,
    which is why the caller bounds the true remnant by the attraction rate instead
    (short_wave_start.keep_plan). (0, nan, inf) if the sizes are not finite."""
    Xp = P @ X
    A = Xp[:4].copy()
    d = determinant(A)
    C = X - Xp
    top, rest = 0.0, 0.0
    for a in range(8):
        for b in range(4):
            v = C[a, b] * (s if b == 3 else 1.0)
            if a == 3:
                v /= s
            elif a == 7:
                v *= s
            rest = max(rest, abs(v))
            if a < 4:
                u = A[a, b] * (s if b == 3 else 1.0) / (s if a == 3 else 1.0)
                top = max(top, abs(u))
    if not (np.isfinite(d) and np.isfinite(rest) and top > 0.0 and np.isfinite(top)):
        return 0.0, np.nan, np.inf
    sign = 1.0 if d > 0.0 else (-1.0 if d < 0.0 else 0.0)
    return sign, (np.log(abs(d)) if d != 0.0 else -np.inf), rest / top


@nb.njit(cache=True)
def growth_rate(Q, z, keep) -> float:
    """tr(Q1 + Q2 z) over the kept pairs: d log|det U| / dR of a basis [U; z U] carried by
    d(eta~)/dR = Q eta~ while its subspace stays z (Liouville)."""
    acc = 0.0
    for i in range(4):
        if (keep >> i) & 1:
            acc += Q[i, i]
            for j in range(4):
                if (keep >> j) & 1:
                    acc += Q[i, 4 + j] * z[j, i]
    return acc
