"""An interrupted curve's finished grid points, kept for the same command run again.

``curve`` and a one-variable ``design`` write, on Ctrl-C or SIGTERM, the finished points
as a table (``<stem>.partial.csv``, for people) and as records (``<stem>.partial.json``,
for the next run: each point's scan whole, runners-up included, which the switches are
located from). Run again with the same arguments, the command takes those points back and
computes only the rest; a complete run removes both files.

The file is data, never code: JSON read by the standard library, at most MAX_BYTES, every
field of every point checked (bifurcation/curve_record.point_of). It is taken back only if
its ``run`` (the package's version, the tube, the control, its side, the abscissa, the grid
and the scan options) equals the new run's, so a changed command, or another version,
starts afresh. A file that cannot be used is named on stderr in one line, with why, and
the command computes every point (it is replaced by the next interrupt, removed by a
complete run).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from .. import __version__
from ..atomic import write_text
from ..bifurcation.curve_record import Curve, point_of, point_record
from ..bifurcation.curves import grid_curve
from .report import warn

FORMAT = "electrogrowth finished curve points"
#: A curve has at most MAX_POINTS points of well under 64 kB each (a traceback's text).
MAX_BYTES = 64 * 2**20


def resumable(out: Path, stem: str, what: tuple, total: int, args, **grid):
    """(earlier, records): the curve of the points an interrupted run of this command kept
    in ``out`` (None: none, or unusable, said on stderr), and (path, run) where this run
    keeps its own. ``what``: along, solve_for, side and tube; ``grid``: what else makes
    the run (the grid's values, the scan options)."""
    run = run_of(dict(zip(("along", "solve_for", "side", "tube"), what, strict=True), **grid))
    path = out / f"{stem}.partial.json"
    earlier = taken_back(path, run, what)
    say_taken_back(earlier, total, args)
    return earlier, (path, run)


def run_of(curve_args: dict) -> dict:
    """What makes two runs the same curve: the package's version and ``curve_args`` (the
    tube, the control solved for, its side, the abscissa, the grid, the scan options), each
    as its exact text (repr: floats with every digit; a tube's energies by their formulas)."""
    return {"version": __version__, **{k: repr(v) for k, v in curve_args.items()}}


def keep(records: tuple[Path, dict] | None, partial: Curve) -> str:
    """Write the finished grid points of an interrupted curve to ``records`` = (path, run)
    for :func:`taken_back`; the interrupt message's hint ("" with no records: no --out)."""
    if records is None:
        return ""
    points = [point_record(pt) for pt in partial.grid]
    write_text(records[0], json.dumps({"format": FORMAT, "run": records[1], "points": points}))
    return "; run the same command again to compute only the rest"


def say_taken_back(earlier: Curve | None, total: int, args) -> None:
    """One line on stderr (not with --quiet or --json) when finished points are taken back:
    in a log too, the run's shorter time says why."""
    if earlier is not None and not (args.quiet or args.json):
        print(
            f"electrogrowth: {len(earlier.grid)} of {total} points taken back from an"
            " interrupted run of this command",
            file=sys.stderr,
        )


def taken_back(path: Path, run: dict, what: tuple) -> Curve | None:
    """The curve of the points kept at ``path`` by an interrupted run of ``run`` (``what``:
    along, solve_for, side and tube of :func:`~..bifurcation.curves.grid_curve`); None, with
    one line on stderr where there is a file that cannot be used."""
    if not path.is_file():
        return None
    try:
        points = _points(path, run)
    except (OSError, UnicodeDecodeError, ValueError, RecursionError) as exc:
        warn(f"{path} not taken back ({exc}); computing every point")
        return None
    return grid_curve(*what, points)


def _points(path: Path, run: dict) -> list:
    if path.stat().st_size > MAX_BYTES:
        raise ValueError(f"larger than {MAX_BYTES // 2**20} MB")
    record = json.loads(path.read_text(encoding="utf-8"))
    if not isinstance(record, dict) or record.get("format") != FORMAT:
        raise ValueError("not a file of finished curve points")
    if record.get("run") != run:
        raise ValueError("it is of another run: other arguments or another version")
    points = record.get("points")
    if not isinstance(points, list):
        raise ValueError("its points are not a list")
    return [point_of(p) for p in points]


def discard(out: Path, stem: str) -> None:
    """Remove what an earlier interrupted run kept in ``out`` (this one is complete)."""
    for suffix in ("csv", "json"):
        (out / f"{stem}.partial.{suffix}").unlink(missing_ok=True)
