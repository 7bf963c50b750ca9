"""A charged, force-free film-lined tube under strong suction (probe 12b, D7).

The voltage branch at the tube's pressure starts at the pressure stage's state (r_i, lambda_z)
= (0.4778, 1.2645) at P_i = -9.78; there two lambda_z close by balance the axial force (1.2645
and ~1.273), and solving it again from the start found none: the walk's grid began with a NaN
load, and solve_on's Brent raised SciPy's bare ValueError "The function value at x=0.4778...
is NaN" (CLI: "internal error", exit 1). Its critical_value of (1, 1) under suction did the
same; the scan of the same tube gives (71, 0) at -0.0565478422141.

The start is now the solved state itself, and a NaN inside a cell is a named
ConvergenceError. The states past P_i ~ -9.70 exist (the voltage threshold there is 2.12 >
0.2) but are not resolved: there the voltage branch's r_i hardly moves with the voltage
(1e-6 at -9.68), and the branch is walked in r_i. So (1, 1) has no root from 0 to -9.70,
and past it the answer is a named ConvergenceError, not a value.
"""

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.basestate.thresholds import prepare
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.errors import ConvergenceError

TUBE = Tube(
    [Layer(1.003, shear_modulus=300.0, growth=(1, 1.02, 1.01)), Layer(2.2)],
    length=4.0,
    axial_force=0.0,
    voltage=0.2,
)
DP = -9.784705508332358  # the march's step that met the NaN


def test_the_voltage_branch_starts_at_its_solved_state():
    """Its first load is the start's (Vbar^2 = 0 within rounding), not NaN."""
    at = TUBE.at("pressure", DP).at("voltage", 0.0)
    grid = prepare(at, 1e-12).voltage_to(0.2).grid
    assert np.isfinite(grid[2][0]) and abs(grid[2][0]) < 1e-12  # was NaN


def test_the_state_past_the_resolved_range_is_a_named_error():
    with pytest.raises(ConvergenceError):  # was ValueError: "... is NaN"
        solve_base_state(TUBE.at("pressure", DP))


@pytest.mark.slow  # 24 s: the march to the unresolved states; the crash is tested above
def test_mode_1_1_under_suction_has_no_root_before_the_unresolved_states():
    """... and no remedy that fails: "loosen --rtol (e.g. 1e-10)" was printed, and the
    states' tolerance is not rtol's (the same states fail at rtol 1e-8)."""
    with pytest.raises(ConvergenceError, match="no mode bifurcates for pressure from 0 up") as e:
        critical_value(TUBE, 1, 1, "pressure", side="compression")
    assert "rtol" not in str(e.value.remedy)
