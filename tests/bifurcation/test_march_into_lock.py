"""A march whose states run next to a Gent layer's lock stops after a bounded number of
base states, and says so in the terms of the lock (bifurcation/state_loss.py).

P6 of check round 35b: a three-layer tube (a neo-Hookean core grown 1.05, a Gent layer jm
1.979, a soft neo-Hookean sleeve), closed, free ends, inflated. ``threshold(tube,
"pressure")`` is a lock (value inf, kind "locking", lambda_i 1.90522): the pressure grows
without bound towards it, the state is never lost. The march's states are continued with
the Gauss rule each needs (basestate/layered.solve_continued: 48 nodes at P = 1.4, 256 from
2.5) up to P = 2.6108 (1 - (I1 - 3)/jm = 1.9e-4), each confirmed by an adaptive quadrature
to ~1e-11 (fix28a); with the neighbour's rule alone they stopped resolving past P ~ 1.467,
and the cold walk fails from P = 1.4. Before that, the march bisected the edge of the
states that solve to 1e-13 from cold, 37 looks of 5-12 s each, and raised a ConvergenceError
"whether the state is lost there is not established" after 383-439 s. The check's own solver
kept (0, 1) stable up to P ~ 1.479, where it stopped resolving too.

P8: growth of a soft outer layer (mu 0.1) around a Gent core (jm 0.8007), stretch 1. The
growth has no threshold of its own: the states past growth[2] ~ 2.973 do not resolve, and
whether the state is lost there is not established (a ConvergenceError, as before), but the
edge is now bisected LOCK_LOOKS times, not 40, and the error names the layer and its margin.
"""

import numpy as np
import pytest

from electrogrowth import Layer, Tube, critical_value, gent, threshold
from electrogrowth.basestate import layered, plies
from electrogrowth.bifurcation import state_loss
from electrogrowth.errors import ConvergenceError, NoBifurcationBeforeLock, NoBifurcationFound

P6 = Tube(
    (
        Layer(1.1, shear_modulus=2.0, growth=1.05),
        Layer(1.25, material=gent(1.979)),
        Layer(1.4, shear_modulus=0.5),
    ),
    length=4.0,
    axial_force=0.0,
    closed_ends=True,
)
P8 = Tube(
    (Layer(1.3, material=gent(0.8007)), Layer(1.8, shear_modulus=0.1)), length=3.0, stretch=1.0
)


class Counts:
    """The base states a call solves (failed ones apart) and the edge's looks at them."""

    def __init__(self, monkeypatch):
        self.states, self.failed, self.looks = 0, 0, 0
        solve, fate = layered.solve_layered_state, state_loss._fate

        def counted_solve(*args, **kwargs):
            self.states += 1
            try:
                return solve(*args, **kwargs)
            except Exception:
                self.failed += 1
                raise

        def counted_fate(*args, **kwargs):
            self.looks += 1
            return fate(*args, **kwargs)

        monkeypatch.setattr(layered, "solve_layered_state", counted_solve)
        monkeypatch.setattr(state_loss, "_fate", counted_fate)


@pytest.mark.slow  # ~30 s: two marches of ~100 states to the lock
def test_an_inflation_to_a_lock_ends_without_looking_past_its_last_state(monkeypatch):
    lock = threshold(P6, "pressure")
    assert lock.kind == "locking" and np.isinf(lock.value)
    counts = Counts(monkeypatch)
    with pytest.raises(NoBifurcationBeforeLock) as err:
        critical_value(P6, 0, 1, "pressure")
    said = str(err.value)
    assert isinstance(err.value, NoBifurcationFound)  # the "no bifurcation" answer
    # up to 1.4667 while the continuation kept the neighbour's Gauss rule
    assert said.startswith("no mode bifurcates for pressure from 0 up to 2.61")
    assert "the Gent layer 2 is next to its lock" in said
    assert "grows without bound towards the lock at lambda_i = 1.90522" in said
    # before: 37 looks at the edge, each a failed cold solve (and the short-wave march's
    # retries); now none, and one failed state in each march
    assert counts.looks == 0
    assert 1 <= counts.failed <= 4  # the state past the last one failed, and was counted
    assert counts.states < 400


def test_growth_towards_a_lock_looks_at_few_states_past_the_last(monkeypatch):
    counts = Counts(monkeypatch)
    with pytest.raises(ConvergenceError, match="not established") as err:
        critical_value(P8, 8, 2, "growth[2]")
    said = str(err.value)
    assert said.startswith("no mode bifurcates for growth[2] from 1 up to 2.97")
    assert "the Gent layer 1 is next to its lock, 1 - (I1 - 3)/jm = " in said
    # before: the edge bisected to 1e-13, ~40 looks
    assert 1 <= counts.looks <= state_loss.LOCK_LOOKS + 1


def test_a_profile_not_finite_fails_at_once():
    # a root past a lock has a NaN integrand: before, every degree to 4096 was tried
    degrees = []

    def nan(x):
        degrees.append(x.size)
        return np.full(x.shape + (1,), np.nan)

    with pytest.raises(ConvergenceError, match="not finite"):
        plies.chebyshev(nan, 1.0, 1.1, 1e-14, "base-state profile")
    assert degrees == [17, 33]


def test_a_curve_point_records_the_lock_as_no_bifurcation():
    # a design sequence reads "NoBifurcationFound" as no mode before the control's end, not
    # as the edge of the valid range (design/sequence.py)
    from electrogrowth.bifurcation.curve_record import _failed_point

    point = _failed_point(1.0, NoBifurcationBeforeLock("no mode bifurcates ... lock"))
    assert point.failure == "NoBifurcationFound"
