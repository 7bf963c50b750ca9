"""The energy of a layered, growing tube of ideal dielectrics under a radial voltage in
three-dimensional deformations at fixed axial stretch: the forms of the wrinkles (m, n)
with the electric potential as an extra field (docs/derivation-koiter.md, "The radial
voltage, wrinkles (m, n)").

As in dielectric_forms.py (the plane) and meridian_dielectric_forms.py (the meridian), the
energy with the nominal field E~ = -Grad phi, on the constraint J = J_g, is

    L = J_g mu_k W(F F_g^-1) - eps_k / (2 J_g) |cof(F) E~|^2 - (p~0 + q)(det F - J_g),

p~0 = p0 - eps_k e_r^2, now with the full cof(F) of the 3 x 3 F = F0 + G (quadratic in G)
and E~ = (s0 e_r - phi_R, -phi_Theta / R, -phi_Z): |cof(F) E~|^2 is a polynomial of degree
six, needed to degree four. The potential phi = e cos(j m Theta) cos(l K Z) (field 4 of
wall_forms.py), zero on the electrodes; every other field as in wall_forms.py. The plane
and meridian dielectric energies are its cases F = diag(F_2, lambda_z) and F = F_m (+) F_tT.
"""

from __future__ import annotations

import itertools

import numpy as np

from .polar_forms import coefficient_arrays
from .strain_energy_forms import times
from .wall_forms import WallForms, deformation

#: the nominal field's entries, J in (R, Theta, Z)
_E = ("ER", "ET", "EZ")


class WallDielectricForms(WallForms):
    """WallForms with the potential (harmonics (4, j, l)) and the electric energy."""

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials of L order by order in (G, q, E~ - E~_0), orders 1 to 4."""
        c = coefficient_arrays(self, state)
        eps, e = np.zeros_like(self.R), np.zeros_like(self.R)
        for k, ply in enumerate(state.tube.layers):
            sel = self.layer == k
            if sel.any():
                eps[sel], e[sel] = ply.permittivity, state.electric_field(self.R[sel])
        c["p0"] = c["p0"] - eps * e**2  # the multiplier of the transformed energy
        E = {name: {(name,): 1.0} for name in _E}
        E["ER"][()] = c["cofT"] * e  # E~_0 = F0^T e: s0 e_r
        cof = cofactor(deformation(c, self.R))
        square: dict = {}
        for i in range(3):
            v: dict = {}
            for J, name in enumerate(_E):
                for key, value in times(cof[i, J], E[name]).items():
                    v[key] = v.get(key, 0.0) + value
            for key, value in times(v, v).items():
                square[key] = square.get(key, 0.0) + value
        return self.with_constraint(state, c, (-eps / (2 * c["J"]), square))


def cofactor(F: dict) -> dict:
    """cof(F)_iJ = F_jK F_kL - F_jL F_kK, (i, j, k) and (J, K, L) cyclic: quadratic."""
    out = {}
    for i, J in itertools.product(range(3), range(3)):
        j, k = (i + 1) % 3, (i + 2) % 3
        K, L = (J + 1) % 3, (J + 2) % 3
        p = times(F[j, K], F[k, L])
        for key, value in times(F[j, L], F[k, K]).items():
            p[key] = p.get(key, 0.0) - value
        out[i, J] = p
    return out
