"""Mode scans: the batched march finds the same first mode as one-by-one solves."""

import functools
import math

import numpy as np
import pytest

from electrogrowth import ParameterError, Tube
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.march import unloaded_signs
from electrogrowth.bifurcation.options import M_CAP
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.bifurcation.scan_grid import mode_grid, scan_grid, stable_signs
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.errors import NoBifurcationFound
from electrogrowth.incremental.targets import impedance_targets
from electrogrowth.model.layers import Layer
from electrogrowth.model.materials import gent, mooney_rivlin

P = Tube.uniform(1.4, 1.0, stretch=1.0, voltage=0.4)


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


@pytest.mark.parametrize(
    "solve_for, side", [("growth", None), ("voltage", None), ("stretch", "compression")]
)
def test_scan_equals_brute_force(solve_for, side):
    params = P if solve_for != "voltage" else Tube.uniform(1.4, 1.0)
    res = scan_modes(
        params, solve_for, side=side, options=ScanOptions((0, 3), (1, 3), top=3, extend=False)
    )
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
    """Vbar = 0.4: finite modes wrinkle just before lambda_z reaches the threshold 2.5117;
    the outer face's short-wave limit (half-space) comes before them all.

    The prismatic family (n = 0, scanned by default) now comes first among the finite
    modes: its probe (15, 0) beats the wrinkles, the m range is widened twice, (31, 0)
    wins the mode-by-mode scan at lambda_z = 2.476792462071, below the best wrinkle (0, 1)
    at 2.496809788768 (the wrinkle-only scan), and its critical value keeps falling with m
    towards the outer face's short-wave limit: the search beyond (msearch.py) follows it
    to the cap (2000, 0). (31, 0) checked by the prismatic single-mode solver by both
    methods: impedance 2.47679246207104, collocation (full march) 2.47679246207128. With
    the short-wave limit on (the default) the widening is not needed: the limit comes
    before the probe (15, 0) and is the result.
    """
    wrinkles = ScanOptions((0, 3), (1, 2), surface=False, prismatic=False, torsional=False)
    only = scan_modes(P, "stretch", side="extension", options=wrinkles).critical
    assert (only.m, only.n, only.family) == (0, 1, "wrinkle")
    assert 2.49 < only.value < 2.5117
    finite = ScanOptions((0, 3), (1, 2), surface=False)
    res = scan_modes(P, "stretch", side="extension", options=finite)
    assert res.critical.kind == "bifurcation"
    assert (res.critical.m, res.critical.n, res.critical.family) == (M_CAP, 0, "prismatic")
    assert 2.4559 < res.critical.value < only.value
    direct = critical_value(P, M_CAP, 0, "stretch", side="extension")
    assert res.critical.value == pytest.approx(direct.value, rel=1e-12)
    direct = critical_value(P, 31, 0, "stretch", side="extension")
    assert direct.value == pytest.approx(2.476792462071, abs=1e-11)
    assert direct.value > res.critical.value
    v, w = direct.value, 1e-6
    col = critical_value(
        P, 31, 0, "stretch", side="extension", method="collocation", bracket=(v - w, v + w)
    )
    assert col.value == pytest.approx(v, abs=1e-10)
    full = scan_modes(P, "stretch", side="extension", options=ScanOptions((0, 3), (1, 2)))
    limit = short_wave_limit(P, "stretch", side="extension")
    assert full.critical.kind == "surface" and full.critical.value == limit.value
    assert (full.critical.face, full.critical.psi) == ("outer", 0.0)
    assert full.critical.value < res.critical.value  # before every finite mode, m <= 2000
    # the best finite mode found follows; the widening stopped once the limit came first
    # (the probe (15, 0) already lies after it), so it is not the widened optimum (31, 0)
    first = full.runners_up[0]
    assert (first.m, first.n, first.family) == (15, 0, "prismatic")
    assert first.value >= res.critical.value
    direct = critical_value(P, 15, 0, "stretch", side="extension")
    assert first.value == pytest.approx(direct.value, rel=1e-9)


@pytest.mark.parametrize(
    "kw, needle",
    [
        (dict(m_range=(-1, 3)), "m range"),
        (dict(n_range=(0, 3)), "n range"),
        (dict(n_range=(4, 2)), "n range"),
        (dict(top=0), "top = 0 is invalid"),
    ],
)
def test_bad_ranges(kw, needle):
    with pytest.raises(ParameterError, match=needle):
        scan_modes(P, "growth", options=ScanOptions(**kw))


def test_bad_side():
    with pytest.raises(ParameterError, match="side"):
        scan_modes(P, "growth", side="up")


def test_surface_instability_is_computed_exactly_not_scanned_forever():
    """Thick, long, compressed tube under voltage: the critical voltage keeps falling with n
    up to the cap; the infimum is the inner face's half-space limit (wrinkles along z),
    which the finite modes approach like 1/n."""
    p = Tube.uniform(2.5, 3.0, stretch=0.8)
    res = scan_modes(p, "voltage", options=ScanOptions((0, 2), (1, 6)))
    c, best = res.critical, res.runners_up[0]
    assert res.surface_instability and c.kind == "surface" and c.m == c.n == -1
    assert (c.face, c.psi) == ("inner", math.pi / 2)
    # the probe n = 24 beyond the range is the best finite mode; the limit comes before it,
    # so the range is not widened (it used to be, to its edge n = 24)
    assert res.n_range == (1, 6) and best.n == 24
    assert res.short_wave_limit == c.value < best.value  # below every finite-n value
    v2 = critical_value(p, best.m, 2 * best.n, "voltage").value
    assert c.value < v2 < best.value
    assert 0.4 < (v2 - c.value) / (best.value - c.value) < 0.6  # O(1/n): halves
    assert res.short_wave_error < 1e-10


def test_short_wave_beyond_the_range_is_found_by_probes():
    """Vbar = 0.4, extension: critical stretch rises from m = 0 to 12, then falls with m
    towards the outer face's short-wave limit, which comes first."""
    res = scan_modes(P, "stretch", side="extension")
    best = res.runners_up[0]
    assert best.m > 12 and res.surface_instability and res.critical.kind == "surface"
    assert res.short_wave_limit == res.critical.value < best.value < 2.4968


def test_no_short_wave_check_where_a_finite_mode_comes_first():
    """The headline tube: growth is a rescaling, mode (0, 1) first; no limit computed."""
    res = scan_modes(Tube.uniform(1.4, 1.0, voltage=0.4), "growth")
    assert res.critical.kind == "bifurcation" and (res.critical.m, res.critical.n) == (0, 1)
    assert res.short_wave_limit is None and not res.surface_instability
    limit = short_wave_limit(Tube.uniform(1.4, 1.0, voltage=0.4), "growth")
    assert limit.value > res.critical.value


@pytest.mark.parametrize(
    "tube",
    [
        Tube.uniform(1.02, 0.2),
        Tube.uniform(5.0, 10.0, material=gent(10.0)),
        Tube.uniform(1.1, 1.0, material=mooney_rivlin(0.3)),
        Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0)), length=1.0),
        Tube(
            (
                Layer(1.3, shear_modulus=0.1, permittivity=5.0),
                Layer(1.4, material=mooney_rivlin(0.3), shear_modulus=30.0),
                Layer(3.0, material=gent(10.0)),
            ),
            length=0.5,
        ),
    ],
    ids=["thin-short", "thick-slender-gent", "mooney-rivlin", "bilayer", "trilayer"],
)
def test_stable_signs_are_those_of_every_unloaded_tube(tube):
    """The scans read the stable signs once, on the paper's tube: they equal the signs of
    the targets on this tube's own unloaded reference, mode by mode (docs/derivation.md 3)."""
    ranges, probes, families = ((0, 12), (1, 30)), True, (True, True)
    grid = scan_grid(*ranges, probes, families)
    own = unloaded_signs(tube, grid, functools.partial(impedance_targets, rtol=1e-8))
    assert np.all(own != 0)
    np.testing.assert_array_equal(stable_signs(*ranges, probes, families), own)
