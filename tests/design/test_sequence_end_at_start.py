"""The end of a design's valid range where the tube turns unstable at the control's start
is that mode's root, with an error estimate that covers it (check round 20, D2;
bifurcation/start_edge.py).

One neo-Hookean layer (Rbar_o 1.5, L 3), growth as the control, Vbar as the design
variable: beyond Vbar_e the ungrown tube is already unstable in (2, 1), so Vbar_e is the
critical voltage of (2, 1) of the ungrown tube (check round 20's own shooting:
0.7111179673235076, its collocation 0.7111179673265). The bisection on "the scan succeeds"
ended at 0.711117967340162, 1.7e-11 above it, stating its bracket 6.4e-14 as the error:
the scans' start check reads loose signs.
"""

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value
from electrogrowth.design import mode_sequence

TUBE = Tube((Layer(1.5),), length=3.0, stretch=1.0)


@pytest.fixture(scope="module")
def sequence():
    options = ScanOptions((0, 8), (1, 5), torsional=False)
    return mode_sequence(TUBE, "growth[1]", ("voltage", 0.05, 0.9), points=7, options=options)


def test_the_end_is_the_modes_onset_at_the_start_within_its_estimate(sequence):
    (end,) = [s for s in sequence.switches if s.kind == "end"]
    assert end.mode_before == (2, 1) and end.mode_after == (-1, -1)
    onset = critical_value(TUBE, 2, 1, "voltage", rtol=1e-14)
    assert abs(end.x - onset.value) <= end.x_error + onset.error_estimate  # was 1.66e-11
    assert end.x_error < 1e-12
    (before,) = [iv for iv in sequence.intervals if iv.mode == (2, 1)]
    assert before.hi == end.x  # the interval ends where its end was located


def test_the_ends_value_is_the_critical_growth_there(sequence):
    (end,) = [s for s in sequence.switches if s.kind == "end"]
    just_before = end.x - 2 * end.x_error  # on the valid side
    c = critical_value(TUBE.at("voltage", just_before), 2, 1, "growth[1]", rtol=1e-12)
    slope_room = 5.0 * 2 * end.x_error  # |dg/dVbar| ~ 4.2 there
    assert abs(end.value - c.value) <= end.value_error + c.error_estimate + slope_room
    assert c.value > 1.04  # a cliff: the growth onset stays away from the start


def test_a_smooth_end_on_the_failed_side_of_the_bisection():
    """Here the scans' loose start check failed past the root: the grown tube (g = 1.1)
    along Rbar_o turns stable at V = 0 where its (2, 1) critical growth is 1.1, by Brent on
    single-mode growth solves (an independent route: the critical value, not the target
    at the start). The bisection's end was 1.0e-11 off with x_error 6.8e-14."""
    from scipy.optimize import brentq

    tube = Tube.uniform(1.3, 1.0, growth=1.1)
    seq = mode_sequence(
        tube, "voltage", ("outer_radius", 1.15, 1.6), points=7, options=ScanOptions((0, 8), (1, 4))
    )
    end = seq.switches[0]
    assert end.kind == "end" and end.mode_after == (2, 1)

    def growth_onset(ro):
        at = Tube.uniform(ro, 1.0, growth=1.0)
        return critical_value(at, 2, 1, "growth", rtol=1e-14).value - 1.1

    root = brentq(growth_onset, 1.16, 1.17, xtol=1e-15, rtol=1e-15)
    assert abs(end.x - root) <= end.x_error + 1e-14  # was 1.0e-11 against 6.8e-14
    assert seq.intervals[1].mode == (2, 1) and seq.intervals[1].lo == end.x
