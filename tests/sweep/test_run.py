"""Parameter sweeps: the unit records failures, a dask cluster and a killed-and-resumed run
give the serial results, and a store of another sweep is left alone."""

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("xarray")
pytest.importorskip("zarr")

import electrogrowth  # noqa: E402
from electrogrowth import Tube  # noqa: E402
from electrogrowth.bifurcation.scan import ScanOptions  # noqa: E402
from electrogrowth.cli import app as cli  # noqa: E402
from electrogrowth.cli import sweep as cli_sweep  # noqa: E402
from electrogrowth.sweep.file import parse_config  # noqa: E402
from electrogrowth.sweep.run import compute_sweep  # noqa: E402
from electrogrowth.sweep.store import block_shape, grid_blocks, open_results  # noqa: E402
from electrogrowth.sweep.unit import ScanSpec, compute_point  # noqa: E402

TINY = """\
[solve]
for = "voltage"
rtol = 1e-10

[modes]
m = [0, 3]
n = [1, 3]
extend = false

[fixed]
length = 1.0

[grid]
stretch = [1.0, 1.2, 1.4]
outer_radius = [1.4, 1.5, 1.6]

[run]
chunk = 1
"""
COMPARED = (
    "critical_value",
    "m",
    "n",
    "kind",
    "error_estimate",
    "status",
    "message",
    "surface_instability",
    "runner_up_value",
    "runner_up_m",
    "runner_up_n",
)
SRC = Path(electrogrowth.__file__).resolve().parents[1]
LAUNCHER = """\
from electrogrowth.cli import app as cli
from electrogrowth.cli import sweep as cli_sweep
cli.COMMANDS["sweep"] = ("sweep", cli_sweep.configure_sweep, cli_sweep.run_sweep)
if __name__ == "__main__":
    raise SystemExit(cli.main())
"""
#: the launcher, crashing as soon as the driver has saved its first chunk: SIGKILL to its
#: process group (the driver and its pool's workers) from inside, so the crash falls between
#: chunks however loaded the machine is (killed from outside after seeing a chunk done, a slow
#: test process sometimes saw all nine done)
CRASHING = LAUNCHER.replace(
    "if __name__",
    """import os, signal
from electrogrowth.sweep.store import SweepStore
_write = SweepStore.write_chunk
def _write_then_crash(self, result, run):
    _write(self, result, run)
    os.killpg(os.getpgid(0), signal.SIGKILL)
SweepStore.write_chunk = _write_then_crash
if __name__""",
)


@pytest.fixture
def commands(monkeypatch):
    """cli.main with the two sweep commands registered (as the lead will in cli.py)."""
    monkeypatch.setitem(
        cli.COMMANDS, "sweep", ("sweep", cli_sweep.configure_sweep, cli_sweep.run_sweep)
    )
    monkeypatch.setitem(
        cli.COMMANDS, "plot", ("plot", cli_sweep.configure_plot, cli_sweep.run_plot)
    )
    return cli.main


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The tiny sweep run serially, in this process: (config, store path, dataset)."""
    config = parse_config(TINY)
    out = tmp_path_factory.mktemp("ref") / "ref.zarr"
    summary = compute_sweep(config, out, workers=1, progress=False, source_text=TINY)
    assert summary.chunks_computed == summary.chunks == 9
    return config, out, open_results(out)


def assert_same_results(ds, ref):
    for name in COMPARED:
        a, b = ds[name].values, ref[name].values
        if a.dtype.kind == "f":
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=0, equal_nan=True, err_msg=name)
        else:
            assert (a == b).all(), name


def test_reference_sweep_is_labelled_and_matches_single_scans(reference):
    config, out, ds = reference
    assert ds["critical_value"].dims == ("stretch", "outer_radius")
    assert list(ds["stretch"].values) == [1.0, 1.2, 1.4] and float(ds["length"]) == 1.0
    assert (ds["status"] == "ok").all() and (ds["kind"] == "bifurcation").all()
    assert (ds["run"] == 1).all() and ds["runner_up_value"].shape == (3, 3, 4)
    assert json.loads(ds.attrs["sweep_config"]) == config.to_dict()
    one = compute_point(Tube.uniform(1.6, 1.0, stretch=1.2), config.spec)
    assert ds["critical_value"].sel(stretch=1.2, outer_radius=1.6) == one.value
    assert (ds["critical_value"] > ds["runner_up_value"].isel(rank=0)).sum() == 0


def test_failing_point_is_recorded_and_the_rest_computed(tmp_path):
    text = TINY.replace("stretch = [1.0, 1.2, 1.4]", "stretch = [0.6, 1.0]")
    text = text.replace("outer_radius = [1.4, 1.5, 1.6]", "outer_radius = [1.4]")
    summary = compute_sweep(parse_config(text), tmp_path / "f.zarr", workers=1, progress=False)
    ds = open_results(tmp_path / "f.zarr")
    bad, good = ds.sel(stretch=0.6, outer_radius=1.4), ds.sel(stretch=1.0, outer_radius=1.4)
    assert str(bad["status"].values) == "failed" and int(bad["m"]) == -1
    assert "already unstable" in str(bad["message"].values)
    assert np.isnan(bad["critical_value"]) and int(bad["run"]) == 1  # done, not retried
    assert str(good["status"].values) == "ok" and good["critical_value"] > 0
    assert summary.counts["failed"] == 1 and summary.counts["bifurcation"] == 1


def test_unit_turns_every_exception_into_a_record(monkeypatch):
    spec = ScanSpec("growth", options=ScanOptions((0, 1), (1, 1)))
    rec = compute_point(Tube.uniform(1.4, voltage=5.0), spec)
    assert rec.status == "failed" and rec.message.startswith("BaseStateError: Vbar = 5")
    import electrogrowth.sweep.unit as sweep

    def boom(*args, **kwargs):
        raise ZeroDivisionError("a bug")

    monkeypatch.setattr(sweep, "scan_modes", boom)
    rec = compute_point(Tube.uniform(1.4), spec)
    assert rec.status == "error" and rec.message == "internal error: ZeroDivisionError: a bug"


def test_dask_cluster_gives_the_serial_results(reference, tmp_path):
    distributed = pytest.importorskip("distributed")
    config, _, ref = reference
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
    ) as cluster:
        summary = compute_sweep(
            config, tmp_path / "d.zarr", scheduler=cluster.scheduler_address, progress=False
        )
    assert summary.chunks_computed == 9
    assert_same_results(open_results(tmp_path / "d.zarr"), ref)


def test_killed_sweep_resumes_without_recomputing(reference, tmp_path, commands):
    _, _, ref = reference
    (tmp_path / "s.toml").write_text(TINY)
    (tmp_path / "launch.py").write_text(CRASHING)
    out = tmp_path / "s.zarr"
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(filter(None, [str(SRC), os.environ.get("PYTHONPATH")])),
    }
    proc = subprocess.Popen(
        [sys.executable, "launch.py", "sweep", "s.toml", "--workers", "2", "--quiet"],
        cwd=tmp_path,
        env=env,
        start_new_session=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    try:
        _, err = proc.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        raise
    assert proc.returncode == -signal.SIGKILL, err.decode()
    before = open_results(out)["run"].values
    done = int((before > 0).sum())
    assert done == 1  # the crash came after the first chunk was saved

    assert (
        commands(
            ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--workers", "1", "--quiet"]
        )
        == 0
    )
    after = open_results(out)
    run = after["run"].values
    assert (run[before > 0] == 1).all()  # finished before the kill: not recomputed
    assert (run[before == 0] == 2).all()  # the rest: computed once, by the resume
    assert_same_results(after, ref)  # ref: the same sweep, uninterrupted


def test_resume_with_another_config_is_refused(reference, tmp_path, commands, capsys):
    _, out, _ = reference
    stamp = sorted((p, p.stat().st_mtime_ns) for p in out.rglob("*"))
    other = tmp_path / "other.toml"
    other.write_text(
        TINY.replace("rtol = 1e-10", "rtol = 1e-11").replace("[1.0, 1.2, 1.4]", "[1.0, 1.3]")
    )
    assert commands(["sweep", str(other), "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "holds a different sweep" in err
    assert "solve.rtol" in err and "grid.stretch" in err
    assert sorted((p, p.stat().st_mtime_ns) for p in out.rglob("*")) == stamp


def test_rerun_of_a_finished_sweep_computes_nothing(reference, commands, capsys, tmp_path):
    _, out, _ = reference
    path = tmp_path / "same.toml"
    path.write_text("# the same sweep, reformatted\n" + TINY.replace("for =", "for  ="))
    assert commands(["sweep", str(path), "--out", str(out), "--check"]) == 0
    assert "same sweep: resumes" in capsys.readouterr().out
    assert commands(["sweep", str(path), "--out", str(out), "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert "computed 0 of 9 chunks" in printed and "(9 done before)" in printed


@pytest.mark.parametrize(
    "shape, points, block, count",
    [
        ((3, 2), 1, (1, 1), 6),
        ((3, 2), 4, (2, 2), 2),
        ((5,), 2, (2,), 3),
        ((4, 3, 2), 7, (1, 3, 2), 4),
        ((2, 2), 100, (2, 2), 1),
    ],
)
def test_blocks_tile_the_grid(shape, points, block, count):
    assert block_shape(shape, points) == block
    blocks = grid_blocks(shape, block)
    cover = np.zeros(shape, int)
    for b in blocks:
        cover[b] += 1
    assert len(blocks) == count and (cover == 1).all()


def test_inaccurate_point_is_stored_as_inaccurate(tmp_path, monkeypatch):
    """A critical value not certified to rtol (status INACCURATE from critical_value, here
    injected at Rbar_o = 1.4) is stored with status "inaccurate", its value, mode and a
    message; it is counted apart, and is no failure."""
    import dataclasses

    from electrogrowth.bifurcation import grid_scan
    from electrogrowth.outcomes import Status

    real = grid_scan.critical_value

    def flagged(params, *args, **kwargs):
        c = real(params, *args, **kwargs)
        return (
            dataclasses.replace(c, status=Status.INACCURATE) if params.outer_radius == 1.4 else c
        )

    monkeypatch.setattr(grid_scan, "critical_value", flagged)
    text = TINY.replace("stretch = [1.0, 1.2, 1.4]", "stretch = [1.0]")
    text = text.replace("outer_radius = [1.4, 1.5, 1.6]", "outer_radius = [1.4, 1.5]")
    summary = compute_sweep(parse_config(text), tmp_path / "i.zarr", workers=1, progress=False)
    ds = open_results(tmp_path / "i.zarr")
    bad, good = ds.sel(stretch=1.0, outer_radius=1.4), ds.sel(stretch=1.0, outer_radius=1.5)
    assert str(bad["status"].values) == "inaccurate" and str(bad["kind"].values) == "bifurcation"
    assert np.isfinite(bad["critical_value"]) and int(bad["m"]) >= 0
    assert str(bad["message"].values).startswith("inaccurate: error estimate")
    assert str(good["status"].values) == "ok" and str(good["message"].values) == ""
    assert summary.counts["inaccurate"] == 1 and summary.counts["bifurcation"] == 1
    assert summary.counts["failed"] == 0 and "1 inaccurate" in summary.text()


def test_compute_sweep_is_silent_by_default(tmp_path, capfd):
    """The Python API prints nothing unless asked (progress=True shows the bar)."""
    text = TINY.replace("stretch = [1.0, 1.2, 1.4]", "stretch = [1.0]")
    text = text.replace("outer_radius = [1.4, 1.5, 1.6]", "outer_radius = [1.4]")
    compute_sweep(parse_config(text), tmp_path / "quiet.zarr", workers=1)
    assert capfd.readouterr() == ("", "")
    compute_sweep(parse_config(text), tmp_path / "loud.zarr", workers=1, progress=True)
    assert "sweep" in capfd.readouterr().err


def test_sweep_command_bars_only_on_a_terminal(tmp_path, capfd, commands, monkeypatch):
    text = TINY.replace("stretch = [1.0, 1.2, 1.4]", "stretch = [1.0]")
    (tmp_path / "s.toml").write_text(
        text.replace("outer_radius = [1.4, 1.5, 1.6]", "outer_radius = [1.4]")
    )
    argv = ["sweep", str(tmp_path / "s.toml"), "--workers", "1", "--out"]
    assert commands([*argv, str(tmp_path / "a.zarr")]) == 0
    assert capfd.readouterr().err == ""  # not a terminal: no bar
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert commands([*argv, str(tmp_path / "b.zarr"), "--quiet"]) == 0
    assert capfd.readouterr().err == ""
    assert commands([*argv, str(tmp_path / "c.zarr")]) == 0
    out, err = capfd.readouterr()
    assert "sweep" in err and "1 points (1 bifurcation)" in out
