"""The conditional impedance z(r_o) by collocation: the Riccati method's quantity computed
without the Stroh matrix, so that the two can be compared term by term (collocation.py)."""

from __future__ import annotations

import numpy as np

from .._types import FloatArray
from .collocation import _assemble, _layers
from .collocation_layout import ALL_PAIRS, _block_indices, _layout, check_pairs


def collocation_impedance(
    state, m: int, n: float, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> FloatArray:
    """The conditional impedance z(r_o) of the kept ``pairs``, by collocation.

    z is defined as in the Riccati method (S = z U at r_o for the solutions with
    S(r_i) = 0; Stroh variables U = [U_r, U_th, U_z, r Delta_r],
    S = [r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi], docs/derivation-stroh.md, units
    R_i = 1), but computed without the Stroh matrix: for each kept pair j the collocated
    problem of :func:`collocation_matrix` with its outer-face condition S_j(r_o) = 0
    replaced by U_j(r_o) = 1 (the other kept U_i(r_o) = 0) is solved, and S(r_o) is read
    off the incremental law. A (kept x kept) array, rows and columns in pair order;
    singular where the mode is at bifurcation, infinite at a pole of z.
    """
    pairs = check_pairs(pairs)
    nn, width, layers = int(nodes), 5 * int(nodes) - 2, _layers(state)
    M, S, Dq, grid = _assemble(state, m, n, nn)
    cols, r_o, h = _layout(nn), grid.r[0], grid.h  # node 0 is the outer face
    off = width * (layers - 1)  # the outermost layer's block
    # outer-face maps of the Stroh U and S (physical units) on the scaled unknowns
    U_out = np.zeros((4, width * layers))
    for j, f in enumerate(("U_r", "U_th", "U_z")):
        U_out[j, off + cols[f].start] = h
    U_out[3, off:] = r_o * Dq[0][0].real
    S_out = np.zeros((4, width * layers))
    S_out[0, off:] = r_o * S[0, 0][0].real
    S_out[1, off:] = r_o * (1j * S[0, 1][0]).real
    S_out[2, off:] = r_o * (1j * S[0, 2][0]).real
    S_out[3, off + cols["Phi"].start] = -h
    face_rows = [off, off + nn, off + 2 * nn, off + 3 * nn]  # S_rr, S_rth, S_rz, Phi at r_o
    A = M.real.copy()
    A[face_rows] = U_out
    rows, keep_cols = _block_indices(nn, pairs, layers)
    kept = [j for j in range(4) if (pairs >> j) & 1]
    rhs = np.zeros((width * layers, len(kept)))
    for c, j in enumerate(kept):
        rhs[face_rows[j], c] = 1.0
    v = np.zeros((width * layers, len(kept)))
    v[keep_cols] = np.linalg.solve(A[np.ix_(rows, keep_cols)], rhs[rows])
    return (S_out @ v)[kept]
