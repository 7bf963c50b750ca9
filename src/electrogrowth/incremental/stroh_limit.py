"""The short-wave limit of the Stroh system at a face: the constant half-space matrix
N(psi) and its decaying solutions (the half-space problem itself: halfspace.py).

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
* :meth:`.halfspace.FaceProblem.target` (vectorised, compiled: decaying_subspace.py): the
  spectral projector P = (I -+ sign N) / 2 (sign N by Newton's iteration
  Z <- (Z + Z^-1)/2) and the basis M = P [0; I]. Its columns are independent because no
  growing solution has U = 0 on the face (the argument of halfspace.py, for the mirrored
  half-space).

The ideal neo-Hookean dielectric reduces to a scalar secular equation,
:func:`neo_hookean_secular` (closed form in docs/derivation-surface.md).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ..errors import ConvergenceError, ParameterError, Remedy
from ..model.moduli import MODULI_INDEX

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

    Moduli whose products overflow (c12^2 past 1e308: an exponential energy's moduli at
    ~1e154 of its modulus) raise ConvergenceError: an infinite entry made every target NaN,
    which reads as a loss of strong ellipticity, and numpy's warning reached stderr.
    """
    mod = np.asarray(mod, float)
    p = np.asarray(p, float)
    try:
        with np.errstate(over="raise"):
            return _expansion(mod, p)
    except FloatingPointError:
        size = float(np.nanmax(np.abs(mod)))
        err = ConvergenceError(
            "the short-wave (half-space) problem overflows double precision: moduli up to"
            f" {size:.3g} (their products pass 1e308)"
        )
        err.remedy = Remedy("")  # neither a looser rtol nor collocation: the range of doubles
        raise err from None


def _expansion(mod, p) -> FloatArray:
    """:func:`limit_expansion` without the check."""
    M = [mod[..., k] for k in range(mod.shape[-1])]
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
    one = np.ones(np.broadcast(gam12, gam13, p).shape)  # (a product could overflow)
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
        Updated moduli at the face (order ``moduli.MODULI_NAMES``).
    p : float or array
        Lagrange multiplier at the face.
    psi : float or array
        Wave direction in the face, tan psi = k r / m (0: along theta, pi/2: along z).

    Returns
    -------
    (..., 8, 8) array, the shapes of ``mod[..., 0]``, ``p`` and ``psi`` broadcast.

    Examples
    --------
    >>> from electrogrowth.model.moduli import neo_hookean_moduli
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
    import scipy.linalg  # the short-wave limit alone needs it: not in every process

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
