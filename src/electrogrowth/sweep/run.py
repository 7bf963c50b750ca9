"""Run a sweep: hand the tasks of a SweepConfig to a pool and store every result as it comes.

Where the tasks run: one worker is in-process; several are a local process pool
(``concurrent.futures.ProcessPoolExecutor``, spawn start method); an address is an
existing ``dask.distributed`` cluster. The local pool is the standard library and starts
in the time the workers take to import the package (the compiled kernel comes from
numba's cache), with no scheduler, nanny or dashboard, and without importing dask at all;
dask is used only for a real cluster. Both run the same :func:`~.unit.compute_chunk`, and
only this process writes the store (store.py), so workers need no shared file system.
"""

from __future__ import annotations

import contextlib
import dataclasses
import os
import signal
import sys
import threading
import time
import uuid
from pathlib import Path

from ..errors import SweepError, UsageError
from ..interrupts import signals_as_interrupts
from ..outcomes import Status
from .unit import ChunkResult, ChunkTask, compute_chunk


@dataclasses.dataclass(frozen=True)
class SweepSummary:
    """What :func:`compute_sweep` did: chunk counts of this run, point counts of the store."""

    out: Path
    run: int
    chunks: int
    chunks_before: int
    chunks_computed: int
    counts: dict
    seconds: float

    def text(self) -> str:
        c = self.counts
        pts = sum(c.values())
        done = ", ".join(f"{v} {k}" for k, v in c.items() if v and k != "pending")
        line = (
            f"{self.out}: {pts} points ({done or 'none computed'}); computed"
            f" {self.chunks_computed} of {self.chunks} chunks in {self.seconds:.1f} s"
        )
        if self.chunks_before:
            line += f" ({self.chunks_before} done before)"
        if c.get("error"):
            line += (
                f"; {c['error']} points hit an internal error (a bug, see their"
                " message: please report it)"
            )
        return line


def compute_sweep(
    config,
    out: str | Path,
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: bool = False,
    source_text: str = "",
) -> SweepSummary:
    """Run the sweep ``config`` (a :class:`sweep_config.SweepConfig`) into the store ``out``.

    Parameters
    ----------
    config : SweepConfig
        The validated sweep.
    out : path
        The Zarr store. Created if missing; if it holds the same sweep only the chunks
        without a completion mark are computed (resume); another sweep there is refused.
    workers : int, optional
        Local worker processes (default: the usable cores); 1 runs in this process.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:8786``); ``workers`` is then
        ignored.
    progress : bool
        A tqdm progress bar (points done, rate, ETA) on stderr; off by default (the library
        prints nothing unless asked; the command shows it on a terminal).
    source_text : str
        The sweep file as written, kept in the store's attributes.

    Raises
    ------
    SweepError
        Another sweep in ``out``, the store in use, or the workers lost.
    """
    from .store import open_store  # xarray and zarr: the sweep extra, imported only here

    start = time.perf_counter()
    store = open_store(out, config, source_text=source_text)
    with store.locked(), signals_as_interrupts():  # SIGTERM too stops the workers
        pending = store.pending_chunks()
        chunks = len(store.blocks)
        run = store.next_run()
        if workers is None:
            workers = _usable_cores()
        material = config.build_material()
        tasks = [
            ChunkTask(
                i,
                tuple((s.start, s.stop) for s in store.blocks[i]),
                tuple(config.points(store.blocks[i], material)),
                config.spec,
            )
            for i in pending
        ]
        bar = _progress_bar(config.size, config.size - sum(len(t.params) for t in tasks), progress)
        results = _results(tasks, workers, scheduler)
        try:
            for result in results:
                try:
                    store.write_chunk(result, run)
                except OSError as exc:  # full disk, read-only store, lost mount
                    raise SweepError(
                        f"cannot write the results to {out}:"
                        f" {exc.strerror or exc}; the chunks finished before are saved:"
                        " free space or fix the permissions and run the same command again"
                    ) from None
                bar.update(len(result.points))
                if any(_failed(p) for p in result.points):
                    bar.set_postfix_str(
                        f"last failure: {_first_failure(result)}"[:60], refresh=False
                    )
        finally:
            results.close()  # stops the workers now if we are interrupted
            bar.close()
        counts = store.counts()
    return SweepSummary(
        Path(out),
        run,
        chunks,
        chunks - len(tasks),
        len(tasks),
        counts,
        time.perf_counter() - start,
    )


def _exit_with_parent(parent: int) -> None:
    """Worker initializer: end this worker when the driver ends, even by SIGKILL (no
    orphan keeps computing, nor keeps the resource tracker alive): the kernel's
    parent-death signal on Linux, and a watcher thread everywhere."""
    with contextlib.suppress(OSError, AttributeError, TypeError):
        import ctypes

        pr_set_pdeathsig = 1
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(pr_set_pdeathsig, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:  # the driver died before the signal was set
        os._exit(1)

    def watch():
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, name="exit-with-parent", daemon=True).start()


def _failed(point) -> bool:
    """A failure (an inaccurate point has a value: it is no failure)."""
    return point.status in (Status.FAILED, Status.ERROR)


def _first_failure(result: ChunkResult) -> str:
    return next(p.message for p in result.points if _failed(p))


#: Local worker processes per usable core at most: each holds the numeric stack (~300 MB),
#: and more processes than cores only contend for them.
WORKERS_PER_CORE = 4


def check_workers(workers: int, option: str = "--workers") -> None:
    """Raise UsageError unless 1 <= workers <= WORKERS_PER_CORE x the usable cores."""
    most = WORKERS_PER_CORE * _usable_cores()
    if not 1 <= workers <= most:
        raise UsageError(
            f"{option} {workers} is out of range; need 1 to {most} ({WORKERS_PER_CORE} per"
            " usable core; a cluster: --scheduler)"
        )


def _usable_cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _progress_bar(total: int, initial: int, enabled: bool):
    from tqdm.auto import tqdm  # a widget in a notebook, text on a terminal

    return tqdm(
        total=total,
        initial=initial,
        unit="pt",
        desc="sweep",
        file=sys.stderr,
        disable=not enabled,
        dynamic_ncols=True,
        smoothing=0.1,
        mininterval=0.2 if sys.stderr.isatty() else 5.0,
    )


def _results(tasks: list[ChunkTask], workers: int, scheduler: str | None):
    """Yield a ChunkResult per task, in completion order."""
    if not tasks:
        return
    if scheduler is not None:
        yield from _on_dask(tasks, scheduler)
    elif workers <= 1:
        for task in tasks:
            yield compute_chunk(task)
    else:
        yield from _on_process_pool(tasks, workers)


def _on_process_pool(tasks, workers):
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    workers = min(workers, len(tasks))
    pool = ProcessPoolExecutor(
        workers,
        mp_context=multiprocessing.get_context("spawn"),
        initializer=_exit_with_parent,
        initargs=(os.getpid(),),
    )
    try:
        futures = [pool.submit(compute_chunk, task) for task in tasks]
        for future in as_completed(futures):
            yield future.result()
    except BrokenProcessPool:
        _stop(pool)
        raise SweepError(
            "a worker process died (out of memory?); the finished chunks are"
            " saved: run the same command again to resume"
        ) from None
    except BaseException:  # interrupted (or the consumer stopped): don't wait for workers
        _stop(pool)
        raise
    pool.shutdown()


def _stop(pool) -> None:
    """Cancel the queued tasks and end the running ones now."""
    if hasattr(pool, "terminate_workers"):  # Python >= 3.14
        pool.terminate_workers()
        return
    for process in list((getattr(pool, "_processes", None) or {}).values()):
        process.terminate()
    pool.shutdown(wait=False, cancel_futures=True)


def _on_dask(tasks, address):
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise SweepError(
            "--scheduler needs dask.distributed: pip install 'electrogrowth[sweep]'"
        ) from None
    try:
        client = Client(address, timeout="20s")
    except (OSError, TimeoutError) as exc:
        raise SweepError(f"cannot reach the dask scheduler at {address}: {exc}") from None
    token = uuid.uuid4().hex[:8]
    try:
        futures = client.map(
            compute_chunk,
            tasks,
            pure=False,
            key=[f"electrogrowth-chunk-{t.index}-{token}" for t in tasks],
        )
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 - e.g. KilledWorker
                raise SweepError(
                    f"the cluster lost chunk {future.key}: {type(exc).__name__}:"
                    f" {exc}; the finished chunks are saved: run the same"
                    " command again to resume"
                ) from None
            future.release()
            yield result
    finally:
        client.close()
