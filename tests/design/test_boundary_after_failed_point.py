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

from electrogrowth import ScanOptions, Tube, critical_value, prescribe, scan_modes

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
