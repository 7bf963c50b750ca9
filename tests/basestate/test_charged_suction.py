"""A charged, force-free film-lined tube under strong suction (probe 12b, D7; fix 17a).

The voltage branch at the tube's pressure starts at the pressure stage's state (r_i, lambda_z)
= (0.4778, 1.2645) at P_i = -9.78; there two lambda_z close by balance the axial force (1.2645
and ~1.273), and solving it again from the start found none: the walk's grid began with a NaN
load, and solve_on's Brent raised SciPy's bare ValueError "The function value at x=0.4778...
is NaN" (CLI: "internal error", exit 1). The start is now the solved state itself.

Past P_i ~ -9.614 the branch's r_i falls as the voltage rises from 0, to a minimum (at
Vbar^2 ~ 0.04 for P_i = -9.75) where it turns and rises to the limit point (Vbar 2.12), while
lambda_z rises throughout (d Vbar^2 / d lambda_z ~ 14 at the start). Walked in rising r_i,
the states before r_i came back to its start were skipped: Vbar = 0.2 was a named
ConvergenceError past -9.70 (and smaller voltages from -9.615 on). Such a branch is now
walked in lambda_z (thresholds.chart). The states are checked against an independent mpmath
balance written from the energy (radial equilibrium with the Maxwell stress, zero axial
force, the charge from the voltage), followed from the unloaded tube in steps of P_i and
then of Vbar (Newton in (r_i, lambda_z, c), 30 digits, adaptive quadrature in r).
"""

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.basestate.branches import Branch
from electrogrowth.basestate.thresholds import chart, prepare
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.errors import NoBifurcationFound

TUBE = Tube(
    [Layer(1.003, shear_modulus=300.0, growth=(1, 1.02, 1.01)), Layer(2.2)],
    length=4.0,
    axial_force=0.0,
    voltage=0.2,
)
DP = -9.784705508332358  # the march's step that met the NaN

#: (P_i, Vbar): (r_i, lambda_z) of the independent mpmath balance (module docstring)
MPMATH = {
    (-9.75, 0.2): (0.4783954199201213, 1.266849491332402),
    (-9.8, 0.2): (0.4775782091630795, 1.267598706969774),
    (DP, 0.2): (0.4778276521285295, 1.2673697899402),
    (-9.8, 0.1): (0.4775802140340869, 1.265453335269933),
}


def test_the_voltage_branch_starts_at_its_solved_state():
    """Its first load is the start's (Vbar^2 = 0 within rounding), not NaN."""
    at = TUBE.at("pressure", DP).at("voltage", 0.0)
    grid = prepare(at, 1e-12).voltage_to(0.2).grid
    assert np.isfinite(grid[2][0]) and abs(grid[2][0]) < 1e-12  # was NaN


@pytest.mark.parametrize(("p_i", "vbar"), list(MPMATH))
def test_the_states_where_r_i_falls_with_the_voltage_are_the_balance(p_i, vbar):
    """Was a ConvergenceError ("layered base state not resolved", "base-state profile ...
    not resolved by Chebyshev degree 4096": Brent in an r_i cell that holds no state)."""
    state = solve_base_state(TUBE.at("pressure", p_i).at("voltage", vbar))
    r_i, lz = MPMATH[p_i, vbar]
    assert state.r_i == pytest.approx(r_i, rel=1e-12)
    assert state.stretch == pytest.approx(lz, rel=1e-12)
    start = prepare(TUBE.at("pressure", p_i).at("voltage", 0.0), 1e-12).loaded
    assert state.r_i < start[0] and state.stretch > start[1]  # r_i fell, lambda_z rose


def test_the_branch_is_walked_in_r_i_while_r_i_rises_with_the_voltage():
    """The chart is lambda_z only where r_i falls from the start (P_i < -9.6141); the
    pressure stage under suction keeps falling r_i (the walks as they were)."""
    for p_i, by in ((-9.6, "r_i"), (-9.75, "stretch")):
        prep = prepare(TUBE.at("pressure", p_i).at("voltage", 0.0), 1e-12)
        assert chart(prep.branch, *prep.loaded).by == by
        suction = chart(Branch(prep.wall, "pressure"), *prep.start, -1)
        assert (suction.by, suction.step) == ("r_i", -1)


def test_the_limit_point_walked_in_lambda_z_is_the_one_walked_in_r_i():
    """Past its minimum r_i rises to the limit point, so the r_i walk (main at 08401fd)
    located it too: Vbar 2.1221114638019367 at r_i 0.6231902954478393, lambda_z
    2.229178886823665 (its Chebyshev interpolant in r_i, here in lambda_z)."""
    thr = prepare(TUBE.at("pressure", -9.75).at("voltage", 0.0), 1e-12).voltage
    assert thr.kind == "limit point" and thr.walked == "stretch"
    assert thr.value == pytest.approx(2.1221114638019367, rel=1e-13)
    assert thr.lambda_i == pytest.approx(0.6231902954478393, rel=1e-10)
    assert thr.stretch == pytest.approx(2.229178886823665, rel=1e-10)


def test_mode_1_1_under_suction_has_no_root_down_to_the_march_end():
    """Was a ConvergenceError at -9.70 ("no mode bifurcates ... from 0 up to -9.70..., and
    the base states past it are not resolved"); the states now solve down to the march's end
    (-33.68, where the tube's voltage threshold is 3.04 > 0.2), and (1, 1) has no root
    there. No remedy that fails: "loosen --rtol" is not offered."""
    with pytest.raises(NoBifurcationFound, match="no mode bifurcates for pressure between 0") as e:
        critical_value(TUBE, 1, 1, "pressure", side="compression")
    assert "rtol" not in str(e.value.remedy)


def test_the_voltage_response_follows_the_dip():
    """`voltage_response` sampled the branch in r_i from its start: the states where r_i
    falls as the voltage rises (below the start's r_i) were never shown. Sampled in
    lambda_z, the branch's walked coordinate, the voltage rises at every sample, r_i dips
    1.4e-5 below its start (at Vbar ~ 0.32 for P_i = -10) and rises to the limit point, and
    each sample is the solved state at its voltage."""
    from electrogrowth.basestate.layered import solve_layered_state, voltage_response

    tube = TUBE.at("pressure", -10.0)
    r = voltage_response(tube, points=400)
    assert abs(r["voltage"][0]) < 1e-7  # Vbar^2 = 0 to rounding (1e-15) at the start
    assert np.all(np.diff(r["voltage"]) > 0)
    dip = int(np.argmin(r["r_i"]))
    assert 0 < dip < len(r["r_i"]) - 1 and r["r_i"][dip] < r["r_i"][0] - 1e-5
    assert r["r_i"][-1] > r["r_i"][0]
    for j in (dip, 200):
        state = solve_layered_state(tube.at("voltage", float(r["voltage"][j])))
        assert state.r_i == pytest.approx(r["r_i"][j], rel=1e-12)
        assert state.stretch == pytest.approx(r["stretch"][j], rel=1e-12)
