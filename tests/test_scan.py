"""Mode scans: the batched march finds the same first mode as one-by-one solves."""

import pytest

from electrogrowth import ParameterError, TubeParameters
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, mode_grid, scan_modes
from electrogrowth.errors import NoBifurcationFound

P = TubeParameters(1.4, 1.0, stretch=1.0, voltage=0.4)


def _brute(params, solve_for, modes, side=None):
    out = []
    for m, n in modes:
        try:
            c = critical_value(params, int(m), int(n), solve_for, side=side)
        except NoBifurcationFound:
            continue
        if c.kind == "bifurcation":
            out.append((c.value, int(m), int(n)))
    return sorted(out, reverse=(side == "compression"))


@pytest.mark.parametrize("solve_for, side", [("growth", None), ("voltage", None),
                                             ("stretch", "compression")])
def test_scan_equals_brute_force(solve_for, side):
    params = P if solve_for != "voltage" else TubeParameters(1.4, 1.0)
    res = scan_modes(params, solve_for, side=side,
                     options=ScanOptions((0, 3), (1, 3), top=3, extend=False))
    brute = _brute(params, solve_for, mode_grid((0, 3), (1, 3)), side)
    value, m, n = brute[0]
    assert (res.critical.m, res.critical.n) == (m, n)
    assert res.critical.value == pytest.approx(value, rel=1e-12)
    for got, (want, mm, nn) in zip(res.runners_up, brute[1:3]):
        assert (got.m, got.n) == (mm, nn)
        assert got.value == pytest.approx(want, rel=1e-8)


def test_range_is_widened_while_the_optimum_sits_on_its_edge():
    res = scan_modes(P, "growth", options=ScanOptions((0, 0), (1, 1)))
    assert res.m_range == (0, 1) and res.n_range == (1, 2)
    assert (res.critical.m, res.critical.n) == (0, 1)
    assert not res.surface_instability


def test_extension_finds_bifurcation_before_the_threshold():
    """Vbar = 0.4: modes wrinkle just before lambda_z reaches the threshold 2.5117."""
    res = scan_modes(P, "stretch", side="extension", options=ScanOptions((0, 3), (1, 2)))
    assert res.critical.kind == "bifurcation"
    assert 2.49 < res.critical.value < 2.5117
    direct = critical_value(P, res.critical.m, res.critical.n, "stretch", side="extension")
    assert res.critical.value == pytest.approx(direct.value, rel=1e-12)


@pytest.mark.parametrize("kw, needle", [
    (dict(m_range=(-1, 3)), "m range"), (dict(n_range=(0, 3)), "n range"),
    (dict(n_range=(4, 2)), "n range"), (dict(top=0), "top = 0 is invalid")])
def test_bad_ranges(kw, needle):
    with pytest.raises(ParameterError, match=needle):
        scan_modes(P, "growth", options=ScanOptions(**kw))


def test_bad_side():
    with pytest.raises(ParameterError, match="side"):
        scan_modes(P, "growth", side="up")


def test_surface_instability_is_extrapolated_not_scanned_forever():
    """Thick, long, compressed tube under voltage: the critical voltage keeps falling with n."""
    p = TubeParameters(2.5, 3.0, stretch=0.8)
    res = scan_modes(p, "voltage", options=ScanOptions((0, 2), (1, 6)))
    c = res.critical
    assert res.surface_instability and res.n_range[1] == c.n >= 24
    assert res.short_wave_limit < c.value  # the limit lies below every finite-n value
    v2 = critical_value(p, c.m, 2 * c.n, "voltage").value
    assert res.short_wave_limit < v2 < c.value
    assert abs(res.short_wave_limit - v2) < 1.5 * abs(v2 - c.value)  # O(1/n) approach
    assert res.short_wave_error < abs(v2 - c.value)


def test_short_wave_beyond_the_range_is_found_by_probes():
    """Vbar = 0.4, extension: critical stretch rises from m = 0 to 12, then falls with m."""
    res = scan_modes(P, "stretch", side="extension")
    assert res.critical.m > 12 and res.surface_instability
    assert res.short_wave_limit < res.critical.value < 2.4968  # below the (0, 1) value
