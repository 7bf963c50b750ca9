"""A mode shape by the paper's two-step surface-impedance method (eq. two_Riccati).

The impedance z(R) of the solutions with S = 0 on the inner face (S = z U) is integrated
outwards from z(1) = 0 by the Riccati equation (SciPy DOP853, dense output); the face
displacement U(r_o) spans the null space of z(r_o); U is carried inwards by
dU/dR = (dr/dR)(1/r)(G1 + G2 z) U, the stable direction, and S = z U. A pole of z inside
the wall stops the route (:class:`_PoleError`); mode_shape.py then falls back to
collocation (null_vector.py).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from .._types import FloatArray
from ..basestate.tube import BaseState
from ..errors import ConvergenceError
from ..incremental.impedance import ALL_PAIRS, impedance_scale
from ..incremental.impedance_reference import impedance_rhs, kept_pairs
from ..incremental.stroh import stroh_matrix


class _PoleError(ConvergenceError):
    """The Riccati integration for z stopped (a pole of the impedance inside the wall)."""


def stroh_at(state: BaseState, R: float, m: float, k: float) -> FloatArray:
    """The Stroh matrix G (8x8) at reference radius R (moduli and p of the base state)."""
    G = np.empty((8, 8))
    r = float(state.radius(R))
    mod = np.ascontiguousarray(state.moduli(np.array(R)), dtype=float)
    stroh_matrix(mod, float(state.pressure(np.array(R))), float(m), k * r, G)
    return G


def impedance_shape(
    state: BaseState,
    m: int,
    k: float,
    R: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Un-normalised eta at R by the paper's two-step impedance method (eq. two_Riccati).

    1. dz/dR = (dr/dR)(1/r)(G3 + G4 z - z G1 - z G2 z), z(1) = 0, to R = Rbar_o (dense).
    2. U(r_o): right singular vector of the smallest singular value of z(r_o).
    3. dU/dR = (dr/dR)(1/r)(G1 + G2 z) U from Rbar_o down to 1; S = z U.

    On the block of the kept ``pairs`` (a mode family); the other components are 0.
    Raises _PoleError when step 1 fails or z blows up (a pole of the impedance).
    """
    Ro = state.params.outer_radius
    z = impedance_profile(state, m, k, rtol=rtol, pairs=pairs)
    U_o = np.linalg.svd(z(Ro))[2][-1]
    U = transport(state, m, k, z, U_o, (Ro, 1.0), R[::-1], rtol=rtol, pairs=pairs)[:, ::-1]
    S = np.stack([z(x) @ U[:, j] for j, x in enumerate(R)], axis=1)
    keep = kept_pairs(pairs)
    eta = np.zeros((8, R.size))
    eta[keep], eta[[4 + j for j in keep]] = U, S
    return eta


def impedance_profile(
    state: BaseState, m: int, k: float, *, rtol: float = 1e-12, pairs: int = ALL_PAIRS
):
    """z(R) for R in [1, Rbar_o]: the Riccati equation (paper eq. Riccati) integrated by
    SciPy DOP853 from z(1) = 0, as a callable R -> symmetric d x d (dense output), d the
    number of kept ``pairs`` (4 for the paper's ansatz)."""
    Ro = state.params.outer_radius
    scale = impedance_scale(float(m), float(k), float(state.r_o))
    d = len(kept_pairs(pairs))
    with np.errstate(all="ignore"):
        ric = solve_ivp(
            impedance_rhs(state, m, k, pairs),
            (1.0, Ro),
            np.zeros(d * d),
            method="DOP853",
            rtol=rtol,
            atol=1e-3 * rtol,
            dense_output=True,
        )
    big = np.abs(ric.y).max() if ric.y.size else np.inf
    if ric.status != 0 or not np.isfinite(big) or big > 1e8 * scale**2:
        r_stop = float(state.radius(min(max(ric.t[-1], 1.0), Ro)))
        raise _PoleError(
            f"the impedance z has a pole near r = {r_stop:.6g}"
            f" (Riccati integration stopped: {ric.message})"
        )

    def z(x: float) -> FloatArray:
        zx = ric.sol(x).reshape(d, d)
        return 0.5 * (zx + zx.T)  # symmetric exactly (docs/derivation-stroh.md, sec. 4)

    return z


def transport(
    state: BaseState,
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
    """Solve dU/dR = (dr/dR)(1/r)(G1 + G2 z) U (paper eq. two_Riccati, second part) from
    U(span[0]) = U0 to span[1]; U at ``R_eval`` (in the order of integration), (d, len),
    on the block of the kept ``pairs`` (d of them; 4 for the paper's ansatz).

    Stable inwards (span = (Rbar_o, 1)); outwards errors grow like exp(2 k (r_o - r_i)).
    """
    b = state.params.growth**3 / state.params.stretch  # r dr/dR = b R
    keep = np.array(kept_pairs(pairs))

    def rhs(x, U):
        G = stroh_at(state, x, m, k)
        G1, G2 = G[np.ix_(keep, keep)], G[np.ix_(keep, 4 + keep)]
        return b * x / float(state.radius(x)) ** 2 * ((G1 + G2 @ z(x)) @ U)

    sol = solve_ivp(rhs, span, U0, method="DOP853", t_eval=R_eval, rtol=rtol, atol=1e-3 * rtol)
    if sol.status != 0:
        raise _PoleError(f"the integration of U failed: {sol.message}")
    return sol.y
