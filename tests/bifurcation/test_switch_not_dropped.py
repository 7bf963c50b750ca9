"""A change of the critical mode is never dropped when the locator's halvings run out
(probe 9b, D1): ``_Locator._split`` at depth 0 returned no switch, so the sequence had a
silent gap between the last two scanned points. A synthetic curve whose scans and
single-mode values disagree (the scans switch from A to B at X_SWITCH, the single-mode
values keep A first: no sign change for Brent) drives the locator to that depth."""

import math

import pytest

from electrogrowth.bifurcation.curve_record import CurvePoint
from electrogrowth.bifurcation.curve_switches import _Locator
from electrogrowth.errors import ConvergenceError
from electrogrowth.outcomes import Kind

A, B, C = (5, 0), (6, 0), (7, 0)
X_SWITCH = 0.3


class _Single:
    """Single-mode critical values: A always first (no sign change of d)."""

    value, kind, error_estimate = 0.0, Kind.BIFURCATION, 0.0


def _solve(params, m, n, solve_for, side=None):
    c = _Single()
    c.value = {A: 1.0, B: 2.0, C: 3.0}[(m, n)]
    return c


class _Params:
    def at(self, key, x):
        return self


def _locator(third_at=None):
    def unit(x):
        if third_at is not None and abs(x - third_at) < 0.05:
            return CurvePoint(x, 0.5, C, Kind.BIFURCATION)
        return CurvePoint(x, 1.0, A if x < X_SWITCH else B, Kind.BIFURCATION)

    return _Locator(_Params(), "growth", "length", None, unit, solve=_solve, limit=None)


def test_switch_located_by_scans_when_the_halvings_run_out():
    loc = _locator()
    a, b = CurvePoint(0.0, 1.0, A, Kind.BIFURCATION), CurvePoint(1.0, 1.0, B, Kind.BIFURCATION)
    _, switches = loc.between(a, b, 2)
    assert len(switches) == 1
    s = switches[0]
    assert (s.mode_before, s.mode_after) == (A, B)
    assert math.isclose(s.x, X_SWITCH, abs_tol=1e-7)
    # its error estimate is half the bisection's last bracket, and covers the error
    assert abs(s.x - X_SWITCH) <= s.x_error <= 1e-7


def test_a_third_mode_out_of_halvings_is_an_error_not_a_gap():
    loc = _locator(third_at=X_SWITCH)
    a, b = CurvePoint(0.0, 1.0, A, Kind.BIFURCATION), CurvePoint(0.5, 1.0, B, Kind.BIFURCATION)
    with pytest.raises(ConvergenceError, match="not located"):
        loc.between(a, b, 0)
