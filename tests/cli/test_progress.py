"""Long work reports its progress on stderr, only on a terminal and without --quiet; stdout
(the results, --json) stays clean; the library is silent unless asked; `electrogrowth`
alone prints the overview."""

import argparse
import json
import sys
import time

import numpy as np

from electrogrowth import ScanOptions, Tube, solve_base_state
from electrogrowth.bifurcation import certify
from electrogrowth.bifurcation.curves import critical_curve
from electrogrowth.cli.app import main
from electrogrowth.cli.critical import _Progress
from electrogrowth.cli.progress import stage
from electrogrowth.incremental.targets import impedance_targets

SWITCHING = dict(side="compression", options=ScanOptions((0, 2), (1, 2)))  # (1, 1) -> (0, 1)


def test_no_command_prints_the_overview_and_succeeds(capsys):
    assert main([]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("usage: electrogrowth")
    for command in ("state", "critical", "curve", "demo", "reproduce", "sweep"):
        assert f"\n    {command}" in out, command
    assert err == ""


def test_curve_reports_each_switch_it_locates(capsys):
    critical_curve(Tube.uniform(), "stretch", "outer_radius", [1.2, 1.3], **SWITCHING)
    assert capsys.readouterr().err == ""  # silent by default
    critical_curve(
        Tube.uniform(), "stretch", "outer_radius", [1.2, 1.3], progress=True, **SWITCHING
    )
    err = capsys.readouterr().err
    assert "stretch along outer_radius" in err and "2/2" in err  # the grid points
    assert "locating mode switches" in err and "1/1" in err
    assert "between (1, 1) and (0, 1)" in err


def test_curve_command_bars_only_on_a_terminal(tmp_path, capsys, monkeypatch):
    argv = [
        "curve", "--solve-for", "stretch", "--side", "compression", "--along", "outer_radius",
        "--from", "1.2", "--to", "1.3", "--points", "2", "--m-max", "2", "--n-max", "2",
        "--out", str(tmp_path),
    ]  # fmt: skip
    assert main(argv) == 0
    assert capsys.readouterr().err == ""  # not a terminal: nothing
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert main([*argv, "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert main(argv) == 0
    out, err = capsys.readouterr()
    assert "between (1, 1) and (0, 1)" in err and "locating" not in out
    assert main([*argv, "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["switches"] and err == ""  # one JSON object, no bar


def test_figure_commands_name_their_stages_on_a_terminal(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)  # (pytest's capture)
    assert main(["figure", "4", "--quick", "--out", str(tmp_path)]) == 0
    out, err = capsys.readouterr()
    assert "electrogrowth: computing figure 4 ..." in err
    assert "computing figure 4: done in" in err
    assert out.split() == [str(tmp_path / "fig4.png"), str(tmp_path / "fig4.csv")]
    assert main(["figure", "4", "--quick", "--quiet", "--out", str(tmp_path)]) == 0
    assert capsys.readouterr().err == ""
    assert main(["reproduce", "--quick", "--figures", "4", "--out", str(tmp_path)]) == 0
    out, err = capsys.readouterr()
    assert err == "electrogrowth: figure 4 (1 of 1) ...\n"  # stdout's line says the time
    assert "figure 4: " in out


def test_certify_counts_the_modes_it_checks_and_changes_no_value(capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    monkeypatch.setattr(certify, "BATCH", 2)  # two batches: 2 of 3 done, then 3
    state = solve_base_state(Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4))
    modes = np.array([[0, 1], [2, 1], [3, 0]], dtype=float)
    progress = _Progress(argparse.Namespace(quiet=False))
    f = certify._in_batches(lambda rows: impedance_targets(state, rows), modes, progress)
    progress.close()
    np.testing.assert_array_equal(f, impedance_targets(state, modes))  # in batches
    err = capsys.readouterr().err
    assert "certifying: every scanned mode stable before it" in err and "3/3" in err
    reports = []
    record = lambda done, total: reports.append((done, total))  # noqa: E731
    certify._in_batches(lambda rows: impedance_targets(state, rows), modes, record)
    assert reports == [(2, 3), (3, 3)]
    quiet = _Progress(argparse.Namespace(quiet=True))
    certify._in_batches(lambda rows: impedance_targets(state, rows), modes, quiet)
    quiet.close()
    assert capsys.readouterr().err == ""


def test_a_step_of_unknown_length_shows_the_time_it_has_taken(capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    with stage(argparse.Namespace(quiet=False), "solving mode (0, 1) by collocation", tick=True):
        time.sleep(2.3)
    err = capsys.readouterr().err
    assert "electrogrowth: solving mode (0, 1) by collocation ... 00:01" in err
    assert "solving mode (0, 1) by collocation: done in 2." in err


def test_a_step_with_a_delay_is_shown_only_once_it_takes_that_long(capsys, monkeypatch):
    """A single mode's march (`critical --mode`): milliseconds mostly, nothing shown; but
    minutes for a mode that never bifurcates on a stiffening tube's voltage path (1e3
    scales, ~2e4 steps): its elapsed time from the delay on, and how long it took."""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    args = argparse.Namespace(quiet=False)
    with stage(args, "solving mode (6, 2) by impedance", tick=True, delay=1.0):
        time.sleep(0.1)
    assert capsys.readouterr().err == ""
    with stage(args, "solving mode (6, 2) by impedance", tick=True, delay=1.0):
        time.sleep(2.3)
    err = capsys.readouterr().err
    assert "electrogrowth: solving mode (6, 2) by impedance ... 00:0" in err
    assert "solving mode (6, 2) by impedance: done in 2." in err


def test_pattern_names_its_stages_on_a_terminal(tmp_path, capsys, monkeypatch):
    argv = [
        "pattern", "--solve-for", "growth", "--outer-radius", "1.4", "--length", "1",
        "--voltage", "0.4", "--m-max", "3", "--n-max", "2", "--out", str(tmp_path), "--json",
    ]  # fmt: skip
    assert main(argv) == 0
    out, err = capsys.readouterr()
    assert err == "" and json.loads(out)["m"] == 0  # not a terminal: nothing
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert main([*argv, "--quiet"]) == 0
    assert capsys.readouterr().err == ""
    assert main(argv) == 0
    out, err = capsys.readouterr()
    rec = json.loads(out)  # stdout: still the one JSON object
    assert len(rec["files"]) == 3
    lines = err.splitlines()
    assert lines[0] == "electrogrowth: solving the critical mode (a scan of the modes) ..."
    assert "electrogrowth: mode shape of (0, 1) through the wall ..." in lines
    assert f"electrogrowth: 3D pattern and mode-shape plot into {tmp_path} ..." in lines
    assert len([line for line in lines if ": done in " in line]) == 3
    assert main([*argv[:-1], "--mode", "0", "1"]) == 0  # one mode, text output
    out, err = capsys.readouterr()
    assert err.startswith("electrogrowth: solving mode (0, 1) ...") and "mode (m, n)" in out
