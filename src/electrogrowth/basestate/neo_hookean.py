"""The closed forms of the ideal neo-Hookean tube's base state (docs/derivation-base-state.md):
the charge c from (V), the axial force N from (NH-4), the traction residual of (*) as the
state's quadrature error, and sigma_rr(R) from (NH-1). lambda_i itself is the root of (NH-6)
(voltage.py, ``nh_lambda_i``); uniform.py builds the state from these.
"""

from __future__ import annotations

import math

import numpy as np

from .voltage import nh_traction


def state_at(tube, b: float, lam: float) -> tuple[float, float, float, float]:
    """(c, r_o, N, error) at lambda_i = lam, b = g^3 / lambda_z: c from (V), N from (NH-4),
    and the traction residual M - c^2 Delta / (2 r_i^2 r_o^2) of (*), M = (g / lz) m by
    (NH-6), over max(1, (g / lz) ln Rbar_o)."""
    Ro, g, lz = tube.outer_radius, tube.growth, tube.stretch
    x = lam * lam
    delta = b * (Ro**2 - 1.0)  # r_o^2 - r_i^2
    s = 0.5 * math.log1p(delta / x)  # ln(r_o / r_i)
    c = tube.voltage * (Ro - 1.0) / s
    residual = g / lz * nh_traction(b / x, Ro**2 - 1.0) - 0.5 * c * c * delta / (x * (x + delta))
    a = x - b  # A = r^2 - b R^2
    force = math.pi * (
        lz**2 * delta / g**2
        - c * c * s
        - g**4 / lz**2 * (0.5 * (Ro**2 - 1.0) - a / b * s)
        - b / g**2 * (a * math.log(Ro) + 0.5 * delta)
    )
    return c, math.sqrt(x + delta), force, abs(residual) / max(1.0, g / lz * math.log(Ro))


def sigma_rr(tube, b: float, r_i: float, r_o: float, R, r) -> np.ndarray:
    """sigma_rr (NH-1) with rho = (R^2 - 1) / (Rbar_o^2 - 1):
    (g / 2 lz) [log1p((R^2 - 1) A / r^2) - log1p(kappa_o) (r_o / r)^2 rho],
    A = r_i^2 - b, kappa_o = (Rbar_o^2 - 1) A / r_o^2: exactly 0 at R = 1 and at Vbar = 0."""
    a, ro2, k = r_i**2 - b, r_o**2, tube.outer_radius**2 - 1.0
    R2m1 = R**2 - 1.0
    return (
        0.5
        * tube.growth
        / tube.stretch
        * (np.log1p(R2m1 * a / r**2) - math.log1p(k * a / ro2) * ro2 / r**2 * R2m1 / k)
    )
