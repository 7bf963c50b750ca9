"""Progress of long commands on stderr: tqdm bars for counted work, one line per stage.

Shown only when stderr is a terminal and ``--quiet`` is not given, so a pipe, a log file and
the tests see nothing; stdout (the results, ``--json``) is never written to. The library's
functions stay silent unless asked (``progress=True`` or a callable).
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import threading
import time
from collections.abc import Iterator
from inspect import signature


def add_quiet_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--quiet",
        action="store_true",
        help="no progress report on stderr (it is shown only when stderr is a terminal)",
    )


def enabled(args) -> bool:
    """Report progress: stderr is a terminal and --quiet was not given (``args`` None: no)."""
    return args is not None and not getattr(args, "quiet", False) and sys.stderr.isatty()


def bar(args, total: int, desc: str, unit: str = "pt"):
    """A tqdm bar on stderr (remaining time estimated from the rate), or None when progress
    is not reported."""
    if not enabled(args):
        return None
    from tqdm import tqdm

    return tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, dynamic_ncols=True)


#: a step of unknown length shown only once it has taken this long (seconds)
LATE_NOTICE = 2.0


@contextlib.contextmanager
def stage(
    args, text: str, *, tick: bool = False, done: bool = True, delay: float = 0.0
) -> Iterator[None]:
    """``electrogrowth: <text> ...`` before a step and (``done``) its duration after it;
    ``tick``: the time elapsed so far, updated every second, for a step of unknown length
    that shows nothing else (a single collocation solve); with a ``delay``, neither is
    shown for a step done sooner (a single mode's march: mostly milliseconds)."""
    if not enabled(args):
        yield
        return
    t = time.perf_counter()
    if tick:
        with _ticking(f"electrogrowth: {text} ...", delay):
            yield
    else:
        print(f"electrogrowth: {text} ...", file=sys.stderr, flush=True)
        yield
    took = time.perf_counter() - t
    if done and took >= delay:
        print(f"electrogrowth: {text}: done in {took:.1f} s", file=sys.stderr)


@contextlib.contextmanager
def _ticking(text: str, delay: float = 0.0) -> Iterator[None]:
    """``text`` and the elapsed time, redrawn every second by a helper thread (shown from
    ``delay`` seconds on)."""
    from tqdm import tqdm

    line = tqdm(
        desc=text, bar_format="{desc} {elapsed}", file=sys.stderr, leave=False, delay=delay
    )
    done = threading.Event()

    def redraw():
        while not done.wait(1.0):
            line.refresh()

    thread = threading.Thread(target=redraw, daemon=True)
    thread.start()
    try:
        yield
    finally:
        done.set()
        thread.join()
        line.close()


def progress_options(fn, args) -> dict:
    """``{"progress": True}`` for a figure function that draws its curves' bars (a
    ``progress`` keyword) when progress is reported, else ``{}``."""
    return {"progress": True} if enabled(args) and "progress" in signature(fn).parameters else {}


def counting(mapper, args, desc: str):
    """``mapper`` (map-like) with a bar over the items of each call."""
    if not enabled(args):
        return mapper

    def mapped(fn, items):
        items = list(items)
        progress = bar(args, len(items), desc, "tube")
        try:
            for result in mapper(fn, items):
                progress.update(1)
                yield result
        finally:
            progress.close()

    return mapped
