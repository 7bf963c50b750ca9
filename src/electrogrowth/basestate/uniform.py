"""The base state of the paper's uniform tube: grown, stretched, radially charged (Sec. 3.1).

Units mu = eps = R_i = 1. The reference tube 1 <= R <= Rbar_o grows isotropically (F_g = g I)
and deforms (det F_e = 1) into r_i <= r <= r_o at total axial stretch lambda_z (eqs. 14-15):

    r(R)^2 = r_i^2 + b (R^2 - 1),   b = g^3 / lambda_z,   dr/dR = b R / r,

with elastic stretches l2 = r / (g R), l3 = lambda_z / g, l1 = 1 / (l2 l3). Maxwell's equation
gives D_r = c / r, the voltage is V = Vbar (Rbar_o - 1) = int_{r_i}^{r_o} E_r dr, and radial
equilibrium with both faces traction-free (eq. 25) fixes c for each lambda_i = r_i: the curve
Vbar(lambda_i) and its threshold live in ``voltage.py``. Here: the solve; the solved state,
its through-wall profile and tables, in ``uniform_state.py``.

Two routes. The ideal neo-Hookean dielectric (the paper's material) is solved in closed form:
lambda_i by brentq on (NH-6), sigma_rr by (NH-1), N by (NH-4), moduli by
``moduli.neo_hookean_moduli``. Every other energy takes the generic route: Gauss-Legendre
quadratures, a scanned threshold, and sigma_rr as a Chebyshev antiderivative, exact to
quadrature accuracy at any R; it is also the reference the closed form is tested against.
Derivation, closed forms and the paper's typos: docs/derivation-base-state.md.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import BaseStateError, Beyond, BranchNotFollowed, ConvergenceError, StartUnresolved
from ..model.layers import Tube
from . import neo_hookean
from .start_probe import UNRESOLVED
from .uniform_state import UniformState
from .voltage import CLOSING, GAUSS_ORDERS, UniformWall, cell_root, threshold_info

__all__ = ["UniformState", "solve_uniform"]


def solve_uniform(tube: Tube, rtol: float) -> UniformState:
    """The base state of a uniform tube (``tube.is_uniform``): lambda_i solves
    Vbar(lambda_i) = Vbar on the monotone branch from lambda_i0 (Vbar = 0) to the threshold,
    in closed form for the ideal neo-Hookean dielectric (a bracketed root solve of NH-6, to
    rounding, ~20 us), else by a Chebyshev root in the cell of the scanned curve that brackets
    Vbar (~2 ms)."""
    info = threshold_info(tube, rtol)
    target = tube.voltage
    if not (target < info.value or target == 0):
        where = (
            f"g = {tube.growth:g}, lambda_z = {tube.stretch:g}, Rbar_o = {tube.outer_radius:g},"
            f" {tube.material.name}"
        )
        if info.kind == "closing":
            raise BranchNotFollowed(f"Vbar = {target:.12g} at {where}: {CLOSING}")
        if info.kind == "unresolved":
            raise StartUnresolved(f"Vbar = {target:.12g} at {where}: {UNRESOLVED}")
        raise BaseStateError(
            f"Vbar = {target:.12g} is at or above the threshold Vbar = {info.value:.12g}"
            f" ({info.kind}) for {where}; no axisymmetric state",
            beyond=Beyond("voltage", target, info.value, tube.outer_radius),
        )
    Ro, g, lz = tube.outer_radius, tube.growth, tube.stretch
    if info.nodes == 0:  # neo-Hookean closed form
        if not (ratio := target / info.value) < 1.0:
            raise BaseStateError(
                f"Vbar = {target:.12g} is within rounding of the threshold"
                f" {info.value:.12g}; no base state resolved"
            )
        wall = UniformWall(tube.material, Ro, g, lz)
        lam = neo_hookean.nh_lambda_i(Ro, g, lz, ratio)
        return UniformState._neo_hookean(tube, wall, lam, info)
    wall = UniformWall(tube.material, Ro, g, lz, info.nodes)
    if target == 0:
        return UniformState._build(tube, wall, info.lambda_i0, info, rtol)
    grid, v = info.grid, info.values
    if target > v[-1]:  # beyond the scan: towards an asymptote or a locking stretch
        far = info.lambda_i
        tail = (
            grid[-1] * 4.0 ** np.arange(1, 21)
            if math.isinf(far)
            else far - (far - grid[-1]) * 4.0 ** -np.arange(1, 21)
        )
        grid, v = np.append(grid[-1], tail), np.append(v[-1], wall.voltage(tail))
    k = np.flatnonzero(v >= target)
    if not k.size:
        raise BaseStateError(
            f"Vbar = {target:.12g} is within rounding of the threshold"
            f" {info.value:.12g}; no base state resolved"
        )
    a, b = sorted((grid[k[0] - 1], grid[k[0]]))  # the grid falls on a branch running inward
    for n in GAUSS_ORDERS[GAUSS_ORDERS.index(wall.nodes) :]:
        wall = dataclasses.replace(wall, nodes=n)
        signed = lambda x, t=wall: np.sign(v := t.voltage(x)) * v**2 - target**2  # noqa: E731
        if n != info.nodes and not signed(np.array([a]))[0] * signed(np.array([b]))[0] <= 0:
            break  # the cell of the scanned rule brackets no root of this one: not resolved
        lam = cell_root(signed, a, b)
        state = UniformState._build(tube, wall, lam, info, rtol)
        if state.quadrature_error <= max(rtol, 1e-14):
            return state
    raise ConvergenceError(f"base state at Vbar = {target:.12g} not resolved to rtol = {rtol}")
