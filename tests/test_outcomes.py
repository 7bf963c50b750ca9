"""One outcome record: critical points, surface limits, curve points and sweep points share
kind, status, value, error estimate, message and remedy (outcomes.Outcome); a bug is never
filed as the user's failure; a remedy speaks flags to the command line and keyword
arguments to Python."""

import math
import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest

from electrogrowth import Tube, critical_value
from electrogrowth.bifurcation import curves
from electrogrowth.bifurcation.critical import no_bifurcation_remedy
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.errors import (
    BaseStateError,
    ConvergenceError,
    ElectrogrowthError,
    FailedPoint,
    InternalError,
    Remedy,
)
from electrogrowth.outcomes import BUG_REMEDY, Kind, Outcome, Status
from electrogrowth.sweep import unit

SRC = Path(__file__).resolve().parents[1] / "src"
SPEC = unit.ScanSpec("growth", options=ScanOptions((0, 1), (1, 1)))


def _raising(exc):
    def scan(*args, **kwargs):
        raise exc

    return scan


def _a_bug():
    return 1 / 0


def _buggy_scan(*args, **kwargs):
    _a_bug()


@pytest.fixture(scope="module")
def computed():
    """One computed record of each kind (a tube of the paper, a cheap mode range)."""
    params = Tube.uniform(voltage=0.2)
    return {
        "critical point": critical_value(params, 1, 1, "growth"),
        "surface limit": short_wave_limit(params, "growth"),
        "curve point": curves.curve_point(
            params, "growth", "voltage", 0.2, options=ScanOptions((0, 1), (1, 1))
        ),
        "sweep point": unit.compute_point(params, SPEC),
    }


def test_the_four_results_share_one_outcome(computed):
    for name, rec in computed.items():
        assert isinstance(rec, Outcome), name
        assert rec.status is Status.OK and rec.ok and rec.unwrap() is rec, name
        d = rec.outcome_dict()
        assert tuple(d) == Outcome.OUTCOME_KEYS, name
        assert d["status"] == "ok" and d["message"] == "" and d["remedy"] == "", name
        assert d["kind"] in (Kind.BIFURCATION, Kind.SURFACE) and d["value"] > 1.0, name
        assert type(d["kind"]) is str and type(d["status"]) is str, name
    # the same critical growth, whichever record carries it
    scanned = computed["curve point"]
    assert scanned.value == computed["sweep point"].value
    assert math.isfinite(scanned.error_estimate)


def test_an_inaccurate_critical_point_says_why_and_what_to_try(monkeypatch):
    from electrogrowth.bifurcation import critical
    from electrogrowth.incremental import accuracy

    monkeypatch.setattr(accuracy, "CERTIFIED", 0.0)  # no estimate is good enough
    monkeypatch.setattr(critical, "REFINE", 1e9)  # and no refinement is tried
    cp = critical_value(Tube.uniform(voltage=0.2), 1, 1, "growth")
    assert cp.status is Status.INACCURATE and cp.ok and cp.unwrap() is cp
    assert cp.message.startswith("error estimate") and "rtol = 1e-12" in cp.message
    assert cp.remedy == ConvergenceError.remedy
    assert "rtol=" in cp.outcome_dict()["remedy"]
    assert "status" in cp.as_dict() and "message" not in cp.as_dict()  # JSON unchanged


def test_a_user_failure_is_failed_with_its_remedy_in_every_record(monkeypatch):
    exc = BaseStateError("Vbar = 5 is above the threshold")
    monkeypatch.setattr(unit, "scan_modes", _raising(exc))
    monkeypatch.setattr(curves, "scan_modes", _raising(exc))
    sweep_pt = unit.compute_point(Tube.uniform(1.4), SPEC)
    curve_pt = curves.curve_point(Tube.uniform(1.4), "growth", "voltage", 5.0)
    for rec in (sweep_pt, curve_pt):
        assert rec.status is Status.FAILED and not rec.ok and rec.kind == ""
        assert "above the threshold" in rec.message and rec.traceback == ""
        assert rec.remedy == BaseStateError.remedy
        with pytest.raises(FailedPoint, match="above the threshold") as raised:
            rec.unwrap()
        assert isinstance(raised.value, ElectrogrowthError)
        assert raised.value.remedy == BaseStateError.remedy
        assert math.isnan(rec.outcome_dict()["value"] or math.nan)
    # the curve's table keeps its columns: the status in the kind column, the message
    row = curves._row(curve_pt)
    assert row[3] == "failed" and row[4] == "Vbar = 5 is above the threshold"


def test_a_bug_is_an_internal_error_with_its_traceback_not_the_users_failure(monkeypatch):
    monkeypatch.setattr(unit, "scan_modes", _buggy_scan)
    monkeypatch.setattr(curves, "scan_modes", _buggy_scan)
    sweep_pt = unit.compute_point(Tube.uniform(1.4), SPEC)
    curve_pt = curves.curve_point(Tube.uniform(1.4), "growth", "voltage", 0.1)
    for rec in (sweep_pt, curve_pt):
        assert rec.status is Status.ERROR and rec.status is not Status.FAILED
        assert rec.message.startswith("internal error: ZeroDivisionError")
        assert rec.remedy == BUG_REMEDY  # report it; nothing about the input
        assert "_a_bug" in rec.traceback and "ZeroDivisionError" in rec.traceback
        with pytest.raises(InternalError, match="_a_bug") as raised:
            rec.unwrap()
        assert not isinstance(raised.value, ElectrogrowthError)
    assert pickle.loads(pickle.dumps(sweep_pt)).traceback == sweep_pt.traceback  # a worker's
    row = curves._row(curve_pt)
    assert row[3] == "error" and row[4].endswith(f"({BUG_REMEDY})")


def test_a_failing_scan_runs_once_when_following_a_curve(monkeypatch):
    calls = []

    def scan(*args, **kwargs):
        calls.append(args)
        raise ConvergenceError("no convergence")

    monkeypatch.setattr(curves, "scan_modes", scan)
    curve = curves.critical_curve(Tube.uniform(1.4), "growth", "voltage", [0.0, 0.1, 0.2])
    assert list(curve.kind) == ["failed"] * 3 and list(curve.status) == ["no convergence"] * 3
    assert len(calls) == 3  # once a point (it used to scan a failing point twice)


def test_a_bug_while_locating_a_switch_is_named_as_a_bug():
    def between(a, b, depth):
        _a_bug()

    loc = type("Locator", (), {"between": staticmethod(between)})()
    pts = [
        curves.CurvePoint(0.0, 1.5, (1, 1), Kind.BIFURCATION),
        curves.CurvePoint(1.0, 1.4, (0, 1), Kind.BIFURCATION, "inaccurate"),
    ]
    rows, switches = curves._located(pts, loc)
    assert switches == [] and [r[3] for r in rows] == ["bifurcation"] * 2
    note = rows[1][4]
    assert note.startswith("inaccurate; switch from (1, 1) not located: internal error:")
    assert note.endswith(f"({BUG_REMEDY})")


def test_a_remedy_has_a_python_and_a_command_line_form():
    r = ConvergenceError.remedy
    assert isinstance(r, Remedy) and r == r.cli and "--rtol" in r.cli
    assert "rtol=" in r.python and "--" not in r.python
    assert pickle.loads(pickle.dumps(r)).python == r.python
    for solve_for, mode in (("stretch", None), ("growth", (1, 1)), ("stretch", (1, 1))):
        advice = no_bifurcation_remedy(solve_for, mode=mode)
        assert "--" in advice.cli and "--" not in advice.python, advice.python
    plain = Remedy("pip install it")
    assert plain.python == plain.cli == "pip install it"


def test_python_shows_the_python_remedy_and_str_stays_the_message():
    exc = ConvergenceError("no root")
    assert str(exc) == "no root"
    assert exc.__notes__ == ["remedy: " + ConvergenceError.remedy.python]
    exc.add_note("more")  # notes added by others (pytest, hypothesis) are kept
    assert exc.__notes__ == ["more", "remedy: " + ConvergenceError.remedy.python]
    exc.remedy = "a remedy of this instance"
    assert exc.__notes__ == ["more", "remedy: a remedy of this instance"]
    code = "from electrogrowth.errors import ConvergenceError\nraise ConvergenceError('no root')"
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    err = run.stderr
    assert err.splitlines()[-2:] == [
        "electrogrowth.errors.ConvergenceError: no root",
        "remedy: " + ConvergenceError.remedy.python,
    ]


def test_the_command_line_prints_the_flag_form(monkeypatch, capsys):
    from electrogrowth.cli import app

    def run(args):
        raise ConvergenceError("no root")

    monkeypatch.setattr(app, "build_parser", lambda command: _Parser(run))
    assert app.main(["critical"]) == 2
    err = capsys.readouterr().err
    assert err == f"electrogrowth: error: no root ({ConvergenceError.remedy.cli})\n"
    assert "rtol=" not in err


class _Parser:
    def __init__(self, run):
        self.run = run

    def parse_args(self, argv):
        return type("Args", (), {"run": staticmethod(self.run)})()
