"""A tube exactly at the onset of a mode at its control's start (probe 12b, D3).

A film 1e-3 thick and 1e4 times as stiff as its substrate, grown to its fold of (69, 0) at
P_i = 0 (the growth scan's g_theta,cr): the march's loose sign said stable at the start, but
the fine det(M2) was -4e-15 there (its rounding), and continuation.events.first_roots called
Brent's method without a sign change: ConvergenceError "f(a) and f(b) must have different
signs", with the remedy "loosen --rtol", which then said "already unstable". The root is the
start within that rounding: the neighbours 1e-13 below give -1.9e-13, above "already
unstable"."""

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, scan_modes
from electrogrowth.errors import ParameterError, UnstableAtStart

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


#: a tube to grow in the hoop direction under an inner pressure (probe 14d): ungrown, (2, 0)
#: is critical at its collapse pressure P_i = -0.0688763701
PRESSED = Tube([Layer(1.5)], length=2.0, stretch=1.0)


def test_a_scan_past_the_onset_at_the_start_is_already_unstable():
    """Probe 14d, D1: past the (2, 0) collapse pressure of the ungrown tube, a scan of the
    growth (its ranges widened, the default) read the start as stable with its loose sign,
    and its solve in a bracket of 1e-7 about the march's root reached below g = 1: it
    returned g_cr = 0.9999999 (2.1e-8 past; 0.99999999816 at 4e-10 past), before the
    control's start, where the single-mode solve says "already unstable" (a design's end
    of the valid range located there was 2.1e-8 off). A solve's bracket stops at the start
    now."""
    collapse = critical_value(PRESSED, 2, 0, "pressure", side="compression").value
    options = ScanOptions((0, 3), (1, 1))
    for past in (2.1e-8, 4e-10):
        at = PRESSED.at("pressure", collapse - past)
        with pytest.raises(UnstableAtStart, match=r"already unstable in mode \(2, 0\)"):
            critical_value(at, 2, 0, "growth[1].theta")
        with pytest.raises(UnstableAtStart, match=r"already unstable in mode \(2, 0\)"):
            scan_modes(at, "growth[1].theta", options=options)  # was g_cr < 1
    just = scan_modes(PRESSED.at("pressure", collapse + 1e-8), "growth[1].theta", options=options)
    assert (just.critical.m, just.critical.n) == (2, 0) and just.critical.value >= 1.0
