"""A load next to the branch's start (probe 9b D2).

`solve_base_state(Tube([Layer(1.5, growth=1.2), Layer(2.0)], voltage=1e-9))` raised
BaseStateError "Vbar = 1e-09 is within rounding of the threshold of its branch" (the CLI:
exit 2, "lower the voltage below the threshold"), while the state exists and is continuous
in Vbar (its threshold is O(1)). basestate/thresholds.py `solve_on` read the march's
direction off the grid's first load, `target >= loads[0]`: the load is Vbar^2, and the
unloaded state's computed Vbar^2 is rounding (3.8e-16), above the target 1e-18, so it
looked downwards and found no crossing. The direction is now the caller's (the voltage's
load rises from 0), and a target between the start's exact and computed load is the start.
"""

import pytest

from electrogrowth import Layer, Tube, solve_base_state


@pytest.mark.parametrize("voltage", [1e-9, 1e-8, 3e-8])
def test_tiny_voltage_has_the_unloaded_state(voltage):
    at_zero = solve_base_state(Tube([Layer(1.5, growth=1.2), Layer(2.0)]))
    tiny = solve_base_state(Tube([Layer(1.5, growth=1.2), Layer(2.0)], voltage=voltage))
    assert abs(tiny.lambda_i - at_zero.lambda_i) < 1e-9


def test_mucosa_hoop_growth_at_tiny_voltage():
    """The failure depended on the growth: the mucosal bilayer failed at g_theta = 1.5."""
    tube = Tube(
        [Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.5, 1.0)), Layer(2.0)],
        length=1.0,
        stretch=1.0,
    )
    tiny = solve_base_state(tube.at("voltage", 1e-9)).lambda_i
    assert abs(tiny - solve_base_state(tube.at("voltage", 1e-7)).lambda_i) < 1e-9


@pytest.mark.parametrize("pressure", [1e-17, -1e-17])
def test_tiny_inner_pressure_has_the_unloaded_state(pressure):
    """The pressure branch is solved the same way, its direction the sign of P_i - P_o."""
    tube = Tube([Layer(1.5, growth=1.2), Layer(2.0)])
    tiny = solve_base_state(tube.at("pressure", pressure)).lambda_i
    assert abs(tiny - solve_base_state(tube).lambda_i) < 1e-9
