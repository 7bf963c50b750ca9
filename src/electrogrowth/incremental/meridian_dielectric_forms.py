"""The energy of a layered, growing tube of ideal dielectrics under a radial
voltage, in axisymmetric deformations (r, z) at fixed axial stretch, expanded about its
axisymmetric state: the forms of the axisymmetric modes (0, n) with the electric potential
as an extra field (docs/derivation-koiter.md, "The radial voltage, axisymmetric family").

As in dielectric_forms.py, the energy with the nominal field E~ = -Grad phi is
J_g mu_k W(F F_g^-1) - eps_k / (2 J) |cof(F) E~|^2 (any W: strain_energy_forms.py),
written on the constraint (J -> J_g, the multiplier p~0 = p0 - eps_k e^2). For
F = F_m (+) F_tT (the meridian block and the hoop stretch) and E~ = (E~_R, E~_Z, 0),
cof(F) E~ = F_tT cof(F_m) E~_m, so

    L = W - eps_k / (2 J_g) F_tT^2 |cof(F_m) E~|^2 - (p~0 + q)(F_tT det F_m - J_g),

a polynomial of degree six in (G, q, E~ - E~_0); the expansion needs it to degree four.
Harmonics of K Z: U_r, q, phi ~ cos, U_z ~ sin; phi on the Lobatto nodes, zero on the
electrodes (the inner and outer faces)."""

from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import ParameterError
from .dielectric_forms import _sum
from .meridian_forms import MeridianForms
from .monomial_forms import by_degree, product
from .polar_forms import unknown_slices
from .ring_basis import potential_maps, radial_maps

FIELDS = ("rR", "rZ", "zR", "zZ", "tT", "q", "ER", "EZ")


@dataclasses.dataclass
class MeridianDielectricForms(MeridianForms):
    """MeridianForms with the potential: fields (field, j) 0 = U_r, 1 = U_z, 2 = q,
    3 = phi."""

    @classmethod
    def build(cls, rings_, K: float, harmonics, *, z_points: int = 8):
        if not K > 0:
            raise ParameterError(f"K = {K}: an axisymmetric mode needs an axial wavenumber > 0")
        if (1, 0) in harmonics:
            raise ParameterError("U_z = b_0 sin(0) is no field: leave (1, 0) out")
        Z = 2 * np.pi * np.arange(z_points) / (z_points * K)
        R, wR, layer, V, D, P = radial_maps(rings_)
        E, DE = potential_maps(rings_)  # nodal: zero on the electrodes
        nR, n_disp, n_pres = len(R), V.shape[1], P.shape[1]
        sizes = {0: n_disp, 1: n_disp, 2: n_pres, 3: n_disp - 2}  # phi: interior nodes
        slices, at = unknown_slices([f for f, _ in harmonics], sizes)
        maps = {k: np.zeros((z_points * nR, at)) for k in FIELDS}
        for (field, j), sl in zip(harmonics, slices):
            k = j * K
            c, s = np.cos(k * Z)[:, None], np.sin(k * Z)[:, None]
            if field == 0:  # U_r = a cos
                maps["rR"][:, sl] += np.kron(c, D)
                maps["rZ"][:, sl] += np.kron(-k * s, V)
                maps["tT"][:, sl] += np.kron(c, V / R[:, None])
            elif field == 1:  # U_z = b sin
                maps["zR"][:, sl] += np.kron(s, D)
                maps["zZ"][:, sl] += np.kron(k * c, V)
            elif field == 2:
                maps["q"][:, sl] += np.kron(c, P)
            else:  # phi = e cos, zero on the electrodes: E~_R = -e' cos, E~_Z = k e sin
                maps["ER"][:, sl] += np.kron(-c, DE)
                maps["EZ"][:, sl] += np.kron(k * s, E)
        weight = np.tile(wR, z_points) / z_points
        tiled = np.tile(R, z_points), np.tile(layer, z_points)
        return cls(
            tuple(rings_), K, tuple(harmonics), maps, tiled[0], weight, tiled[1], slices, at
        )

    def coefficients(self, state) -> dict:
        """MeridianForms' coefficients with p~0 = p0 - eps_k e^2, E~_0 = s0 e and
        eps_k / J_g."""
        out = super().coefficients(state)
        out["E0"], out["ce"] = np.zeros_like(self.R), np.zeros_like(self.R)
        for k, ply in enumerate(state.tube.layers):
            sel = self.layer == k
            if not sel.any():
                continue
            e = state.electric_field(self.R[sel])
            out["p0"][sel] -= ply.permittivity * e**2
            out["E0"][sel] = out["s0"][sel] * e
            out["ce"][sel] = ply.permittivity / out["J"][sel]
        return out

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials of L order by order in (G, q, E~ - E~_0), orders 1 to 4."""
        c = self.coefficients(state)
        a, b = {(): c["s0"], ("rR",): 1.0}, {("rZ",): 1.0}  # F_m = [[a, b], [cc, d]]
        cc, d = {("zR",): 1.0}, {(): c["lz"], ("zZ",): 1.0}
        t = {(): c["t0"], ("tT",): 1.0}
        ER, EZ = {(): c["E0"], ("ER",): 1.0}, {("EZ",): 1.0}
        v1 = _sum(product(d, ER), product(cc, EZ), -1.0)  # cof(F_m) E~
        v2 = _sum(product(a, EZ), product(b, ER), -1.0)
        det = product(t, _sum(product(a, d), product(b, cc), -1.0))
        tt = product(t, t)
        energy = [
            (-c["ce"] / 2, product(tt, v1, v1)),
            (-c["ce"] / 2, product(tt, v2, v2)),
            (-c["p0"], det),
            (-1.0, product({("q",): 1.0}, det)),
            (c["J"], {("q",): 1.0}),
        ]
        out = by_degree(*energy)
        for order, monomials in self.strain_energy(state, c).items():  # any W
            out[order] = out.get(order, []) + monomials
        return {k: out.get(k, []) for k in (1, 2, 3, 4)}
