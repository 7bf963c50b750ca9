"""The energy of a layered, growing tube in three-dimensional deformations (r, theta, z) at
fixed axial stretch, expanded about its axisymmetric state: the forms of the wrinkles
(m, n) that the Koiter coefficient needs (docs/derivation-koiter.md, "The tube's general
family (m, n)"), for any strain energy (strain_energy_forms.py).

A displacement u = U_r e_r + U_th e_th + U_z e_z from the base state r0(R), theta = Theta,
z = lambda_z Z (physical components on the base's basis) gives the deformation gradient,
exactly and linearly in u, F = F0 + G with F0 = diag(r0', r0 / R, lambda_z) and

    G_rR = U_r,R   G_rT = (U_r,T - U_th) / R   G_rZ = U_r,Z
    G_tR = U_th,R  G_tT = (U_r + U_th,T) / R   G_tZ = U_th,Z
    G_zR = U_z,R   G_zT = U_z,T / R            G_zZ = U_z,Z.

The Lagrangian L = J_g mu_k W(F F_g^-1) - (p0 + q)(det F - J_g) is a polynomial in (G, q)
to fourth order (det F is cubic in G). Harmonics (j, l) of (m Theta, K Z) with the
package's mode parities (shapes/mode_shape.py):

    U_r = a cos(j m T) cos(l K Z),  U_th = b sin(j m T) cos(l K Z),
    U_z = c cos(j m T) sin(l K Z),  q = d cos(j m T) cos(l K Z),

a, b, c on the Lobatto nodes of each ring (bonded, free faces), d on the interior nodes,
as in polar_forms.py. The quadrature is a tensor grid of ``angular_points`` equispaced
points a period in Theta and in Z (exact for trigonometric polynomials of degree below it
in each) times the rings' Gauss points in R.

Each field at the quadrature points is a sum of blocks (unknowns' slice, angular factor,
radial matrix), so the forms never hold the (angle x radius) x unknowns matrices: a
field is an outer product per block, a gradient a contraction in angle then in radius.
At m = 0 (one Theta point) the forms are the meridian forms, at K = 0 (one Z point) the
polar forms: the tests compare them.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from ..errors import ParameterError
from .monomial_forms import by_degree, pair_weights
from .polar_forms import Ring, coefficient_arrays, peak_on_rings, unknown_slices
from .ring_basis import potential_maps, radial_maps
from .strain_energy_forms import strain_energy, times

#: the gradient's entries (i, J), i in (r, theta, z) = (0, 1, 2), J in (R, Theta, Z)
ENTRIES = {
    "rR": (0, 0),
    "rT": (0, 1),
    "rZ": (0, 2),
    "tR": (1, 0),
    "tT": (1, 1),
    "tZ": (1, 2),
    "zR": (2, 0),
    "zT": (2, 1),
    "zZ": (2, 2),
}

#: the fields of the Lagrangian: the gradient's entries, the pressure increment and the
#: increment of the nominal field E~ = -Grad phi (the potential's, field 4, when present)
FIELDS = (*ENTRIES, "q", "ER", "ET", "EZ")


@dataclasses.dataclass(frozen=True)
class Block:
    """One harmonic's share of a field: ``radial @ v[part]`` times ``angular``."""

    part: slice
    angular: FloatArray  # (angles,)
    radial: FloatArray  # (radii, unknowns of the harmonic)


@dataclasses.dataclass
class WallForms:
    """The maps of ``harmonics`` ((field, j, l): field 0 = a, 1 = b, 2 = c, 3 = d, 4 = e the
    potential, wall_dielectric_forms.py) to the
    local fields, mode numbers m (around) and K (the reference axial wavenumber), and the
    integral, gradient and Hessian of monomial lists (monomial_forms.py's interface, the
    fields (angles, radii) arrays, the coefficients (radii,) arrays)."""

    rings: tuple[Ring, ...]
    m: int
    K: float
    harmonics: tuple[tuple[int, int, int], ...]
    blocks: dict
    R: FloatArray
    layer: np.ndarray
    weight: FloatArray  # (angles, radii): R dR times the mean over the angles
    slices: list
    size: int

    @classmethod
    def build(
        cls, rings_: tuple[Ring, ...], m: int, K: float, harmonics, *, angular_points: int = 8
    ) -> WallForms:
        if m < 0 or K < 0:
            raise ParameterError(f"(m, K) = ({m}, {K}): the mode numbers must be >= 0")
        for field, j, l in harmonics:
            if (field == 1 and j * m == 0) or (field == 2 and l * K == 0):
                raise ParameterError(f"harmonic {(field, j, l)} is sin(0): no field")
        T, Zg = angular_grid(m, K, angular_points)
        R, wR, layer, V, D, P = radial_maps(rings_)
        radials = R, V, D, P, potential_maps(rings_)  # the potential nodal: zero on the faces
        nV, nP = V.shape[1], P.shape[1]
        sizes = {0: nV, 1: nV, 2: nV, 3: nP, 4: nV - 2}  # phi: interior nodes
        slices, at = unknown_slices([h[0] for h in harmonics], sizes)
        blocks: dict = {k: [] for k in FIELDS}
        for (field, j, l), part in zip(harmonics, slices):
            for name, angular, radial in _derivatives(field, j * m, l * K, T, Zg, *radials):
                if np.any(angular) and np.any(radial):
                    blocks[name].append(Block(part, angular, radial))
        weight = np.outer(np.full(T.size, 1.0 / T.size), wR)
        return cls(tuple(rings_), m, K, tuple(harmonics), blocks, R, layer, weight, slices, at)

    # ---- the Lagrangian --------------------------------------------------------------

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials of L = J_g mu_k W(F F_g^-1) - (p0 + q)(det F - J_g) order by order
        (1 to 4) in (G, q), their coefficients at the radial points."""
        return self.with_constraint(state, coefficient_arrays(self, state))

    def with_constraint(self, state, c: dict, *extra) -> dict[int, list]:
        """The strain energy and the constraint with the multiplier ``c["p0"]``, plus the
        ``extra`` terms (scale, polynomial), order by order (1 to 4)."""
        F = deformation(c, self.R)
        det = determinant(F)
        out = by_degree(
            (-1.0, times({(): c["p0"], ("q",): 1.0}, det)),
            (1.0, times({("q",): 1.0}, {(): c["J"]})),
            *extra,
        )
        energy = strain_energy(self, state, F)
        return {k: out.get(k, []) + energy.get(k, []) for k in range(1, 5)}

    def stiffness(self, state) -> FloatArray:
        """A = the Hessian of the quadratic part of ``lagrangian`` at the state."""
        return self.hessian(self.lagrangian(state)[2])

    def peak_radial(self, v: FloatArray, field_slice: slice) -> tuple[float, float]:
        """(R, a(R)) where |a| of ``v[field_slice]`` is largest (polar_forms.peak_on_rings)."""
        return peak_on_rings(self.rings, v[field_slice])

    # ---- the engine ------------------------------------------------------------------

    def fields(self, v: FloatArray) -> dict:
        """Each local field at the quadrature points, (angles, radii)."""
        shape = self.weight.shape
        out = {}
        for name, blocks in self.blocks.items():
            f = np.zeros(shape)
            for b in blocks:
                f += np.outer(b.angular, b.radial @ v[b.part])
            out[name] = f
        return out

    def energy(self, monomials, f: dict) -> float:
        """The integral of the monomials at the local fields ``f``."""
        total = 0.0
        for k, xs in monomials:
            total += float(np.sum(self.weight * k * np.prod([f[x] for x in xs], axis=0)))
        return total

    def gradient(self, monomials, f: dict) -> FloatArray:
        """The derivative of ``energy`` with respect to the unknowns, at the fields ``f``:
        the local derivative in each field summed over the monomials first."""
        local: dict = {}
        for k, xs in monomials:
            for i, x in enumerate(xs):
                rest = [f[y] for n, y in enumerate(xs) if n != i]
                value = np.prod(rest, axis=0) if rest else 1.0
                local[x] = local.get(x, 0.0) + self.weight * k * value
        return self.contract(local)

    def contract(self, local: dict) -> FloatArray:
        """sum over fields x of the map of x transposed times ``local[x]`` (angles, radii)."""
        out = np.zeros(self.size)
        for x, g in local.items():
            g = np.broadcast_to(g, self.weight.shape)
            for b in self.blocks[x]:
                out[b.part] += b.radial.T @ (b.angular @ g)
        return out

    def hessian(self, monomials, f: dict | None = None) -> FloatArray:
        """The second derivative of ``energy`` (for quadratic monomials ``f`` is unused),
        the weights of each pair of fields summed first."""
        H = self.pair_matrices(pair_weights(monomials, self.weight, f))
        return H + H.T

    def pair_matrices(self, pairs: dict) -> FloatArray:
        """sum over (a, b) of M_a^T diag(w_ab) M_b, w_ab (angles, radii) the weight of the
        pair: per pair of blocks, the angular mean first, then one radial product."""
        H = np.zeros((self.size, self.size))
        for (a, b), w in pairs.items():
            w = np.broadcast_to(w, self.weight.shape)
            for p in self.blocks[a]:
                for q in self.blocks[b]:
                    radial = (p.angular * q.angular) @ w
                    if np.any(radial):
                        H[p.part, q.part] += p.radial.T @ (radial[:, None] * q.radial)
        return H


#: the permutations of (0, 1, 2) and their signs (det F = sum sign F_0p0 F_1p1 F_2p2)
_PERMUTATIONS = (
    ((0, 1, 2), 1.0),
    ((1, 2, 0), 1.0),
    ((2, 0, 1), 1.0),
    ((0, 2, 1), -1.0),
    ((2, 1, 0), -1.0),
    ((1, 0, 2), -1.0),
)


def deformation(c: dict, R: FloatArray) -> dict:
    """F = F0 + G entry by entry ({(i, J): polynomial}), F0 = diag(r0', r0 / R, lambda_z)
    from the base state's ``c`` (polar_forms.coefficient_arrays)."""
    diagonal = {(0, 0): c["cofT"], (1, 1): c["cofR"], (2, 2): np.full_like(R, c["lz"])}
    F = {}
    for name, key in ENTRIES.items():
        F[key] = {(name,): 1.0}
        if key in diagonal:
            F[key][()] = diagonal[key]
    return F


def determinant(F: dict) -> dict:
    """det F as a polynomial (cubic in the fields)."""
    det: dict = {}
    for perm, sign in _PERMUTATIONS:
        term = times(times(F[0, perm[0]], F[1, perm[1]]), F[2, perm[2]])
        for k, v in term.items():
            det[k] = det.get(k, 0.0) + sign * v
    return det


def angular_grid(m: float, K: float, points: int) -> tuple[FloatArray, FloatArray]:
    """(Theta, Z) of the tensor grid of ``points`` a period in each direction, flattened."""
    theta, Z = _period(m, points), _period(K, points)
    T, Zg = np.meshgrid(theta, Z, indexing="ij")
    return T.ravel(), Zg.ravel()


def _period(number: float, points: int) -> FloatArray:
    """Equispaced points of one period 2 pi / number; one point when the direction has no
    wave (number 0: every harmonic is constant there)."""
    if number == 0:
        return np.zeros(1)
    return 2 * np.pi * np.arange(points) / (points * number)


def _derivatives(field, nt, nz, T, Z, R, V, D, P, potential):
    """(field name, angular factor, radial matrix) of one harmonic of one unknown field,
    angular numbers nt = j m around and nz = l K along; ``potential`` the potential's
    (value, R-derivative) maps (ring_basis.potential_maps)."""
    ct, st, cz, sz = np.cos(nt * T), np.sin(nt * T), np.cos(nz * Z), np.sin(nz * Z)
    inv = (1.0 / R)[:, None]
    if field == 0:  # U_r = a cos cos
        return [
            ("rR", ct * cz, D),
            ("rT", st * cz, -nt * inv * V),
            ("rZ", ct * sz, -nz * V),
            ("tT", ct * cz, inv * V),
        ]
    if field == 1:  # U_th = b sin cos
        return [
            ("rT", st * cz, -inv * V),
            ("tR", st * cz, D),
            ("tT", ct * cz, nt * inv * V),
            ("tZ", st * sz, -nz * V),
        ]
    if field == 2:  # U_z = c cos sin
        return [("zR", ct * sz, D), ("zT", st * sz, -nt * inv * V), ("zZ", ct * cz, nz * V)]
    if field == 4:  # phi = e cos cos, zero on the electrodes (the faces): E~ = -Grad phi
        E, DE = potential
        return [
            ("ER", ct * cz, -DE),
            ("ET", st * cz, nt * inv * E),
            ("EZ", ct * sz, nz * E),
        ]
    return [("q", ct * cz, P)]
