"""The records of the gallery (figures/gallery.py): a tube to solve (:class:`Job`), the
unit of work (:func:`solve`: one pure, picklable function of the tube, the control and the
mode), the drivers that run the jobs through any ``map``-like function, the onset of a tube
(:class:`Onset`, a row of the CSV), the result (:class:`GalleryFigure`) and the onset plot.

The CSV (``<name>.csv``) has the columns :data:`COLUMNS`: the case, the parameter varied and
its value x, the control solved for, the critical value, the mode (m, n) ((-1, -1) when there
is none), its family, the kind (bifurcation, threshold, surface, none) and, for none, the
reason.
"""

from __future__ import annotations

import csv
import dataclasses
import functools
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from ..atomic import replaced
from ..bifurcation.critical import CriticalPoint, critical_value
from ..bifurcation.scan import ScanOptions, scan_modes
from ..errors import BaseStateError, ConvergenceError, NoBifurcationFound
from ..model.layers import Tube
from .style import FigureResult

COLUMNS = ("case", "parameter", "x", "control", "value", "m", "n", "family", "kind", "note")
#: Mode ranges of every scan: widened while the optimum is on an upper edge.
FULL = ScanOptions(m_range=(0, 16), n_range=(1, 16), top=3)
QUICK = ScanOptions(m_range=(0, 12), n_range=(1, 4), top=1, extend=False)


@dataclasses.dataclass(frozen=True)
class Onset:
    """The onset of one tube: ``critical`` is None when no mode bifurcates (``note`` says
    why: the scan's message)."""

    case: str
    parameter: str
    x: float
    control: str
    critical: CriticalPoint | None
    note: str = ""

    @property
    def value(self) -> float:
        return math.nan if self.critical is None else self.critical.value

    @property
    def mode(self) -> tuple[int, int]:
        c = self.critical
        return (-1, -1) if c is None or c.kind != "bifurcation" else (c.m, c.n)

    def row(self) -> tuple:
        c = self.critical
        m, n = self.mode
        family = "" if c is None or c.family is None else str(c.family)
        kind = "none" if c is None else str(c.kind)
        return (
            self.case,
            self.parameter,
            self.x,
            self.control,
            self.value,
            m,
            n,
            family,
            kind,
            self.note,
        )


@dataclasses.dataclass(frozen=True)
class GalleryFigure(FigureResult):
    """A gallery example: its ``name`` (file stem), ``title``, the onsets, and the named
    critical points to draw in 3D."""

    name: str = ""
    title: str = ""
    onsets: tuple[Onset, ...] = ()
    points: tuple[tuple[str, CriticalPoint], ...] = ()

    def save(self, directory: str | Path, *, dpi: int = 200) -> list[Path]:
        """Write <name>.png and <name>.csv into ``directory`` (created); return the paths."""
        out = Path(directory)
        out.mkdir(parents=True, exist_ok=True)
        png, path = out / f"{self.name}.png", out / f"{self.name}.csv"
        with replaced(png, "wb") as fh:  # whole or not at all (see FigureResult.save)
            self.figure.savefig(fh, dpi=dpi, format="png")
        with replaced(path, newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(self.columns)
            for row in self.table:
                writer.writerow([repr(v) if isinstance(v, float) else v for v in row])
        return [png, path]


@dataclasses.dataclass(frozen=True)
class Job:
    """One tube to solve: the critical ``control`` over all modes, or of one ``mode`` (m, n)
    when given; ``case``, ``parameter`` and ``x`` label its row."""

    tube: Tube
    control: str
    case: str
    parameter: str
    x: float
    mode: tuple[int, int] | None = None


def solve(key: tuple, options: ScanOptions) -> tuple[CriticalPoint | None, str]:
    """The unit of work: the critical point of ``key = (tube, control, mode)`` (a scan over all
    modes when ``mode`` is None), or None and the reason when no mode bifurcates."""
    tube, control, mode = key
    try:
        if mode is None:
            return scan_modes(tube, control, options=options).critical, ""
        return critical_value(tube, mode[0], mode[1], control), ""
    except (NoBifurcationFound, ConvergenceError, BaseStateError) as exc:
        return None, str(exc)


def run_jobs(jobs, options: ScanOptions, mapper: Callable = map) -> list[Onset]:
    """The :class:`Onset` of every job, one solve per distinct (tube, control, mode), run by
    ``mapper`` (builtin ``map``, or a process pool's)."""
    keys = list(dict.fromkeys((j.tube, j.control, j.mode) for j in jobs))
    done = dict(zip(keys, mapper(functools.partial(solve, options=options), keys), strict=True))
    return [
        Onset(j.case, j.parameter, float(j.x), j.control, *done[j.tube, j.control, j.mode])
        for j in jobs
    ]


def run_groups(groups: dict, options: ScanOptions, mapper: Callable = map) -> dict:
    """:func:`run_jobs` over every group of jobs at once; the onsets by group."""
    onsets = iter(run_jobs([j for jobs in groups.values() for j in jobs], options, mapper))
    return {name: [next(onsets) for _ in jobs] for name, jobs in groups.items()}


def result(name, title, onsets, fig, headline, points=(), extra_rows=()) -> GalleryFigure:
    rows = [o.row() for o in onsets] + list(extra_rows)
    table = np.empty((len(rows), len(COLUMNS)), dtype=object)
    for i, row in enumerate(rows):
        table[i] = row
    return GalleryFigure(
        0,
        COLUMNS,
        table,
        fig,
        headline,
        name=name,
        title=title,
        onsets=tuple(onsets),
        points=tuple(points),
    )


def draw_onsets(ax, onsets, *, color, label, marker="o", annotate=True):
    """Critical value against x, each point labelled with its mode "(m, n)" (the
    short-wave limit "∞"); a tube with no onset is a cross on the x axis (and, when no tube of the
    panel has one, the reason is written in it)."""
    ok = [o for o in onsets if o.critical is not None]
    ax.plot(
        [o.x for o in ok], [o.value for o in ok], "-" + marker, color=color, label=label, ms=3.5
    )
    for o in ok:
        m, n = o.mode
        text = f"({m}, {n})" if m >= 0 else ("∞" if o.critical.kind == "surface" else "threshold")
        if annotate:
            ax.annotate(
                text,
                (o.x, o.value),
                xytext=(0, 5),
                textcoords="offset points",
                ha="center",
                fontsize=6.5,
                color=color,
            )
    none = [o for o in onsets if o.critical is None]
    ax.plot(
        [o.x for o in none],
        [0.03] * len(none),
        "x",
        color=color,
        transform=ax.get_xaxis_transform(),
        label=f"{label}: no onset" if none else None,
    )
    if none and not ok and not ax.texts:
        ax.text(
            0.5,
            0.5,
            none[0].note.replace(" between", "\nbetween"),
            ha="center",
            va="center",
            fontsize=7,
            transform=ax.transAxes,
        )
        ax.set_yticks([])
