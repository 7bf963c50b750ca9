"""The energy of a layered, growing tube in plane deformations (r, theta) at fixed axial
stretch, expanded about its axisymmetric state: the forms of the prismatic modes (n = 0)
that the Koiter coefficient needs (docs/derivation-koiter.md, "The tube's prismatic
family"), for any strain energy (``lagrangian``, via strain_energy_forms.py), and written
out by hand for neo-Hookean layers (``neo_hookean_stiffness``, ``cubic_gradient``: the
slow twin the tests compare with).

A displacement u = U_r e_r + U_th e_th from the base state r(R) (reference polar
coordinates R, Theta; physical components) has the in-plane gradient G = F - F0,

    G_rR = U_r,R,  G_rT = (U_r,T - U_th) / R,  G_tR = U_th,R,  G_tT = (U_r + U_th,T) / R,

F0 = diag(r', r / R), F_zZ = lambda_z fixed. For a layer with growth F_g = diag(g_r, g_t,
g_z), J_g = g_r g_t g_z, the energy per reference volume J_g mu_k/2 |F F_g^-1|^2 and the
constraint lambda_z det F_2 = J_g (det F_2 the in-plane determinant) are quadratic in G,
so with p0 the base Lagrange multiplier (the state's ``pressure``) and q its increment

    E2 = J_g mu_k / 2 (G_rR^2 / g_r^2 + G_rT^2 / g_t^2 + G_tR^2 / g_r^2 + G_tT^2 / g_t^2)
         - p0 lambda_z det G - q lambda_z cof(F0) : G,   cof(F0) = diag(r / R, r'),
    E3 = -q lambda_z det G,

per unit reference volume, integrated over R dR and averaged over Theta. Harmonics of
m Theta with the reflection symmetry Theta -> -Theta: U_r = a_j cos(j m Theta),
U_th = b_j sin(j m Theta), q = c_j cos(j m Theta); a, b on Chebyshev-Lobatto nodes of each
segment (continuous across segments and layers: bonded; their unknowns each ring's inner
value and differences, ring_basis.py), c on the interior nodes (P_N - P_{N-2}), as in
plane_forms.py; no node is clamped (free faces).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from ..errors import ParameterError
from .monomial_forms import MonomialForms, by_degree
from .plane_forms import _barycentric
from .ring_basis import nodal_values, radial_maps
from .strain_energy_forms import strain_energy, times

_THETA_POINTS = 8


@dataclasses.dataclass(frozen=True)
class Ring:
    """One radial segment R_a <= R <= R_b of layer ``layer`` (0-based) with ``nodes``
    Lobatto points."""

    inner: float
    outer: float
    layer: int
    nodes: int = 24


def rings(tube, m: float, nodes: int = 24) -> tuple[Ring, ...]:
    """Each layer cut at 3 / m, 12 / m and 30 / m from its faces where it is thick enough (a
    mode of number m decays like (R / R_face)^(+-m) away from a face; an axial wave of
    reference wavenumber K like exp(-K |R - R_face|): m = K)."""
    out = []
    radii = tube.radii
    for k in range(len(radii) - 1):
        a, b = radii[k], radii[k + 1]
        cuts = [a]
        for d in (3.0 / m, 12.0 / m, 30.0 / m):
            if d < (b - a) / 4:
                cuts.append(a + d)
        for d in (30.0 / m, 12.0 / m, 3.0 / m):
            if d < (b - a) / 4 and b - d > cuts[-1] + d / 2:
                cuts.append(b - d)
        cuts.append(b)
        cuts = sorted(set(cuts))
        out += [Ring(x, y, k, nodes) for x, y in zip(cuts, cuts[1:])]
    return tuple(out)


def unknown_slices(fields, sizes: dict) -> tuple[list[slice], int]:
    """The unknowns of a list of harmonics, one after the other: the slice of each (its
    field's ``sizes[field]`` values: radial nodes of a displacement, of a pressure, the
    interior nodes of a potential) and their total."""
    slices, at = [], 0
    for field in fields:
        slices.append(slice(at, at + sizes[field]))
        at += sizes[field]
    return slices, at


@dataclasses.dataclass
class PolarForms(MonomialForms):
    """The maps from the unknowns of ``harmonics`` ((field, j): 0 = a, 1 = b, 2 = c) to the
    gradient and pressure at the quadrature points, for mode number m. ``theta_points``
    equispaced points a period integrate trigonometric polynomials of degree below it
    exactly (8: the quartic term of the first harmonic)."""

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
    def build(
        cls, rings_: tuple[Ring, ...], m: int, harmonics, *, theta_points: int = _THETA_POINTS
    ) -> PolarForms:
        if m < 2:
            raise ParameterError(f"m = {m}: prismatic modes need m >= 2")
        theta = 2 * np.pi * np.arange(theta_points) / (theta_points * m)  # one period
        R, wR, layer, V, D, P = radial_maps(rings_)
        nR, n_disp, n_pres = len(R), V.shape[1], P.shape[1]
        slices, at = unknown_slices([f for f, _ in harmonics], {0: n_disp, 1: n_disp, 2: n_pres})
        npts = theta_points * nR
        maps = {k: np.zeros((npts, at)) for k in ("rR", "rT", "tR", "tT", "q")}
        inv = (1.0 / R)[:, None]
        for (field, j), sl in zip(harmonics, slices):
            n = j * m
            c, s = np.cos(n * theta)[:, None], np.sin(n * theta)[:, None]
            if field == 0:  # U_r = a cos: G_rR = a' cos, G_rT = -n a / R sin, G_tT = a / R cos
                maps["rR"][:, sl] += np.kron(c, D)
                maps["rT"][:, sl] += np.kron(-n * s, inv * V)
                maps["tT"][:, sl] += np.kron(c, inv * V)
            elif field == 1:  # U_th = b sin: G_rT = -b / R sin, G_tR = b' sin, G_tT = n b / R cos
                maps["rT"][:, sl] += np.kron(-s, inv * V)
                maps["tR"][:, sl] += np.kron(s, D)
                maps["tT"][:, sl] += np.kron(n * c, inv * V)
            else:
                maps["q"][:, sl] += np.kron(c, P)
        weight = np.tile(wR, theta_points) / theta_points
        tiled = np.tile(R, theta_points), np.tile(layer, theta_points)
        return cls(
            tuple(rings_), m, tuple(harmonics), maps, tiled[0], weight, tiled[1], slices, at
        )

    def coefficients(self, state) -> dict:
        """The base state at the quadrature points (:func:`coefficient_arrays`)."""
        return coefficient_arrays(self, state)

    def lagrangian(self, state) -> dict[int, list]:
        """The monomials of L = J_g mu_k W(F F_g^-1) - (p0 + q)(lambda_z det F_2 - J_g)
        order by order (1 to 4) in (G, q), F = [[r' + G_rR, G_rT], [G_tR, r / R + G_tT]]
        in the plane and F_zZ = lambda_z."""
        c = self.coefficients(state)
        lz = c["lz"]
        F = {
            (0, 0): {(): c["cofT"], ("rR",): 1.0},
            (0, 1): {("rT",): 1.0},
            (1, 0): {("tR",): 1.0},
            (1, 1): {(): c["cofR"], ("tT",): 1.0},
            (2, 2): {(): np.full_like(self.R, lz)},
        }
        det = times(F[0, 0], F[1, 1])
        for k, v in times(F[0, 1], F[1, 0]).items():
            det[k] = det.get(k, 0.0) - v
        J = {(): c["J"]}
        out = by_degree(
            (-lz, times({(): c["p0"], ("q",): 1.0}, det)), (1.0, times({("q",): 1.0}, J))
        )
        out.pop(0, None)
        energy = strain_energy(self, state, F)
        return {k: out.get(k, []) + energy.get(k, []) for k in range(1, 5)}

    def stiffness(self, state) -> FloatArray:
        """A = the Hessian of the quadratic part of ``lagrangian`` at the state."""
        return self.hessian(self.lagrangian(state)[2])

    def neo_hookean_stiffness(self, state) -> FloatArray:
        """A = the Hessian of E2 at the state, written out for neo-Hookean layers."""
        c = self.coefficients(state)
        lz = c["lz"]
        terms = [
            (c["cr"] / 2, "rR", "rR"),
            (c["ct"] / 2, "rT", "rT"),
            (c["cr"] / 2, "tR", "tR"),
            (c["ct"] / 2, "tT", "tT"),
            (-c["p0"] * lz, "rR", "tT"),  # -p0 lz det G
            (c["p0"] * lz, "rT", "tR"),
            (-lz * c["cofR"], "q", "rR"),  # -q lz cof(F0) : G
            (-lz * c["cofT"], "q", "tT"),
        ]
        A = np.zeros((self.size, self.size))
        for coeff, a, b in terms:
            M = self.maps[a].T @ ((coeff * self.weight)[:, None] * self.maps[b])
            A += M + M.T
        return A

    def peak_radial(self, v: FloatArray, field_slice: slice) -> tuple[float, float]:
        """(R, a(R)) where |a| of the displacement values ``v[field_slice]`` is largest."""
        return peak_on_rings(self.rings, v[field_slice])

    def cubic_gradient(self, fa: dict, fb: dict, lz: float) -> FloatArray:
        """C[a, b, .] for E3 = -lambda_z int q det G (as plane_forms.Forms.cubic_gradient)."""
        w, M = self.weight * lz, self.maps
        two_d = (
            fa["rR"] * fb["tT"] + fb["rR"] * fa["tT"] - fa["rT"] * fb["tR"] - fb["rT"] * fa["tR"]
        )
        out = -(M["q"].T @ (w * two_d))
        for qx, g in ((fa["q"], fb), (fb["q"], fa)):
            out -= M["rR"].T @ (w * qx * g["tT"]) + M["tT"].T @ (w * qx * g["rR"])
            out += M["rT"].T @ (w * qx * g["tR"]) + M["tR"].T @ (w * qx * g["rT"])
        return out

    def cubic_hessian(self, fa: dict, lz: float) -> FloatArray:
        """The matrix C[a, ., .] (as plane_forms.Forms.cubic_hessian)."""
        w, M = self.weight * lz, self.maps
        qw = (w * fa["q"])[:, None]
        H = M["rR"].T @ (qw * M["tT"]) - M["rT"].T @ (qw * M["tR"])
        H = H + H.T
        L = fa["rR"][:, None] * M["tT"] + fa["tT"][:, None] * M["rR"]
        L -= fa["rT"][:, None] * M["tR"] + fa["tR"][:, None] * M["rT"]
        T = M["q"].T @ (w[:, None] * L)
        return -(H + T + T.T)


def coefficient_arrays(forms, state) -> dict:
    """The base state at the points ``forms.R`` (of the layers ``forms.layer``):
    J_g mu_k / g_r^2, J_g mu_k / g_t^2, p0, lambda_z, r / R, r' (= J_g R / (lambda_z r)),
    J_g."""
    tube = state.tube
    lz = state.stretch
    out = {k: np.zeros_like(forms.R) for k in ("cr", "ct", "p0", "cofR", "cofT", "J")}
    for k, ply in enumerate(tube.layers):
        sel = forms.layer == k
        if not sel.any():
            continue
        R = forms.R[sel]
        gr, gt, gz = ply.growth_at(R)  # graded growth: g(R) at the points
        J = gr * gt * gz
        r = state.radius(R)
        mu = ply.shear_modulus
        out["J"][sel] = J
        out["cr"][sel] = J * mu / gr**2
        out["ct"][sel] = J * mu / gt**2
        out["p0"][sel] = state.pressure(R)
        out["cofR"][sel] = r / R  # cof(F0)_rR = F0_tT
        out["cofT"][sel] = J * R / (lz * r)  # cof(F0)_tT = F0_rR = r'
    out["lz"] = lz
    return out


def peak_on_rings(rings_, unknowns: FloatArray) -> tuple[float, float]:
    """(R, a(R)) where |a| of a displacement (its ``unknowns`` in ring_basis.radial_maps'
    basis, continuous across ``rings_``) is largest: on a dense grid of each ring, then a
    parabola through the best three points."""
    a_nodes = nodal_values(rings_, unknowns)
    at, best = 0, (0.0, 0.0)
    for r in rings_:
        t = np.cos(np.pi * np.arange(r.nodes) / (r.nodes - 1))[::-1]
        dense = np.linspace(-1.0, 1.0, 2001)
        vals = _barycentric(t, dense) @ a_nodes[at : at + r.nodes]
        i = int(np.argmax(np.abs(vals)))
        if 0 < i < len(dense) - 1:  # vertex of the parabola through i - 1, i, i + 1
            y0, y1, y2 = vals[i - 1 : i + 2]
            den = y0 - 2 * y1 + y2
            shift = 0.5 * (y0 - y2) / den if den else 0.0
            peak = y1 - 0.25 * (y0 - y2) * shift
            xi = dense[i] + shift * (dense[1] - dense[0])
        else:
            peak, xi = vals[i], dense[i]
        if abs(peak) > abs(best[1]):
            best = (r.inner + 0.5 * (xi + 1) * (r.outer - r.inner), float(peak))
        at += r.nodes - 1
    return best
