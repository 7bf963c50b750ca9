"""The closed forms of the ideal neo-Hookean tube's base state (docs/derivation-base-state.md):
the charge c from (V), the axial force N from (NH-4), the traction residual of (*) as the
state's quadrature error, and sigma_rr(R) from (NH-1). lambda_i itself is the root of (NH-6)
(``nh_lambda_i``, below); uniform.py builds the state from these.
"""

from __future__ import annotations

import math
import sys

import numpy as np

from ..brent import brentq

_RTOL_MIN = 4.0 * np.finfo(float).eps  # brentq's smallest rtol


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


# -- the ideal neo-Hookean tube in closed form (docs eqs. NH-3, NH-5, NH-6) --------------------


def nh_asymptote(outer_radius: float, growth: float, stretch: float) -> float:
    """Vbar_inf = g^2 / (lambda_z (Rbar_o - 1)) sqrt((Rbar_o^2 - 1) ln(Rbar_o) / 2)   (NH-5)."""
    Ro = outer_radius
    return growth**2 / (stretch * (Ro - 1.0)) * math.sqrt((Ro**2 - 1.0) * math.log(Ro) / 2.0)


def nh_traction(y: float, k: float) -> float:
    """m = (lambda_z / g) M = ln(lambda_i / lambda_o) + b (lambda_o^-2 - lambda_i^-2) / 2 of (NH-6)
    at y = (lambda_i0 / lambda_i)^2 >= 0, k = Rbar_o^2 - 1: [log1p(kappa) + y kappa] / 2, free of
    cancellation, exactly 0 at y = 1 (lambda_i0) and strictly decreasing in y."""
    kappa = k * (1.0 - y) / (1.0 + k * y)  # (lambda_i / lambda_o)^2 - 1
    return 0.5 * (math.log1p(kappa) + y * kappa)


def nh_square(y: float, k: float) -> float:
    """(Vbar / Vbar_inf)^2 = (s / sinh s)^2 m / ln Rbar_o of (NH-6), signed like m (negative
    below lambda_i0), analytic in y, exactly 1 at y = 0; s = log1p(k y) / 2 = ln(r_o / r_i)."""
    s = 0.5 * math.log1p(k * y)
    damp = s / math.sinh(s) if s > 0.0 else 1.0
    return 2.0 * nh_traction(y, k) / math.log1p(k) * damp * damp


def nh_voltage(outer_radius: float, growth: float, stretch: float, lam_i) -> np.ndarray:
    """Vbar(lambda_i) by (NH-6), vectorised; signed (negative below lambda_i0)."""
    y = (growth**3 / stretch) / np.asarray(lam_i, float) ** 2
    ratio = np.vectorize(nh_square, otypes=[float])(y, outer_radius**2 - 1.0)
    return nh_asymptote(outer_radius, growth, stretch) * np.sign(ratio) * np.sqrt(abs(ratio))


def nh_lambda_i(outer_radius: float, growth: float, stretch: float, ratio: float) -> float:
    """lambda_i with Vbar = ratio Vbar_inf, 0 <= ratio < 1. (NH-6) falls strictly from 1 at y = 0
    to 0 at y = 1 (docs), so brentq on [0, 1] holds the one root, to 4e-16 relative in y. The
    result is backward stable (Vbar(lambda_i) = Vbar to rounding); near the asymptote lambda_i
    is ill-conditioned (relative condition number ~ 1 / (4 (1 - ratio))), where (NH-6) is flat
    at rounding level and brentq falls back to bisection: up to ~120 iterations, hence maxiter."""
    lam0 = math.sqrt(growth**3 / stretch)
    if ratio == 0.0:
        return lam0
    k, target = outer_radius**2 - 1.0, ratio * ratio
    root = _compiled_root()
    y, ok = (math.nan, False) if root is None else root(k, target, 1e-300, _RTOL_MIN, 500)
    if not ok:  # Python's brentq: before numba is loaded, and for its error where it fails
        y = brentq(
            lambda y: nh_square(y, k) - target, 0.0, 1.0, xtol=1e-300, rtol=_RTOL_MIN, maxiter=500
        )
    return lam0 / math.sqrt(y)


def _compiled_root():
    """nh_root_kernel.nh_root (the same root, compiled) once the compiled kernels have
    loaded numba, else None: a base state alone (the ``state`` command) never imports it.
    Remembered once loaded: a march asks at every state."""
    global _NH_ROOT
    if _NH_ROOT is None and "numba" in sys.modules:
        from .nh_root_kernel import nh_root

        _NH_ROOT = nh_root
    return _NH_ROOT


_NH_ROOT = None
