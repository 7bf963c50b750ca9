"""A tube exactly at the onset of a mode at its control's start (probe 12b, D3).

A film 1e-3 thick and 1e4 times as stiff as its substrate, grown to its fold of (69, 0) at
P_i = 0 (the growth scan's g_theta,cr): the march's loose sign said stable at the start, but
the fine det(M2) was -4e-15 there (its rounding), and continuation.events.first_roots called
Brent's method without a sign change: ConvergenceError "f(a) and f(b) must have different
signs", with the remedy "loosen --rtol", which then said "already unstable". The root is the
start within that rounding: the neighbours 1e-13 below give -1.9e-13, above "already
unstable"."""

import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.errors import ParameterError

G0 = 1.026926558161777  # the growth scan's g_theta,cr of (69, 0) at P_i = 0


def _film(g_theta: float) -> Tube:
    return Tube([Layer(1.001, shear_modulus=1e4, growth=(1, g_theta, 1)), Layer(3.0)], length=2.0)


def test_the_onset_at_the_start_is_the_start_within_its_estimate():
    c = critical_value(_film(G0), 69, 0, "pressure", side="compression")
    assert abs(c.value) <= c.error_estimate < 1e-13  # was: ConvergenceError (Brent's text)
    assert str(c.status) == "ok"


@pytest.mark.parametrize("dg", [-1e-13, 1e-13])
def test_the_neighbours_either_side_of_the_onset(dg):
    """Below: a pressure of -1.9e-13 within its estimate; above: already unstable."""
    if dg > 0:
        with pytest.raises(ParameterError, match="already unstable"):
            critical_value(_film(G0 + dg), 69, 0, "pressure", side="compression")
        return
    c = critical_value(_film(G0 + dg), 69, 0, "pressure", side="compression")
    assert abs(c.value + 1.93e-13) < 1e-14 + c.error_estimate
