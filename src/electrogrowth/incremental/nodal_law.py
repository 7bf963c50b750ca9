"""The incremental constitutive law at the collocation nodes (collocation.py).

The 23 principal moduli expanded to the full tensors A_piqj, Gamma_piq, K_pq, and the
nodal maps (linear in the unknowns U_r, U_th, U_z, P, Phi) of the displacement gradient
L_jq, the field E_p, the pressure pdot, the incremental stress S_pi and the electric
displacement D_q (paper eqs. 52 and 16-1; lengths in units of the half-thickness h).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import numpy.typing as npt

from .._types import FloatArray
from ..model.moduli import MODULI_INDEX
from .chebyshev import interior_interpolation
from .collocation_layout import _layout

#: A linear map from the 5 nodes - 2 unknowns (U_r, U_th, U_z, P, Phi) to nodal values.
Operator = npt.NDArray[np.complex128]


def full_moduli(moduli: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Expand the 23 principal moduli (last axis, order MODULI_NAMES) into full tensors.

    Returns A[p, i, q, j, ...], G[p, i, q, ...] and K[p, q, ...] with the node axis last,
    filled with the symmetries A_piqj = A_qjpi and Gamma_piq = Gamma_ipq
    (docs/conventions.md).
    """
    mod = np.moveaxis(np.asarray(moduli, float), -1, 0)
    shape = mod.shape[1:]
    A = np.zeros((3, 3, 3, 3) + shape)
    G = np.zeros((3, 3, 3) + shape)
    K = np.zeros((3, 3) + shape)
    for name, k in MODULI_INDEX.items():
        idx = tuple(int(c) - 1 for c in name[1:])
        if name[0] == "A":
            p, i, q, j = idx
            A[p, i, q, j] = A[q, j, p, i] = mod[k]
        elif name[0] == "G":
            p, i, q = idx
            G[p, i, q] = G[i, p, q] = mod[k]
        else:
            K[idx] = K[idx[::-1]] = mod[k]
    return A, G, K


@dataclasses.dataclass(frozen=True)
class _Grid:
    """Nodes of one discretisation: r = h (c + x), everything in units of h."""

    r: FloatArray  # physical current radius at the nodes (outer face first)
    rh: FloatArray  # r / h
    Dx: FloatArray  # d/d(r/h) = d/dx
    kh: float  # k h
    h: float


def _operators(grid: _Grid, m: float) -> tuple[Operator, Operator, Operator]:
    """Nodal maps of L_jq = du_j/dx_q (paper eq. 52), E_p = -(grad phidot)_p and pdot.

    With u = (U_r, -i U_th, -i U_z) e^{i(m th + k z)}, phidot = Phi e^{...}, d/dth -> i m,
    d/dz -> i k. Returns L[j, q], E[p] and pdot, each of shape (nodes, 5 nodes - 2).
    """
    nn = grid.rh.size
    cols = _layout(nn)
    eye, D, inv_r, ik = np.eye(nn), grid.Dx, np.diag(1.0 / grid.rh), 1j * grid.kh

    def op(**parts):
        out = np.zeros((nn, 5 * nn - 2), complex)
        for f, block in parts.items():
            out[:, cols[f]] = block
        return out

    Ur, Ut, Uz = "U_r", "U_th", "U_z"
    L = np.empty((3, 3, nn, 5 * nn - 2), complex)
    L[0, 0] = op(**{Ur: D})  # dU_r/dr
    L[0, 1] = op(**{Ur: 1j * m * inv_r, Ut: 1j * inv_r})  # (d_th u_r - u_th)/r
    L[0, 2] = op(**{Ur: ik * eye})  # d_z u_r
    L[1, 0] = op(**{Ut: -1j * D})  # d_r u_th
    L[1, 1] = op(**{Ur: inv_r, Ut: m * inv_r})  # (d_th u_th + u_r)/r
    L[1, 2] = op(**{Ut: grid.kh * eye})  # d_z u_th
    L[2, 0] = op(**{Uz: -1j * D})  # d_r u_z
    L[2, 1] = op(**{Uz: m * inv_r})  # d_th u_z / r
    L[2, 2] = op(**{Uz: grid.kh * eye})  # d_z u_z
    E = np.stack([op(Phi=-D), op(Phi=-1j * m * inv_r), op(Phi=-ik * eye)])
    pdot = op(P=interior_interpolation(nn))
    return L, E, pdot


def _contract(T: FloatArray, X: Operator, out_rank: int) -> Operator:
    """sum over the trailing tensor indices of T[..., n] X[..., n, c] over the non-zero
    entries of T only (the moduli are sparse: 21 of 81 A, 7 of 27 Gamma)."""
    out = np.zeros(T.shape[:out_rank] + X.shape[-2:], complex)
    for idx in np.argwhere(np.any(T != 0, axis=-1)):
        out[tuple(idx[:out_rank])] += T[tuple(idx)][:, None] * X[tuple(idx[out_rank:])]
    return out


def _shift_out_of_the_face_mode(A: FloatArray, p: FloatArray) -> None:
    """Add c delta_pi delta_qj to A (in place) at the nodes where A_rrrr + p < A_rthrth, with
    c = A_rthrth - A_rrrr - p, so that A_rrrr + p + c >= A_rthrth > 0 at every node.

    Why: for an incompressible solid such a shift changes S only by c tr(L) I, which the
    incremental pressure absorbs (tr L = 0): the continuous problem is the same. The
    collocation enforces tr L = 0 at the interior nodes only (P_N - P_{N-2}), so tr L at a
    face (or interface) node is free and enters the equations only through the coefficient
    A_rrrr + p of S_rr. Where that coefficient passes through zero near a face, the
    discrete matrix becomes singular in a mode the continuous problem does not have, at
    the same control value for every (m, n) and node count: a softening energy
    (0.5 (I1-3) + I5/2 - 0.25 (I1-3)^2, A_rrrr + p = 0 unloaded) gave a spurious onset
    g = 1.04861 for the true 1.37439 (probe 13a D2), and its sign past it, the
    opposite of the stable side. The floor A_rthrth (a shear modulus, positive on the
    stable side) leaves every node where A_rrrr + p is already above it bit-identical,
    and the shift, continuous in the state, keeps the target continuous. Interior nodes'
    c multiplies tr L = 0 there, so it moves no root, only the floor at the faces does.
    """
    c = np.maximum(0.0, A[0, 1, 0, 1] - (A[0, 0, 0, 0] + p))
    if not np.any(c > 0):
        return
    for i in range(3):
        for j in range(3):
            A[i, i, j, j] += c


def _fluxes_at(moduli, p, grid: _Grid, m: float) -> tuple[Operator, Operator, Operator]:
    """The maps of :func:`_fluxes` from the moduli and p at the nodes."""
    A, G, K = full_moduli(moduli)
    _shift_out_of_the_face_mode(A, p)
    L, E, pdot = _operators(grid, m)
    Lt = L.transpose(1, 0, 2, 3)  # Lt[q, j] = L_jq
    # E_p = Gamma_qjp L_jq + K_pq D_q  =>  D = K^{-1} (E - Gamma_qjp L_jq)
    Kinv = np.moveaxis(np.linalg.inv(np.moveaxis(K, -1, 0)), 0, -1)
    Dq = _contract(Kinv, E - _contract(G.transpose(2, 0, 1, 3), Lt, 1), 1)
    # S_pi = A_piqj L_jq + Gamma_piq D_q + p L_pi - pdot delta_pi
    S = _contract(A, Lt, 2) + _contract(G, Dq, 2) + p[:, None] * L
    for a in range(3):
        S[a, a] -= pdot
    return L, S, Dq
