"""The margin of the loads a force march holds (state_loss.held_loads, along.LoadMargin):
check round 28's pulled trilayer (res_61 #12) holds P_i 0.0825 and Vbar 0.363 while F
rises. Past F ~ 248.218 its inflation threshold at V = 0 lies below P_i: the pressure stage
is lost, and the voltage branch, which starts from its end, has no start (BaseStateError).
The margin read the voltage first, so past the loss it raised; the march then bisected the
states that solve, continued ones among them, and ended at 248.519 ("threshold ok")."""

import dataclasses

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from electrogrowth import critical_value
from electrogrowth.basestate.thresholds import prepare
from electrogrowth.bifurcation.along import LoadMargin, TubeAt
from electrogrowth.bifurcation.state_loss import held_loads
from tests.tubes import PULLED_TRILAYER as TUBE

#: a force past the loss (margin -2e-5)
PAST = 248.28
#: the loss by the route below, brentq on its peak P_i(F) - P_i to 1e-12 (probe/indep_pthr.py)
LOST = 248.21807564357286


def _peak_inflation(F: float) -> float:
    """The V = 0 inflation threshold at F by another route: P_i = T(r_i, lambda_z, 0) with
    lambda_z from N = F by scipy's brentq, maximised over r_i by bounded Brent."""
    wall = prepare(dataclasses.replace(TUBE, voltage=0.0), 1e-12).wall  # no F in its integrals

    def integrals(r, lz):
        return wall.integrals(np.array([r]), np.array([lz]), np.zeros(1))

    def inflation(r):
        lz = brentq(lambda s: integrals(r, s)[3][0] - F, 10.8, 11.4, xtol=1e-15, rtol=1e-15)
        return integrals(r, lz)[0][0]

    top = minimize_scalar(lambda r: -inflation(r), bounds=(2.3, 2.8), method="bounded")
    return -top.fun


def test_the_inflation_stage_is_read_before_the_voltage_branch():
    # on main: BaseStateError ("inner pressure ... beyond the pressure threshold") at PAST
    at = TubeAt(TUBE, "force")
    margin = held_loads(at, TUBE, "force")
    assert margin(PAST) == pytest.approx(_peak_inflation(PAST) - TUBE.inner_pressure, abs=1e-10)
    assert margin(PAST) < 0
    # the inflation stage's own margin changes sign at the other route's loss, to 1e-7
    inflation = LoadMargin(at, (("pressure", TUBE.inner_pressure),))
    assert inflation(LOST - 1e-7) > 0 > inflation(LOST + 1e-7)


@pytest.mark.slow
def test_the_force_march_ends_at_the_inflation_stages_loss():
    # check round 28 doubt 1: past 400 s on main; 248.51907004635 "threshold ok" once its
    # voltage thresholds were cheap (a loss read past the inflation stage's); ~25 s CPU now
    found = critical_value(TUBE, 10, 0, "force", side="extension")
    assert found.kind == "threshold" and found.value == pytest.approx(LOST, abs=1e-9)
