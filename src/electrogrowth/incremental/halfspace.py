"""The short-wave limit of the Stroh system: a half-space at a face of the tube.

A wrinkle with m, k -> infinity (wave vector in the face fixed in direction) decays within
a distance ~ 1 / |(m / r, k)| of a face, where the base state is frozen: the tube looks
like a homogeneous, pre-stressed, pre-polarised half-space. Derivation and checks:
docs/derivation-surface.md.

**Limit of the Stroh matrix.** In d(eta)/dr = G(m, kr) eta / r (stroh.py, eta = [U_r, U_th,
U_z, r Delta_r, r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi]) put

    (m, k r) = Lam (cos psi, sin psi),    Lam = q r,    q = |(m / r, k)|,

with psi in [0, pi/2] the direction of the wave in the face (psi = 0: along theta,
psi = pi/2: along z; tan psi = k r / m). Displacements are O(1), stresses and D O(q), so
r Sigma and r Delta_r are O(Lam) and Phi is O(1): the scaled vector

    eta = T eta~,   T = diag(1, 1, 1, Lam, Lam, Lam, Lam, 1)

obeys d(eta~)/dr = (1/r) T^-1 G T eta~ = q [N(psi) + O(1 / Lam)] eta~, with the constant
limit (c = cos psi, s = sin psi; e, gamma, t, q_1a, h, b, a_13, g_a1 as in stroh.py)

    N1 = [[0, -c, -s, 0], [c t12, 0, 0, 0], [s t13, 0, 0, 0], [-xi, 0, 0, 0]],
    N2 = [[0, 0, 0, 0], [0, 1/gam12, 0, c e12/gam12], [0, 0, 1/gam13, s e13/gam13],
          [0, c e12/gam12, s e13/gam13, chi]],
    N3 = [[c^2 h12 + s^2 h13, 0, 0, 0],
          [0, c^2 b12 + s^2 A3232, c s (a13 + A2332 + 2p), c g21],
          [0, c s (a13 + A2332 + 2p), s^2 b13 + c^2 A2323, s g31],
          [0, c g21, s g31, K11]],
    N4 = -N1^T,
    xi = c^2 q12 + s^2 q13,   chi = c^2 (1/K22 + e12^2/gam12) + s^2 (1/K33 + e13^2/gam13).

N is Hamiltonian (J N symmetric, like G), so its eigenvalues come in pairs +-nu (and, N
being real, in conjugate pairs). It is homogeneous of degree 0 in (m, kr): the half-space
problem does not depend on q.

**Decaying solutions.** eta~ = v exp(q nu (r - r_f)) with N v = nu v. Into the wall means
Re nu < 0 at the inner face (r > r_i) and Re nu > 0 at the outer face (r < r_o). While
the incremental problem is strongly elliptic no nu is imaginary and exactly four decay;
they span the stable (resp. unstable) invariant subspace of N. Two routes compute it,
both well defined where nu is defective (the unloaded neo-Hookean state has every
nu = +-1, with Jordan blocks), where eigenvectors are not:

* :func:`decaying_solutions`: an ordered real Schur form N Z = Z T, whose first four
  columns Q = [X; Y] (X the U rows, Y the S rows) are an orthonormal basis;
* :meth:`FaceProblem.target` (vectorised, compiled): the spectral projector
  P = (I -+ sign N) / 2 (sign N by Newton's iteration Z <- (Z + Z^-1)/2) and the basis
  M = P [0; I]. Its columns are independent because no growing solution has U = 0 on the
  face (the argument below, for the mirrored half-space).

**Face conditions** (as the finite-mode solvers, stroh.py section 5): traction-free and
earthed increment of potential, Sigma_rr = Sigma_rth = Sigma_rz = Phi = 0, i.e. S = 0. A
decaying solution Q a satisfies them iff Y a = 0: the 4x4 boundary matrix is Y and the
half-space bifurcates when det Y = 0. The real, bounded target

    f = sign(det X) det Y / sqrt(det(M^T M)) = det(z) / sqrt(det(I + z^T z)),
    M = [X; Y] any basis,   z = Y X^-1 (S = z U),

depends only on the subspace (not on the basis) and vanishes exactly at bifurcation. It
has no poles: det X = 0 would be a decaying solution with U = 0 on the face, excluded by
strong ellipticity (its energy, a boundary term U.S, is 0).
On the unloaded tube z is negative (inner face) or positive (outer face) definite, so
f > 0 there for both faces and every psi.

**Loss of ellipticity.** When the four decaying nu cannot be split off (an eigenvalue
reaches the imaginary axis: a real wave vector solves the incremental equations, the
margin min |Re nu| / max |nu| <= ELLIPTICITY_TOL), the half-space problem is not
defined: the target is NaN and :func:`ellipticity_margin` says how far a state is.

The ideal neo-Hookean dielectric reduces to a scalar secular equation,
:func:`neo_hookean_secular` (closed form in docs/derivation-surface.md).
"""

from __future__ import annotations

import dataclasses
import math

import numba
import numpy as np
import numpy.typing as npt
import scipy.linalg

from ..errors import ParameterError
from ..model.materials import MODULI_INDEX
from .charts import determinant, inverse
from .dominant import matrix_sign

FloatArray = npt.NDArray[np.float64]

FACES = ("inner", "outer")
#: relative margin min |Re nu| / max |nu| below which the decaying split is refused
ELLIPTICITY_TOL = 1e-9

_I = MODULI_INDEX


def check_face(face: str) -> str:
    """Raise ParameterError unless ``face`` is "inner" or "outer"."""
    if face not in FACES:
        raise ParameterError(f"face = {face!r} is unknown; choose inner or outer")
    return face


#: the weights of :func:`limit_expansion`: N(psi) = sum_k w_k(psi) E_k
WEIGHTS = ("1", "c", "s", "c^2", "s^2", "c s")


def _weights(psi) -> FloatArray:
    psi = np.asarray(psi, float)
    c, s = np.cos(psi), np.sin(psi)
    w = np.empty(psi.shape + (6,))
    w[..., 0], w[..., 1], w[..., 2] = 1.0, c, s
    w[..., 3], w[..., 4], w[..., 5] = c * c, s * s, c * s
    return w


def limit_expansion(mod, p) -> FloatArray:
    """The six constant matrices E_k with N(psi) = sum_k w_k E_k, w = (1, c, s, c^2, s^2,
    c s), c = cos psi, s = sin psi (module docstring; the E_1 term is zero).

    ``mod`` (..., 23) and ``p`` broadcast; returns (..., 6, 8, 8). Building them once per
    face makes N for many directions one small matrix product.
    """
    mod = np.asarray(mod, float)
    M = [mod[..., k] for k in range(mod.shape[-1])]
    p = np.asarray(p, float)
    e12 = M[_I["G122"]] / M[_I["K22"]]
    e13 = M[_I["G133"]] / M[_I["K33"]]
    gam12 = M[_I["A1212"]] - e12 * M[_I["G122"]]
    gam13 = M[_I["A1313"]] - e13 * M[_I["G133"]]
    c12 = M[_I["A1221"]] + p - e12 * M[_I["G122"]]
    c13 = M[_I["A1331"]] + p - e13 * M[_I["G133"]]
    t12, t13 = c12 / gam12, c13 / gam13
    q12 = e12 * (gam12 - c12) / gam12  # xi = c^2 q12 + s^2 q13
    q13 = e13 * (gam13 - c13) / gam13
    h12 = M[_I["A2121"]] - e12 * M[_I["G122"]] - c12 * c12 / gam12
    h13 = M[_I["A3131"]] - e13 * M[_I["G133"]] - c13 * c13 / gam13
    b12 = M[_I["A1111"]] - 2.0 * M[_I["A1122"]] + M[_I["A2222"]] + 2.0 * p
    b13 = M[_I["A1111"]] - 2.0 * M[_I["A1133"]] + M[_I["A3333"]] + 2.0 * p
    a13 = M[_I["A1111"]] - M[_I["A1122"]] - M[_I["A1133"]] + M[_I["A2233"]]
    g21 = M[_I["G221"]] - M[_I["G111"]]
    g31 = M[_I["G331"]] - M[_I["G111"]]
    chi2 = 1.0 / M[_I["K22"]] + e12 * e12 / gam12  # chi = c^2 chi2 + s^2 chi3
    chi3 = 1.0 / M[_I["K33"]] + e13 * e13 / gam13
    k23 = a13 + M[_I["A2332"]] + 2.0 * p
    one = np.ones_like(gam12 * gam13 * p)
    c, s, cc, ss, cs = 1, 2, 3, 4, 5
    entries = [  # (weight, row, column, value)
        (c, 0, 1, -one),
        (s, 0, 2, -one),
        (c, 1, 0, t12),
        (0, 1, 5, 1.0 / gam12),
        (c, 1, 7, e12 / gam12),
        (s, 2, 0, t13),
        (0, 2, 6, 1.0 / gam13),
        (s, 2, 7, e13 / gam13),
        (cc, 3, 0, -q12),
        (ss, 3, 0, -q13),
        (c, 3, 5, e12 / gam12),
        (s, 3, 6, e13 / gam13),
        (cc, 3, 7, chi2),
        (ss, 3, 7, chi3),
        (cc, 4, 0, h12),
        (ss, 4, 0, h13),
        (c, 4, 5, -t12),
        (s, 4, 6, -t13),
        (cc, 4, 7, q12),
        (ss, 4, 7, q13),
        (cc, 5, 1, b12),
        (ss, 5, 1, M[_I["A3232"]]),
        (cs, 5, 2, k23),
        (c, 5, 3, g21),
        (c, 5, 4, one),
        (cs, 6, 1, k23),
        (ss, 6, 2, b13),
        (cc, 6, 2, M[_I["A2323"]]),
        (s, 6, 3, g31),
        (s, 6, 4, one),
        (c, 7, 1, g21),
        (s, 7, 2, g31),
        (0, 7, 3, M[_I["K11"]]),
    ]
    E = np.zeros(one.shape + (6, 8, 8))
    for w, i, j, v in entries:
        E[..., w, i, j] += v
    return E


def limit_matrix(mod, p, psi) -> FloatArray:
    """The constant half-space Stroh matrix N(psi) = lim T^-1 G T / Lam (module docstring).

    Parameters
    ----------
    mod : (..., 23) array
        Updated moduli at the face (order ``materials.MODULI_NAMES``).
    p : float or array
        Lagrange multiplier at the face.
    psi : float or array
        Wave direction in the face, tan psi = k r / m (0: along theta, pi/2: along z).

    Returns
    -------
    (..., 8, 8) array, the shapes of ``mod[..., 0]``, ``p`` and ``psi`` broadcast.

    Examples
    --------
    >>> from electrogrowth.model.materials import neo_hookean_moduli
    >>> N = limit_matrix(neo_hookean_moduli(1.0, 1.0, 1.0, 0.0), 1.0, 0.3)
    >>> bool(np.allclose(np.sort(np.linalg.eigvals(N).real), [-1] * 4 + [1] * 4, atol=1e-6))
    True
    """
    return np.einsum("...k,...kij->...ij", _weights(psi), limit_expansion(mod, p))


def decaying_solutions(N, face: str) -> tuple[FloatArray, FloatArray, float]:
    """The four solutions of the constant Stroh system d(eta~)/dr = q N eta~ decaying into
    the wall from ``face``.

    Returns
    -------
    (Q, nu, margin)
        Q (8, 4): orthonormal basis of the decaying invariant subspace (rows eta~);
        nu (4,): its eigenvalues (Re nu < 0 at the inner face, > 0 at the outer face);
        margin = min |Re nu| / max |nu| over all eight eigenvalues (0 < margin: elliptic).
        Q and nu are NaN when the split fails (margin <= ELLIPTICITY_TOL).
    """
    check_face(face)
    N = np.asarray(N, float)
    if not np.all(np.isfinite(N)):
        return np.full((8, 4), np.nan), np.full(4, np.nan), 0.0
    T, Z, sdim = scipy.linalg.schur(N, output="real", sort="lhp" if face == "inner" else "rhp")
    ev = _schur_eigenvalues(T)  # in Schur order: the decaying ones first
    margin = float(np.min(np.abs(ev.real)) / max(np.max(np.abs(ev)), 1e-300))
    if sdim != 4 or margin <= ELLIPTICITY_TOL:
        return np.full((8, 4), np.nan), np.full(4, np.nan), margin
    return Z[:, :4], ev[:4], margin


def _schur_eigenvalues(T) -> np.ndarray:
    """Eigenvalues of a real quasi-triangular T in diagonal order."""
    out = np.empty(T.shape[0], complex)
    i = 0
    while i < T.shape[0]:
        if i + 1 < T.shape[0] and T[i + 1, i] != 0.0:
            out[i : i + 2] = np.linalg.eigvals(T[i : i + 2, i : i + 2])
            i += 2
        else:
            out[i] = T[i, i]
            i += 1
    return out


def boundary_matrix(N, face: str) -> tuple[FloatArray, float]:
    """The 4x4 boundary matrix Y (the S = [r Sigma_r*, -Phi] rows of the orthonormal
    decaying basis) and the orientation sign(det X) of its U rows."""
    Q, _, _ = decaying_solutions(N, face)
    if not np.all(np.isfinite(Q)):
        return Q[4:], math.nan
    return Q[4:], float(np.sign(np.linalg.det(Q[:4])))


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


def _direction_weights(psi: float) -> FloatArray:
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[1.0, c, s, c * c, s * s, c * s]])


def _masked(problem, psi) -> FloatArray:
    """problem.target over an array of psi: NaN where the margin is below ELLIPTICITY_TOL."""
    psi = np.asarray(psi, float)
    if psi.ndim == 0:
        return np.float64(problem.target_scalar(float(psi)))
    f, margin = problem.target_and_margin(psi.reshape(-1))
    return np.where(margin > ELLIPTICITY_TOL, f, np.nan).reshape(psi.shape)


@dataclasses.dataclass(frozen=True)
class FaceProblem:
    """The half-space at one face: N(psi) = sum_k w_k(psi) E_k and its target.

    Build with :meth:`from_state` (a solved base state) or :meth:`from_moduli`; then
    :meth:`target` and :meth:`margin` are vectorised over psi. ``pressure`` is the follower
    pressure P on the face (sigma_rr = -P there; P_i at the inner face, P_o at the outer):
    the face condition is S~ = Z U~, Z = -P [[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], 0]
    (docs/derivation-layered-modes.md), and the target sign(det X) det(Y - Z X) /
    sqrt(det M^T M).
    """

    face: str
    expansion: FloatArray  # (6, 8, 8), see limit_expansion
    radius: float = math.nan  # current radius of the face (for k r / m), if known
    pressure: float = 0.0  # follower pressure on the face

    @property
    def name(self) -> str:
        return self.face

    @classmethod
    def from_moduli(
        cls, mod, p, face: str, radius: float = math.nan, pressure: float = 0.0
    ) -> FaceProblem:
        return cls(
            check_face(face),
            limit_expansion(np.asarray(mod, float).reshape(23), float(p)),
            float(radius),
            float(pressure),
        )

    @classmethod
    def from_state(cls, state, face: str) -> FaceProblem:
        mod, p, r = face_data(state, face)
        return cls.from_moduli(mod, p, face, r, face_pressure(state, face))

    def matrix(self, psi) -> FloatArray:
        """N(psi), shape psi.shape + (8, 8)."""
        return np.einsum("...k,kij->...ij", _weights(psi), self.expansion)

    def margin(self, psi) -> FloatArray:
        """Ellipticity margin min |Re nu| / max |nu| of N(psi) (0: not strongly elliptic)."""
        psi = np.asarray(psi, float)
        ev = np.linalg.eigvals(self.matrix(psi.reshape(-1)))
        out = np.min(np.abs(ev.real), -1) / np.maximum(np.max(np.abs(ev), -1), 1e-300)
        return out.reshape(psi.shape)

    def target(self, psi) -> FloatArray:
        """f = sign(det X) det(Y - Z X) / sqrt(det(M^T M)) for a basis M = [X; Y] of the
        decaying subspace (module docstring; Z = 0 without pressure), NaN where the
        decaying split fails.

        The basis is M = P [0; I], P = (I -+ sign N) / 2 the spectral projector on the
        decaying subspace (sign N by Newton's iteration, vectorised over psi): its columns
        span the subspace because no growing solution has U = 0 on the face (strong
        ellipticity, the argument that excludes poles)."""
        return _masked(self, psi)

    def target_scalar(self, psi: float) -> float:
        """:meth:`target` for one direction, as a float (less overhead)."""
        f, margin = np.empty(1), np.empty(1)
        _targets_kernel(
            self.expansion, _direction_weights(psi), self.face == "inner", self.pressure, f, margin
        )
        return float(f[0]) if margin[0] > ELLIPTICITY_TOL else math.nan

    def target_and_margin(self, psi) -> tuple[FloatArray, FloatArray]:
        """(f, margin) for a 1-D array of psi, f not masked (NaN only if no split at all);
        margin of the decaying eigenvalues as in :meth:`margin`."""
        flat = np.ascontiguousarray(np.asarray(psi, float).reshape(-1))
        f = np.empty(flat.size)
        margin = np.empty(flat.size)
        _targets_kernel(
            self.expansion, _weights(flat), self.face == "inner", self.pressure, f, margin
        )
        return f, margin


@dataclasses.dataclass(frozen=True)
class InterfaceProblem:
    """The short-wave problem at a bonded interface: two half-spaces, the layer below
    (moduli and p on its side, solutions decaying as r decreases, like an outer face) and
    the layer above (decaying as r increases, like an inner face), with eta~ continuous.

    With z_b = Y_b X_b^-1, z_a = Y_a X_a^-1 the interface bifurcates iff det(z_b - z_a) = 0;
    the target

        f = det(z_b - z_a) / sqrt(det(I + z_b^T z_b) det(I + z_a^T z_a))
          = sign(det X_b det X_a) det [M_b M_a] / sqrt(det(M_b^T M_b) det(M_a^T M_a))

    depends on the subspaces only, |f| <= 1 (Hadamard), and has no poles (X_b, X_a are
    invertible under strong ellipticity). On the unloaded tube z_b > 0 and z_a < 0, so
    f > 0. docs/derivation-layered-modes.md.
    """

    name: str
    below: FloatArray  # (6, 8, 8) expansion of the layer inside the interface
    above: FloatArray  # (6, 8, 8) expansion of the layer outside it
    radius: float = math.nan

    @classmethod
    def from_moduli(
        cls, mod_below, p_below, mod_above, p_above, name: str = "interface", radius=math.nan
    ) -> InterfaceProblem:
        return cls(
            name,
            limit_expansion(np.asarray(mod_below, float).reshape(23), float(p_below)),
            limit_expansion(np.asarray(mod_above, float).reshape(23), float(p_above)),
            float(radius),
        )

    @classmethod
    def from_state(cls, state, name: str) -> InterfaceProblem:
        k = _interface_index(state, name)
        R = state.tube.radii[k]
        return cls.from_moduli(
            np.asarray(state.moduli(R, side="inner"), float),
            float(state.pressure(R, side="inner")),
            np.asarray(state.moduli(R, side="outer"), float),
            float(state.pressure(R, side="outer")),
            name,
            float(state.radii[k]),
        )

    def margin(self, psi) -> FloatArray:
        """The smaller ellipticity margin of the two layers' N(psi)."""
        psi = np.asarray(psi, float)
        out = []
        for E in (self.below, self.above):
            N = np.einsum("...k,kij->...ij", _weights(psi.reshape(-1)), E)
            ev = np.linalg.eigvals(N)
            out.append(np.min(np.abs(ev.real), -1) / np.maximum(np.max(np.abs(ev), -1), 1e-300))
        return np.minimum(*out).reshape(psi.shape)

    def target(self, psi) -> FloatArray:
        """f(psi) (class docstring), NaN where either decaying split fails."""
        return _masked(self, psi)

    def target_scalar(self, psi: float) -> float:
        f, margin = np.empty(1), np.empty(1)
        _interface_kernel(self.below, self.above, _direction_weights(psi), f, margin)
        return float(f[0]) if margin[0] > ELLIPTICITY_TOL else math.nan

    def target_and_margin(self, psi) -> tuple[FloatArray, FloatArray]:
        flat = np.ascontiguousarray(np.asarray(psi, float).reshape(-1))
        f = np.empty(flat.size)
        margin = np.empty(flat.size)
        _interface_kernel(self.below, self.above, _weights(flat), f, margin)
        return f, margin


def surfaces(state_or_tube) -> tuple[str, ...]:
    """The surfaces where short waves can live: ("inner", "outer") for a homogeneous tube,
    and "interface-1", ..., "interface-(N-1)" (between layers k and k + 1) for a tube of N
    layers (a base state or a Tube)."""
    tube = getattr(state_or_tube, "tube", state_or_tube)
    return FACES + tuple(f"interface-{k}" for k in range(1, len(tube.layers)))


def _interface_index(state, name: str) -> int:
    n = len(state.tube.layers)
    prefix = "interface-"
    if isinstance(name, str) and name.startswith(prefix) and name[len(prefix) :].isdigit():
        k = int(name[len(prefix) :])
        if 1 <= k < n:
            return k
    raise ParameterError(
        f"surface = {name!r} is unknown; choose one of {', '.join(surfaces(state))}"
    )


def surface_radius(state, name: str) -> float:
    """Current radius of the surface ``name`` of a solved base state."""
    if name in FACES:
        return state.r_i if name == "inner" else state.r_o
    return float(state.radii[_interface_index(state, name)])


def surface_problem(state, name: str) -> FaceProblem | InterfaceProblem:
    """The short-wave problem at the surface ``name`` (:func:`surfaces`) of a solved base
    state: a FaceProblem (with the face's follower pressure) or an InterfaceProblem."""
    if name in FACES:
        return FaceProblem.from_state(state, name)
    return InterfaceProblem.from_state(state, name)


def target_from_moduli(mod, p, psi, face: str) -> FloatArray:
    """f(psi) of the half-space with moduli ``mod`` and multiplier ``p`` at ``face``.

    Bounded by 1 in modulus, continuous, zero exactly when the half-space bifurcates in
    direction psi, NaN where it is not strongly elliptic (:meth:`FaceProblem.target`).
    """
    return FaceProblem.from_moduli(mod, p, face).target(psi)


def schur_target(mod, p, psi: float, face: str) -> float:
    """The same f from the ordered real Schur basis of :func:`decaying_solutions` (one
    direction; slower, an independent route used to test :meth:`FaceProblem.target`)."""
    Q, _, _ = decaying_solutions(limit_matrix(mod, p, psi), face)
    if np.isnan(Q[0, 0]):
        return math.nan
    return math.copysign(1.0, np.linalg.det(Q[:4])) * float(np.linalg.det(Q[4:]))


def face_radius(state, face: str) -> float:
    """Reference radius R of the face: 1 (inner) or the outer radius (Rbar_o, R_N)."""
    if check_face(face) == "inner":
        return 1.0
    return state.tube.outer_radius


def face_data(state, face: str) -> tuple[FloatArray, float, float]:
    """(moduli (23,), p, current radius r) of a solved base state at ``face`` (for a layered
    state, of the layer at that face)."""
    R = face_radius(state, face)
    r = state.r_i if face == "inner" else state.r_o
    side = "outer" if face == "inner" else "inner"  # the layer on the wall's side
    return (
        np.asarray(state.moduli(R, side=side), float).reshape(23),
        float(state.pressure(R, side=side)),
        r,
    )


def face_pressure(state, face: str) -> float:
    """The follower pressure on ``face`` (P_i inner, P_o outer)."""
    return float(state.face_pressures[0 if check_face(face) == "inner" else 1])


def surface_target(state, face: str, psi) -> FloatArray:
    """The half-space target f(state, face, psi) (:meth:`FaceProblem.target`) at a face
    of a solved base state (basestate.tube.BaseState), vectorised over psi."""
    return FaceProblem.from_state(state, face).target(psi)


def ellipticity_margin(state, face: str, psi) -> FloatArray:
    """min |Re nu| / max |nu| of N(psi) at a face (0 where strong ellipticity fails)."""
    return FaceProblem.from_state(state, face).margin(psi)


def neo_hookean_secular(l1, l2, l3, d, psi):
    """Scalar half-space criterion of the ideal neo-Hookean dielectric with electrodes.

    Traction-free face with an earthed potential increment, principal stretches l1
    (normal), l2, l3 and normal displacement d at the face (docs/derivation-surface.md):

        P = beta^3 + beta^2 + (3 - delta) beta - (1 + delta),
        beta^2 = (l2^2 cos^2 psi + l3^2 sin^2 psi) / l1^2,   delta = d^2 / l1^2.

    P = 0 is the bifurcation condition (the spurious root beta = 1 of the unreduced
    determinant removed); P > 0 on the unloaded state. delta = 0 gives Biot's cubic.
    """
    l1, l2, l3, d, psi = (np.asarray(x, float) for x in (l1, l2, l3, d, psi))
    beta = np.sqrt(l2**2 * np.cos(psi) ** 2 + l3**2 * np.sin(psi) ** 2) / l1
    delta = d**2 / l1**2
    return beta**3 + beta**2 + (3.0 - delta) * beta - (1.0 + delta)
