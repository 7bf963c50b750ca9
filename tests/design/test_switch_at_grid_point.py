"""A design range that starts exactly at a switch (probe 9b, D1; the natural zoom: the two
switches that bound the target's region taken as the range).

Film [1, 1.01] (mu 100) on [1.01, 2] (mu 1), hoop growth of the film, its thickness varied
over [A, B], A and B the switches (35, 0) -> (34, 0) and (34, 0) -> (33, 0) of the same
design over [0.008, 0.012]. The scan at A picks (35, 0) (right: single-mode solves put it
5e-16 before (34, 0)) but lists (34, 0) 5e-12 *before* it. ``_Locator._crossing`` judged
the sign change by those remembered scan values, saw none ("a third mode in between"),
halved towards A until the depth ran out, and ``_split`` at depth 0 dropped the switch:
(35, 0) on [A, A], then (34, 0) only from A + 2.5e-6, a silent gap of 0.8 % of the range.
Now the ends are judged by single-mode solves, a tie there is the switch, and a switch is
never dropped when the halvings run out.
"""

import math

import pytest
from scipy.optimize import brentq

from electrogrowth import Layer, ScanOptions, Tube, critical_value, mode_sequence
from electrogrowth.cli.design import summary
from electrogrowth.design import prescribe

A = 0.00978754728637357  # the switch (35, 0) -> (34, 0) of the same sequence on [0.008, 0.012]
B = 0.01011219017563628  # the switch (34, 0) -> (33, 0)
KEY, CONTROL = "layers[1].thickness", "growth[1].theta"
OPTIONS = ScanOptions((28, 40), (1, 1), top=5)


def _film():
    return Tube([Layer(1.01, shear_modulus=100.0), Layer(2.0)], length=1.0, stretch=1.0)


@pytest.fixture(scope="module")
def sequence():
    return mode_sequence(_film(), CONTROL, (KEY, A, B), points=3, options=OPTIONS)


def test_sequence_starting_at_a_switch_covers_its_range(sequence):
    ivs = sequence.intervals
    # the intervals tile [A, B]: each starts where the previous ends (a switch)
    for left, right in zip(ivs, ivs[1:]):
        assert abs(right.lo - left.hi) <= 1e-13 * A, (left, right, sequence.switches)
    assert abs(ivs[-1].hi - B) <= 1e-13 * B
    # (34, 0) is first on the whole open range (single-mode solves: the switches are A, B)
    assert any(iv.mode == (34, 0) and iv.lo - A <= 1e-12 * A for iv in ivs), ivs


def _v(mode, x):
    return critical_value(_film().at(KEY, x), *mode, CONTROL).value


def test_target_tied_only_at_the_range_end_is_not_first(sequence):
    """(35, 0) ties with (34, 0) at A and comes after it on the rest of [A, B]: it was
    "found" with the zero-width region [A, A] and to_boundary 0."""
    d = prescribe(_film(), CONTROL, (35, 0), (KEY, A, B), sequence=sequence, options=OPTIONS)
    assert d.status == "not_first", (d.status, d.region)
    assert d.region == ()
    assert d.x == A and d.next_mode == (34, 0)
    assert abs(d.margin) <= 1e-12  # the tie: M -> 0 from below towards A
    assert any("only ties with (34, 0)" in line for line in summary(d)), summary(d)


@pytest.mark.slow  # 20 s: two prescribe runs over a film
def test_widest_margin_at_a_kink_is_the_tie_of_its_two_competitors():
    """The widest margin for (34, 0) sits where (33, 0) and (35, 0) tie; bounded Brent
    maximisation of M left it 4.5e-8 (relative) off, M 2.7e-6 low. The independent check:
    brentq on the difference of two single-mode critical values."""
    film = _film()
    seq = mode_sequence(film, CONTROL, (KEY, 0.008, 0.012), points=9, options=OPTIONS)
    d = prescribe(film, CONTROL, (34, 0), (KEY, 0.008, 0.012), sequence=seq, options=OPTIONS)
    kink = brentq(lambda x: _v((33, 0), x) - _v((35, 0), x), A, B, xtol=1e-16, rtol=1e-15)
    assert abs(kink - 0.009950296465216089) <= 1e-12 * kink
    assert d.status == "found" and d.mode == (34, 0)
    assert abs(d.x - kink) <= 1e-10 * kink, (d.x, kink)
    v, w = _v((34, 0), kink), _v((33, 0), kink)
    assert math.isclose(d.margin, (w - v) / v, rel_tol=1e-9), (d.margin, (w - v) / v)
    assert set(d.tied_with) | {d.next_mode} == {(33, 0), (35, 0)}


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_to_boundary_counts_the_switch_at_the_range_start(sequence):
    """The widest margin for (34, 0) on [A, B] is at the tie of (33, 0) and (35, 0); its
    distance to the switch at A was measured to the false boundary A + 2.5e-6 (0.000160213)
    while the switch was lost, and the switch located at A is a switch, not just the end of
    the range."""
    d = prescribe(_film(), CONTROL, (34, 0), (KEY, A, B), sequence=sequence, options=OPTIONS)
    # the switch at A located again: within its x_error of A (1.7e-15 apart)
    (start,) = [s for s in sequence.switches if s.x == d.region[0].lo]
    assert d.status == "found" and abs(start.x - A) <= start.x_error and not d.region[0].lo_edge
    assert d.to_boundary == d.x - start.x
