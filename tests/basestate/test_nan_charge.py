"""A locking layer beside a non-ideal dielectric layer: past the lock no charge balances the
traction (c NaN), and that NaN must end the branch as a lock, not reach a polynomial layer's
stress and be reported as the user's energy being "not finite" (ParameterError).

Found by probe 7a (D1): the charge of a non-ideal wall is solved (branches.Branch._charge);
Ply.finite took a polynomial energy as finite without looking at the state. The neighbouring
tubes agree on "locking": the same tube with an ideal dielectric text, and Mooney-Rivlin beside
the built-in Gent.
"""

import dataclasses

import pytest

from electrogrowth import (
    Layer,
    Material,
    Tube,
    critical_value,
    gent,
    mooney_rivlin,
    solve_base_state,
    threshold,
)
from electrogrowth.errors import ConvergenceError

NON_IDEAL = "(I1-3)/2 + I5/2 + 0.05*(I6-I4)"


def gent_beside(text: str) -> Tube:
    return Tube(
        [Layer(1.3, material=gent(5.0)), Layer(2.0, material=Material("a", text))],
        length=1.0,
        voltage=0.1,
        stretch=1.0,
    )


@pytest.mark.parametrize("text", [NON_IDEAL, "(I1-3)/2 + I5/2"])
def test_the_voltage_branch_ends_at_the_lock(text):
    # both: lambda_i 2.618034 = the Gent layer's lock at lambda_z = 1 (I1 - 3 = jm)
    thr = threshold(gent_beside(text), "voltage")
    assert thr.kind == "locking" and thr.value == float("inf")
    assert thr.lambda_i == pytest.approx(2.618033988749877, rel=1e-9)


def test_a_polynomial_layer_beside_a_locking_text():
    # the lock is the text's own (a Gent log); Mooney-Rivlin, blamed before, is a polynomial
    text = Material("gt", "-2.5*log(1-(I1-3)/5) + I5/2 + 0.05*(I6-I4)")
    tube = Tube(
        [Layer(1.3, material=mooney_rivlin(0.3)), Layer(2.0, material=text)],
        length=1.0,
        voltage=0.1,
        stretch=1.0,
    )
    assert threshold(tube, "voltage").kind == "locking"


def test_a_state_reports_its_threshold():
    # as_dict walks the voltage branch (its threshold is part of the record; inf -> null)
    tube = dataclasses.replace(gent_beside(NON_IDEAL), voltage=0.05)
    record = solve_base_state(tube).as_dict()
    assert record["threshold_kind"] == "locking" and record["voltage_threshold"] is None


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_growth_control_at_a_voltage_meets_the_lock_as_the_ideal_neighbour_does():
    # the march's state-loss search walks the voltage branch at each growth: with the ideal
    # text it ends "not resolved" next to the lock at g_theta 5.60103; the non-ideal one at
    # 5.60107 (it raised ParameterError, blaming the text, before)
    with pytest.raises(ConvergenceError, match="no mode bifurcates .* up to 5.601"):
        critical_value(gent_beside(NON_IDEAL), 2, 1, "growth[2].theta")
