"""The margin's sensitivity at a kink of M.

The widest margin usually sits where two competitors tie: for a bilayer under a voltage,
target (1, 1) along Rbar_o, (0, 1) and (2, 1) are equal there to 1e-11. M = min of the two
gaps is not differentiable there; `margin_sensitivity` was the derivative against
`next_mode` alone, dM/dlength = +0.0610, where M falls by 0.0450 per unit towards longer
tubes (probe 8b, D5): a user lengthening the tube by it loses margin. Now such a key's
`margin_sensitivity` is None and `margin_sides` holds the two one-sided derivatives,
checked here against one-sided differences of direct single-mode solves."""

import json
from types import SimpleNamespace

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, prescribe
from electrogrowth.cli.app import main
from electrogrowth.figures.design import plotted_modes

TUBE = Tube([Layer(1.2, shear_modulus=2.0), Layer(1.5)], length=1.5, stretch=1.0)
OPTIONS = ScanOptions((0, 4), (1, 3))
VARY = ("outer_radius", 1.3, 1.8)


RIVALS = ((0, 1), (2, 1))


def _gaps(tube):
    """The gap s (v_c - v_T) / |v_T| to each rival c, M the smaller."""
    v = {m: critical_value(tube, *m, "voltage", rtol=1e-12).value for m in ((1, 1), *RIVALS)}
    return {c: v[c] / v[(1, 1)] - 1.0 for c in RIVALS}


def _slopes(at, key):
    """dM_c/dp of each rival's gap: central differences of direct solves, Richardson of
    steps h and h / 2."""
    p, h = at.value_of(key), 1e-4
    g = {t: _gaps(at.at(key, p + t)) for t in (-h, -h / 2, h / 2, h)}
    return {c: (8 * (g[h / 2][c] - g[-h / 2][c]) - (g[h][c] - g[-h][c])) / (6 * h) for c in RIVALS}


@pytest.fixture(scope="module")
def design():
    return prescribe(TUBE, "voltage", (1, 1), VARY, points=4, options=OPTIONS)


@pytest.mark.parametrize("key", ["length", "layers[1].shear_modulus"])
def test_margin_sensitivity_at_a_tie_gives_both_sides(design, key):
    at = TUBE.at("outer_radius", design.x)
    gaps = _gaps(at)
    assert abs(design.margin - min(gaps.values())) < 1e-9
    assert abs(gaps[(0, 1)] - gaps[(2, 1)]) < 1e-8  # the two rivals tie at the design
    d = _slopes(at, key)
    up, down = min(d.values()), max(d.values())  # raising p M follows the falling gap
    assert up < 0 < down  # a kink: M falls both ways (length: -0.0450, +0.0610)
    assert design.margin_sensitivity[key] is None  # was +0.0610 for the length
    assert set(design.tied_with) | {design.next_mode} == set(RIVALS)
    got_down, got_up = design.margin_sides[key]
    assert abs(got_up - up) < 1e-7 and abs(got_down - down) < 1e-7, (got_down, got_up, down, up)


def test_design_json_reports_the_kink(design, tmp_path, capsys):
    """`design --json` says the same: null for the two-sided number, both sides, the tie."""
    tube_file = tmp_path / "bilayer.toml"
    tube_file.write_text(
        "length = 1.5\nstretch = 1.0\n[[layers]]\nouter_radius = 1.2\nshear_modulus = 2.0\n"
        "[[layers]]\nouter_radius = 1.5\n"
    )
    args = ["design", "--tube", str(tube_file), "--solve-for", "voltage", "--target", "1", "1"]
    args += ["--vary", "outer_radius", "1.3", "1.8", "--points", "4", "--m-max", "4"]
    assert main([*args, "--n-max", "3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["sensitivity"]["margin"]["length"] is None  # was +0.0610
    sides = out["sensitivity"]["margin_sides"]["length"]
    assert (sides["down"], sides["up"]) == pytest.approx(design.margin_sides["length"], rel=1e-9)
    assert sorted(out["best"]["tied_with"] + [out["best"]["next_mode"]]) == [[0, 1], [2, 1]]


def test_an_exact_zero_slope_prints_as_zero_not_minus_zero():
    """probe round 14e: the design text printed "d(margin)/dvoltage = -0"."""
    from types import SimpleNamespace

    from electrogrowth.cli.design import _margin_slope

    one = SimpleNamespace(margin_sensitivity={"voltage": -0.0}, margin_sides={})
    assert _margin_slope(one, "voltage") == ", d(margin)/dvoltage = 0"
    kink = SimpleNamespace(margin_sensitivity={}, margin_sides={"voltage": (-0.0, 1.5)})
    assert _margin_slope(kink, "voltage").startswith(", d(margin)/dvoltage = 0 lowering")


def test_the_design_figure_draws_every_competitor_of_the_tie(design):
    """Probe 14e D4: the README design's figure drew (1, 1) and (0, 1) only while the margin
    at its star is set by (0, 1) and (2, 1) together; every tied mode is drawn (the crease
    or the short-wave limit is no mode curve)."""
    assert design.tied_with and {design.next_mode, *design.tied_with} == set(RIVALS)
    assert set(RIVALS) | {(1, 1)} <= set(plotted_modes(design))


def test_the_design_figure_draws_a_tied_mode_first_nowhere():
    """The README's design (probe 14e D4), its result in outline (no solve): (2, 1) ties
    with the next mode (0, 1) at the star and is first nowhere along the sequence."""
    readme = SimpleNamespace(  # its sequence: (1, 1) then (0, 1); (2, 1) first nowhere
        sequence=SimpleNamespace(
            intervals=[SimpleNamespace(mode=m, kind="bifurcation") for m in ((1, 1), (0, 1))]
        ),
        mode=(1, 1),
        next_mode=(0, 1),
        tied_with=((2, 1), "crease"),
    )
    assert plotted_modes(readme) == [(0, 1), (1, 1), (2, 1)]


def test_rounding_of_an_exact_zero_slope_is_no_kink(capsys, tmp_path):
    """Check round 29, doubt: the README's design (uncharged, compressed, along Rbar_o)
    printed "d(margin)/dgrowth = 2.31518e-12 lowering it, -8.68818e-12 raising it (a kink)".
    At Vbar = 0 a growth g rescales the tube and every critical stretch alike, so the margin
    does not move with g: the exact slope is 0 (the independent route). Slopes within their
    own error (sensitivity.margin_error) are one, and one within it of 0 prints as 0."""
    tube = Tube.uniform(1.25, 1.0)
    opts = ScanOptions((0, 2), (1, 2))
    d = prescribe(tube, "stretch", (1, 1), ("outer_radius", 1.2, 1.3), side="compression",
                  points=6, options=opts)  # fmt: skip
    assert d.tied_with  # the design sits at a tie: the length's slopes are a real kink
    assert d.margin_sensitivity["length"] is None
    down, up = d.margin_sides["length"]
    assert down - up > 1e3 * d.margin_error["length"]
    assert "growth" not in d.margin_sides  # was (2.3e-12, -8.7e-12)
    assert abs(d.margin_sensitivity["growth"]) <= d.margin_error["growth"] < 1e-6
    argv = ["design", "--solve-for", "stretch", "--side", "compression", "--target", "1", "1"]
    argv += ["--vary", "outer_radius", "1.2", "1.3", "--points", "6", "--m-max", "2"]
    assert main([*argv, "--n-max", "2", "--quiet", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "d(margin)/dgrowth = 0 (within its error 3.0e-07)" in out
