"""The finite-element model of a tube's meridian: the axisymmetric modes (0, n) on a window of
the wall in reference cylindrical coordinates (R, Z), its kinematics, parameters and follower
pressures (the mesh, the unknowns and the assembly: wall.py; the density: energy.py).

The mesh is the rectangle [1, R_N] x [0, L / n] of (R, Z): half an axial wavelength of mode
(0, n), whose current axial wavenumber is k = n pi / (lambda_z L) (incremental/targets.py).
The position is r = R + u_R, z = lambda_z Z + u_Z, theta = Theta, so in the frames
(e_R, e_Theta, e_Z) -> (e_r, e_theta, e_z)

    F = [[1 + u_R,R, 0, u_R,Z], [0, (R + u_R) / R, 0], [u_Z,R, 0, lambda_z + u_Z,Z]]:

the plane (R, Z) with the hoop stretch s = r / R out of it. Symmetry: u_Z = 0 on the planes
Z = 0 and Z = L / n, the tube's sliding ends (paper eq. 57; docs/derivation-families.md)
repeated every half wavelength. They fix the mean axial stretch at lambda_z and hold the
modes u_R ~ cos(j k z), u_Z ~ sin(j k z), j = 0, 1, 2, ...: the mode, its harmonics and the
axisymmetric state; non-axisymmetric modes (m >= 1) and torsion (u_theta) are absent by
construction. Follower pressures through the potential -P_i V_i + P_o V_o, V the volume a
face encloses per radian, V = 1/2 int r^2 z_Z dZ (the end planes z = 0 and z = lambda_z L/n
stay put). The energy is per radian of the window: int psi R dR dZ + the pressures'.
"""

from __future__ import annotations

import math

import numpy as np
from skfem import BilinearForm, Functional, LinearForm, asm

from ..errors import ParameterError
from ..model.layers import Tube
from .energy import cauchy_stress, hoop_stress
from .wall import MeshSize, Wall, check_periods, energy_forms, pressure_field, radial_counts


def _avec(u, p0, p1, p2, A, w):
    """The 8 variables (in-plane F - diag(1, lambda_z) flattened, D, p, s - 1) linear in one
    (trial or test) field. The Lagrangian electric displacement D = (A_Z / R, -A_R / R) is
    divergence-free, (R D_R)_R / R + (D_Z)_Z = 0, for every stream function A."""
    R = w.x[0]
    g = u.grad
    return (
        g[0, 0],
        g[0, 1],
        g[1, 0],
        g[1, 1],
        A.grad[1] / R,
        -A.grad[0] / R,
        pressure_field(p0, p1, p2, w),
        u[0] / R,
    )


# -- the volume a face R = const encloses per radian, c = 1/2 (R + u_R)^2 (lambda_z + u_Z,Z)
def _face_vars(u):
    """(u_R, u_Z,Z) on a face R = const."""
    return (u[0], u.grad[1, 1])


@Functional
def _face_integral(w):
    r = w.x[0] + w["prev"][0]
    return w["load"] * 0.5 * r**2 * (w["lz"] + w["prev"].grad[1, 1])


@LinearForm
def _face_residual(v, q0, q1, q2, vA, w):
    r = w.x[0] + w["prev"][0]
    zz = w["lz"] + w["prev"].grad[1, 1]
    b = _face_vars(v)
    return w["load"] * (r * zz * b[0] + 0.5 * r**2 * b[1])


@BilinearForm
def _face_tangent(du, dp0, dp1, dp2, dA, v, q0, q1, q2, vA, w):
    r = w.x[0] + w["prev"][0]
    zz = w["lz"] + w["prev"].grad[1, 1]
    a, b = _face_vars(du), _face_vars(v)
    return w["load"] * (zz * a[0] * b[0] + r * (a[0] * b[1] + a[1] * b[0]))


def window(tube: Tube, n: int) -> float:
    """The reference length of half an axial wavelength of mode (0, n), L / n."""
    return tube.length / n


def meridian_size(
    tube: Tube, n: int, density: float, *, axial: int | None = None, periods: int = 1
) -> MeshSize:
    """A mesh of about ``density`` elements per unit reference length across the wall (at
    least 2 per layer), and ``axial`` elements along each L / n of the window (default: as
    many per unit length, at least 4), ``periods`` times that in all."""
    if axial is None:
        axial = max(4, math.ceil(density * window(tube, n)))
    return MeshSize(radial_counts(tube, density), int(axial) * periods)


class Meridian(Wall):
    """The meridian window k L / n (k = ``periods`` divides n) of ``tube`` for mode
    (0, ``n``): mesh, bases, constraints and the energy's residual and tangent at a vector
    of unknowns ``x`` (the tube's loads as given; :meth:`set_tube` swaps the tube).
    ``size.hoop`` counts the elements along the window."""

    kind = "meridian"
    kinematics = staticmethod(_avec)
    forms = energy_forms(_avec)

    def __init__(self, tube: Tube, n: int, size: MeshSize, *, periods: int = 1):
        if n < 1:
            raise ParameterError(f"n = {n} is out of range; valid range: n >= 1")
        check_periods(periods, n, "n")
        self.n, self.periods = n, periods
        super().__init__(tube, size, periods * window(tube, n))
        self.axial_fixed = self.end_fixed

    def set_tube(self, tube: Tube) -> None:
        if getattr(self, "_tube", None) is not None and tube.length != self.tube.length:
            raise ParameterError("the tube's length differs from the mesh's")
        super().set_tube(tube)

    def _parameters(self, tube, mu, eps, g):
        # the plane's growth (g_R, g_Z), out of it g_Theta
        return np.array([mu, eps, g[0], g[2], g[1]])

    def _identity(self):
        return {0: 1.0, 3: float(self.tube.stretch), 7: 1.0}

    def _face_loads(self):
        t = self.tube
        out = []
        if t.inner_pressure:
            out.append(("inner", -t.inner_pressure))
        if t.outer_pressure:
            out.append(("outer", t.outer_pressure))
        return out

    def _face_args(self, fb, x, load):
        return {"prev": fb.interpolate(x)[0], "load": load, "lz": float(self.tube.stretch)}

    def _face_residual(self, fb, x, load):
        return asm(_face_residual, fb, **self._face_args(fb, x, load))

    def _face_energy(self, fb, x, load):
        return float(asm(_face_integral, fb, **self._face_args(fb, x, load)))

    def _face_tangent(self, fb, x, load):
        return asm(_face_tangent, fb, **self._face_args(fb, x, load))

    def stresses(self, x: np.ndarray) -> np.ndarray:
        """The Cauchy stress at the quadrature points, (3, 3, ne, nq), frame (e_r, e_theta,
        e_z) where the point has not turned (the axisymmetric state)."""
        state = self.state(x)
        plane = cauchy_stress(state, self.params, "meridian")
        out = np.zeros((3, 3) + plane.shape[2:])
        out[np.ix_([0, 2], [0, 2])] = plane
        out[1, 1] = hoop_stress(state, self.params)
        return out


__all__ = ["Meridian", "meridian_size", "window"]
