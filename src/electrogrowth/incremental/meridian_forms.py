"""The energy of a layered, growing tube in axisymmetric deformations (r, z)
at fixed axial stretch, expanded about its axisymmetric state: the forms A, C and the
quartic term that the Koiter coefficient of the axisymmetric modes (0, n) needs
(docs/derivation-koiter.md, "The tube's axisymmetric family").

A displacement u = U_r e_r + U_z e_z (U_r, U_z functions of the reference R, Z) from the
base state r0(R), z = lambda_z Z gives the deformation gradient, exactly,

    F = [[r0' + G_rR, G_rZ], [G_zR, lambda_z + G_zZ]]  (meridian)  and  F_tT = t0 + G_tT,

G_rR = U_r,R, G_rZ = U_r,Z, G_zR = U_z,R, G_zZ = U_z,Z, G_tT = U_r / R, t0 = r0 / R. The
energy J_g mu_k W(F F_g^-1) is taken to fourth order in G (strain_energy_forms.py; for
neo-Hookean layers J_g mu_k / 2 |F F_g^-1|^2, quadratic); the constraint det F = F_tT
det F_m is cubic, so the Lagrangian L = W - (p0 + q)(det F - J_g) to fourth order is a
polynomial in (G, q), written below as its monomials order by order (``lagrangian``). Harmonics of
K Z, K = n pi / L (the package's k = n pi / (lambda_z L) in the current length): U_r =
a_j cos(j K Z), U_z = b_j sin(j K Z) (zero at the sliding ends Z = 0, L: no mean axial
strain, the axial stretch being prescribed), q = c_j cos(j K Z); a, b on the Lobatto nodes
of each ring, c on the interior nodes, as in polar_forms.py.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from ..errors import ParameterError
from .monomial_forms import MonomialForms
from .polar_forms import Ring, peak_on_rings, unknown_slices
from .ring_basis import radial_maps
from .strain_energy_forms import strain_energy

#: the local fields of the energy: the displacement gradient and the pressure increment
FIELDS = ("rR", "rZ", "zR", "zZ", "tT", "q")


@dataclasses.dataclass
class MeridianForms(MonomialForms):
    """The maps from the unknowns of ``harmonics`` ((field, j): 0 = a, 1 = b, 2 = c) to the
    local fields at the quadrature points, for the reference axial wavenumber K.
    ``z_points`` equispaced points per period integrate trigonometric polynomials of
    degree below it exactly (8: the quartic term of the first harmonic, degree 4)."""

    rings: tuple[Ring, ...]
    K: float
    harmonics: tuple[tuple[int, int], ...]
    maps: dict
    R: FloatArray
    weight: FloatArray
    layer: np.ndarray
    slices: list
    size: int

    @classmethod
    def build(cls, rings_, K: float, harmonics, *, z_points: int = 8) -> MeridianForms:
        if not K > 0:
            raise ParameterError(f"K = {K}: an axisymmetric mode needs an axial wavenumber > 0")
        if (1, 0) in harmonics:
            raise ParameterError("U_z = b_0 sin(0) is no field: leave (1, 0) out")
        Z = 2 * np.pi * np.arange(z_points) / (z_points * K)  # one period
        R, wR, layer, V, D, P = radial_maps(rings_)
        nR, n_disp, n_pres = len(R), V.shape[1], P.shape[1]
        slices, at = unknown_slices([f for f, _ in harmonics], {0: n_disp, 1: n_disp, 2: n_pres})
        maps = {k: np.zeros((z_points * nR, at)) for k in FIELDS}
        for (field, j), sl in zip(harmonics, slices):
            k = j * K
            c, s = np.cos(k * Z)[:, None], np.sin(k * Z)[:, None]
            if field == 0:  # U_r = a cos: G_rR = a' cos, G_rZ = -k a sin, G_tT = a / R cos
                maps["rR"][:, sl] += np.kron(c, D)
                maps["rZ"][:, sl] += np.kron(-k * s, V)
                maps["tT"][:, sl] += np.kron(c, V / R[:, None])
            elif field == 1:  # U_z = b sin: G_zR = b' sin, G_zZ = k b cos
                maps["zR"][:, sl] += np.kron(s, D)
                maps["zZ"][:, sl] += np.kron(k * c, V)
            else:
                maps["q"][:, sl] += np.kron(c, P)
        weight = np.tile(wR, z_points) / z_points
        tiled = np.tile(R, z_points), np.tile(layer, z_points)
        return cls(
            tuple(rings_), K, tuple(harmonics), maps, tiled[0], weight, tiled[1], slices, at
        )

    def coefficients(self, state) -> dict:
        """The base state at the quadrature points: J_g mu_k / g_r^2, / g_z^2, / g_t^2,
        p0, t0 = r0 / R, s0 = r0' (= J_g R / (lambda_z r0)), J_g and lambda_z."""
        keys = ("cr", "cz", "ct", "p0", "t0", "s0", "J")
        out = {k: np.zeros_like(self.R) for k in keys}
        lz = state.stretch
        for k, ply in enumerate(state.tube.layers):
            sel = self.layer == k
            if not sel.any():
                continue
            R = self.R[sel]
            gr, gt, gz = ply.growth_at(R)  # graded growth: g(R) at the points
            J, mu = gr * gt * gz, ply.shear_modulus
            r = state.radius(R)
            out["cr"][sel], out["cz"][sel], out["ct"][sel] = (
                J * mu / gr**2,
                J * mu / gz**2,
                J * mu / gt**2,
            )
            out["p0"][sel], out["t0"][sel], out["J"][sel] = state.pressure(R), r / R, J
            out["s0"][sel] = J * R / (lz * r)
        out["lz"] = np.full_like(self.R, lz)
        return out

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials (coefficient, fields) of L = W - (p0 + q)(det F - J_g) order by
        order in (G, q): det F = (t0 + G_tT)(s0 lz + lz G_rR + s0 G_zZ + det G_m)."""
        c = self.coefficients(state)
        p0, t0, s0, lz = (c[k] for k in ("p0", "t0", "s0", "lz"))

        def det_m(coeff):  # coeff * det G_m = coeff (G_rR G_zZ - G_rZ G_zR)
            return [(coeff, ("rR", "zZ")), (-coeff, ("rZ", "zR"))]

        def cof_m(coeff):  # coeff * cof(F0_m) : G_m = coeff (lz G_rR + s0 G_zZ)
            return [(coeff * lz, ("rR",)), (coeff * s0, ("zZ",))]

        def times(field, monomials):
            return [(k, (field, *f)) for k, f in monomials]

        one = np.ones_like(p0)
        constraint = {
            1: cof_m(-p0 * t0) + [(-p0 * s0 * lz, ("tT",))],
            2: det_m(-p0 * t0)
            + times("tT", cof_m(-p0))
            + times("q", cof_m(-t0))
            + [(-s0 * lz, ("q", "tT"))],
            3: times("tT", det_m(-p0))
            + times("q", det_m(-t0))
            + times("q", times("tT", cof_m(-one))),
            4: times("q", times("tT", det_m(-one))),
        }
        return _with_strain_energy(constraint, self.strain_energy(state, c))

    def strain_energy(self, state, c: dict) -> dict[int, list]:
        """The monomials of J_g mu_k W(F F_g^-1) (strain_energy_forms.py), F = [[r0' + G_rR,
        G_rZ], [G_zR, lambda_z + G_zZ]] in the meridian and r0 / R + G_tT in the hoop."""
        F = {
            (0, 0): {(): c["s0"], ("rR",): 1.0},
            (0, 2): {("rZ",): 1.0},
            (2, 0): {("zR",): 1.0},
            (2, 2): {(): c["lz"], ("zZ",): 1.0},
            (1, 1): {(): c["t0"], ("tT",): 1.0},
        }
        return strain_energy(self, state, F)

    def stiffness(self, state) -> FloatArray:
        """A = the Hessian of the quadratic part E2 at the state."""
        return self.hessian(self.lagrangian(state)[2])

    def peak_radial(self, v: FloatArray, field_slice: slice) -> tuple[float, float]:
        """(R, a(R)) where |a| of ``v[field_slice]`` is largest (polar_forms.peak_on_rings)."""
        return peak_on_rings(self.rings, v[field_slice])


def _with_strain_energy(constraint: dict[int, list], energy: dict[int, list]) -> dict:
    """The Lagrangian's monomials: the constraint's and the strain energy's, order by order."""
    return {k: constraint.get(k, []) + energy.get(k, []) for k in sorted({*constraint, *energy})}
