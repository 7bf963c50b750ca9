"""The boundary tracer's triple points (src/electrogrowth/design/map_trace.py) on patterns
whose critical values are known in closed form: a step long enough to pass two triple
points at once, and a pattern only a full scan knows, must not hide the first one."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from electrogrowth.continuation.contour import CONTOUR_STEPS, LOST
from electrogrowth.design.map_trace import JUMP, TRIPLE, Values, follow

LONG = dataclasses.replace(CONTOUR_STEPS, largest=0.5)  # the gallery's longest step


def _linear(a, b, c):
    return lambda u: a + b * (u[0] - 0.5) + c * u[1]


#: v_P = v_Q on the line u_0 = 1/2, at 2 - 0.1 u_1; C and D come first beyond u_1 = 0.4
#: and 0.45 along it (v_C - v = 0.1 (0.4 - u_1) there), each off the line at another
#: slope: the steps 0.02, 0.04, ... reach u_1 = 0.3, then 0.62, past both
PATTERNS = {
    "P": _linear(2.0, 1.0, -0.1),
    "Q": _linear(2.0, -1.0, -0.1),
    "C": _linear(2.0 + 0.1 * 0.4, 0.3, -0.2),
    "D": _linear(2.0 + 0.1 * 0.45, -0.4, -0.2),
}


class Linear(Values):
    """The patterns' critical values as the closed forms above (lower comes first)."""

    def __init__(self, patterns):
        super().__init__(None, "g", ("x", "y"), ((0.0, 1.0), (0.0, 1.0)), None, 1e-12)
        self.patterns = patterns

    def _solve(self, label, u, hinted):
        return self.patterns[label](u)


@pytest.mark.parametrize("order", [("C", "D"), ("D", "C")])
def test_a_long_step_past_two_triple_points_stops_at_the_first(order):
    values = Linear(PATTERNS)
    pts, end, (labels, u, v) = follow(
        values, "P", "Q", np.array([0.5, 0.0]), np.array([0.0, 1.0]), lambda u: order, LONG
    )
    assert end == TRIPLE and labels == ("P", "Q", "C")
    assert abs(u[0] - 0.5) < 1e-12 and abs(u[1] - 0.4) < 1e-12 and abs(v - 1.96) < 1e-12
    assert all(p[1] <= 0.4 + 1e-12 for p in pts)  # no point beyond it


def _scan_finding_d(values, seen, u, v):
    """A full scan that knows one more pattern, D: it names D where D comes first."""
    if values.value("D", u) >= v - 1e-9:
        return None
    if "D" not in seen:
        seen.append("D")
    return "D"


def test_a_pattern_only_a_scan_finds_is_met_first():
    """D is not among the compared patterns; the scan at the triple point of C names it
    (as the tracer's full scan does), and the curve is taken again to D's triple point."""

    patterns = dict(PATTERNS, D=_linear(2.0 + 0.1 * 0.38, -0.4, -0.2))  # D first at 0.38
    values = Linear(patterns)
    seen = ["C"]
    pts, end, (labels, u, v) = follow(
        values, "P", "Q", np.array([0.5, 0.0]), np.array([0.0, 1.0]), lambda u: seen, LONG,
        check=lambda u, v: _scan_finding_d(values, seen, u, v),
    )  # fmt: skip
    assert end == TRIPLE and labels == ("P", "Q", "D")
    assert abs(u[1] - 0.38) < 1e-12 and all(p[1] <= 0.38 + 1e-12 for p in pts)


def test_a_pattern_only_a_scan_finds_at_the_box_edge_is_met_first():
    """probe14f D1: the P|Q curve leaves the box (u_1 = 1) where D, not compared, comes
    first (from u_1 = 0.8 on, v_D - v = 0.1 (0.8 - u_1) on the curve). The scan where it
    leaves names D, and the curve is taken again to the triple point of P, Q and D, found
    where the closed forms cross: (0.5, 0.8), value 2 - 0.08."""

    patterns = dict(PATTERNS, D=_linear(2.0 + 0.1 * 0.8, -0.4, -0.2))
    values = Linear(patterns)
    seen: list = []
    pts, end, (labels, u, v) = follow(
        values, "P", "Q", np.array([0.5, 0.0]), np.array([0.0, 1.0]), lambda u: seen,
        check=lambda u, v: _scan_finding_d(values, seen, u, v),
    )  # fmt: skip
    assert end == TRIPLE and labels == ("P", "Q", "D")
    assert abs(u[0] - 0.5) < 1e-12 and abs(u[1] - 0.8) < 1e-12 and abs(v - 1.92) < 1e-12
    assert all(p[1] <= 0.8 + 1e-12 for p in pts)


def test_a_mode_with_no_root_in_the_range_does_not_come():
    """At the gut map's thick, stiff corner the prismatic (10, 0) has no critical hoop
    growth in [1, 6] (its first root rises steeply and vanishes near R_1 = 1.125): the
    map's value of that pattern is None (it does not come), not an error that stops the
    trace, while a mode that does come is solved as before."""
    from electrogrowth import critical_value
    from electrogrowth.errors import NoBifurcationFound
    from electrogrowth.figures.design_gallery import CONTROL, FULL_BOX, gut_bilayer

    (kx, *bx), (ky, *by) = FULL_BOX
    values = Values(gut_bilayer(), CONTROL, (kx, ky), (tuple(bx), tuple(by)), None, 1e-12)
    corner = gut_bilayer().at(kx, bx[1]).at(ky, by[1])
    with pytest.raises(NoBifurcationFound):
        critical_value(corner, 10, 0, CONTROL)
    assert values.value((10, 0), (1.0, 1.0), hinted=False) is None
    v = values.value((2, 1), (1.0, 1.0), hinted=False)
    assert v == pytest.approx(critical_value(corner, 2, 1, CONTROL).value, abs=1e-10)


class Jumping(Linear):
    """P's first root jumps down by 1 (an earlier root appears) left of the line
    u_0 = 1/2 + tilt (u_1 - 0.663): the P|Q curve runs into that line at (0.5, 0.663). At a
    shallow angle (tilt 1/4) the corrector lands on the jump and d_PQ jumps there instead
    of vanishing (the curve ends "jump"); more across it (tilt 1) the shortened steps find
    the root on their corrector's line too far off, and the curve is lost at the smallest
    step."""

    def __init__(self, patterns, tilt=0.25):
        super().__init__(patterns)
        self.tilt = tilt

    def _solve(self, label, u, hinted):
        v = super()._solve(label, u, hinted)
        return v - 1.0 if label == "P" and u[0] < 0.5 + self.tilt * (u[1] - 0.663) else v


@pytest.mark.parametrize("tilt", [0.25, 1.0])
def test_a_pattern_only_a_scan_finds_at_a_jump_or_where_lost_is_met_first(tilt):
    """D, which no traced point compares, comes first on the P|Q curve only from
    u_1 = 0.647 on, a little before the curve's jump at 0.663 (v_D - v = 0.1 (0.647 - u_1)
    on it). The jump is located to the smallest step and scanned there: the scan names D,
    the curve is taken again to the triple point of P, Q and D, found where the closed
    forms cross: (0.5, 0.647), value 2 - 0.0647. Before, the curve ended "jump" at
    u_1 = 0.62 (its last point before a step of 0.08 past the jump), or "lost" near 0.663,
    D unseen. Where the curve is lost (tilt 1) the scan there names D the same way."""
    patterns = dict(PATTERNS, D=_linear(2.0 + 0.1 * 0.647, -0.4, -0.2))
    values = Jumping(patterns, tilt)
    seen: list = []
    pts, end, triple = follow(
        values, "P", "Q", np.array([0.5, 0.0]), np.array([0.0, 1.0]), lambda u: seen,
        check=lambda u, v: _scan_finding_d(values, seen, u, v),
    )  # fmt: skip
    assert end == TRIPLE and triple is not None and triple[0] == ("P", "Q", "D")
    u, v = triple[1:]
    assert abs(u[0] - 0.5) < 1e-12 and abs(u[1] - 0.647) < 1e-12 and abs(v - 1.9353) < 1e-12
    assert all(p[1] <= 0.647 + 1e-12 for p in pts)


def test_a_jump_is_located_to_the_smallest_step():
    """With nothing else first, the curve still ends "jump", now within two of the smallest
    steps (2e-4 of the side) of where it meets the jump at u_1 = 0.663, not a step of
    0.08 short of it; the scan there finds nothing and the curve is not taken again."""
    values = Jumping({"P": PATTERNS["P"], "Q": PATTERNS["Q"], "D": _linear(3.0, 0.0, 0.0)})
    seen: list = []
    pts, end, triple = follow(
        values, "P", "Q", np.array([0.5, 0.0]), np.array([0.0, 1.0]), lambda u: seen,
        check=lambda u, v: _scan_finding_d(values, seen, u, v),
    )  # fmt: skip
    assert end == JUMP and triple is None and seen == []
    lost = Jumping(values.patterns, 1.0)
    assert follow(lost, "P", "Q", pts[0], np.array([0.0, 1.0]), lambda u: [])[1] == LOST
    assert 0.663 - 4e-4 <= pts[-1][1] <= 0.663 and abs(pts[-1][0] - 0.5) < 1e-12
