"""A layered tube stretched towards a Gent layer's kinematic lock ends at the lock
(bifurcation/state_loss.py, bifurcation/march.py).

The tube (check round 28, D2): a neo-Hookean core to R = 1.3 inside a Gent (jm 3) layer to
1.6 grown axially by g_z = 1.0693254142336346, stretched in extension from 1.1. The Gent
layer locks kinematically where lambda_e^2 + 2 / lambda_e - 3 = jm, lambda_e = lambda_z / g_z
(state_loss.py docstring): lambda_z = 2.418602622827184 (brentq below, the independent
route; the modes (0, 1), (3, 0), the same (2, 1) at Vbar 0.3 and the swapped layers all
ended there). An independent collocation kept (2, 1)'s sign up to 2.8e-7 below the lock.

Found by probing: with one BLAS thread (the check's OMP_NUM_THREADS=1), the march's loose
target of (2, 1) jumped negative at its step 2.41860184657514, 7.8e-7 short of the lock
(a jump of log|det|, not a root), and the refinement of that sign change asked for a fine
target whose radial table did not resolve: "base state not resolved by 1025 Chebyshev
points", with the remedy "loosen rtol", escaped the march. A four-layer charged tube with
the same Gent layer ended "the state search fails from 2.41860261063: whether the state is
lost there is not established", the lock 1.2e-8 past that point: the search failed within
LOCK_MARGIN of the lock, short of it.
"""

import pytest
from scipy.optimize import brentq
from threadpoolctl import threadpool_limits

from electrogrowth import Layer, Tube, critical_value, gent, neo_hookean, solve_base_state
from electrogrowth.bifurcation import state_loss
from electrogrowth.bifurcation.along import TubeAt
from electrogrowth.errors import BaseStateError

GZ = 1.0693254142336346
TUBE = Tube(
    (Layer(1.3, material=neo_hookean()), Layer(1.6, material=gent(3.0), growth=(1.0, 1.0, GZ))),
    length=5.0,
    stretch=1.1,
)
#: the kinematic lock: lambda_e^2 + 2 / lambda_e - 3 = 3, lambda_z = g_z lambda_e
LOCK = GZ * brentq(lambda le: le * le + 2.0 / le - 6.0, 1.0, 3.0, xtol=1e-16, rtol=1e-15)
#: the march's last two steps with one BLAS thread
STEPS = (2.39979554076425, 2.41860184657514)


def test_a_table_unresolved_next_to_the_lock_ends_at_the_lock():
    # before: ConvergenceError "base state not resolved by 1025 Chebyshev points"
    with threadpool_limits(1):
        crit = critical_value(TUBE, 2, 1, "stretch", side="extension")
    assert crit.kind == "threshold" and crit.status == "ok"
    assert crit.value == pytest.approx(LOCK, rel=1e-12)


def test_unresolved_tables_at_a_step_short_of_the_lock_end_there():
    at = TubeAt(TUBE, "stretch")
    value, _, _ = state_loss.threshold_between(at, TUBE, *STEPS, tables=True)
    assert value == pytest.approx(LOCK, rel=1e-12)


def test_a_search_failing_short_of_the_lock_ends_at_the_lock(monkeypatch):
    # the four-layer tube's search failed 1.2e-8 short of the lock: the same here, from cold
    # (no state to continue from); before: (None, ..., "whether the state is lost there is
    # not established")
    fails = LOCK - 1.2e-8

    def solve(tube, *, rtol=1e-12, near=None, guess=None):
        if tube.stretch > fails:
            raise BaseStateError("no unloaded state found")
        return solve_base_state(tube, rtol=rtol, near=near, guess=guess)

    monkeypatch.setattr(state_loss, "solve_base_state", solve)
    at = TubeAt(TUBE, "stretch")
    value, edge, pending = state_loss.threshold_between(at, TUBE, STEPS[0], 2.43)
    assert pending is None
    assert value == pytest.approx(LOCK, rel=1e-12)
    assert edge < fails
