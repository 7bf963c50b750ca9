"""Where independent tasks run: in this process, a local process pool, or a dask cluster.

One engine for every job made of independent pure calls (a sweep's chunks, a mode map's
grid scans and certificates). One worker runs the tasks here, in order; several are a
local ``concurrent.futures.ProcessPoolExecutor`` (spawn start method: each worker imports
the package once and loads the compiled kernels from numba's cache, with no scheduler and
without importing dask); an address is an existing ``dask.distributed`` cluster. Results
come back in completion order, each with its task's index, so the caller decides what
order to keep. An interrupt (or a consumer that stops reading) ends the workers at once.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time
import uuid
from collections.abc import Callable, Iterator, Sequence

from .errors import SweepError, UsageError

#: Local worker processes per usable core at most: each holds the numeric stack (~300 MB),
#: and more processes than cores only contend for them.
WORKERS_PER_CORE = 4


def usable_cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def check_workers(workers: int, option: str = "--workers") -> None:
    """Raise UsageError unless 1 <= workers <= WORKERS_PER_CORE x the usable cores."""
    most = WORKERS_PER_CORE * usable_cores()
    if isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= most:
        raise UsageError(
            f"{option} {workers} is out of range; need 1 to {most} ({WORKERS_PER_CORE} per"
            " usable core; a cluster: --scheduler)"
        )


def run_tasks(
    fn: Callable,
    tasks: Sequence,
    *,
    workers: int = 1,
    scheduler: str | None = None,
    name: str = "task",
    keys: Sequence | None = None,
    lost: str = "",
    processes=None,
) -> Iterator[tuple[int, object]]:
    """Yield ``(i, fn(tasks[i]))`` for every task, in completion order.

    ``fn`` must be a picklable module-level function of one argument when ``workers`` > 1
    or a ``scheduler`` is given. ``keys`` name the tasks on a cluster (default: their
    indices); ``lost`` is added to the one-line error when a worker dies (what was kept,
    how to go on). ``processes`` is a pool from :func:`local_processes` to run them on
    (``workers`` > 1), kept for the next call instead of started again.
    """
    if not tasks:
        return
    if scheduler is not None:
        yield from _on_dask(fn, tasks, scheduler, name, keys or range(len(tasks)), lost)
    elif workers <= 1:
        for i, task in enumerate(tasks):
            yield i, fn(task)
    else:
        yield from _on_process_pool(fn, tasks, workers, lost, processes)


def _start(workers: int):
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    return ProcessPoolExecutor(
        workers,
        mp_context=multiprocessing.get_context("spawn"),
        initializer=_exit_with_parent,
        initargs=(os.getpid(),),
    )


@contextlib.contextmanager
def local_processes(workers: int, scheduler: str | None = None):
    """A local process pool shared by the ``run_tasks`` calls of one job (its workers
    import the package once, not once a call): None for one worker or a cluster. An
    exception ends the workers at once."""
    if workers <= 1 or scheduler is not None:
        yield None
        return
    pool = _start(workers)
    try:
        yield pool
    except BaseException:
        _stop(pool)
        raise
    pool.shutdown()


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


def _on_process_pool(fn, tasks, workers, lost, shared=None):
    from concurrent.futures import as_completed
    from concurrent.futures.process import BrokenProcessPool

    pool = shared if shared is not None else _start(min(workers, len(tasks)))
    try:
        futures = {pool.submit(fn, task): i for i, task in enumerate(tasks)}
        for future in as_completed(futures):
            yield futures[future], future.result()
    except BrokenProcessPool:
        _stop(pool)
        raise SweepError(f"a worker process died (out of memory?){lost}") from None
    except BaseException:  # interrupted (or the consumer stopped): don't wait for workers
        _stop(pool)
        raise
    if shared is None:
        pool.shutdown()


def _stop(pool) -> None:
    """Cancel the queued tasks and end the running ones now."""
    if hasattr(pool, "terminate_workers"):  # Python >= 3.14
        pool.terminate_workers()
        return
    for process in list((getattr(pool, "_processes", None) or {}).values()):
        process.terminate()
    pool.shutdown(wait=False, cancel_futures=True)


def _on_dask(fn, tasks, address, name, keys, lost):
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
        names = [f"electrogrowth-{name}-{k}-{token}" for k in keys]
        futures = client.map(fn, tasks, pure=False, key=names)
        index = {f.key: i for i, f in enumerate(futures)}
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 - e.g. KilledWorker
                raise SweepError(
                    f"the cluster lost {name} {future.key}: {type(exc).__name__}: {exc}{lost}"
                ) from None
            future.release()
            yield index[future.key], result
    finally:
        client.close()
