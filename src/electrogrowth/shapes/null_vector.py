"""A mode shape from the null vector of the Chebyshev collocation matrix
(incremental/collocation.py), one polynomial per field and layer.

The nodal U_r, U_th, U_z, Phi and P are interpolated and differentiated; the rest of the
Stroh vector eta = [U_r, U_th, U_z, r Delta_r, r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi]
follows from the incremental law (the rows of the Stroh matrix and S_rr of
docs/derivation-stroh.md).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import chebyshev as cheb

from .._types import FloatArray, State
from ..incremental.collocation import mode_shape_collocation
from ..incremental.impedance import ALL_PAIRS
from ..incremental.stroh import stroh_matrix
from ..model.moduli import MODULI_INDEX


def collocation_shape(
    state: State, m: int, n: int, R: FloatArray, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> FloatArray:
    """Un-normalised eta at R from the collocation null vector.

    U_r, U_th, U_z, Phi and P are the nodal values of polynomials in r (degree nodes - 1;
    P from the collocation's interior interpolation); they are interpolated, differentiated
    where needed, and the rest of eta follows from the incremental law (stroh.py rows 1, 2,
    7 for r Sigma_rth, r Sigma_rz, r Delta_r; S_rr from docs/derivation-stroh.md):

        r Sigma_rr = r [(A1111 + p) U_r' + A1122 (U_r + m U_th)/r + A1133 k U_z
                        + Gamma111 Delta_r - P].

    ``pairs``: the block of a mode family (collocation.py); the other fields are 0. Layer
    by layer: each layer's nodal values are its own polynomial; a sample on an interface is
    taken from the layer inside it, eta being continuous there.
    """
    shape = mode_shape_collocation(state, m, n, nodes=nodes, pairs=pairs)
    radii = state.tube.radii
    layer_of = np.clip(np.searchsorted(np.array(radii[1:-1]), R, side="left"), 0, len(radii) - 2)
    k = n * math.pi / state.current_length
    eta = np.empty((8, R.size))
    for j in range(len(radii) - 1):
        sel = layer_of == j
        if not sel.any():
            continue
        part = {f: v[j * nodes : (j + 1) * nodes] for f, v in shape.items()}
        side = "inner" if j < len(radii) - 2 else "outer"  # R on the outer end is this layer's
        eta[:, sel] = _eta_from_nodes(state, part, m, k, R[sel], side)
    return eta


def _eta_from_nodes(state, part: dict, m: float, k: float, R: FloatArray, side=None):
    """eta at R (one layer: ``side`` picks it at an interface of a layered state) from its
    nodal U_r, U_th, U_z, Phi, P (see collocation_shape)."""
    r_nodes = part["r"]
    domain = [r_nodes.min(), r_nodes.max()]
    poly = {
        f: cheb.Chebyshev.fit(r_nodes, part[f], len(r_nodes) - 1, domain=domain)
        for f in ("U_r", "U_th", "U_z", "Phi", "P")
    }
    where = {} if side is None else {"side": side}
    r = state.radius(R, **where)
    mod = state.moduli(R, **where)
    p = state.pressure(R, **where)
    val = {f: q(r) for f, q in poly.items()}
    der = {f: poly[f].deriv()(r) for f in ("U_r", "U_th", "U_z", "Phi")}
    eta = np.empty((8, R.size))
    eta[0], eta[1], eta[2], eta[7] = val["U_r"], val["U_th"], val["U_z"], -val["Phi"]
    G = np.empty((8, 8))
    for j in range(R.size):
        stroh_matrix(np.ascontiguousarray(mod[j]), float(p[j]), float(m), k * r[j], G)
        e = eta[:, j]
        # row 7: r (-Phi)' = G70 U_r + G71 U_th + G72 U_z + G73 r Delta_r
        e[3] = (-r[j] * der["Phi"][j] - G[7, :3] @ e[:3]) / G[7, 3]
        # rows 1, 2: r U' = G[i, :4] U + G[i, 5 or 6] r Sigma + G[i, 7] (-Phi)
        e[5] = (r[j] * der["U_th"][j] - G[1, :4] @ e[:4] - G[1, 7] * e[7]) / G[1, 5]
        e[6] = (r[j] * der["U_z"][j] - G[2, :4] @ e[:4] - G[2, 7] * e[7]) / G[2, 6]
    a = {name: mod[..., MODULI_INDEX[name]] for name in ("A1111", "A1122", "A1133", "G111")}
    eta[4] = r * (
        (a["A1111"] + p) * der["U_r"]
        + a["A1122"] * (eta[0] + m * eta[1]) / r
        + a["A1133"] * k * eta[2]
        + a["G111"] * eta[3] / r
        - val["P"]
    )
    return eta
