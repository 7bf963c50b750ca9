"""Figures 6-10 at low resolution: each runs, writes PNG + CSV, and a headline number
agrees with an independent single-mode computation (or the paper's own cross-reference
between figures)."""

import csv

import numpy as np
import pytest

from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.figures import FIGURES
from electrogrowth.figures import critical as fm
from electrogrowth.model.layers import Tube

MODE_FIGURES = (6, 7, 8, 9, 10)

RO14 = Tube.uniform(outer_radius=1.4, length=1.0)


@pytest.fixture(scope="module")
def figures():
    """Every figure once, quick (shared by the tests below)."""
    return {n: FIGURES[n](quick=True) for n in MODE_FIGURES}


@pytest.mark.parametrize("number", MODE_FIGURES)
def test_figure_writes_png_and_csv(figures, number, tmp_path):
    res = figures[number]
    paths = res.save(tmp_path)
    png, table = tmp_path / f"fig{number}.png", tmp_path / f"fig{number}.csv"
    assert png in paths and table in paths and png.stat().st_size > 10_000
    data = np.loadtxt(table, delimiter=",", skiprows=1, ndmin=2)
    assert data.shape == res.table.shape and len(res.columns) == data.shape[1]
    assert set(data[:, res.columns.index("kind")]) <= set(fm.KIND_CODES.values())
    if res.points:
        with (tmp_path / f"fig{number}_points.csv").open() as fh:
            assert len(list(csv.DictReader(fh))) == len(res.points)


def test_figure6_matches_single_mode_solves(figures):
    h = figures[6].headline
    assert (h["m_lambda_cr_Ro1.4"], h["n_lambda_cr_Ro1.4"]) == (0, 1)
    assert h["lambda_cr_Ro1.4"] == pytest.approx(
        critical_value(RO14, 0, 1, "stretch", side="compression").value, abs=1e-10
    )
    assert (h["m_V_cr_Ro1.2"], h["n_V_cr_Ro1.2"]) == (2, 1)  # a thin tube: 3D pattern
    assert h["V_cr_Ro1.4"] == pytest.approx(critical_value(RO14, 0, 1, "voltage").value, abs=1e-10)
    # thicker tubes are more stable: stronger compression and higher voltage to buckle
    a, b = figures[6].curves
    assert np.all(np.diff(a.value) < 1e-9) and np.all(np.diff(b.value) > -1e-9)


def test_figure7_brackets_the_stable_stretches(figures):
    h = figures[7].headline
    p = Tube.uniform(outer_radius=1.4, voltage=0.4)
    assert h["compression_V0.4_Ro1.4"] == pytest.approx(
        critical_value(p, 0, 1, "stretch", side="compression").value, abs=1e-10
    )
    # in extension at Vbar = 0.4 the outer face's short-wave limit comes first (issue 10)
    limit = short_wave_limit(p, "stretch", side="extension")
    assert (
        h["extension_V0.4_Ro1.4"]
        == limit.value
        < critical_value(p, 0, 1, "stretch", side="extension").value
    )
    assert h["m_extension_V0.4_Ro1.4"] == h["n_extension_V0.4_Ro1.4"] == -1  # m, n -> inf
    assert h["compression_V0.4_Ro1.4"] < 1 < h["extension_V0.6_Ro1.4"] < h["extension_V0.4_Ro1.4"]
    finite = {h[k] for k in h if k.startswith("n_") and h[k] >= 0}
    assert finite == {1}  # the axial mode of every finite critical mode is n = 1


def test_figure8_starts_at_zero_voltage_and_has_a_maximum(figures):
    res = figures[8]
    h = res.headline
    assert h["lambda_start_L1"] == pytest.approx(figures[6].headline["lambda_cr_Ro1.4"], abs=1e-10)
    for c in res.curves:
        ok = np.isfinite(c.value)
        assert c.value[0] < 0.02  # Vbar_cr -> 0 at the Vbar = 0 critical stretch
        i = int(np.argmax(np.where(ok, c.value, -np.inf)))
        assert 0 < i < len(c.x) - 1  # an interior maximum
    at_one = res.curves[0].value[res.curves[0].x == 1.0]
    assert at_one[0] == pytest.approx(figures[6].headline["V_cr_Ro1.4"], abs=1e-10)


def test_figure9_ends_at_the_ungrown_critical_stretches(figures):
    res = figures[9]
    h = res.headline
    p = Tube.uniform(outer_radius=1.4, voltage=0.4)
    lo = scan_modes(p, "stretch", side="compression", options=ScanOptions((0, 2), (1, 2)))
    assert h["lambda_compression_V0.4"] == pytest.approx(lo.critical.value, abs=1e-10)
    c = res.curves[0]
    assert c.x[0] == pytest.approx(lo.critical.value, rel=2e-6)
    assert c.value[0] == pytest.approx(1.0, abs=1e-4)  # g_cr = 1 at N1
    assert np.all(np.diff(c.value) > 0)  # increases monotonically up to N4
    names = [pt.name for pt in res.points]
    assert names[0] == "N1" and "M1" in names
    n1 = res.points[0]
    assert n1.params.stretch == c.x[0] and n1.params.growth == c.value[0]


@pytest.mark.parametrize("number", [9, 10])
def test_growth_curves_obey_the_growth_rescaling(figures, number):
    """Isotropic growth only magnifies the reference tube by g, so the tube (g, lambda_z,
    Vbar) wrinkles exactly when the ungrown tube (1, lambda_z/g, Vbar/g) of the same Rbar_o
    and L does (docs/derivation-base-state.md, sec. 5): every point of a growth curve is a
    critical compressive stretch of an ungrown tube, found here without any growth."""
    for c in figures[number].curves:
        for x, g, m, n in zip(c.x, c.value, c.m, c.n):
            if not np.isfinite(g):
                continue
            p = c.params.at(c.along, x)
            ungrown = p.at("growth", 1.0).at("voltage", p.voltage / g)
            lam = critical_value(ungrown, int(m), int(n), "stretch", side="compression")
            assert lam.value == pytest.approx(p.stretch / g, abs=1e-9)


def test_figure10_starts_at_the_growth_only_value(figures):
    res = figures[10]
    h = res.headline
    assert h["V_cr_lz1"] == pytest.approx(figures[6].headline["V_cr_Ro1.4"], abs=1e-10)
    c = res.curves[0]
    assert c.x[0] == 0.0 and c.x[-1] == pytest.approx(h["V_cr_lz1"], rel=2e-6)
    direct = critical_value(RO14, int(c.m[0]), int(c.n[0]), "growth").value
    assert h["g_start_lz1"] == pytest.approx(direct, abs=1e-10)
    assert res.points[0].name == "P1" and res.points[0].params.voltage == 0.0


@pytest.mark.slow
def test_figure7_headline_by_collocation(figures):
    """The second, independent method (spectral collocation) at one headline point."""
    h = figures[7].headline
    p = Tube.uniform(outer_radius=1.4, voltage=0.4)
    v = h["compression_V0.4_Ro1.4"]
    col = critical_value(
        p, 0, 1, "stretch", side="compression", method="collocation", bracket=(v - 1e-4, v + 1e-4)
    )
    assert col.value == pytest.approx(v, abs=1e-9)
