"""Ctrl-C and SIGTERM: any command stops within seconds with exit 130 / 143 and one line on
stderr, keeps what it finished (a curve's points, a sweep's chunks), and an interrupt that
the compiled kernel wraps in a SystemError is never filed as a failed point."""

import csv
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation import curves
from electrogrowth.cli import app as cli
from electrogrowth.interrupts import Interrupted, interrupt_of, signals_as_interrupts
from electrogrowth.outcomes import Status
from electrogrowth.sweep import unit

#: Real signals to a child process, timed: run alone after the parallel tests (make test).
pytestmark = pytest.mark.serial

SRC = Path(__file__).resolve().parents[1] / "src"
#: Runs the command line, with a file "mark" written once the work is under way: after
#: each finished point of a curve, when a scan starts.
#: Both launchers first let SIGINT interrupt, as at a terminal: a process started from a
#: background job inherits SIGINT ignored, and the package respects an ignored SIGINT.
LAUNCHER = """\
import pathlib
import signal
import time
signal.signal(signal.SIGINT, signal.default_int_handler)
from electrogrowth.bifurcation import scan
from electrogrowth.cli import app, curve

def point_done(n):
    pathlib.Path("mark").write_text("point")
    time.sleep(0.05)  # 60 points last at least 3 s, however fast the machine

def marking(compute):
    def run(*args, **kwargs):
        if "progress" in kwargs:
            kwargs["progress"] = point_done
            return compute(*args, **kwargs)
        pathlib.Path("mark").write_text("scan")
        for _ in range(20):  # a scan lasts a fraction of a second: keep the signal inside one
            compute(*args, **kwargs)
        return compute(*args, **kwargs)
    return run

curve.critical_curve = marking(curve.critical_curve)
scan.scan_modes = marking(scan.scan_modes)  # `critical` reads it here when it runs
raise SystemExit(app.main())
"""
#: The sweep's launcher paces the chunks after the first (one second each) so that a fast
#: machine cannot finish the whole sweep between the first saved chunk and the signal.
SWEEP_LAUNCHER = """\
import signal
import time
signal.signal(signal.SIGINT, signal.default_int_handler)
from electrogrowth.cli import app
from electrogrowth.sweep import run

computed = []

def paced(task, *args, **kwargs):
    if computed:
        time.sleep(1.0)
    computed.append(task)
    return compute(task, *args, **kwargs)

compute, run.compute_chunk = run.compute_chunk, paced
raise SystemExit(app.main())
"""
STOPS_WITHIN = 10.0  # seconds from the signal to the exit (~1.5 s measured on a busy machine)


def _wrapped_interrupt() -> SystemError:
    """What numba raises when Ctrl-C arrives inside a compiled kernel."""
    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as stop:
            raise SystemError(
                "CPUDispatcher(...) returned a result with an exception set"
            ) from stop
    except SystemError as exc:
        return exc


def _interrupt(tmp_path, sig, *argv, ready=None, timeout=300, launcher=LAUNCHER):
    """Run the command, send ``sig`` once ``ready()`` (default: the launcher's mark exists);
    check the exit and return stderr."""
    ready = ready or (tmp_path / "mark").exists
    (tmp_path / "launch.py").write_text(launcher)
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(filter(None, [str(SRC), os.environ.get("PYTHONPATH")])),
    }
    # faulthandler: a crash of the child prints its stack instead of ending silently
    proc = subprocess.Popen(
        [sys.executable, "-X", "faulthandler", "launch.py", *argv],
        cwd=tmp_path,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    try:
        deadline = time.monotonic() + timeout
        while not ready():
            assert proc.poll() is None, proc.stderr.read().decode()
            assert time.monotonic() < deadline, f"not under way within {timeout} s"
            time.sleep(0.05)
        time.sleep(0.5)  # well inside the computation
        proc.send_signal(sig)
        sent = time.monotonic()
        code = proc.wait(timeout=60)
        took = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    err = proc.stderr.read().decode()
    proc.stderr.close()
    assert took < STOPS_WITHIN, f"{took:.1f} s after the signal"
    said = f"exit status {code}, stderr {err!r}"
    assert "Traceback" not in err and err.count("\n") == 1, said
    assert code == 128 + sig, said
    return err


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_interrupted_curve_writes_its_points(tmp_path, sig):
    err = _interrupt(
        tmp_path,
        sig,
        *"curve --solve-for growth --along voltage --from 0 --to 0.4 --points 60".split(),
        *"--outer-radius 1.4 --out out".split(),
    )
    partial = tmp_path / "out" / "curve_growth_vs_voltage.partial.csv"
    first = "interrupted" if sig == signal.SIGINT else "terminated by signal 15"
    assert err.startswith(f"electrogrowth: {first}; ")
    rows = list(csv.DictReader(partial.open()))
    assert f"{len(rows)} of 60 points written to {Path('out') / partial.name}" in err
    assert 1 <= len(rows) < 60
    assert all(r["kind"] == "bifurcation" and math.isfinite(float(r["growth_cr"])) for r in rows)
    assert not (tmp_path / "out" / "curve_growth_vs_voltage.csv").exists()


def test_interrupted_scan(tmp_path):
    err = _interrupt(
        tmp_path,
        signal.SIGINT,
        *"critical --solve-for growth --outer-radius 1.4 --voltage 0.4".split(),
    )
    assert err == "electrogrowth: interrupted\n"


def test_interrupted_sweep_keeps_its_chunks(tmp_path):
    pytest.importorskip("zarr")
    from electrogrowth.sweep.store import open_results
    from tests.sweep.test_run import TINY

    (tmp_path / "s.toml").write_text(TINY)
    marks = tmp_path / "s.zarr" / "run" / "c"  # the completion marks of the chunks
    err = _interrupt(
        tmp_path,
        signal.SIGINT,
        *"sweep s.toml --workers 1 --quiet".split(),
        ready=lambda: marks.exists() and any(p.is_file() for p in marks.rglob("*")),
        launcher=SWEEP_LAUNCHER,
    )
    assert "interrupted; the finished chunks are saved in s.zarr" in err
    done = int((open_results(tmp_path / "s.zarr")["run"] > 0).sum())
    assert 1 <= done < 9


# -- the same, in-process: a wrapped interrupt is no failed point, a bug no ordinary failure --


def test_a_wrapped_interrupt_is_recognised():
    assert isinstance(interrupt_of(_wrapped_interrupt()), Interrupted)
    assert interrupt_of(SystemError("another")) is None
    assert interrupt_of(ValueError("x")) is None
    stop = interrupt_of(Interrupted(signal.SIGTERM))
    assert (str(stop), stop.exit_status) == ("terminated by signal 15", 143)


def _scan_raising(exc):
    def scan(*args, **kwargs):
        raise exc

    return scan


def test_a_curve_point_lets_an_interrupt_through_and_records_a_bug(monkeypatch):
    params = Tube.uniform(1.4)
    monkeypatch.setattr(curves, "scan_modes", _scan_raising(_wrapped_interrupt()))
    with pytest.raises(Interrupted):
        curves.curve_point(params, "growth", "voltage", 0.1)
    monkeypatch.setattr(curves, "scan_modes", _scan_raising(ZeroDivisionError("oops")))
    pt = curves.curve_point(params, "growth", "voltage", 0.1)
    assert pt.status == Status.ERROR and pt.message.startswith("internal error: ZeroDivisionError")


def test_an_interrupted_curve_hands_back_its_points(monkeypatch):
    calls = []

    def scan(params, *args, **kwargs):
        if calls:
            raise _wrapped_interrupt()
        calls.append(params)
        return real(params, *args, **kwargs)

    real = curves.scan_modes
    monkeypatch.setattr(curves, "scan_modes", scan)
    with pytest.raises(Interrupted) as stop:
        curves.critical_curve(
            Tube.uniform(1.4), "growth", "voltage", [0.0, 0.1, 0.2], follow=False
        )
    assert stop.value.partial.x.tolist() == [0.0]
    assert stop.value.partial.kind.tolist() == ["bifurcation"]


def test_a_sweep_point_lets_an_interrupt_through(monkeypatch):
    monkeypatch.setattr(unit, "scan_modes", _scan_raising(_wrapped_interrupt()))
    with pytest.raises(Interrupted):
        unit.compute_point(Tube.uniform(1.4), unit.ScanSpec("growth"))
    monkeypatch.setattr(unit, "scan_modes", _scan_raising(ZeroDivisionError("oops")))
    assert unit.compute_point(Tube.uniform(1.4), unit.ScanSpec("growth")).status == Status.ERROR


def test_main_reports_a_wrapped_interrupt_in_one_line(monkeypatch, capsys):
    def run(args):
        raise _wrapped_interrupt()

    monkeypatch.setitem(cli.COMMANDS, "state", ("state", lambda parser: None, run))
    assert cli.main(["state"]) == 130
    assert capsys.readouterr().err == "electrogrowth: interrupted\n"


def test_sigterm_raises_an_interrupt_and_the_handlers_come_back():
    before = signal.getsignal(signal.SIGTERM)
    with pytest.raises(Interrupted) as stop, signals_as_interrupts():
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(5)  # the handler runs at once
    assert stop.value.signum == signal.SIGTERM
    assert signal.getsignal(signal.SIGTERM) is before


def test_ctrl_c_while_the_command_line_loads_is_one_line(monkeypatch, capsys):
    """The console script and `python -m electrogrowth` load the command line inside
    _console.main: a Ctrl-C during those imports (before cli.main handles signals) is one
    line and 130, not Python's traceback."""
    import types

    from electrogrowth import _console

    class Loading(types.ModuleType):
        def __getattr__(self, name):
            raise KeyboardInterrupt

    monkeypatch.setitem(sys.modules, "electrogrowth.cli", Loading("electrogrowth.cli"))
    assert _console.main() == 130
    assert capsys.readouterr().err == "electrogrowth: interrupted\n"


@pytest.fixture
def sigint_interrupts():
    """SIGINT interrupts, as at a terminal: a test run started as a background job inherits
    it ignored, and the package respects an ignored SIGINT."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)


def test_a_signal_in_a_finaliser_interrupts_the_code_after_it(capsys, sigint_interrupts):
    """A signal handled inside a __del__ (llvmlite's, while numba compiles: seen once in a
    fresh CI run) raises where Python can only print it; it is delivered again, so the
    block is interrupted all the same and nothing is printed."""
    import gc
    import signal as sig

    from electrogrowth.interrupts import Interrupted, signals_as_interrupts

    class Finalised:
        def __del__(self):
            sig.raise_signal(sig.SIGINT)

    with pytest.raises(Interrupted):
        with signals_as_interrupts():
            Finalised()  # dropped at once: the signal arrives inside __del__
            gc.collect()
            deadline = time.monotonic() + 5.0  # the code after it: the signal comes again
            while time.monotonic() < deadline:
                pass
            raise AssertionError("the interrupt was lost in the finaliser")
    assert "Exception ignored" not in capsys.readouterr().err


DESIGN = (
    "design --solve-for growth --outer-radius 1.4 --vary voltage 0 0.3 --points 3"
    " --target 0 1 --m-max 3 --n-max 3"
).split()


def test_an_interrupted_design_keeps_its_finished_scans(monkeypatch, tmp_path, capsys):
    """Probe 11b D3: Ctrl-C during `design` kept nothing (curve keeps its points). Stopped
    at its second full scan (the last point): the two finished points in a .partial.csv,
    named in the one line."""
    calls = []

    def scan(params, *args, **kwargs):
        if len(calls) == 1:
            raise _wrapped_interrupt()
        calls.append(params)
        return real(params, *args, **kwargs)

    real = curves.scan_modes
    monkeypatch.setattr(curves, "scan_modes", scan)
    assert cli.main([*DESIGN, "--out", str(tmp_path)]) == 130
    err = capsys.readouterr().err
    partial = tmp_path / "design_0_1_vs_voltage.partial.csv"
    rows = list(csv.DictReader(partial.open()))
    kept = f"2 of 3 points written to {partial} (switches not located)"
    again = "run the same command again to compute only the rest"
    assert err == f"electrogrowth: interrupted; {kept}; {again}\n"
    assert [float(r["voltage"]) for r in rows] == [0.0, 0.15]
    assert all(r["kind"] == "bifurcation" and float(r["growth_cr"]) > 1 for r in rows)
    calls.clear()
    assert cli.main(DESIGN) == 130  # without --out: nothing to write, and it says how
    assert "give --out DIR to keep the finished points" in capsys.readouterr().err


def test_a_design_interrupted_after_its_sequence_keeps_the_sequence(monkeypatch, tmp_path, capsys):
    """Stopped while choosing the design (margins, sensitivities): the mode sequence is
    whole, its CSV is written; a later complete run removes a stale .partial.csv."""
    import electrogrowth.design as design

    def prescribe(*args, **kwargs):
        raise Interrupted()

    (tmp_path / "design_0_1_vs_voltage.partial.csv").write_text("stale\n")
    real = design.prescribe
    monkeypatch.setattr(design, "prescribe", prescribe)
    assert cli.main([*DESIGN, "--out", str(tmp_path)]) == 130
    path = tmp_path / "design_0_1_vs_voltage.csv"
    assert f"the mode sequence written to {path} (no design chosen)" in capsys.readouterr().err
    assert len(list(csv.DictReader(path.open()))) >= 3  # the grid and the located switches
    monkeypatch.setattr(design, "prescribe", real)
    assert cli.main([*DESIGN, "--out", str(tmp_path)]) == 0
    assert not (tmp_path / "design_0_1_vs_voltage.partial.csv").exists()
