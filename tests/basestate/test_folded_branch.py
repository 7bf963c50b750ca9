"""A voltage branch that runs inward and turns back outward in r_i (check round 30 D2).

`(I1-3)/2 + I5/2 (1 + 2 (I1-3)) + 0.05 I5^2`, one layer [1, 2], lambda_z 1, P_i 0.3: at the
uncharged state the field raises T (dT/dq > 0 at q = 0), at large charge the I5^2 term lowers
it. The branch leaving the uncharged state r0 = 1.28158 runs inward, turns in r_i at
0.99826 r0 (c 0.575) and passes outward through r0 at Vbar 0.544, the charge and the voltage
rising throughout. Just outward of r0 a large charge (c 0.847) balances the traction: the
branch walked from it refused every Vbar below 0.544 on main.

The other route: at each charge c, r_i from T(r_i, c) = P_i - P_o by brentq on the wall's
integrals (no chart, walk or charge solve of the package's), then c from V(c) = Vbar by
brentq; check round 30's own solver (probe/k30/caseE_pts.py) gives the same r_i to 4e-16.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from electrogrowth import Layer, Material, Tube, solve_base_state
from electrogrowth.basestate import thresholds
from electrogrowth.basestate.layered import solve_continued
from electrogrowth.basestate.thresholds import prepare

FOLD = Material("foldE", "(I1-3)/2 + I5/2*(1 + 2.0*(I1-3)) + 0.05*I5**2")
#: check round 30's case A: the same coupling without I5^2, its charge unbounded at a lock
LOCKS = Material("caseA", "(I1-3)/2 + I5/2*(1 + 2.0*(I1-3))")


def _tube(material, inner_pressure=0.3, voltage=0.0):
    return Tube(
        [Layer(2.0, material=material)],
        stretch=1.0,
        inner_pressure=inner_pressure,
        voltage=voltage,
        length=3.0,
    )


def _by_charge(inner_pressure: float, vbar: float) -> float:
    """r_i at Vbar on the branch, parametrised by its charge (the module docstring)."""
    wall = prepare(_tube(FOLD, inner_pressure), 1e-12).wall

    def integrals(r_i, c):
        return wall.integrals(np.array([r_i]), np.array([1.0]), np.array([c]))

    def r_of(c):
        return brentq(lambda x: integrals(x, c)[0][0] - inner_pressure, 1.1, 1.6, xtol=1e-15)

    c = brentq(lambda c: integrals(r_of(c), c)[2][0] - vbar, 1e-6, 3.0, xtol=1e-15)
    return r_of(c)


def test_the_branch_leaves_the_uncharged_state_inward():
    # the charge outward of r0 is the detached large one: main walked outward from it
    prep = prepare(_tube(FOLD), 1e-12)
    walk = thresholds.chart(prep.branch, *prep.loaded)
    assert not thresholds.opens(walk, *prep.loaded)
    far = prep.branch.at([prep.loaded[0] * (1 + 1e-5)], 1.0)
    assert far["voltage"][0] == pytest.approx(0.544, abs=1e-3)  # check round 30's 0.544


@pytest.mark.parametrize("vbar", [0.1, 0.3, 0.5, 0.6])
def test_states_below_and_past_the_fold_solve(vbar):
    # main: ConvergenceError "not resolved" for Vbar 0.1, 0.3, 0.5; 0.6 solved there too
    state = solve_base_state(_tube(FOLD, voltage=vbar))
    assert state.lambda_i == pytest.approx(_by_charge(0.3, vbar), rel=1e-13)


def test_the_threshold_is_walked_in_the_charge_past_the_fold():
    thr = prepare(_tube(FOLD), 1e-12).voltage
    assert (thr.kind, thr.value, thr.walked) == ("none", math.inf, "charge")
    r_i, _, loads, c = thr.grid
    assert np.all(np.diff(c) > 0) and np.all(np.diff(loads) > 0)
    turn = int(np.argmin(r_i))  # r_i falls to the fold, then rises
    assert 0 < turn < len(r_i) - 1
    assert r_i[turn] / r_i[0] == pytest.approx(0.99826, abs=2e-5)  # check round 30's fold


def test_a_pressure_state_past_where_the_march_stopped():
    # main's pressure march at Vbar 0.3 stopped at P_i 0.28966, where the state crosses to
    # the inward side of the uncharged one
    state = solve_base_state(_tube(FOLD, inner_pressure=0.2897, voltage=0.3))
    assert state.lambda_i == pytest.approx(_by_charge(0.2897, 0.3), rel=1e-13)


def test_a_lock_of_the_coupling_is_not_read_as_a_fold():
    # the charge walk past the r_i walk's end finds r_i still falling: the lock stands
    thr = prepare(_tube(LOCKS), 1e-12).voltage
    assert thr.kind == "locking" and thr.walked == "r_i"
    assert thr.lambda_i == pytest.approx(1.2612165916, rel=1e-10)  # check round 30's table


def test_a_state_on_an_inward_branch_is_continued_from_its_neighbour():
    # main: refused (its load does not rise with r_i), every state of a march a cold walk
    near = solve_base_state(_tube(LOCKS, voltage=1.0))
    warm = solve_continued(_tube(LOCKS, voltage=1.05), near)
    assert warm is not None
    cold = solve_base_state(_tube(LOCKS, voltage=1.05))
    assert warm.lambda_i == pytest.approx(cold.lambda_i, rel=1e-12)
