"""The exact short-wave limit as a competitor in the margin (design/short_waves.py).

A thick tube, Rbar_o = 2.1, charged (voltage control), target (0, 1) along its length: for
L below 1.6618 the inner face's surface limit (Vbar_S = 0.78748, independent of L) comes
first, above it (0, 1), until (1, 1) takes over at L = 1.9541. The gap to (1, 1) falls
with L, the gap to the limit rises from 0 at the switch. The margin left the limit out:
with modes up to (2, 2) the design sat on the switch to the surface interval (L =
1.66184252, 5e-8 from it) with M = 0.00525, the gap to (1, 1), while the limit came
7e-10 (relative) after the target there. Counted, M vanishes at that switch and the design
is the tie of (1, 1) with the limit, L = 1.87047, M = 0.00183973."""

import json

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.cli.app import main
from electrogrowth.cli.design import summary
from electrogrowth.design.prescribe import FOUND, prescribe
from electrogrowth.digits import supported

R = 2.1
NEAR = ScanOptions((0, 2), (1, 2), extend=False)


def _design(lo, hi, points, options=NEAR):
    tube = Tube.uniform(R, length=lo)
    return prescribe(tube, "voltage", (0, 1), ("length", lo, hi), options=options, points=points)


def _values(tube):
    """(v_T of (0, 1), v_S) at a tube, by full solves."""
    v = critical_value(tube, 0, 1, "voltage").value
    return v, short_wave_limit(tube, "voltage").value


@pytest.fixture(scope="module")
def tied():
    return _design(1.5, 2.0, 5)


@pytest.fixture(scope="module")
def by_surface():
    return _design(1.5, 1.8, 4)


def test_the_design_is_off_the_switch_to_the_surface_limit(tied):
    d = tied
    (switch,) = [iv.lo for iv in d.sequence.intervals if iv.mode == (0, 1)]
    assert d.status == FOUND and d.mode == (0, 1)
    assert d.x - switch > 0.1  # it sat on the switch: 4.9e-8 from it
    tube = Tube.uniform(R, length=d.x)
    v, v_s = _values(tube)
    assert d.value == pytest.approx(v, rel=1e-11)
    assert d.surface_value == pytest.approx(v_s, rel=1e-11)
    v_11 = critical_value(tube, 1, 1, "voltage").value
    direct = min(v_s - v, v_11 - v) / v
    assert d.margin == pytest.approx(direct, rel=1e-8)  # 0.00525 before, the gap to (1, 1)
    # the widest margin is the tie of (1, 1) with the limit: a kink of M
    assert v_11 == pytest.approx(v_s, rel=1e-10)
    rivals = {d.limited_by, *d.tied_with}
    assert rivals == {"mode", "surface"} or rivals == {"surface", (1, 1)}


def test_the_limit_sets_the_margin_with_its_sensitivity(by_surface):
    d = by_surface
    assert d.x == 1.8 and d.limited_by == "surface" and not d.tied_with
    tube = Tube.uniform(R, length=d.x)
    v, v_s = _values(tube)
    assert d.margin == pytest.approx((v_s - v) / v, rel=1e-8)  # the gap to (1, 1) before
    assert d.surface_margin == d.margin
    for key in ("outer_radius", "length", "growth", "stretch"):
        p = tube.value_of(key)
        h = 1e-4 * p
        (v_lo, s_lo), (v_hi, s_hi) = (_values(tube.at(key, q)) for q in (p - h, p + h))
        ds = (s_hi - s_lo) / (2 * h)
        dm = ((s_hi - v_hi) / v_hi - (s_lo - v_lo) / v_lo) / (2 * h)
        # implicit differentiation of the half-space condition against full solves
        assert d.surface_sensitivity[key] == pytest.approx(ds, rel=1e-6, abs=1e-9)
        assert d.margin_sensitivity[key] == pytest.approx(dm, rel=1e-5, abs=1e-8)
    text = "\n".join(summary(d))
    assert "margin 0.001522 to the short-wave limit (0.7874776504)" in text


def test_cli_json_says_the_limit_sets_the_margin(capsys):
    args = ["design", "--solve-for", "voltage", "--target", "0", "1", "--vary", "length"]
    args += ["1.5", "1.8", "--points", "4", "--outer-radius", str(R), "--length", "1.5"]
    args += ["--m-max", "2", "--n-max", "2", "--json", "--quiet"]
    assert main(args) == 0
    best = json.loads(capsys.readouterr().out)["best"]
    assert best["limited_by"] == "surface" and best["design"] == 1.8
    v, v_s = _values(Tube.uniform(R, length=1.8))
    assert best["surface_value"] == pytest.approx(v_s, rel=1e-11)
    assert best["margin"] == pytest.approx((v_s - v) / v, rel=1e-8)


def test_no_surface_in_the_scans_none_in_the_margin():
    """ScanOptions(surface=False) leaves the limit out of every scan, and so of M."""
    d = _design(1.75, 1.8, 2, ScanOptions((0, 2), (1, 2), extend=False, surface=False))
    assert d.limited_by == "mode" and d.next_mode == (1, 1)
    assert d.surface_value != d.surface_value  # NaN: not located


def test_a_map_pattern_that_is_no_mode_is_not_in_a_target():
    """A map's "surface" (or "threshold", "failed") label was unpacked into the target's
    accepts(m, n): TypeError, so no map with a surface region could be designed on."""
    from electrogrowth.design.targets import check_target

    for target in ((0, 1), "axisymmetric", [(0, 1), (1, 1)], lambda m, n: True):
        goal = check_target(target)
        assert "surface" not in goal and "threshold" not in goal and None not in goal
    assert (0, 1) in check_target("axisymmetric") and [0, 1] in check_target((0, 1))


@pytest.mark.slow  # 40 s: a map of two variables and its design
def test_map_design_counts_the_surface_limit():
    """The same tube over L and Rbar_o: the map's design is the tie of (1, 1) with the
    limit (it raised TypeError on the map's "surface" region before; its margin left the
    limit out, as along one variable)."""
    from electrogrowth.design.mode_map import mode_map
    from electrogrowth.design.prescribe_map import prescribe_map

    tube = Tube.uniform(R, length=1.6)
    vary = (("length", 1.6, 1.95), ("outer_radius", 2.08, 2.12))
    mm = mode_map(tube, "voltage", vary, points=2, options=NEAR, certify=2)
    assert any("surface" in (b.left, b.right) for b in mm.boundaries)
    d = prescribe_map(tube, (0, 1), mm, options=NEAR)
    at = tube.at("length", d.x).at("outer_radius", d.y)
    v, v_s = _values(at)
    v_11 = critical_value(at, 1, 1, "voltage").value
    assert d.status == FOUND and d.value == pytest.approx(v, rel=1e-11)
    assert d.margin == pytest.approx(min(v_s - v, v_11 - v) / v, rel=1e-8)
    assert v_11 == pytest.approx(v_s, rel=1e-9)  # the tie: a kink of M
    assert "surface" in {d.limited_by, *d.tied_with}
    best = d.as_dict()["best"]
    assert best["surface_value"] == pytest.approx(v_s, rel=1e-11)


def test_the_intervals_end_at_a_switch_with_its_digits(by_surface):
    """An interval's located end prints the digits its switch's estimate supports, as the
    switch's own line (they printed 10 digits); the searched range's ends as given."""
    seq = by_surface.sequence
    assert seq.switches
    lines = summary(by_surface)
    for s in seq.switches:
        shown = supported(s.x, s.x_error)
        assert any(f" .. {shown}: " in line for line in lines), (shown, lines)
        assert any(f"  {seq.key} {shown} .. " in line for line in lines), (shown, lines)
    assert any(line.startswith(f"  {seq.key} 1.5 .. ") for line in lines)
