"""Sweeps under faults: a scheduler's SIGTERM or a SIGKILL of the driver leaves no process
behind, a worker killed mid-chunk on a dask cluster loses and duplicates nothing, an
all-failed sweep exits non-zero, an unwritable store and a store in use are one clear error."""

import errno
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

pytest.importorskip("xarray")
pytest.importorskip("zarr")
psutil = pytest.importorskip("psutil")

from electrogrowth.cli import app as cli  # noqa: E402
from electrogrowth.cli import sweep as cli_sweep  # noqa: E402
from electrogrowth.errors import SweepError  # noqa: E402
from electrogrowth.sweep import store as sweep_store  # noqa: E402
from electrogrowth.sweep.file import parse_config  # noqa: E402
from electrogrowth.sweep.run import compute_sweep  # noqa: E402
from electrogrowth.sweep.store import open_results, open_store  # noqa: E402
from tests.sweep.test_run import LAUNCHER, SRC, TINY, assert_same_results  # noqa: E402


@pytest.fixture
def commands(monkeypatch):
    """cli.main with the sweep command registered (as in tests/sweep/test_run.py)."""
    monkeypatch.setitem(
        cli.COMMANDS, "sweep", ("sweep", cli_sweep.configure_sweep, cli_sweep.run_sweep)
    )
    return cli.main


def _launch(tmp_path, *extra):
    (tmp_path / "s.toml").write_text(TINY)
    (tmp_path / "launch.py").write_text(LAUNCHER)
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(filter(None, [str(SRC), os.environ.get("PYTHONPATH")])),
    }
    return subprocess.Popen(
        [sys.executable, "launch.py", "sweep", "s.toml", "--quiet", *extra],
        cwd=tmp_path,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )


def _wait_for_workers(proc, count, timeout=120):
    """The driver's descendants once ``count`` workers run (the resource tracker too)."""
    deadline = time.monotonic() + timeout
    while True:
        assert proc.poll() is None, proc.stderr.read().decode()
        kids = psutil.Process(proc.pid).children(recursive=True)
        if len(kids) >= count + 1:
            return kids
        assert time.monotonic() < deadline, f"only {len(kids)} child processes"
        time.sleep(0.05)


def _gone(procs, timeout=20):
    _, alive = psutil.wait_procs(procs, timeout=timeout)
    for p in alive:  # leave nothing behind even when the test fails
        p.kill()
    return [p.pid for p in alive]


@pytest.mark.parametrize(
    "sig", [signal.SIGTERM, pytest.param(signal.SIGKILL, marks=pytest.mark.slow)]
)
def test_killed_driver_leaves_no_process(tmp_path, sig):
    proc = _launch(tmp_path, "--workers", "2")
    kids = _wait_for_workers(proc, 2)
    time.sleep(1.0)  # the workers are importing or computing
    proc.send_signal(sig)
    code = proc.wait(timeout=60)
    err = proc.stderr.read().decode()
    proc.stderr.close()
    assert _gone(kids) == []
    if sig == signal.SIGTERM:
        assert code == 128 + signal.SIGTERM, err
        assert "terminated by signal 15" in err and "run the same command again" in err
        assert "Traceback" not in err


def test_all_failed_sweep_exits_nonzero_with_a_summary(tmp_path, commands, capsys):
    text = TINY.replace('for = "voltage"', 'for = "growth"')  # above every threshold:
    text = text.replace("length = 1.0", "length = 1.0\nvoltage = 50.0")
    (tmp_path / "f.toml").write_text(text)
    code = commands(
        [
            "sweep",
            str(tmp_path / "f.toml"),
            "--out",
            str(tmp_path / "f.zarr"),
            "--workers",
            "1",
            "--quiet",
        ]
    )
    out, err = capsys.readouterr()
    assert code == 2
    assert "9 failed" in out  # the summary
    assert err.count("\n") == 1 and "every computed point of the sweep failed (9)" in err


@pytest.mark.parametrize(
    "code, text",
    [(errno.ENOSPC, "No space left on device"), (errno.EROFS, "Read-only file system")],
)
def test_unwritable_store_is_one_clear_error(tmp_path, monkeypatch, commands, capsys, code, text):
    def refuse(self, result, run):
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(sweep_store.SweepStore, "write_chunk", refuse)
    (tmp_path / "s.toml").write_text(TINY.replace("stretch = [1.0, 1.2, 1.4]", "stretch = [1.0]"))
    status = commands(
        [
            "sweep",
            str(tmp_path / "s.toml"),
            "--out",
            str(tmp_path / "s.zarr"),
            "--workers",
            "1",
            "--quiet",
        ]
    )
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1
    assert f"cannot write the results to {tmp_path / 's.zarr'}: {text}" in err


def test_two_sweeps_on_one_store_are_refused(tmp_path):
    config = parse_config(TINY)
    out = tmp_path / "s.zarr"
    held = open_store(out, config)
    with held.locked():  # another sweep is writing it
        with pytest.raises(SweepError, match="being written by another running sweep"):
            compute_sweep(config, out, workers=1, progress=False)
    assert (open_results(out)["run"] == 0).all()  # nothing was written


@pytest.mark.slow
def test_dask_worker_killed_mid_chunk_loses_and_repeats_nothing(tmp_path, monkeypatch):
    distributed = pytest.importorskip("distributed")
    config = parse_config(TINY)
    compute_sweep(config, tmp_path / "ref.zarr", workers=1, progress=False)
    ref = open_results(tmp_path / "ref.zarr")
    written = []
    original = sweep_store.SweepStore.write_chunk

    def count(self, result, run):
        written.append(result.index)
        original(self, result, run)

    monkeypatch.setattr(sweep_store.SweepStore, "write_chunk", count)
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=None,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        box = {}
        run = threading.Thread(
            target=lambda: box.setdefault(
                "summary",
                compute_sweep(
                    config,
                    tmp_path / "k.zarr",
                    scheduler=cluster.scheduler_address,
                    progress=False,
                ),
            )
        )
        run.start()
        deadline = time.monotonic() + 120
        victim = None
        while victim is None:  # a worker with a chunk in progress for a while
            assert time.monotonic() < deadline and run.is_alive()
            busy = [w for w, keys in client.processing().items() if keys]
            if busy:
                time.sleep(0.3)
                busy = [w for w, keys in client.processing().items() if keys]
                if busy:
                    pids = client.run(os.getpid, workers=[busy[0]])
                    victim = pids[busy[0]]
            time.sleep(0.05)
        os.kill(victim, signal.SIGKILL)
        run.join(300)
    assert not run.is_alive() and "summary" in box
    assert sorted(written) == list(range(9))  # every chunk written exactly once
    ds = open_results(tmp_path / "k.zarr")
    assert (ds["run"] == 1).all()
    assert_same_results(ds, ref)
