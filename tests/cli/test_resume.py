"""`curve` and `design` interrupted, then run again: the finished points are taken back
(cli/resume.py) and the result is the uninterrupted run's; a kept file of another run, or
one that is not such a file, is named in one warning line and every point is computed."""

import json

import pytest

from electrogrowth.cli import app as cli
from tests.interrupting import interrupt_scan_at

CURVE = (
    "curve --solve-for growth --along voltage --from 0 --to 0.5 --points 6 --outer-radius 1.4"
    " --m-max 4 --n-max 3 --json"
).split()
STEM = "curve_growth_vs_voltage"


def _run(args, capsys):
    rc = cli.main(args)
    out, err = capsys.readouterr()
    return rc, (json.loads(out) if rc == 0 else None), err


@pytest.fixture(scope="module")
def whole(tmp_path_factory):
    """The uninterrupted curve's CSV."""
    out = tmp_path_factory.mktemp("whole")
    assert cli.main([*CURVE, "--out", str(out)]) == 0
    return (out / f"{STEM}.csv").read_text()


def test_an_interrupted_curve_is_resumed(monkeypatch, tmp_path, capsys, whole):
    args = [*CURVE, "--out", str(tmp_path)]
    interrupt_scan_at(monkeypatch, 2)  # the grid's last point: its first five are finished
    rc, _, err = _run(args, capsys)
    assert rc == 130 and "run the same command again to compute only the rest" in err
    assert (tmp_path / f"{STEM}.partial.json").is_file()
    monkeypatch.undo()
    rc, record, err = _run(args, capsys)
    assert rc == 0 and record["resumed_points"] == 5
    assert (tmp_path / f"{STEM}.csv").read_text() == whole
    assert not list(tmp_path.glob("*.partial.*"))  # a complete run removes what was kept


def test_the_text_output_says_what_was_taken_back(monkeypatch, tmp_path, capsys):
    args = [a for a in CURVE if a != "--json"] + ["--out", str(tmp_path)]
    interrupt_scan_at(monkeypatch, 2)
    assert cli.main(args) == 130
    monkeypatch.undo()
    capsys.readouterr()
    assert cli.main(args) == 0
    err = capsys.readouterr().err
    assert "5 of 6 points taken back from an interrupted run of this command" in err


@pytest.mark.parametrize(
    "kept",
    [
        "not json",
        '{"format": "electrogrowth finished curve points", "run": 3}',
        "[1, 2]",
        "\xff\xfe",
    ],
)
def test_a_kept_file_that_is_no_such_file_is_named_and_ignored(tmp_path, capsys, kept, whole):
    path = tmp_path / f"{STEM}.partial.json"
    path.write_bytes(kept.encode("latin-1"))
    rc, record, err = _run([*CURVE, "--out", str(tmp_path)], capsys)
    assert rc == 0 and record["resumed_points"] == 0
    assert err.startswith(f"electrogrowth: warning: {path} not taken back (")
    assert err.count("\n") == 1
    assert (tmp_path / f"{STEM}.csv").read_text() == whole
    assert not path.exists()


def test_points_of_another_run_are_not_taken_back(monkeypatch, tmp_path, capsys):
    interrupt_scan_at(monkeypatch, 2)
    assert cli.main([*CURVE, "--out", str(tmp_path)]) == 130
    monkeypatch.undo()
    capsys.readouterr()
    changed = [a if a != "4" else "3" for a in CURVE]  # --m-max 3: another scan
    rc, record, err = _run([*changed, "--out", str(tmp_path)], capsys)
    assert rc == 0 and record["resumed_points"] == 0
    assert "not taken back (it is of another run: other arguments or another version)" in err


def test_a_points_record_that_is_tampered_with_is_refused(monkeypatch, tmp_path, capsys):
    interrupt_scan_at(monkeypatch, 2)
    assert cli.main([*CURVE, "--out", str(tmp_path)]) == 130
    monkeypatch.undo()
    capsys.readouterr()
    path = tmp_path / f"{STEM}.partial.json"
    kept = json.loads(path.read_text())
    kept["points"][1]["mode"] = "__import__('os')"
    path.write_text(json.dumps(kept))
    rc, record, err = _run([*CURVE, "--out", str(tmp_path)], capsys)
    assert rc == 0 and record["resumed_points"] == 0
    assert "is not two integers (m, n)" in err


DESIGN = (
    "design --solve-for growth --outer-radius 1.4 --vary voltage 0 0.3 --points 3"
    " --target 0 1 --m-max 3 --n-max 3 --json"
).split()


@pytest.mark.slow  # three designs: ~18 s (the resume itself is the curve's, tested above)
def test_an_interrupted_design_is_resumed(monkeypatch, tmp_path, capsys):
    args = [*DESIGN, "--out", str(tmp_path)]
    rc, whole, _ = _run(args, capsys)
    assert rc == 0
    interrupt_scan_at(monkeypatch, 2)
    assert cli.main(args) == 130
    assert "run the same command again" in capsys.readouterr().err
    monkeypatch.undo()
    rc, resumed, err = _run(args, capsys)
    assert rc == 0 and whole.pop("resumed_points") == 0 and resumed.pop("resumed_points") == 2
    assert resumed == whole
    assert "2 of 3 points taken back" not in err  # --json: nothing but warnings on stderr
    assert not list(tmp_path.glob("*.partial.*"))
