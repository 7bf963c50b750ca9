"""The strain energy of a growing tube's layers as a polynomial in the local fields, to
fourth order about the axisymmetric state, for any isotropic energy W(I1, I2) the package
accepts (docs/derivation-koiter.md, "Any strain energy").

Per reference volume a layer stores J_g mu_k W(I1, I2) of its elastic gradient
F_e = F F_g^-1, F_g = diag(g_r, g_t, g_z), J_g = g_r g_t g_z. The caller gives the
deformation gradient F = F0 + G entry by entry, each a polynomial of degree <= 1 in the
local fields (monomial_forms.py: {sorted field names: coefficient}); then, exactly,

    I1 = sum_iJ (F_iJ / g_J)^2,   I2 = |cof F_e|^2 = sum of the squared 2x2 minors of F_e,

polynomials of degree 2 and 4 in the fields, and with d1 = I1 - I1(F0), d2 = I2 - I2(F0)

    W = W(F0) + sum_{1 <= a + b <= 4} W_ab d1^a d2^b / (a! b!) + O(|G|^5),

each product truncated at degree 4 (d1 and d2 have no constant term, so no term of
a + b > 4 reaches degree 4). The W_ab come from model/energy_taylor.py per layer.
"""

from __future__ import annotations

import itertools

import numpy as np

from ..errors import ParameterError
from ..model.energy_taylor import ORDERS, strain_derivatives, taylor_weight
from .monomial_forms import by_degree

#: the highest degree the amplitude equation needs (the quartic term E4)
TOP = 4


def times(p1: dict, p2: dict, top: int = TOP) -> dict:
    """The product of two polynomials ({sorted field names: coefficient}), its terms of
    degree above ``top`` dropped."""
    out: dict = {}
    for (k1, c1), (k2, c2) in itertools.product(p1.items(), p2.items()):
        if len(k1) + len(k2) <= top:
            key = tuple(sorted(k1 + k2))
            out[key] = out.get(key, 0.0) + c1 * c2
    return out


def _plus(*polys: dict, signs=None) -> dict:
    out: dict = {}
    for p, s in zip(polys, signs or [1.0] * len(polys)):
        for k, c in p.items():
            out[k] = out.get(k, 0.0) + s * c
    return out


def invariants(Fe: dict) -> tuple[dict, dict]:
    """(I1, I2) of the elastic gradient given entry by entry ({(i, J): polynomial}, absent
    entries zero), as polynomials: |F_e|^2 and the sum of F_e's squared 2x2 minors."""
    I1 = _plus(*(times(p, p) for p in Fe.values()))
    minors = []
    for (i, j), (K, L) in itertools.product(
        itertools.combinations(range(3), 2), itertools.combinations(range(3), 2)
    ):
        pairs = [((i, K), (j, L), 1.0), ((i, L), (j, K), -1.0)]
        terms = [times(Fe[a], Fe[b]) for a, b, _ in pairs if a in Fe and b in Fe]
        signs = [s for a, b, s in pairs if a in Fe and b in Fe]
        if terms:
            minor = _plus(*terms, signs=signs)
            minors.append(times(minor, minor))
    return I1, _plus(*minors)


def _increment(p: dict) -> dict:
    return {k: c for k, c in p.items() if k}


def _powers(d: dict) -> list[dict]:
    out = [{(): 1.0}]
    for _ in range(TOP):
        out.append(times(out[-1], d))
    return out


def strain_energy(forms, state, F: dict) -> dict[int, list]:
    """The monomials of J_g mu_k W(F F_g^-1) order by order (1 to 4) in the local fields,
    at the quadrature points of ``forms`` (its ``R`` and ``layer``) for the base state
    ``state``; ``F`` the deformation gradient {(i, J): polynomial of degree <= 1}, i, J in
    (0, 1, 2) = (r, theta, z), (R, Theta, Z), its constants the base F0 at the points."""
    g = np.ones((3, forms.R.size))
    scale = np.zeros(forms.R.size)
    for k, ply in enumerate(state.tube.layers):
        sel = forms.layer == k
        g[:, sel] = ply.growth_at(forms.R[sel])  # graded growth: g(R) at the points
        scale[sel] = np.prod(g[:, sel], axis=0) * ply.shear_modulus
    Fe = {(i, J): {k: c / g[J] for k, c in p.items()} for (i, J), p in F.items()}
    I1, I2 = invariants(Fe)
    base = (np.broadcast_to(I1.get((), 0.0), forms.R.shape), I2.get((), 0.0))
    W = _layer_derivatives(forms, state, *base)
    p1, p2 = _powers(_increment(I1)), _powers(_increment(I2))
    terms = []
    for a, b in ORDERS:
        if np.any(W[a, b]):  # e.g. all but W_10 vanish for neo-Hookean
            terms.append((scale * W[a, b] * taylor_weight(a, b), times(p1[a], p2[b])))
    out = by_degree(*terms)
    out.pop(0, None)  # the base energy
    return out


def _layer_derivatives(forms, state, I1, I2) -> dict:
    """W_ab at the points, each layer's from its own material."""
    W = {k: np.zeros(forms.R.shape) for k in ORDERS}
    I1, I2 = np.broadcast_arrays(I1, I2)
    for k, ply in enumerate(state.tube.layers):
        sel = forms.layer == k
        if sel.any():
            for key, value in strain_derivatives(ply.material, I1[sel], I2[sel]).items():
                if not np.isfinite(value).all():
                    raise ParameterError(
                        f"the derivatives of the energy {ply.material.name!r} are not finite"
                        f" at the base state of layer {k + 1} (I1 up to {I1[sel].max():.6g})"
                    )
                W[key][sel] = value
    return W
