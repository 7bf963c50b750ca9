"""Where a march's state search fails next to a Gent lock, the failure of the search is not
the loss of the state (bifurcation/state_loss.py).

The tube (probe 11a, D4): a film 10 times as stiff, to R = 1.04, grown in the hoop direction
inside a Gent (jm 3) layer to 1.6. The Gent layer's inner face nears its lock, and the film
is compressed against it; the state goes on towards the lock for every growth: an
independent quadrature of the radial equilibrium (tests/basestate/test_near_lock.py) gives
the face's margin 1 - (I1 - 3) / jm as 0.0018 at g_theta 5.41, 1.3e-4 at 6, 3.7e-7 at 7,
1.2e-10 at 8 and 5e-21 at 10: a lock approached, never reached, and no loss at any finite
growth (nothing locks kinematically: lambda_z = 1, no axial growth).

Found by probing: critical_value(tube, 6, 0, "growth[1].theta") returned kind THRESHOLD at
5.409999999999989, the march's last step, error estimate 0, status OK. Every cold solve
past that step failed ("no unloaded state found", a search at too coarse a Gauss rule, now
refined: basestate/thresholds.py), threshold_between read each failure as a lost state and
bisected to the step itself, and the lock rule (a loss next to a lock is established only
kinematically) was never reached. Now a failed cold search is tried again continued from
the nearest state the march solved, and a search that meets a layer's lock (LockedSearch)
is a loss only where a layer locks kinematically.
"""

import warnings

import pytest

from electrogrowth import Layer, Tube, critical_value, gent, solve_base_state
from electrogrowth.bifurcation import state_loss
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.errors import NEAR_LOCK, BaseStateError, ConvergenceError

TUBE = Tube(
    (Layer(1.04, shear_modulus=10.0), Layer(1.6, material=gent(3.0))), length=3.0, stretch=1.0
)
CONTROL = "growth[1].theta"


def _failing_cold(monkeypatch, error, past=5.405):
    """Make every cold solve past ``past`` raise ``error`` (as the search did on 90305a1),
    continued solves (``near``) untouched."""

    def solve(tube, *, rtol=1e-12, near=None, guess=None):
        if near is None and tube.layers[0].growth[1] > past:
            raise error
        return solve_base_state(tube, rtol=rtol, near=near, guess=guess)

    monkeypatch.setattr(state_loss, "solve_base_state", solve)


def test_a_failed_search_next_to_solved_states_is_not_a_loss(monkeypatch):
    # on 90305a1: (5.41, 5.41, None), the loss at the march's last step
    at = TubeAt(TUBE, CONTROL)
    for x in (5.3, 5.35, 5.4, 5.41):  # the march's path (from 5.3, which solves from cold)
        at.state(x)
    _failing_cold(monkeypatch, BaseStateError("no unloaded state found"))
    value, edge, pending = state_loss.threshold_between(at, TUBE, 5.41, 5.42)
    assert value is None
    assert edge == 5.41 and isinstance(pending, ConvergenceError)


def test_a_search_that_meets_a_lock_is_a_loss_only_kinematically(monkeypatch):
    # no state to continue from: the search meets the Gent layer's lock from 5.405 on, and
    # nothing locks kinematically (lambda_z = 1): the loss is not established
    from electrogrowth.basestate.thresholds import LockedSearch  # (not on 90305a1)

    _failing_cold(monkeypatch, LockedSearch("no unloaded state found before a lock", 256))
    at = TubeAt(TUBE, CONTROL)
    value, edge, pending = state_loss.threshold_between(at, TUBE, 5.40, 5.42)
    assert value is None
    assert 5.40 <= edge <= 5.405
    assert "not established" in str(pending) and pending.remedy == NEAR_LOCK


@pytest.mark.slow
def test_no_loss_is_reported_where_states_exist():
    # on 90305a1: kind THRESHOLD, 5.409999999999989, error estimate 0 (~140 s)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ConvergenceError, match="not established") as err:
            critical_value(TUBE, 6, 0, CONTROL)
    reached = float(err.value.args[0].split(" up to ")[1].split(",")[0])
    # where the states stop resolving (the face's margin ~8.8e-4 there): cold solves
    # resolve at 5.6 and not at 5.6133; the march's search reads its boundary 5.6133 since
    # fix23d's lock rule (below 5.6 before it, between cc5dcff and 9b2276c)
    assert 5.59 < reached < 5.62
    assert not isinstance(err.value, BaseStateError)
