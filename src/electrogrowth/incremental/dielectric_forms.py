"""The energy of a layered, growing tube of ideal dielectrics under a radial voltage, in
plane deformations (r, theta) at fixed axial stretch, expanded about its axisymmetric
state: the forms of the prismatic modes (m, 0) with the electric potential as an extra
field (docs/derivation-koiter.md, "The radial voltage").

In terms of the nominal field E~ = -Grad phi, the energy of a layer per reference volume
(Legendre transform of Omega = mu_k W(I1, I2) + I5 / (2 eps_k) in the displacement) is
J_g mu_k W(F F_g^-1) - eps_k J / 2 E~ . C^-1 E~, and J C^-1 = cof(F)^T cof(F) / J. On
the constraint J = J_g, and with F = diag(F_2, lambda_z), E~_Z = 0,

    L = J_g mu_k W(F F_g^-1) - eps_k lambda_z^2 / (2 J_g) |cof(F_2) E~|^2
        - (p~0 + q)(lambda_z det F_2 - J_g),

the strain energy to fourth order in G (strain_energy_forms.py; quadratic for neo-Hookean
layers) and the rest a polynomial of degree four in (G, grad phi): cof(F_2) is linear in
G. Replacing J by J_g changes the multiplier: p~0 = p0 - eps_k |e|^2 (p0 the state's, e
the current field).
Harmonics of m Theta: U_r, q and phi ~ cos, U_theta ~ sin; phi on the Lobatto nodes,
zero on the electrodes (the inner and outer faces of the wall).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from ..errors import ParameterError
from .monomial_forms import MonomialForms, by_degree, product
from .polar_forms import Ring, peak_on_rings, unknown_slices
from .ring_basis import potential_maps, radial_maps
from .strain_energy_forms import strain_energy


@dataclasses.dataclass
class DielectricForms(MonomialForms):
    """The maps from the unknowns of ``harmonics`` ((field, j): 0 = U_r, 1 = U_theta,
    2 = q, 3 = phi) to the local fields G, q and E~ - E~_0 at the quadrature points."""

    rings: tuple[Ring, ...]
    m: int
    harmonics: tuple[tuple[int, int], ...]
    maps: dict
    R: FloatArray
    weight: FloatArray
    layer: np.ndarray
    slices: list
    size: int

    @classmethod
    def build(cls, rings_, m: int, harmonics, *, theta_points: int = 8) -> DielectricForms:
        """``theta_points`` equispaced points a period integrate trigonometric polynomials
        of degree below it exactly (8: the quartic term of the first harmonic)."""
        if m < 2:
            raise ParameterError(f"m = {m}: prismatic modes need m >= 2")
        theta = 2 * np.pi * np.arange(theta_points) / (theta_points * m)
        R, wR, layer, V, D, P = radial_maps(rings_)
        E, DE = potential_maps(rings_)  # nodal: zero on the electrodes
        nR, n_disp, n_pres = len(R), V.shape[1], P.shape[1]
        sizes = {0: n_disp, 1: n_disp, 2: n_pres, 3: n_disp - 2}  # phi: interior nodes
        slices, at = unknown_slices([f for f, _ in harmonics], sizes)
        maps = {
            k: np.zeros((theta_points * nR, at)) for k in ("rR", "rT", "tR", "tT", "q", "ER", "ET")
        }
        inv = (1.0 / R)[:, None]
        for (field, j), sl in zip(harmonics, slices):
            n = j * m
            c, s = np.cos(n * theta)[:, None], np.sin(n * theta)[:, None]
            if field == 0:  # U_r = a cos
                maps["rR"][:, sl] += np.kron(c, D)
                maps["rT"][:, sl] += np.kron(-n * s, inv * V)
                maps["tT"][:, sl] += np.kron(c, inv * V)
            elif field == 1:  # U_th = b sin
                maps["rT"][:, sl] += np.kron(-s, inv * V)
                maps["tR"][:, sl] += np.kron(s, D)
                maps["tT"][:, sl] += np.kron(n * c, inv * V)
            elif field == 2:
                maps["q"][:, sl] += np.kron(c, P)
            else:  # phi = e cos, zero on the electrodes: E~_R = -e' cos, E~_T = n e / R sin
                maps["ER"][:, sl] += np.kron(-c, DE)
                maps["ET"][:, sl] += np.kron(n * s, inv * E)
        weight = np.tile(wR, theta_points) / theta_points
        tiled = np.tile(R, theta_points), np.tile(layer, theta_points)
        return cls(
            tuple(rings_), m, tuple(harmonics), maps, tiled[0], weight, tiled[1], slices, at
        )

    def coefficients(self, state) -> dict:
        """The base state at the quadrature points: J_g mu_k / g_r^2, / g_t^2, p~0, t0 = r / R,
        s0 = r', E~_0 = s0 e_r, eps_k lambda_z^2 / J_g, J_g, lambda_z."""
        keys = ("cr", "ct", "p0", "t0", "s0", "E0", "ce", "J")
        out = {k: np.zeros_like(self.R) for k in keys}
        lz = state.stretch
        for k, ply in enumerate(state.tube.layers):
            sel = self.layer == k
            if not sel.any():
                continue
            R = self.R[sel]
            gr, gt, gz = ply.growth_at(R)  # graded growth: g(R) at the points
            J, mu, eps = gr * gt * gz, ply.shear_modulus, ply.permittivity
            r, e = state.radius(R), state.electric_field(R)
            out["cr"][sel], out["ct"][sel], out["J"][sel] = J * mu / gr**2, J * mu / gt**2, J
            out["p0"][sel] = state.pressure(R) - eps * e**2
            out["t0"][sel], out["s0"][sel] = r / R, J * R / (lz * r)
            out["E0"][sel], out["ce"][sel] = J * R / (lz * r) * e, eps * lz**2 / J
        out["lz"] = np.full_like(self.R, lz)
        return out

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials of L order by order in (G, q, E~ - E~_0), orders 1 to 4."""
        c = self.coefficients(state)
        lz = c["lz"]
        a = {(): c["s0"], ("rR",): 1.0}  # F_2 = [[a, b], [cc, d]]
        b, cc, d = {("rT",): 1.0}, {("tR",): 1.0}, {(): c["t0"], ("tT",): 1.0}
        ER, ET = {(): c["E0"], ("ER",): 1.0}, {("ET",): 1.0}
        v1 = _sum(product(d, ER), product(cc, ET), -1.0)  # cof(F_2) E~
        v2 = _sum(product(a, ET), product(b, ER), -1.0)
        det = _sum(product(a, d), product(b, cc), -1.0)
        energy = [
            (-c["ce"] / 2, product(v1, v1)),
            (-c["ce"] / 2, product(v2, v2)),
            (-c["p0"] * lz, det),
            (-lz, product({("q",): 1.0}, det)),
            (c["J"], {("q",): 1.0}),
        ]
        out = by_degree(*energy)
        out.pop(0, None)  # the base energy
        F = {(0, 0): a, (0, 1): b, (1, 0): cc, (1, 1): d, (2, 2): {(): lz}}
        for order, monomials in strain_energy(self, state, F).items():
            out[order] = out.get(order, []) + monomials
        return out

    def stiffness(self, state) -> FloatArray:
        return self.hessian(self.lagrangian(state)[2])

    def peak_radial(self, v: FloatArray, field_slice: slice) -> tuple[float, float]:
        return peak_on_rings(self.rings, v[field_slice])


def _sum(p1: dict, p2: dict, s2: float) -> dict:
    out = dict(p1)
    for k, c in p2.items():
        out[k] = out.get(k, 0.0) + s2 * c
    return out
