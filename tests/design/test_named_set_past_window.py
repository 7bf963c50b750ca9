"""A named set's closest member is the set's, not the scan window's (probe 13c, a doubt).

A film's rings (0, n) are never first under hoop growth (its folds (m, 0) come first), and
with a narrow ScanOptions (n <= 4) the closest design named the window's edge ring: the
probe's film [1, 1.001] gave (0, 8) at g = 1.618, M = -0.370, while its best ring is
(0, 182) at 1.0387, M = -0.0185. The set's members were only those of the scanned window
(and nothing said the chosen one sat at its edge). Now a set's best member found is
followed past the window by single-mode solves until the values turn away.

Here a film 0.05 thick, 20 times its substrate, L = 4: the window's edge ring (0, 4) at
g = 2.162, M = -0.375, was reported; the best ring is (0, 12) at g ~ 1.61, M ~ -0.162."""

from __future__ import annotations

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value
from electrogrowth.design import prescribe
from electrogrowth.errors import NoBifurcationFound

FILM = Tube((Layer(1.05, shear_modulus=20.0, growth=(1, 1.0, 1)), Layer(2.0)), length=4.0)
HOOP, MU = "growth[1].theta", "layers[1].shear_modulus"


@pytest.mark.slow
def test_the_closest_ring_lies_past_the_scan_window():
    """~40 s: two grid points, a window of n <= 4; the rings checked by direct solves."""
    window = ScanOptions((0, 12), (1, 4))
    d = prescribe(FILM, HOOP, "axisymmetric", (MU, 20.0, 21.0), options=window, points=2)
    assert d.status == "not_first" and d.mode is not None and d.mode[0] == 0
    assert d.mode[1] > 4, f"{d.mode}: the edge of the window n <= 4, not the closest ring"
    at = FILM.at(MU, d.x)
    rings = {n: v for n in range(1, 49) if (v := _ring(at, n)) is not None}
    closest = min(rings, key=rings.__getitem__)
    assert d.mode == (0, closest)
    assert d.value == pytest.approx(rings[closest], rel=1e-10)
    assert d.margin == pytest.approx((d.next_value - d.value) / d.value, rel=1e-12)
    assert -0.2 < d.margin < 0  # was -0.375 at the window's edge ring (0, 4)
    assert d.note == ""  # far from the mode cap


@pytest.mark.slow
def test_the_maps_closest_ring_lies_past_the_scan_window():
    """~40 s: the map over mu and L (2 x 2 nodes) with the same window. Its closest design
    ranked only a scan's first 6 modes, none of them a ring (the film's folds come first):
    "axisymmetric" was not_reached. It now takes a set's member as along one variable
    (prescribe.best_member: further down the scan, then followed past the window)."""
    from electrogrowth.design.mode_map import mode_map
    from electrogrowth.design.prescribe_map import prescribe_map

    window = ScanOptions((0, 12), (1, 4))
    vary = ((MU, 20.0, 21.0), ("length", 4.0, 4.2))
    mmap = mode_map(FILM, HOOP, vary, options=window, points=2, certify=0)
    d = prescribe_map(FILM, "axisymmetric", mmap, options=window)
    assert d.status == "not_first", f"{d.status}: the film's rings are never first"
    assert d.mode is not None and d.mode[0] == 0 and d.mode[1] > 4
    at = FILM.at(MU, d.x).at("length", d.y)
    rings = {n: v for n in range(1, 49) if (v := _ring(at, n)) is not None}
    closest = min(rings, key=rings.__getitem__)
    assert d.mode == (0, closest)
    assert d.value == pytest.approx(rings[closest], rel=1e-10)
    assert d.margin == pytest.approx((d.next_value - d.value) / d.value, rel=1e-12)
    assert -0.2 < d.margin < 0  # (0, 12) at M = -0.162 in the corner mu = 20, L = 4
    assert d.note == ""  # far from the mode cap


def _ring(tube, n):
    """The critical hoop growth of (0, n), or None where it never bifurcates."""
    try:
        c = critical_value(tube, 0, n, HOOP)
    except NoBifurcationFound:
        return None
    return c.value if c.kind == "bifurcation" else None


class _Parabola:
    """Margins' single-mode values for a ring family with one minimum at n = ``low``."""

    sense = 1.0

    def __init__(self, low):
        self.low, self.solved = low, 0

    def value(self, mode, x):
        self.solved += 1
        return 1.0 + ((mode[1] - self.low) / 1000.0) ** 2

    def caps(self, x):  # those of a tube with no thin layer (options.mode_caps)
        return (2000, 2000)


@pytest.mark.parametrize("low", [5, 37, 182, 1999])
def test_a_sets_member_is_followed_to_its_minimum(low):
    from electrogrowth.design.prescribe import _past_window, cap_note
    from electrogrowth.design.targets import check_target

    margins = _Parabola(low)
    v = margins.value((0, 4), 0.0)
    goal = check_target("axisymmetric")
    mode, v = _past_window((0, 4), v, 0.0, goal, margins)
    assert mode == (0, low)
    assert cap_note(mode, goal, margins.caps(0.0)) == ""
    assert margins.solved < 60  # geometric steps and a refined bracket, not every n


def test_a_member_at_the_mode_cap_is_said_to_be():
    from electrogrowth.design.prescribe import _past_window, cap_note
    from electrogrowth.design.targets import check_target

    margins = _Parabola(5000)  # the minimum lies beyond the cap
    v = margins.value((0, 4), 0.0)
    goal = check_target("axisymmetric")
    mode, _ = _past_window((0, 4), v, 0.0, goal, margins)
    assert mode == (0, 2000)
    assert "at the mode cap 2000" in cap_note(mode, goal, margins.caps(0.0))
    assert cap_note(mode, check_target([(0, 2000)]), margins.caps(0.0)) == ""  # a listed mode


def test_a_thin_layers_caps_take_the_members_past_2000():
    """The members go on as far as the scans of the design's tube do (its caps, chosen by
    its thinnest layer, options.mode_caps): a lining 1e-3 thick on a tube L = 3 reaches
    n = 61115, and its minimum (0, 5000) is found, not the cap 2000 of every tube before."""
    from electrogrowth.design.prescribe import _past_window, cap_note
    from electrogrowth.design.targets import check_target

    margins = _Parabola(5000)
    margins.caps = lambda x: (64064, 61115)
    v = margins.value((0, 4), 0.0)
    goal = check_target("axisymmetric")
    mode, _ = _past_window((0, 4), v, 0.0, goal, margins)
    assert mode == (0, 5000) and cap_note(mode, goal, margins.caps(0.0)) == ""


def test_members_that_turn_away_at_once_stay():
    from electrogrowth.design.prescribe import _past_window
    from electrogrowth.design.targets import check_target

    margins = _Parabola(2)  # (0, 4) is past the minimum: (0, 5) is later
    v = margins.value((0, 4), 0.0)
    assert _past_window((0, 4), v, 0.0, check_target("axisymmetric"), margins)[:2] == ((0, 4), v)
