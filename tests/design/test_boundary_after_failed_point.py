"""A design region that starts at a grid point next to a failed scan: its distance to the
boundary (found by probing). A grown tube (g = 1.1) is already wrinkled at zero voltage
for the thinnest walls of the range (Rbar_o = 1.15: mode (2, 1) at g = 1.0906), so the
sequence's first point fails and the target's interval starts at the next grid point,
1.225, which is not a located switch (Interval.lo_edge is False only because it is not the
end of the range). The Design docstring and docs/design.md define ``to_boundary`` as the
distance to the nearest end of the region that *is* a located switch; it was measured to
that grid point instead (0.0025), though the true (2, 1) | (1, 1) switch is near 1.2045,
ten times further, and the only located switch is at 1.2843."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from electrogrowth import (
    ScanOptions,
    Tube,
    critical_curve,
    critical_value,
    mode_sequence,
    prescribe,
    scan_modes,
)
from electrogrowth.outcomes import NO_MODE

GROWN = Tube.uniform(1.3, 1.0, growth=1.1)
OPTIONS = ScanOptions((0, 8), (1, 4))


def test_to_boundary_is_measured_to_a_located_switch_not_to_a_grid_point():
    d = prescribe(GROWN, "voltage", (1, 1), ("outer_radius", 1.15, 1.6), points=7, options=OPTIONS)
    assert d.status == "found" and d.mode == (1, 1)
    assert d.sequence.intervals[0].kind == "failed"  # the premise: the first point fails
    switches = [s.x for s in d.sequence.switches]
    assert d.to_boundary is not None
    assert any(abs(abs(d.x - xs) - d.to_boundary) < 1e-9 for xs in switches), (
        f"to_boundary = {d.to_boundary} from x = {d.x}, but the located switches are at"
        f" {switches}: it was measured to the grid point {d.region[0].lo}"
    )


def test_the_widest_margin_is_not_cut_off_at_the_grid_point_after_a_failed_scan():
    """With 13 points the (2, 1) interval is found, from the grid point 1.1875 next to the
    failed first point; but the tube is stable at zero voltage, with (2, 1) first, down to
    Rbar_o ~ 1.163 (where g = 1.1 is its critical growth), and its margin grows as its
    critical voltage falls: at Rbar_o = 1.17, M = (v_(1,1) - v_(2,1)) / v_(2,1) = 0.82,
    seven times the reported widest margin (0.111, at the grid point itself)."""
    d = prescribe(
        GROWN, "voltage", (2, 1), ("outer_radius", 1.15, 1.6), points=13, options=OPTIONS
    )
    assert d.status == "found" and d.mode == (2, 1)
    at = GROWN.at("outer_radius", 1.17)
    first = scan_modes(at, "voltage", options=OPTIONS).critical
    assert (first.m, first.n) == (2, 1)  # the target is first there
    v_t = critical_value(at, 2, 1, "voltage").value
    v_n = min(critical_value(at, *mode, "voltage").value for mode in ((1, 1), (0, 1), (3, 1)))
    margin = (v_n - v_t) / abs(v_t)
    assert d.margin >= margin - 1e-9, (
        f"the widest margin reported is {d.margin} at x = {d.x}; at x = 1.17 it is {margin}"
    )


def _end(sequence):
    """The located end of the valid range: the switch to or from no mode."""
    (end,) = [s for s in sequence.switches if NO_MODE in (s.mode_before, s.mode_after)]
    return end


def test_the_end_of_the_valid_range_is_where_the_start_turns_unstable():
    """Independent route: the end along Rbar_o is where the (2, 1) critical *growth* of the
    ungrown tube at zero voltage equals the tube's growth 1.1 (Brent on single-mode growth
    solves, another control); measured 1e-11 apart, the resolution of the scan's sign check
    at the start. The (2, 1) interval is found with 7 points, though no grid point lands in
    it."""
    seq = mode_sequence(GROWN, "voltage", ("outer_radius", 1.15, 1.6), points=7, options=OPTIONS)
    end = _end(seq)
    assert (end.mode_before, end.mode_after, end.kind) == (NO_MODE, (2, 1), "end")
    g21 = lambda r: critical_value(Tube.uniform(r, 1.0), 2, 1, "growth").value  # noqa: E731
    root = brentq(lambda r: g21(r) - 1.1, 1.15, 1.2, xtol=1e-15, rtol=1e-15)
    assert abs(end.x - root) < 1e-9
    assert end.value_after < 1e-4  # the target's critical voltage falls to the start, 0
    assert [(iv.kind, iv.mode) for iv in seq.intervals[:2]] == [
        ("failed", NO_MODE),
        ("bifurcation", (2, 1)),
    ]
    # the last failed scan lies past the end located as the mode's root: its row is there
    assert seq.intervals[1].lo == end.x and 0 <= end.x - seq.intervals[0].hi < 1e-12
    d = prescribe(
        GROWN, "voltage", (2, 1), ("outer_radius", 1.15, 1.6), options=OPTIONS, sequence=seq
    )
    assert d.status == "found" and d.region[0].lo == end.x
    switch = seq.intervals[1].hi
    assert abs(d.to_boundary - min(d.x - end.x, switch - d.x)) < 1e-12


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_an_end_after_the_valid_range_is_the_critical_growth_at_zero_voltage():
    """Growing past g_cr(V = 0) the tube is wrinkled before any voltage: the end of the
    valid range along g is the critical growth of a scan at zero voltage (the other
    control), to 1e-9 (measured 1e-13); the sliver of (1, 1) between the last grid point
    and the end is found from the end."""
    tube, options = Tube.uniform(1.2, 1.0), ScanOptions((0, 4), (1, 3))
    g_cr = scan_modes(tube, "growth", options=options).critical
    seq = mode_sequence(tube, "voltage", ("growth", 1.0, 1.3), points=4, options=options)
    end = _end(seq)
    assert (end.mode_before, end.mode_after) == ((g_cr.m, g_cr.n), NO_MODE)
    assert abs(end.x - g_cr.value) < 1e-9
    assert seq.intervals[-1].kind == "failed" and seq.intervals[-2].hi == end.x
    assert seq.intervals[-2].mode == (1, 1) and seq.intervals[-3].mode == (2, 1)


def test_the_margin_next_to_the_end_balances_the_room_below_and_above_the_target():
    """As Rbar_o falls to the end, v_(2,1) -> 0 and M = (v_N - v_T) / v_T grows without
    bound; the room below the target, M_0 = (v_T - 0) / (v_N - v_T), counts as a competitor
    (docs/design.md), so the widest margin is where the two balance, v_N = 2 v_T (M = 1),
    not on the end. Checked by direct single-mode solves at the design and at samples of
    the region."""
    d = prescribe(
        GROWN, "voltage", (2, 1), ("outer_radius", 1.15, 1.6), points=13, options=OPTIONS
    )
    assert d.status == "found" and d.limited_by == "no design"

    def by_solves(x):
        at = GROWN.at("outer_radius", x)
        v_t = critical_value(at, 2, 1, "voltage").value
        v_n = min(critical_value(at, *m, "voltage").value for m in ((1, 1), (0, 1), (3, 1)))
        return min((v_n - v_t) / v_t, v_t / (v_n - v_t)), v_n

    margin, v_n = by_solves(d.x)
    assert abs(d.margin - margin) < 1e-9 and abs(d.next_value - v_n) < 1e-9
    assert 0.9999 < d.margin <= 1.0
    end, switch = d.region[0].lo, d.region[0].hi
    for x in np.linspace(end, switch, 12)[1:-1]:
        assert by_solves(x)[0] <= d.margin + 1e-9


def test_a_sequence_without_failed_points_is_unchanged():
    """Locating ends costs nothing where no scan fails: the curve is the one without."""
    tube, vary = Tube.uniform(), ("outer_radius", 1.2, 1.3)
    options = ScanOptions((0, 2), (1, 2))
    seq = mode_sequence(tube, "stretch", vary, side="compression", points=3, options=options)
    plain = critical_curve(
        tube, "stretch", "outer_radius", [1.2, 1.25, 1.3], side="compression", options=options
    )
    assert seq.curve.as_dict() == plain.as_dict()
