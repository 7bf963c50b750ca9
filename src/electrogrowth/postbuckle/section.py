"""The finite-element model of a tube's cross-section: a sector of the wall in reference polar
coordinates (R, Theta), its kinematics, parameters and follower pressures (the mesh, the
unknowns and the assembly: wall.py).

The mesh is the rectangle [1, R_N] x [0, k pi / m] of (R, Theta), k = ``periods`` half
wavelengths of mode m (1 by default). The position is
x = (R + u_R) e_R(Theta) + u_Theta e_Theta(Theta), so

    F = [[1 + u_R,R, (u_R,Theta - u_Theta) / R], [u_Theta,R, 1 + (u_R + u_Theta,Theta) / R]],

F_zz = lambda_z. Symmetry: u_Theta = 0 on the rays Theta = 0 and Theta = k pi / m (the
sector then holds the modes cos(j m Theta / k), j = 0, 1, 2, ...: for k = 1 the mode's
family cos(j m Theta) alone, period doubling suppressed; for k = 2 also the subharmonics
cos((2 j + 1) m Theta / 2), period doubling; k must divide m for them to close around the
ring, and m / k >= 2: the half ring k = m holds the rigid translation cos(Theta)).
Follower pressures through the potential -P_i lambda_z A_i + P_o lambda_z A_o, A the area
the face encloses in the sector, A = 1/2 int x cross x_Theta dTheta.
"""

from __future__ import annotations

import math

import numpy as np
import skfem
from skfem import BilinearForm, Functional, LinearForm, asm

from ..errors import ParameterError
from ..model.layers import Tube
from .energy import cauchy_stress
from .wall import (
    INTORDER,
    MeshSize,
    Wall,
    check_periods,
    energy_forms,
    pressure_field,
    radial_counts,
)


def _avec(u, p0, p1, p2, A, w):
    """The 7 variables (F - I flattened, D, p) linear in one (trial or test) field. The
    Lagrangian electric displacement D = (A_Theta / R, -A_R) is divergence-free,
    (R D_R)_R / R + (D_Theta)_Theta / R = 0, for every stream function A."""
    R = w.x[0]
    g = u.grad
    return (
        g[0, 0],
        (g[0, 1] - u[1]) / R,
        g[1, 0],
        (g[1, 1] + u[0]) / R,
        A.grad[1] / R,
        -A.grad[0],
        pressure_field(p0, p1, p2, w),
    )


@Functional
def _face_integral(w):
    b = _face_vars(w["prev"], w.x[0])
    R = w.x[0]
    return w["load"] * 0.5 * ((R + b[0]) * (R + b[0] + b[3]) - b[1] * (b[2] - b[1]))


def _face_vars(u, R):
    """(u_R, u_Theta, u_R,Theta, u_Theta,Theta) on a face R = const."""
    return (u[0], u[1], u.grad[0, 1], u.grad[1, 1])


def _enclosed_gradient(b, R):
    """d c / d b of c = (R + b0)(R + b0 + b3) - b1 (b2 - b1) = x cross x_Theta."""
    return (2 * R + 2 * b[0] + b[3], 2 * b[1] - b[2], -b[1], R + b[0])


#: its constant Hessian (i, j, value), symmetric pairs listed both ways
_ENCLOSED_HESSIAN = (
    (0, 0, 2.0),
    (0, 3, 1.0),
    (3, 0, 1.0),
    (1, 1, 2.0),
    (1, 2, -1.0),
    (2, 1, -1.0),
)


@LinearForm
def _face_residual(v, q0, q1, q2, vA, w):
    R = w.x[0]
    g = _enclosed_gradient(_face_vars(w["prev"], R), R)
    b = _face_vars(v, R)
    return w["load"] * 0.5 * sum(gi * bi for gi, bi in zip(g, b))


@BilinearForm
def _face_tangent(du, dp0, dp1, dp2, dA, v, q0, q1, q2, vA, w):
    a = _face_vars(du, w.x[0])
    b = _face_vars(v, w.x[0])
    return w["load"] * 0.5 * sum(h * a[i] * b[j] for i, j, h in _ENCLOSED_HESSIAN)


def mesh_size(
    tube: Tube, m: int, density: float, *, hoop: int | None = None, periods: int = 1
) -> MeshSize:
    """A mesh of about ``density`` elements per unit reference length across the wall (at
    least 2 per layer), and ``hoop`` elements along each pi / m of the sector (default: as
    many per unit arc length at R = 1 as across, at least 4), ``periods`` times that in all:
    the sector k pi / m is the mesh of pi / m mirrored k - 1 times."""
    if hoop is None:
        hoop = max(4, math.ceil(density * math.pi / m))
    return MeshSize(radial_counts(tube, density), int(hoop) * periods)


class Section(Wall):
    """The cross-section sector k pi / m (k = ``periods`` divides m) of ``tube`` for mode
    ``m``: mesh, bases, constraints and the energy's residual and tangent at a vector of
    unknowns ``x`` (the tube's loads as given; :meth:`set_tube` swaps the tube). The energy
    is the sector's per unit reference length along the axis."""

    kind = "section"
    kinematics = staticmethod(_avec)
    forms = energy_forms(_avec)

    def __init__(self, tube: Tube, m: int, size: MeshSize, *, periods: int = 1):
        if m < 1:
            raise ParameterError(f"m = {m} is out of range; valid range: m >= 1")
        # k = m would be the half ring, which holds the rigid translation cos(Theta)
        check_periods(periods, m, "m", largest=m // 2)
        self.m, self.periods = m, periods
        self.sector = periods * math.pi / m
        super().__init__(tube, size, self.sector)
        self.hoop_fixed = self.end_fixed

    def _parameters(self, tube, mu, eps, g):
        lz = np.full(mu.shape, float(tube.stretch))
        return np.array([mu, eps, lz, g[0], g[1], g[2]])

    def _identity(self):
        return {0: 1.0, 3: 1.0}

    def _face_loads(self):
        t = self.tube
        lz = float(t.stretch)
        out = []
        if t.inner_pressure:
            out.append(("inner", -t.inner_pressure * lz))
        if t.outer_pressure:
            out.append(("outer", t.outer_pressure * lz))
        return out

    def _face_residual(self, fb, x, load):
        return asm(_face_residual, fb, prev=fb.interpolate(x)[0], load=load)

    def _face_energy(self, fb, x, load):
        return float(asm(_face_integral, fb, prev=fb.interpolate(x)[0], load=load))

    def _face_tangent(self, fb, x, load):
        return asm(_face_tangent, fb, load=load)

    def stresses(self, x: np.ndarray) -> np.ndarray:
        """The in-plane Cauchy stress at the quadrature points, (2, 2, ne, nq)."""
        return cauchy_stress(self.state(x), self.params)


__all__ = ["INTORDER", "MeshSize", "Section", "mesh_size", "skfem"]
