"""A mode shape by the paper's two-step surface-impedance method (eq. two_Riccati).

The impedance z(R) of the solutions that meet the inner face's condition (S = z U) is
integrated outwards from z(1) = z_P(P_i) (0 on a traction-free face) by the Riccati
equation (SciPy DOP853, dense output), layer by layer: eta, hence z, is continuous across
a bonded interface. The face displacement U(r_o) spans the null space of z(r_o) - z_P(P_o);
U is carried inwards by dU/dR = (dr/dR)(1/r)(G1 + G2 z) U, the stable direction, and
S = z U. A pole of z inside
the wall stops the route (:class:`_PoleError`); mode_shape.py then falls back to
collocation (null_vector.py).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from .._types import FloatArray, State
from ..errors import ConvergenceError
from ..incremental.impedance import ALL_PAIRS, face_impedance, impedance_scale
from ..incremental.impedance_reference import kept_pairs, layer_fields
from ..incremental.stroh import stroh_matrix


class _PoleError(ConvergenceError):
    """The Riccati integration for z stopped (a pole of the impedance inside the wall)."""


def stroh_at(state: State, R: float, m: float, k: float) -> FloatArray:
    """The Stroh matrix G (8x8) at reference radius R (moduli and p of the base state)."""
    G = np.empty((8, 8))
    r = float(state.radius(R))
    mod = np.ascontiguousarray(state.moduli(np.array(R)), dtype=float)
    stroh_matrix(mod, float(state.pressure(np.array(R))), float(m), k * r, G)
    return G


def impedance_shape(
    state: State,
    m: int,
    k: float,
    R: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Un-normalised eta at R by the paper's two-step impedance method (eq. two_Riccati),
    layer by layer (eta, hence z = S U^-1, is continuous across a bonded interface):

    1. dz/dR = w (G3 + G4 z - z G1 - z G2 z), w = (dr/dR) / r, from z(1) = z_P(P_i) (0 on a
       traction-free face) to R = R_N (dense);
    2. U(r_o): right singular vector of the smallest singular value of z(r_o) - z_P(P_o);
    3. dU/dR = w (G1 + G2 z) U from R_N down to 1; S = z U.

    On the block of the kept ``pairs`` (a mode family); the other components are 0.
    Raises _PoleError when step 1 fails or z blows up (a pole of the impedance).
    """
    keep = kept_pairs(pairs)
    Ro = state.tube.outer_radius
    z = impedance_profile(state, m, k, rtol=rtol, pairs=pairs)
    zo = face_impedances(state, m, k)[1][np.ix_(keep, keep)]
    U_o = np.linalg.svd(z(Ro) - zo)[2][-1]
    U = transport(state, m, k, z, U_o, (Ro, 1.0), R[::-1], rtol=rtol, pairs=pairs)[:, ::-1]
    S = np.stack([z(x) @ U[:, j] for j, x in enumerate(R)], axis=1)
    eta = np.zeros((8, R.size))
    eta[keep], eta[[4 + j for j in keep]] = U, S
    return eta


def _stroh_blocks(pairs: int):
    """A function (fields, m, k, R) -> (w, G1, G2, G3, G4): the Stroh matrix's blocks on the
    kept ``pairs`` at R, times nothing, and w = (dr/dR) / r of the layer of ``fields``."""
    keep = kept_pairs(pairs)
    rows, d = np.array(keep + [4 + j for j in keep]), len(keep)
    G = np.empty((8, 8))

    def blocks(fields, m, k, R):
        mod, p, r, w = fields(R)
        stroh_matrix(np.ascontiguousarray(mod, dtype=float), p, float(m), k * r, G)
        Gk = G[np.ix_(rows, rows)]
        return w, Gk[:d, :d], Gk[:d, d:], Gk[d:, :d], Gk[d:, d:]

    return blocks


def impedance_profile(
    state: State, m: int, k: float, *, rtol: float = 1e-12, pairs: int = ALL_PAIRS
):
    """z(R) for R in [1, R_N]: the Riccati equation (paper eq. Riccati) integrated by SciPy
    DOP853 from z(1) = z_P(P_i), layer by layer (z continuous at interfaces), as a callable
    R -> symmetric d x d (dense output), d the number of kept ``pairs`` (4 for the paper's
    ansatz)."""
    keep = kept_pairs(pairs)
    d = len(keep)
    scale = impedance_scale(float(m), float(k), float(state.r_o))
    blocks = _stroh_blocks(pairs)
    z0 = face_impedances(state, m, k)[0][np.ix_(keep, keep)].ravel()
    pieces = []
    for a, b, fields in layer_fields(state):

        def rhs(R, y, fields=fields):
            w, G1, G2, G3, G4 = blocks(fields, m, k, R)
            z = y.reshape(d, d)
            return (w * (G3 + G4 @ z - z @ G1 - z @ G2 @ z)).ravel()

        with np.errstate(all="ignore"):
            ric = solve_ivp(
                rhs, (a, b), z0, method="DOP853", rtol=rtol, atol=1e-3 * rtol, dense_output=True
            )
        big = np.abs(ric.y).max() if ric.y.size else np.inf
        if ric.status != 0 or not np.isfinite(big) or big > 1e8 * scale**2:
            r_stop = float(state.radius(min(max(ric.t[-1], a), b), side="outer"))
            raise _PoleError(
                f"the impedance z has a pole near r = {r_stop:.6g}"
                f" (Riccati integration stopped: {ric.message})"
            )
        pieces.append((b, ric.sol))
        z0 = ric.y[:, -1]
    ends = np.array([b for b, _ in pieces])

    def z(x: float) -> FloatArray:
        sol = pieces[min(int(np.searchsorted(ends, x)), len(pieces) - 1)][1]
        zx = sol(x).reshape(d, d)
        return 0.5 * (zx + zx.T)  # symmetric exactly (docs/derivation-stroh.md, sec. 4)

    return z


def transport(
    state: State,
    m: int,
    k: float,
    z,
    U0: FloatArray,
    span: tuple[float, float],
    R_eval: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Solve dU/dR = w (G1 + G2 z) U (paper eq. two_Riccati, second part) from
    U(span[0]) = U0 to span[1], layer by layer (U continuous at interfaces); U at ``R_eval``
    (in the order of integration), (d, len), on the block of the kept ``pairs`` (d of
    them; 4 for the paper's ansatz).

    Stable inwards (span = (R_N, 1)); outwards errors grow like exp(2 k (r_o - r_i)).
    """
    blocks = _stroh_blocks(pairs)
    start, end = span
    sense = 1.0 if end > start else -1.0
    R_eval = np.asarray(R_eval, float)
    out = np.empty((len(U0), R_eval.size))
    segments = layer_fields(state)
    U = np.asarray(U0, float)
    for a, b, fields in segments if sense > 0 else segments[::-1]:
        lo, hi = max(a, min(span)), min(b, max(span))
        if not lo < hi:
            continue
        t0, t1 = (lo, hi) if sense > 0 else (hi, lo)

        def rhs(x, U, fields=fields):
            w, G1, G2, _, _ = blocks(fields, m, k, x)
            return w * ((G1 + G2 @ z(x)) @ U)

        here = np.flatnonzero(((R_eval - t0) * sense >= 0) & ((R_eval - t1) * sense <= 0))
        sol = solve_ivp(
            rhs, (t0, t1), U, method="DOP853", dense_output=True, rtol=rtol, atol=1e-3 * rtol
        )
        if sol.status != 0:
            raise _PoleError(f"the integration of U failed: {sol.message}")
        if here.size:
            out[:, here] = sol.sol(R_eval[here])
        U = sol.y[:, -1]
    return out


# -- collocation route -----------------------------------------------------------------------


def face_impedances(state, m: float, k: float):
    """z_P of the inner and outer face (incremental/impedance.py ``face_impedance``; zero on
    a traction-free face)."""
    return tuple(
        face_impedance(P, float(m), k * r, ALL_PAIRS, 1.0)
        for P, r in zip(state.face_pressures, (state.r_i, state.r_o))
    )
