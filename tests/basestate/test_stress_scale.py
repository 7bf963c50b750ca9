"""The stress scale of a layered state's check, int (|tau_1| + |tau_2|) dr / r, has a kink
where a stress changes sign in a layer: its Chebyshev series converges like 1 / degree^2,
and asking it for 1e-2 rtol refused states that exist (check round 24, case 2-108: a scan
of g_r "not resolved (why is not known)" from 4.31575885022, between states that were).
It is a magnitude that divides the residuals: resolved to layered_state.SCALE_TOL."""

import numpy as np
import pytest

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.basestate.plies import chebyshev
from electrogrowth.errors import ConvergenceError

SOFTENING = Material("mr-", "(1.801*(I1-3) + (-0.801)*(I2-3))/2 + I5/2")


def _tube(g_r: float) -> Tube:
    layer = Layer(1.05401, material=SOFTENING, shear_modulus=16.78, permittivity=0.3837,
                  growth=(g_r, 1.732, 1.732))  # fmt: skip
    return Tube((layer,), length=0.1284, stretch=2.11, voltage=0.4797445)


def test_a_state_whose_stress_changes_sign_in_the_wall_resolves():
    state = solve_base_state(_tube(4.3158))  # was "not resolved by Chebyshev degree 4096"
    assert state.quadrature_error <= 1e-12
    # why: tau_1 = sigma_rr + p or tau_2 = sigma_tt + p changes sign inside the wall
    prof = state.profiles(201)
    tau1, tau2 = prof["sigma_rr"] + prof["p"], prof["sigma_tt"] + prof["p"]
    assert any(t.min() < 0 < t.max() for t in (tau1, tau2))
    # the value: on the smooth curve through its neighbours, which resolved before
    xs = np.array([4.3157, 4.316, 4.32])
    ys = np.array([solve_base_state(_tube(x)).lambda_i for x in xs])
    assert state.lambda_i == pytest.approx(np.polyval(np.polyfit(xs, ys, 2), 4.3158), rel=1e-10)


def test_an_unresolved_series_says_by_how_much():
    """What was observed, not 'why is not known': the tail left and the one asked for."""
    with pytest.raises(ConvergenceError, match=r"tail is 5e-08 of its size, above 1e-14"):
        chebyshev(lambda x: np.abs(x - 0.3)[:, None], -1.0, 1.0, 1e-14, "a kink")
