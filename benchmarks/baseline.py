"""The baseline: how a careful Python user computes a critical value today.

The paper's method, written plainly: for each trial value of the control parameter, solve
the base state, integrate the Riccati equation of the conditional impedance with
``scipy.integrate.solve_ivp`` (DOP853) from the inner face (z = 0) to the outer face,
and take det z(r_o) as the dispersion function; march the parameter in 1 % steps until
det z changes sign, then ``scipy.optimize.brentq``. One mode at a time, no compiled code,
no pruning of modes. The Stroh matrix and base state are the package's (they are not what
is being timed); what is timed is the per-mode SciPy integration inside a root finder.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from electrogrowth.basestate.tube import solve_base_state, voltage_threshold
from electrogrowth.errors import BaseStateError
from electrogrowth.incremental.stroh import stroh_matrix_py


def det_impedance(params, m: int, n: int, rtol: float) -> float:
    """det z(r_o) of mode (m, n), with z scaled like S / max(1, |(m, k r_o)|)."""
    state = solve_base_state(params)
    k = n * math.pi / (params.stretch * params.length)
    a = params.growth**3 / params.stretch
    G = np.empty((8, 8))

    def rhs(R, y):
        z = y.reshape(4, 4)
        r = math.sqrt(state.r_i**2 + a * (R * R - 1.0))
        stroh_matrix_py(
            state.moduli(np.array(R)), float(state.pressure(np.array(R))), float(m), k * r, G
        )
        G1, G2, G3, G4 = G[:4, :4], G[:4, 4:], G[4:, :4], G[4:, 4:]
        return (a * R / r**2 * (G3 + G4 @ z - z @ G1 - z @ G2 @ z)).ravel()

    sol = solve_ivp(
        rhs, (1.0, params.outer_radius), np.zeros(16), method="DOP853", rtol=rtol, atol=rtol * 1e-2
    )
    s = max(1.0, math.hypot(m, k * state.r_o))
    return float(np.linalg.det(sol.y[:, -1].reshape(4, 4) / s))


def critical_value(
    params, m: int, n: int, solve_for: str, side: str | None = None, *, rtol: float = 1e-10
) -> float:
    """First root of det z(r_o) of mode (m, n) marching ``solve_for`` in 1 % steps from the
    unloaded value (growth from 1, the stretch from 1 down or up, the voltage from 0 up to
    its threshold), then brentq."""
    if solve_for == "voltage":
        start, scale, sense, end = 0.0, voltage_threshold(params)[0], 1.0, None
        end = scale * (1 - 1e-9)
    else:
        start, scale = 1.0, 1.0
        sense = -1.0 if side in (None, "compression") and solve_for == "stretch" else 1.0
        end = 0.05 if sense < 0 else 8.0
    f = lambda x: det_impedance(params.at(solve_for, x), m, n, rtol)  # noqa
    x, fx = start, f(start)
    while (end - x) * sense > 0:
        x_new = x + sense * 0.01 * scale
        if (x_new - end) * sense > 0:
            x_new = end
        try:
            f_new = f(x_new)
        except BaseStateError:
            break
        if fx * f_new <= 0:
            return brentq(f, *sorted((x, x_new)), xtol=1e-14, rtol=1e-14)
        x, fx = x_new, f_new
    raise RuntimeError(f"no critical {solve_for} for mode ({m}, {n})")


def critical_growth(params, m: int, n: int, *, rtol: float = 1e-10) -> float:
    """Smallest g > 1 with det z(r_o) = 0 for mode (m, n): 1 % march, then brentq."""
    return critical_value(params, m, n, "growth", rtol=rtol)
