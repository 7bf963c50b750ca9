"""A valid window between two kinds of failure (probe 14d, D1).

A hoop-growing tube under an inner pressure P_i is already unstable in (2, 0) at g = 1 for
P_i below about -0.0689 (its collapse pressure at g = 1), and wrinkles in no mode before
the control's cap g = 6 above about -0.0003: in between the (2, 0) critical growth runs
from 1 to 6, and (2, 0) comes first with a margin near 0.4. The design's sequence took the
two failures for one: the end of its valid range was bisected on "the scan succeeds", its
first midpoint P_i = 0 failed the other way, and the whole stretch -0.3 .. 0.0676 was one
"failed" interval, the design "not_reached" with the remedy "widen --m-max / --n-max".
Now each failure is bisected on its own kind, and the window is found with both ends.
"""

from __future__ import annotations

import math

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, mode_sequence, prescribe
from electrogrowth.bifurcation.curve_record import CurvePoint, _failed_point
from electrogrowth.bifurcation.curve_switches import _Locator
from electrogrowth.bifurcation.curves import _curve, _located
from electrogrowth.cli.design import _change_line
from electrogrowth.continuation.events import SWITCH
from electrogrowth.design.margins import Margins
from electrogrowth.design.prescribe import unreached_note
from electrogrowth.design.sequence import from_curve
from electrogrowth.design.targets import check_target
from electrogrowth.errors import BaseStateError, NoBifurcationFound, UnstableAtStart
from electrogrowth.outcomes import NO_MODE, Kind

UNSTABLE = "the tube is already unstable in mode (2, 0) (prismatic) at growth = 1"
NOTHING = "no mode bifurcates for growth between 1 and 6"
W1, W2 = 0.3, 0.6  # the synthetic window


class _Params:
    def at(self, key, x):
        return self


def _window_unit(x: float) -> CurvePoint:
    """Already unstable below W1, no bifurcation above W2, (2, 0) from g = 1 to 6 between."""
    if x < W1:
        return _failed_point(x, UnstableAtStart(f"{UNSTABLE}; start from a stable state"))
    if x > W2:
        return _failed_point(x, NoBifurcationFound(NOTHING))
    return CurvePoint(x, 1.0 + 5.0 * (x - W1) / (W2 - W1), (2, 0), Kind.BIFURCATION)


def _sequence(unit, xs):
    calls = []

    def counted(x):
        calls.append(x)
        return unit(x)

    loc = _Locator(_Params(), "growth", "pressure", None, counted, solve=None, limit=None)
    rows, switches = _located([unit(x) for x in xs], loc, None, edges=True)
    curve = _curve("pressure", "growth", None, _Params(), rows, switches)
    return from_curve(curve, "pressure", xs[0], xs[-1]), calls


def test_the_window_between_two_failures_is_found_with_both_ends():
    seq, calls = _sequence(_window_unit, [0.0, 1.0])
    labels = [(iv.kind, iv.mode, iv.failure) for iv in seq.intervals]
    assert labels == [
        ("failed", NO_MODE, "UnstableAtStart"),
        ("bifurcation", (2, 0), ""),
        ("failed", NO_MODE, "NoBifurcationFound"),
    ]  # was one failed interval [0, 1]
    (start, stop) = seq.switches
    assert (start.mode_before, start.mode_after, start.kind) == (NO_MODE, (2, 0), "end")
    assert (stop.mode_before, stop.mode_after, stop.kind) == ((2, 0), NO_MODE, "end")
    assert abs(start.x - W1) <= SWITCH.at(W1) and abs(stop.x - W2) <= SWITCH.at(W2)
    assert abs(start.value_after - 1.0) < 1e-11 and abs(stop.value - 6.0) < 1e-11
    window = seq.intervals[1]
    assert window.lo == start.x and window.hi == stop.x
    assert len(calls) < 90  # the window found at the first midpoint, two bisections of 42


def test_two_failures_that_meet_stay_two_intervals_without_an_end():
    def unit(x):
        if x < 0.5:
            return _failed_point(x, UnstableAtStart(UNSTABLE))
        return _failed_point(x, NoBifurcationFound(NOTHING))

    seq, _ = _sequence(unit, [0.0, 1.0])
    assert [(iv.failure, iv.reason) for iv in seq.intervals] == [
        ("UnstableAtStart", UNSTABLE),
        ("NoBifurcationFound", NOTHING),
    ]
    assert seq.switches == ()
    assert abs(seq.intervals[0].hi - 0.5) <= SWITCH.at(0.5)


def test_failures_that_bound_no_window_are_kept_apart_at_no_cost():
    """Unstable at the start next to no state at all (past a voltage's threshold): no
    window is implied, none is searched (a bisection towards the threshold, where each scan
    takes seconds, cost a design 200 s), and the two stay two intervals."""

    def unit(x):
        if x < 0.5:
            return _failed_point(x, UnstableAtStart(UNSTABLE))
        return _failed_point(x, BaseStateError("no state"))

    seq, calls = _sequence(unit, [0.0, 0.25, 1.0])
    assert calls == [] and seq.switches == ()
    assert [(iv.lo, iv.hi, iv.failure) for iv in seq.intervals] == [
        (0.0, 0.25, "UnstableAtStart"),
        (1.0, 1.0, "BaseStateError"),
    ]


def test_a_window_met_by_an_end_s_bisection_is_searched():
    """The probe's grid: unstable at the start at -0.1 (here 0), valid at 0.1 (here 1)
    with no mode before the control's end in between: the end's bisection from the valid
    point met the second failure first, and the window behind it was missed."""

    def unit(x):  # the window [W1, 0.45], as the probe's, out of the bisection's way
        if x >= 0.8:
            return CurvePoint(x, 2.0, (0, 1), Kind.BIFURCATION)
        return _window_unit(x) if x <= 0.45 else _failed_point(x, NoBifurcationFound(NOTHING))

    seq, _ = _sequence(unit, [0.0, 1.0])
    assert [iv.mode for iv in seq.intervals] == [NO_MODE, (2, 0), NO_MODE, (0, 1)]
    ends = [(s.x, s.mode_before, s.mode_after) for s in seq.switches]
    assert [e[1:] for e in ends] == [(NO_MODE, (2, 0)), ((2, 0), NO_MODE), (NO_MODE, (0, 1))]
    for (x, *_), where in zip(ends, (W1, 0.45, 0.8)):
        assert abs(x - where) <= SWITCH.at(where)


def test_one_failure_next_to_a_valid_point_costs_what_it_did():
    """No second kind of failure: the bisection on "fails as the failed point does" is the
    bisection on "the scan succeeds" it replaces, scan for scan."""
    seq, calls = _sequence(_window_unit, [0.0, 0.5])
    assert [iv.mode for iv in seq.intervals] == [NO_MODE, (2, 0)]
    good, bad, expected = 0.5, 0.0, 0
    while abs(bad - good) > SWITCH.at(good):
        mid = 0.5 * (good + bad)
        good, bad = (mid, bad) if mid >= W1 else (good, mid)
        expected += 1
    assert len(calls) == expected and seq.switches[0].x == good


def test_the_end_lines_name_both_sides_and_the_failure():
    """The text said "(-1, -1) -> (-1, -1), growth_cr = 6" at the end of a range where no
    mode bifurcates before the cap 6: neither side nor what 6 is."""
    seq, _ = _sequence(_window_unit, [0.0, 1.0])
    start, stop = (_change_line(seq, s) for s in seq.switches)
    assert "failed -> mode (2, 0), growth_cr = 1; before it: " + UNSTABLE in start
    assert "start from" not in start and "(-1, -1)" not in start
    assert stop.endswith(f"mode (2, 0) -> failed, growth_cr = 6; after it: {NOTHING}")


def test_not_reached_advises_a_finer_grid_not_a_wider_window_for_listed_modes():
    listed = unreached_note(check_target((2, 0)), failed=True)
    assert "--m-max" not in listed and "--points" in listed and "failed intervals" in listed
    assert "points=" in listed.python and "ScanOptions" not in listed.python
    named = unreached_note(check_target("prismatic"), failed=False)
    assert "--m-max / --n-max" in named and "ScanOptions(m_range" in named.python


#: the probe's tube: one layer to 1.5, L = 2, growing in the hoop direction, under P_i
TUBE = Tube((Layer(1.5, growth=(1.0, 1.2, 1.0)),), length=2.0, stretch=1.0, inner_pressure=0.2)
CONTROL = "growth[1].theta"
#: the first modes there (extend=False: the window holds them, probe14d/case5c.py)
OPTIONS = ScanOptions((0, 3), (1, 1), extend=False)


def _collapse_pressure(g: float) -> float:
    """The (2, 0) critical inner pressure of the tube grown to g (another control)."""
    return critical_value(TUBE.at(CONTROL, g), 2, 0, "pressure", side="compression").value


def test_next_to_the_cap_the_margin_is_the_room_up_to_it_not_infinite():
    """At P_i = -0.0005 (2, 0) wrinkles at g = 4.99 and (3, 0) not before the cap 6: M was
    inf there, and a design over [-0.005, 0] sat 6e-10 from the window's end with M = inf.
    Nothing is known past the cap: M is the room up to it, (6 - v_T) / v_T, by a direct
    single-mode solve."""
    x = -0.0005
    at = TUBE.at("pressure", x)
    v_t = critical_value(at, 2, 0, CONTROL).value
    with pytest.raises(NoBifurcationFound):
        critical_value(at, 3, 0, CONTROL)
    margins = Margins(TUBE, CONTROL, "pressure", None, width=0.1)
    m, nxt = margins.best_margin((2, 0), ((3, 0),), x)
    assert nxt == (3, 0) and math.isclose(m, (6.0 - v_t) / v_t, rel_tol=1e-12)


@pytest.mark.slow
def test_the_pressurised_tube_s_window_and_design():
    """The grid's two points fail, the other way each (P_i = -0.1 already unstable, 0 no
    mode before g = 6): the (2, 0) window between them, its ends the (2, 0) collapse
    pressures of the tube grown to 1 and to 6 (single-mode solves along another control),
    and its design. Measured 1.5e-11 and 8.5e-11 apart: at the cap the scans' march finds a
    root within its loose sign's resolution (~1e-7 of g, grid_scan.finished), and g rises
    by ~2800 per unit P_i there."""
    seq = mode_sequence(TUBE, CONTROL, ("pressure", -0.1, 0.0), options=OPTIONS, points=2)
    (window,) = [iv for iv in seq.intervals if iv.kind == "bifurcation"]
    assert window.mode == (2, 0)
    assert abs(window.lo - _collapse_pressure(1.0)) < 1e-9
    assert abs(window.hi - _collapse_pressure(6.0)) < 1e-9
    d = prescribe(TUBE, CONTROL, (2, 0), ("pressure", -0.1, 0.0), options=OPTIONS, sequence=seq)
    assert d.status == "found" and d.mode == (2, 0) and window.lo < d.x < window.hi
    at = TUBE.at("pressure", d.x)
    v_t, v_n = (critical_value(at, *mode, CONTROL).value for mode in ((2, 0), (3, 0)))
    assert math.isclose(d.value, v_t, rel_tol=1e-9) and d.next_mode == (3, 0)
    # widest margin: (3, 0)'s gap, balanced against the room below (v_T - 1) / (v_N - v_T)
    assert math.isclose(d.margin, min((v_n - v_t) / v_t, (v_t - 1) / (v_n - v_t)), rel_tol=1e-6)
    assert 0.39 < d.margin < 0.41
