"""Critical curves along a parameter: located mode switches, consistency with single-mode
solves, failures as data, and the ``electrogrowth curve`` command."""

import argparse
import csv
import dataclasses
import json
import math

import numpy as np
import pytest

from electrogrowth.bifurcation import curve_switches
from electrogrowth.bifurcation.critical import critical_value
from electrogrowth.bifurcation.curve_record import Curve
from electrogrowth.bifurcation.curves import Switch, critical_curve
from electrogrowth.bifurcation.scan import ScanOptions, scan_modes
from electrogrowth.cli.curve import configure_curve, run_curve
from electrogrowth.continuation.events import MODE_EDGE, SWITCH
from electrogrowth.digits import supported
from electrogrowth.errors import NoBifurcationFound, ParameterError
from electrogrowth.figures.plots import plot_curve
from electrogrowth.model.layers import Tube

SMALL = {"options": ScanOptions((0, 2), (1, 2))}  # the optimum on an edge extends the range


@pytest.fixture(scope="module")
def thin_to_thick():
    """lambda_z,cr (compression, Vbar = 0, L = 1) across Rbar_o = 1.2 .. 1.3: the critical
    mode switches from (m, n) = (1, 1) to (0, 1) near Rbar_o = 1.256."""
    calls = []
    curve = critical_curve(
        Tube.uniform(length=1.0),
        "stretch",
        "outer_radius",
        [1.2, 1.3],
        side="compression",
        progress=calls.append,
        **SMALL,
    )
    return curve, calls


def test_switch_is_where_the_two_modes_are_equally_critical(thin_to_thick):
    curve, calls = thin_to_thick
    assert calls == [1, 1]
    (sw,) = curve.switches
    assert isinstance(sw, Switch) and 1.2 < sw.x < 1.3
    assert sw.value_after == pytest.approx(sw.value, abs=1e-10)  # a crossing, not a jump
    assert (sw.mode_before, sw.mode_after) == ((1, 1), (0, 1))
    at = curve.params.at("outer_radius", sw.x)
    before = critical_value(at, 1, 1, "stretch", side="compression").value
    after = critical_value(at, 0, 1, "stretch", side="compression").value
    assert abs(before - after) < 1e-8
    assert sw.value == pytest.approx(before, abs=1e-10)
    rows = np.nonzero(curve.kind == "switch")[0]  # end of one branch, start of the next
    assert len(rows) == 2 and np.all(curve.x[rows] == sw.x)
    assert [(curve.m[i], curve.n[i]) for i in rows] == [(1, 1), (0, 1)]


def test_values_between_grid_points_are_the_direct_critical_values(thin_to_thick):
    curve, _ = thin_to_thick
    sw = curve.switches[0]
    for x in (0.5 * (1.2 + sw.x), 0.5 * (sw.x + 1.3)):  # inside each branch
        p = curve.params.at("outer_radius", x)
        scan = scan_modes(p, "stretch", side="compression", **SMALL).critical
        mode = (1, 1) if x < sw.x else (0, 1)
        assert (scan.m, scan.n) == mode
        direct = critical_value(p, *mode, "stretch", side="compression").value
        assert scan.value == pytest.approx(direct, abs=1e-10)
        # monotone pieces: thicker tubes need a stronger compression (smaller lambda_z)
        lo, hi = (1.2, sw.x) if x < sw.x else (sw.x, 1.3)
        v_lo = curve.value[curve.x == lo][-1 if lo == sw.x else 0]
        v_hi = curve.value[curve.x == hi][0]
        assert v_lo > direct > v_hi
    assert np.all(np.diff(curve.x) >= 0) and np.all(np.diff(curve.value) < 1e-9)


def test_branches_csv_and_plot(thin_to_thick, tmp_path):
    curve, _ = thin_to_thick
    modes = [mode for mode, _ in curve.branches()]
    assert modes == [(1, 1), (0, 1)]
    path = curve.to_csv(tmp_path / "c.csv")
    with path.open() as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == [
        "outer_radius",
        "stretch_cr",
        "m",
        "n",
        "kind",
        "surface",
        "surface_face",
        "short_wave_limit",
        "status",
        "crease_value",
        "crease_face",
        "crease_trigger",
        "crease_error",
        "crease_first",
    ]
    assert len(rows) == 1 + len(curve.x) and float(rows[1][1]) == curve.value[0]
    ax = plot_curve(curve)
    labels = {t.get_text() for t in ax.texts}
    assert labels == {"(1, 1)", "(0, 1)"}  # (m, n), the paper's "n, m" reversed
    assert "lambda" in ax.get_ylabel() and "R" in ax.get_xlabel()
    json.dumps(curve.as_dict())


def test_failures_are_data():
    """At Vbar = 0.6 the ungrown tube (Rbar_o = 1.4, L = 1) buckles in extension at
    lambda_z = 1.583: beyond it there is no stable start for the growth factor."""
    p = Tube.uniform(outer_radius=1.4, voltage=0.6)
    curve = critical_curve(p, "growth", "stretch", [1.6, 1.65], **SMALL)
    assert list(curve.kind) == ["failed", "failed"]
    assert np.isnan(curve.value).all() and "already unstable" in curve.status[0]
    assert curve.branches() == [] and curve.switches == ()


@pytest.mark.parametrize(
    "solve_for, along, extra, named",
    [
        ("growth", "growth", {}, "along = 'growth'"),
        ("stretch", "stretch", {}, "along = 'stretch'"),
        ("growth", "radius", {}, "along = 'radius'"),
        ("force", "stretch", {}, "solve_for = force is not a control of this tube"),
        ("voltage", "stretch", {"side": "extension"}, "side"),
        ("stretch", "voltage", {"side": "sideways"}, "sideways"),
    ],
)
def test_bad_combinations_raise(solve_for, along, extra, named):
    with pytest.raises(ParameterError, match=named):
        critical_curve(Tube.uniform(), solve_for, along, [1.0, 1.1], **extra)


@pytest.mark.parametrize(
    "values, named",
    [
        ([1.2, 1.1, 1.3], "monotone"),
        ([], "non-empty"),
        ([0.5, 1.5], "Rbar_o = 0.5"),
    ],
)
def test_bad_grids_raise(values, named):
    with pytest.raises(ParameterError, match=named):
        critical_curve(Tube.uniform(), "voltage", "outer_radius", values)


def _args(*argv):
    parser = argparse.ArgumentParser()
    configure_curve(parser)
    return parser.parse_args(list(argv))


def test_cli_writes_csv_png_and_json(tmp_path, capsys):
    args = _args(
        "--solve-for",
        "stretch",
        "--side",
        "compression",
        "--along",
        "outer_radius",
        "--from",
        "1.2",
        "--to",
        "1.3",
        "--points",
        "2",
        "--m-max",
        "2",
        "--n-max",
        "2",
        "--out",
        str(tmp_path),
        "--json",
    )
    assert run_curve(args) == 0
    out, err = capsys.readouterr()
    rec = json.loads(out)
    assert err == ""  # no progress bar with --json
    assert rec["switches"][0]["mode_before"] == [1, 1] and rec["fixed"]["voltage"] == 0.0
    assert (tmp_path / "curve_stretch_vs_outer_radius.csv").exists()
    assert (tmp_path / "curve_stretch_vs_outer_radius.png").stat().st_size > 0


def test_cli_text_summary(tmp_path, capsys):
    args = _args(
        "--solve-for",
        "growth",
        "--along",
        "stretch",
        "--from",
        "1.6",
        "--to",
        "1.65",
        "--points",
        "2",
        "--voltage",
        "0.6",
        "--out",
        str(tmp_path),
    )
    assert run_curve(args) == 2  # every point failed: written, but no result (as a sweep)
    out, err = capsys.readouterr()
    assert "critical growth along stretch" in out and "Vbar = 0.6" in out
    assert "failed at stretch = 1.6" in out and "already unstable" in out
    assert err.count("\n") == 1 and "every point of the curve failed (2)" in err
    assert (tmp_path / "curve_growth_vs_stretch.csv").exists()


def test_cli_a_curve_with_a_failed_point_exits_0(tmp_path, capsys):
    args = _args(
        "--solve-for", "growth", "--along", "stretch", "--from", "1.0", "--to", "1.6",
        "--points", "2", "--voltage", "0.6", "--out", str(tmp_path),
    )  # fmt: skip
    assert run_curve(args) == 0
    out, err = capsys.readouterr()
    assert "failed at stretch = 1.6" in out and "every point" not in err


def test_cli_help_speaks_the_papers_terms():
    parser = argparse.ArgumentParser()
    configure_curve(parser)
    text = parser.format_help()
    for word in ("g_cr", "lambda_z", "Vbar", "Rbar_o", "(m, n)", "--m-max", "--json"):
        assert word in text


@pytest.mark.parametrize(
    "argv, named",
    [
        (["--solve-for", "growth", "--along", "growth"], "along = 'growth'"),
        (["--solve-for", "voltage", "--along", "stretch", "--side", "extension"], "--side"),
        (["--solve-for", "voltage", "--along", "stretch", "--points", "1"], "--points = 1"),
        (["--solve-for", "voltage", "--along", "stretch", "--to", "1"], "--from = --to"),
        (["--solve-for", "voltage", "--along", "length", "--from", "-1"], "L = -1"),
    ],
)
def test_cli_bad_input_is_a_parameter_error(argv, named, tmp_path):
    argv = list(argv)
    for flag, value in (("--from", "1"), ("--to", "2")):
        if flag not in argv:
            argv += [flag, value]
    with pytest.raises(ParameterError, match=named):
        run_curve(_args(*argv, "--out", str(tmp_path)))


@pytest.mark.parametrize(
    "params, solve_for, along, grid, side",
    [
        # no switch: most points are followed, not scanned
        (
            Tube.uniform(1.4, 1.0, voltage=0.4),
            "growth",
            "stretch",
            np.linspace(0.9, 1.3, 9),
            None,
        ),
        # the outer face's short-wave limit comes first all along (Fig. 7, extension)
        (
            Tube.uniform(1.3, 1.0, voltage=0.4),
            "stretch",
            "outer_radius",
            [1.3, 1.35, 1.4, 1.45],
            "extension",
        ),
        # two switches of the critical mode along Rbar_o
        (Tube.uniform(length=1.0), "voltage", "outer_radius", np.linspace(1.1, 1.35, 6), None),
    ],
)
def test_continuation_equals_full_scans(params, solve_for, along, grid, side, monkeypatch):
    """A curve by continuation gives the values, modes, kinds and switches of the curve of
    full scans at every point (to the solver's tolerance), with fewer scans."""
    from electrogrowth.bifurcation import curves

    options = ScanOptions((0, 4), (1, 4))
    full = critical_curve(params, solve_for, along, grid, side=side, options=options, follow=False)
    scans = []
    counting = lambda *a, **k: scans.append(1) or scan_modes(*a, **k)  # noqa: E731
    monkeypatch.setattr(curves, "scan_modes", counting)
    followed = critical_curve(params, solve_for, along, grid, side=side, options=options)
    assert followed.x == pytest.approx(full.x, rel=1e-12, abs=0)
    assert (followed.surface == full.surface).all()
    both = np.isfinite(full.short_wave_limit)
    assert (np.isfinite(followed.short_wave_limit) == both).all()
    assert followed.short_wave_limit[both] == pytest.approx(full.short_wave_limit[both], rel=1e-12)
    assert followed.value == pytest.approx(full.value, rel=1e-11, abs=0)
    assert (followed.m == full.m).all() and (followed.n == full.n).all()
    assert (followed.kind == full.kind).all()
    assert [(s.mode_before, s.mode_after) for s in followed.switches] == [
        (s.mode_before, s.mode_after) for s in full.switches
    ]
    if not full.switches:
        assert len(scans) < len(grid)


#: the fake single-mode values' error estimate
ERROR = 1e-12


def _fake_modes(monkeypatch, values, threshold=None, inaccurate=()):
    """Replace the scans and single-mode solves by closed forms: ``values[mode](x)`` is the
    first critical value of a mode at voltage x (NaN: the mode is not reached before the
    threshold, whose value is ``threshold(x)``; None: it has no root before the end of the
    march); the scans at the voltages ``inaccurate`` return a critical value of status
    "inaccurate"."""
    import math
    from types import SimpleNamespace

    from electrogrowth.bifurcation import curves

    def one(at, m, n, solve_for, side=None, bracket=None, rtol=1e-12):
        v = values[m, n](at.voltage)
        error = ERROR * rtol / 1e-12  # as the package's estimate, ~ rtol |v|
        if v is None:
            raise NoBifurcationFound(f"({m}, {n}) has no root")
        if math.isnan(v):
            return SimpleNamespace(
                value=threshold(at.voltage), kind="threshold", error_estimate=error
            )
        return SimpleNamespace(value=v, kind="bifurcation", error_estimate=error)

    def scan(at, solve_for, side=None, options=None):
        found = [
            (v, mode)
            for mode, f in values.items()
            if (v := f(at.voltage)) is not None and not math.isnan(v)
        ]
        if found:
            v, (m, n) = min(found)
            crit = SimpleNamespace(kind="bifurcation", m=m, n=n, value=v, error_estimate=0.0)
        else:
            crit = SimpleNamespace(
                kind="threshold", m=-1, n=-1, value=threshold(at.voltage), error_estimate=0.0
            )
        crit.status = "inaccurate" if at.voltage in inaccurate else "ok"
        return SimpleNamespace(
            critical=crit, runners_up=(), short_wave_limit=None, surface_instability=False
        )

    monkeypatch.setattr(curves, "critical_value", one)
    monkeypatch.setattr(curves, "scan_modes", scan)


def _curve(grid):
    return critical_curve(Tube.uniform(), "growth", "voltage", grid, follow=False)


def test_a_crossing_is_a_switch(monkeypatch):
    """Modes (0, 1): 1 + 2x and (1, 1): 1.5 + x cross at x = 0.5, value 2."""
    _fake_modes(monkeypatch, {(0, 1): lambda x: 1 + 2 * x, (1, 1): lambda x: 1.5 + x})
    curve = _curve([0.1, 0.9])
    (sw,) = curve.switches
    assert curve.ends == () and sw.kind == "switch"
    assert sw.x == pytest.approx(0.5, abs=1e-12) and sw.value == pytest.approx(2.0, abs=1e-12)
    assert list(curve.kind) == ["bifurcation", "switch", "switch", "bifurcation"]
    assert list(curve.status) == ["ok"] * 4  # a located switch's rows too
    # d = x - 0.5 (slope 1), each value +- ERROR: x +- 2 ERROR beyond Brent's tolerance,
    # the value +- ERROR + 2 (the steeper slope) x_error
    tol = SWITCH.at(0.5)
    assert sw.x_error == pytest.approx(tol + 2 * ERROR, rel=1e-3)
    assert sw.value_error == pytest.approx(ERROR + 2 * sw.x_error, rel=1e-3)


def test_the_error_of_a_switch_between_nearly_parallel_modes(monkeypatch):
    """Neighbouring folds: values nearly parallel (here d = 1e-4 (x - 0.5)), so their
    errors move the tie 1e4 times as far (check round 16c: 1e-12 in the values moved a
    fold switch 1e-8); the switch says so: x_error 2e-8 at the default rtol, above
    REFINE_ABOVE, so the two modes are solved again at the finest rtol (1e-14: errors 1e-2
    ERROR) either side and x_error is 2e-10. The secant slopes are exact here."""
    _fake_modes(
        monkeypatch, {(0, 1): lambda x: 1 + 2 * x, (1, 1): lambda x: 1 + 0.5e-4 + (2 - 1e-4) * x}
    )
    (sw,) = _curve([0.1, 0.9]).switches
    assert sw.x == pytest.approx(0.5, abs=1e-9)
    finest = 1e-2 * ERROR
    assert sw.x_error == pytest.approx(SWITCH.at(0.5) + 2 * finest / 1e-4, rel=1e-3)
    assert abs(sw.x - 0.5) <= sw.x_error
    assert sw.value_error == pytest.approx(finest + 2 * sw.x_error, rel=1e-3)
    record = _curve([0.1, 0.9]).as_dict()["switches"][0]
    assert record["x_error"] == sw.x_error and record["value_error"] == sw.value_error
    monkeypatch.setattr(curve_switches, "REFINE_ABOVE", math.inf)  # the default rtol's
    (sw,) = _curve([0.1, 0.9]).switches
    assert sw.x_error == pytest.approx(SWITCH.at(0.5) + 2 * ERROR / 1e-4, rel=1e-3)


def test_the_branches_end_at_a_switch_with_its_digits(monkeypatch):
    """The branches' lines end at a switch with the digits its estimate supports (8 at
    x_error 2e-8, nearly parallel modes at the default rtol), as the switch's own line;
    the grid's ends as given. They printed 10 digits."""
    tie = 0.45678912345678
    _fake_modes(
        monkeypatch,
        {(0, 1): lambda x: 1 + 2 * x, (1, 1): lambda x: 1 + 1e-4 * tie + (2 - 1e-4) * x},
    )
    monkeypatch.setattr(curve_switches, "REFINE_ABOVE", math.inf)
    curve = _curve([0.1, 0.9])
    (sw,) = curve.switches
    from electrogrowth.cli.curve import summary

    shown = supported(sw.x, sw.x_error)
    assert shown == "0.45678912"
    lines = summary(curve)
    assert f"  voltage 0.1 .. {shown}: mode (m, n) = (0, 1)" in lines
    assert f"  voltage {shown} .. 0.9: mode (m, n) = (1, 1)" in lines
    assert any(f"switch at voltage = {shown}," in line for line in lines)


def test_a_crossing_is_a_switch_when_a_mode_has_no_root_at_the_far_grid_point(monkeypatch):
    """Modes (0, 1): 1 + 2x and (1, 1): 1.5 + x cross at x = 0.5, value 2; (0, 1) has no
    root before the end of the march beyond x = 0.8. Found by probing (round 8b, D3): the
    single-mode solve's NoBifurcationFound at the grid point x = 0.9 sent the switch to the
    bisection with scans, which located it to 1e-7 only and, its two values taken 1e-7
    apart, labelled it an "end". A mode with no root comes after every other: +-inf in
    Brent's d."""
    _fake_modes(
        monkeypatch,
        {(0, 1): lambda x: 1 + 2 * x if x < 0.8 else None, (1, 1): lambda x: 1.5 + x},
    )
    curve = _curve([0.1, 0.9])
    (sw,) = curve.switches
    assert curve.ends == () and sw.kind == "switch"
    assert sw.x == pytest.approx(0.5, abs=1e-12) and sw.value == pytest.approx(2.0, abs=1e-12)


def test_a_branch_that_ends_at_a_jump_is_an_end(monkeypatch, tmp_path):
    """Mode (0, 1) is critical at 1 + x until its window of instability closes at x = 0.5
    (beyond, its first critical value is 3 + x); mode (1, 1), 2 + x, is critical after: the
    critical value jumps from 1.5 to 2.5. That is the end of the branch (0, 1), not a
    switch: recorded in ``ends``, rows of kind "end", open circles on the plot."""
    _fake_modes(
        monkeypatch, {(0, 1): lambda x: 1 + x if x < 0.5 else 3 + x, (1, 1): lambda x: 2 + x}
    )
    curve = _curve([0.1, 0.9])
    assert curve.switches == ()
    (end,) = curve.ends
    assert (end.kind, end.mode_before, end.mode_after) == ("end", (0, 1), (1, 1))
    assert end.x == pytest.approx(0.5, abs=1e-9)
    assert (end.value, end.value_after) == (
        pytest.approx(1.5, abs=1e-9),
        pytest.approx(2.5, abs=1e-9),
    )
    assert list(curve.kind) == ["bifurcation", "end", "end", "bifurcation"]
    # a jump is located to Brent's tolerance and the one-sided values' offset, whatever
    # the values' errors; its values are as good as their estimates
    assert abs(end.x - 0.5) <= end.x_error <= 5 * SWITCH.at(0.5)
    assert end.value_error == ERROR
    rec = json.loads(json.dumps(curve.as_dict(), allow_nan=False))
    assert rec["switches"] == [] and rec["ends"][0]["mode_before"] == [0, 1]
    assert rec["ends"][0]["x_error"] == end.x_error
    ds = curve.to_xarray()
    assert ds.sizes["end"] == 1 and ds.sizes["switch"] == 0
    assert float(ds["end_x_error"][0]) == end.x_error
    assert ds["end_mode_after"].values.tolist() == [[1, 1]]
    assert float(ds["end_value_after"][0]) == pytest.approx(2.5, abs=1e-9)
    with curve.to_csv(tmp_path / "c.csv").open() as fh:
        assert [r["kind"] for r in csv.DictReader(fh)] == list(curve.kind)
    from electrogrowth.cli.curve import summary

    text = "\n".join(summary(curve))
    assert "switch" not in text and "branch (0, 1) ends at voltage = 0.5" in text
    assert "then (1, 1) from 2.5" in text
    ax = plot_curve(curve)
    marks = {line.get_label(): line for line in ax.get_lines()}
    assert "switch" not in marks
    assert sorted(marks["branch ends"].get_ydata()) == pytest.approx([1.5, 2.5], abs=1e-9)


def test_a_branch_that_meets_the_threshold_ends(monkeypatch):
    """Mode (0, 1) bifurcates at 1 + x before the threshold 1.5 only for x < 0.5: beyond,
    the axisymmetric state is lost first. No wrinkling mode follows: an end."""
    _fake_modes(
        monkeypatch,
        {(0, 1): lambda x: 1 + x if x < 0.5 else float("nan")},
        threshold=lambda x: 1.5,
    )
    curve = _curve([0.1, 0.9])
    assert curve.switches == ()
    (end,) = curve.ends
    assert end.mode_after == (-1, -1) and end.x == pytest.approx(0.5, abs=1e-9)
    assert list(curve.kind) == ["bifurcation", "end", "end", "threshold"]
    # the bisection's last bracket (MODE_EDGE) holds the end
    assert abs(end.x - 0.5) <= end.x_error <= MODE_EDGE.at(0.5)
    from electrogrowth.cli.curve import summary

    assert "then the threshold (axisymmetric state lost)" in "\n".join(summary(curve))


def test_an_inaccurate_critical_value_stays_marked(monkeypatch, tmp_path):
    """A grid point whose critical value is not certified (status "inaccurate" from
    critical_value) keeps that status in the curve, its CSV, JSON and xarray; the others
    say "ok" (check round 29: an empty cell, as before, read as a missing value)."""
    _fake_modes(monkeypatch, {(0, 1): lambda x: 1 + x}, inaccurate=(0.5,))
    curve = _curve([0.1, 0.5, 0.9])
    assert list(curve.status) == ["ok", "inaccurate", "ok"]
    assert curve.inaccurate.tolist() == [False, True, False]
    assert list(curve.kind) == ["bifurcation"] * 3  # still a value and a mode
    assert json.loads(json.dumps(curve.as_dict()))["status"] == ["ok", "inaccurate", "ok"]
    with curve.to_csv(tmp_path / "c.csv").open() as fh:
        assert [r["status"] for r in csv.DictReader(fh)] == ["ok", "inaccurate", "ok"]
    assert curve.to_xarray()["status"].values.tolist() == ["ok", "inaccurate", "ok"]


def test_cli_warns_of_inaccurate_points_and_exits_0(monkeypatch, tmp_path, capsys):
    from electrogrowth.cli import curve as cli_curve

    _fake_modes(monkeypatch, {(0, 1): lambda x: 1 + x}, inaccurate=(0.5,))
    real = cli_curve.critical_curve
    monkeypatch.setattr(
        cli_curve, "critical_curve", lambda *a, **k: real(*a, **{**k, "follow": False})
    )
    argv = ("--solve-for", "growth", "--along", "voltage", "--from", "0.1", "--to", "0.9")
    args = _args(*argv, "--points", "3", "--out", str(tmp_path), "--json")
    assert run_curve(args) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["status"] == ["ok", "inaccurate", "ok"]
    assert err.count("\n") == 1 and "warning: 1 of 3 points are inaccurate" in err


@pytest.mark.slow
def test_a_sequence_switch_with_a_mode_rootless_at_the_far_grid_point_is_brents():
    """Probe round 8b (D2, D3), ~90 s: bilayer (mu 10 | 1), hoop growth, m range (8, 16),
    along the inner pressure. (15, 1) -> (8, 2) cross continuously at p = 0.16111873085
    (Brent on two single-mode solves, both 2.5310340968); the sequence put the switch at
    0.16111871595 as an "end" ((15, 1) has no root up to g = 6 at the grid point p = 0.3, so
    the scans' bisection took over), and left a gap [0.153455, 0.154053] with no mode (the
    scan at 0.1545 reported (14, 1) behind its runner-up (17, 0))."""
    from scipy.optimize import brentq

    from electrogrowth import Layer, mode_sequence

    def tube(p):
        return Tube(
            [Layer(1.1, shear_modulus=10.0), Layer(2.0)],
            length=1.0,
            stretch=1.0,
            inner_pressure=p,
        )

    ctrl = "growth[1].theta"
    seq = mode_sequence(
        tube(0.0), ctrl, ("pressure", -0.05, 0.3), points=3, options=ScanOptions((8, 16), (1, 1))
    )
    ivs = seq.intervals
    assert not [(a.hi, b.lo) for a, b in zip(ivs, ivs[1:]) if b.lo - a.hi > 1e-12]
    (sw,) = [s for s in seq.switches if tuple(s.mode_after) == (8, 2)]

    def d(p):
        v15 = critical_value(tube(p), 15, 1, ctrl, rtol=1e-12).value
        return v15 - critical_value(tube(p), 8, 2, ctrl, rtol=1e-12).value

    root = brentq(d, 0.1605, 0.1615, xtol=1e-14)
    assert str(sw.kind) == "switch" and abs(sw.x - root) < 1e-10, (sw, root)


def test_an_older_curves_empty_status_still_reads_as_ok():
    """Curves written before 2026-12-08 left an ok row's status empty: still not inaccurate."""
    curve = dataclasses.replace(_fixed_curve(), status=("", "inaccurate; note", "ok"))
    assert curve.inaccurate.tolist() == [False, True, False]


def _fixed_curve():
    n = 3
    x, ones, kinds = np.linspace(0.1, 0.9, n), np.ones(n), np.array(["bifurcation"] * n)
    m, ok, no = np.zeros(n, int), ("ok",) * n, np.zeros(n, bool)
    return Curve("voltage", "growth", None, x, ones, m, m + 1, kinds, ok, (), Tube.uniform(),
                 no, np.full(n, np.nan))  # fmt: skip


def _fake_limit_and_threshold(monkeypatch, limit, threshold):
    """Scans and short-wave limits by closed forms at voltage x, no finite mode: the exact
    short-wave limit ``limit(x)`` (inner face) where it comes before ``threshold(x)``, else
    the threshold (the limit's march reports which comes first)."""
    from types import SimpleNamespace

    from electrogrowth.bifurcation import curves

    def first(x):
        if limit(x) < threshold(x):
            return SimpleNamespace(kind="surface", value=limit(x), error_estimate=ERROR,
                                   face="inner")  # fmt: skip
        return SimpleNamespace(kind="threshold", value=threshold(x), error_estimate=0.0, face=None)

    def short_wave(at, solve_for, side=None):
        return first(at.voltage)

    def scan(at, solve_for, side=None, options=None):
        c = first(at.voltage)
        crit = SimpleNamespace(m=-1, n=-1, status="ok", **vars(c))
        surface = c.kind == "surface"
        return SimpleNamespace(critical=crit, runners_up=(), surface_instability=surface,
                               short_wave_limit=c.value if surface else None)  # fmt: skip

    monkeypatch.setattr(curves, "short_wave_limit", short_wave)
    monkeypatch.setattr(curves, "scan_modes", scan)


@pytest.mark.parametrize("grid", [[0.1, 0.9], [0.9, 0.1]])
def test_a_change_between_the_short_wave_limit_and_the_threshold_is_located(
    monkeypatch, tmp_path, grid
):
    """Check round 29 ("Left out"; fix23c): the short-wave limit 1 + x x^2 (inner face) comes
    before the threshold 1.6 - x/2 up to their crossing; the change was drawn as two branches
    but not located (both have m = n = -1, and only modes were compared). It is an end
    (the threshold wrinkles in no mode), located by bisection to MODE_EDGE; checked
    against the crossing of the two branches' own values by brentq."""
    from scipy.optimize import brentq

    from electrogrowth.cli.curve import summary

    limit, threshold = (lambda x: 1 + x * x), (lambda x: 1.6 - x / 2)
    _fake_limit_and_threshold(monkeypatch, limit, threshold)
    crossing = brentq(lambda x: limit(x) - threshold(x), 0.1, 0.9, xtol=1e-15)
    curve = _curve(grid)
    assert curve.switches == ()
    (end,) = curve.ends
    assert abs(end.x - crossing) <= end.x_error <= MODE_EDGE.at(crossing)
    assert end.value == pytest.approx(threshold(crossing), abs=1e-11)
    assert end.value_after == pytest.approx(threshold(crossing), abs=1e-11)
    limit_first = grid[0] < grid[1]
    before, after = ((-1, -1), (-1, -1))
    assert (end.mode_before, end.mode_after) == (before, after)
    assert list(curve.kind) == ["surface" if limit_first else "threshold", "end", "end",
                                "threshold" if limit_first else "surface"]  # fmt: skip
    assert list(curve.surface) == [limit_first, limit_first, not limit_first, not limit_first]
    record = json.loads(json.dumps(curve.as_dict(), allow_nan=False))
    assert record["ends"][0]["x"] == end.x and record["ends"][0]["x_error"] == end.x_error
    assert float(curve.to_xarray()["end_x"][0]) == end.x
    with curve.to_csv(tmp_path / "c.csv").open() as fh:
        assert [r["kind"] for r in csv.DictReader(fh)] == list(curve.kind)
    marks = {line.get_label(): line for line in plot_curve(curve).get_lines()}
    assert sorted(marks["branch ends"].get_ydata()) == pytest.approx([end.value] * 2, abs=1e-11)
    text = "\n".join(summary(curve))
    shown = supported(end.x, end.x_error)
    if limit_first:
        assert (
            f"the short-wave limit at the inner face ends at voltage = {shown}, growth_cr ="
            in text
        )
        assert "; then the threshold (axisymmetric state lost)" in text
    else:
        assert f"the threshold (axisymmetric state lost) ends at voltage = {shown}" in text
        assert "; then the short-wave limit at the inner face from" in text


def test_the_csv_abscissae_are_the_grid_as_given(monkeypatch, tmp_path, capsys):
    """Check round 29 (cosmetic): `--from 0 --to 0.3 --points 4` wrote 0.09999999999999999
    (np.linspace's 0.3 * (1/3)); the grid is now the doubles nearest the decimal grid
    points 0.1, 0.2, and the CSV reads back the same numbers (repr round trip)."""
    import functools

    from electrogrowth.cli import curve as cli_curve

    _fake_modes(monkeypatch, {(0, 1): lambda x: 1.5 + x})
    monkeypatch.setattr(
        cli_curve, "critical_curve", functools.partial(critical_curve, follow=False)
    )  # the fake scans are full scans
    argv = ["--solve-for", "growth", "--along", "voltage", "--from", "0", "--to", "0.3"]
    assert run_curve(_args(*argv, "--points", "4", "--out", str(tmp_path), "--json")) == 0
    capsys.readouterr()
    with (tmp_path / "curve_growth_vs_voltage.csv").open() as fh:
        column = [row["voltage"] for row in csv.DictReader(fh)]
    assert column == ["0.0", "0.1", "0.2", "0.3"]
