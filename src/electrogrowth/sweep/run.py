"""Run a sweep: hand the tasks of a SweepConfig to a pool and store every result as it comes.

Where the tasks run (pool.py): one worker is in-process; several are a local process pool
(``concurrent.futures.ProcessPoolExecutor``, spawn start method); an address is an
existing ``dask.distributed`` cluster. Both run the same :func:`~.unit.compute_chunk`, and
only this process writes the store (store.py), so workers need no shared file system.
"""

from __future__ import annotations

import dataclasses
import sys
import time
from pathlib import Path

from ..errors import SweepError
from ..interrupts import signals_as_interrupts
from ..outcomes import Status
from ..pool import run_tasks, usable_cores
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
    verdicts: dict = dataclasses.field(default_factory=dict)  # SweepStore.verdicts()

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
        for key, head in (("first", "what comes first"), ("branch", "branch")):
            if self.verdicts.get(key):
                line += f"; {head}: " + ", ".join(
                    f"{v} {_plain(k)}" for k, v in self.verdicts[key].items()
                )
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
            workers = usable_cores()
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
        counts, verdicts = store.counts(), store.verdicts()
    return SweepSummary(
        Path(out),
        run,
        chunks,
        chunks - len(tasks),
        len(tasks),
        counts,
        time.perf_counter() - start,
        verdicts,
    )


def _plain(kind: str) -> str:
    """A verdict kind as the summary says it ("bifurcation": a smooth wrinkle)."""
    return {"bifurcation": "wrinkle", "crease": "crease", "none": "nothing found"}.get(kind, kind)


def _failed(point) -> bool:
    """A failure (an inaccurate point has a value: it is no failure)."""
    return point.status in (Status.FAILED, Status.ERROR)


def _first_failure(result: ChunkResult) -> str:
    return next(p.message for p in result.points if _failed(p))


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
    resume = "; the finished chunks are saved: run the same command again to resume"
    for _, result in run_tasks(
        compute_chunk, tasks, workers=workers, scheduler=scheduler, name="chunk",
        keys=[t.index for t in tasks], lost=resume,
    ):  # fmt: skip
        yield result
