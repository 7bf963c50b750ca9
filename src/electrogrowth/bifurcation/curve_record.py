"""The record of a critical curve: its grid points, the switches of the critical mode, the
table (CSV, JSON, xarray) they make (bifurcation/curves.py computes them)."""

from __future__ import annotations

import csv
import dataclasses
import math
from pathlib import Path
from typing import NamedTuple

import numpy as np

from ..atomic import replaced
from ..errors import NoBifurcationFound, UnstableAtStart
from ..labelled import curve_dataset
from ..model.layers import Tube
from ..outcomes import NO_MODE, Kind, Outcome, Status, json_number, remedy, status_of, traceback_of
from ..summary import curve_html
from .curve_crease import CreaseAlong


class Switch(NamedTuple):
    """The critical mode changes at ``x`` from ``mode_before`` to ``mode_after`` (m, n), in
    the order of the grid; (-1, -1) stands for the threshold or the short-wave limit.
    ``kind`` "switch": the two are equally critical there (a crossing), ``value`` =
    ``value_after``. ``kind`` "end": the branch before ends there without a crossing, either
    at a jump (a mode's first critical value appears or vanishes discontinuously, e.g. a
    window of instability closes; ``value`` and ``value_after`` are the one-sided limits of
    the critical value) or where one side does not wrinkle (the threshold comes first).
    ``x_error`` and ``value_error``: estimates of the absolute errors of ``x`` and of the
    values (bifurcation/curve_switches.py; NaN: not known)."""

    x: float
    value: float
    mode_before: tuple[int, int]
    mode_after: tuple[int, int]
    value_after: float
    kind: str = Kind.SWITCH
    x_error: float = math.nan
    value_error: float = math.nan


def _change_kind(a: CurvePoint, b: CurvePoint, v_before: float, v_after: float) -> Kind:
    """ "switch" where the critical value is continuous and both sides wrinkle (a mode or the
    short-wave limit); otherwise the branch before "end"s."""
    wrinkles = a.kind in (Kind.BIFURCATION, Kind.SURFACE) and b.kind in (
        Kind.BIFURCATION,
        Kind.SURFACE,
    )
    equal = abs(v_after - v_before) <= 1e-9 * max(1.0, abs(v_before))
    return Kind.SWITCH if wrinkles and equal else Kind.END


@dataclasses.dataclass(frozen=True)
class CurvePoint(Outcome):
    """One grid point, an :class:`~electrogrowth.outcomes.Outcome`: critical value and
    mode, kind "bifurcation", "threshold" or "surface" ("" where the scan failed: then
    value NaN and ``status`` FAILED, an electrogrowth error, or ERROR, a bug, with
    ``message``, ``remedy`` and, for a bug, its ``traceback``), status OK or INACCURATE
    (the critical value's error estimate exceeds the accuracy asked even after
    refinement, :func:`bifurcation.critical_value`), the runners-up (m, n, value: a scanned
    point's; a followed point solved its critical mode alone and has none), whether
    the critical point is the short-wave limit (``surface``), and that limit where the
    scan computed it (else NaN). A status given as text ("", "inaccurate") is read as the
    Status. The curve's table writes a failure's status in its kind column (:func:`_row`).
    ``failure`` names a failure's kind, its exception's class ("UnstableAtStart": the
    tube is already unstable at the control's start; "NoBifurcationFound": no mode before
    the control's end; "BaseStateError": no state; ...), "" where none. ``face``: where
    the short-wave limit that is the critical point wrinkles ("inner", "outer",
    "interface-K"), "" elsewhere.
    """

    x: float
    value: float
    mode: tuple[int, int]
    kind: str
    status: Status = Status.OK
    runners_up: tuple[tuple[int, int, float], ...] = ()
    surface: bool = False
    short_wave_limit: float = math.nan
    error_estimate: float = math.nan
    message: str = ""
    remedy: str = ""
    traceback: str = dataclasses.field(default="", repr=False, compare=False)
    failure: str = ""
    #: the mode (m, n, family code) an UnstableAtStart failure found unstable at the
    #: control's start: where the end of a valid range is located (curve_switches.py)
    unstable_row: tuple = dataclasses.field(default=(), repr=False, compare=False)
    face: str = ""

    def __post_init__(self):
        object.__setattr__(self, "status", Status(self.status or Status.OK))


#: The kinds a grid point can have ("" where its scan failed).
POINT_KINDS = ("", Kind.BIFURCATION, Kind.THRESHOLD, Kind.SURFACE)


def point_record(pt: CurvePoint) -> dict:
    """A grid point as a JSON-ready record (:func:`point_of` reads it back exactly: floats
    keep every digit through JSON's repr, NaN as None)."""
    record = dataclasses.asdict(pt)
    record["unstable_row"] = list(pt.unstable_row)
    for key in ("x", "value", "short_wave_limit", "error_estimate"):
        record[key] = None if math.isnan(record[key]) else record[key]
    record["status"], record["kind"] = str(pt.status), str(pt.kind)
    record["runners_up"] = [[m, n, None if math.isnan(v) else v] for m, n, v in pt.runners_up]
    return record


def point_of(record: dict) -> CurvePoint:
    """The grid point of a :func:`point_record`, its every field checked (the record comes
    from a file: ValueError names the first field that is not what a point holds)."""
    if not isinstance(record, dict) or set(record) - _OPTIONAL != _FIELDS:
        raise ValueError("not a curve point's record (its fields differ)")
    kind, status, surface = record["kind"], record["status"], record["surface"]
    if kind not in POINT_KINDS or status not in set(Status) or not isinstance(surface, bool):
        raise ValueError(f"kind {kind!r}, status {status!r} or surface {surface!r} unknown")
    runners = record["runners_up"]
    if not isinstance(runners, (list, tuple)):
        raise ValueError(f"runners_up = {runners!r} is not a list")
    texts = [record[k] for k in ("message", "remedy", "traceback", "failure")]
    face = record.get("face", "")  # absent in records before 2026-12-08
    if not all(isinstance(t, str) and _printable(t) for t in (*texts, face)):
        raise ValueError("message, remedy, traceback, failure or face is not a printable text")
    x, value, limit, error = (
        _float(record[k], k) for k in ("x", "value", "short_wave_limit", "error_estimate")
    )
    runners_up = tuple(_runner(r) for r in runners)
    row = _unstable_row(record.get("unstable_row", []))  # absent in records before 2026-12-07
    return CurvePoint(x, value, _mode(record["mode"]), kind, Status(status), runners_up,
                      surface, limit, error, *texts, unstable_row=row, face=face)  # fmt: skip


def _unstable_row(v) -> tuple:
    """A record's unstable mode: () or three integers (m, n, family code)."""
    if not isinstance(v, (list, tuple)) or len(v) not in (0, 3):
        raise ValueError(f"unstable_row {v!r} is not (m, n, family code)")
    if any(isinstance(i, bool) or not isinstance(i, int) or i < 0 for i in v):
        raise ValueError(f"unstable_row {v!r} is not (m, n, family code)")
    return tuple(int(i) for i in v)


def _printable(text: str) -> bool:
    """No control characters but line breaks and tabs (a text of a file is printed later:
    no terminal escape sequences)."""
    return all(c.isprintable() or c in "\n\t" for c in text)


def _float(v, name: str) -> float:
    """A record's number as a float (None: NaN, as :func:`point_record` writes it)."""
    if v is None:
        return math.nan
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ValueError(f"{name} = {v!r} is not a number")
    return float(v)


def _runner(r) -> tuple[int, int, float]:
    """A runner-up (m, n, value) of a record."""
    if not isinstance(r, (list, tuple)) or len(r) != 3:
        raise ValueError(f"runner-up {r!r} is not (m, n, value)")
    return (*_mode(r[:2]), _float(r[2], "a runner-up's value"))


def _mode(v) -> tuple[int, int]:
    """(m, n) of a record's two integers."""
    if not isinstance(v, (list, tuple)) or len(v) != 2:
        raise ValueError(f"mode {v!r} is not two integers (m, n)")
    if any(isinstance(i, bool) or not isinstance(i, int) for i in v):
        raise ValueError(f"mode {v!r} is not two integers (m, n)")
    return (int(v[0]), int(v[1]))


#: the fields a record written before them lacks (read as none)
_OPTIONAL = {"unstable_row", "face"}
_FIELDS = {f.name for f in dataclasses.fields(CurvePoint)} - _OPTIONAL


def _failure_kind(exc: Exception) -> str:
    """``failure`` of a point that raised ``exc``: its class, "NoBifurcationFound" for every
    kind of it (one that stopped next to its control's lock, NoBifurcationBeforeLock, is
    a "no bifurcation" answer too: design/sequence.py reads the name)."""
    kind = NoBifurcationFound if isinstance(exc, NoBifurcationFound) else type(exc)
    return kind.__name__


def _failed_point(x: float, exc: Exception) -> CurvePoint:
    """The grid point at x whose scan raised ``exc``: FAILED (an electrogrowth error) or
    ERROR (a bug, its traceback kept)."""
    status = status_of(exc)
    text = " ".join(str(exc).split())
    message = text if status is Status.FAILED else f"internal error: {type(exc).__name__}: {text}"
    return CurvePoint(
        float(x),
        math.nan,
        NO_MODE,
        "",
        status,
        message=message,
        remedy=remedy(exc),
        traceback=traceback_of(exc),
        failure=_failure_kind(exc),
        unstable_row=getattr(exc, "row", None) or (),
    )


def _failed(pt: CurvePoint) -> bool:
    """A grid point without a value: its scan failed, or hit a bug."""
    return pt.status in (Status.FAILED, Status.ERROR)


def _fails_alike(pt: CurvePoint, other: CurvePoint) -> bool:
    """Both points failed, and in the same way (the same kind of failure)."""
    return _failed(pt) and _failed(other) and pt.failure == other.failure


def _critical(pt: CurvePoint):
    """What is critical at a point: its mode, or without one the threshold or the short-wave
    limit (its kind: both have m = n = -1, and a change between them is located too)."""
    return pt.mode if pt.mode != NO_MODE else pt.kind


def _changes(prev: CurvePoint, pt: CurvePoint) -> bool:
    """What is critical changes between two neighbouring points: a switch to locate."""
    return not (_failed(prev) or _failed(pt)) and _critical(prev) != _critical(pt)


def _window_between(a: CurvePoint, b: CurvePoint) -> bool:
    """One point's tube is already unstable at the control's start (its critical value at
    or before the start) and the other's wrinkles in no mode before the control's end (past
    the end): by continuity the critical value runs through the whole range in between."""
    kinds = {a.failure, b.failure} if _failed(a) and _failed(b) else set()
    return kinds == {UnstableAtStart.__name__, NoBifurcationFound.__name__}


def _edge(prev: CurvePoint, pt: CurvePoint) -> bool:
    """One of two neighbouring points failed and the other not, or both failed in
    different ways: an end of the valid range, or a valid window between two kinds of
    failure (:func:`_window_between`), to locate (with ``critical_curve(...,
    edges=True)``)."""
    return (_failed(prev) or _failed(pt)) and not _fails_alike(prev, pt)


def _failed_row(kind) -> bool:
    """A row of a curve's table without a value (its kind column holds the status)."""
    return kind in (Status.FAILED, Status.ERROR)


def _message(exc: Exception) -> str:
    """One line; an unexpected (non-electrogrowth) error is named by its type, as a bug."""
    return _row_status(_failed_point(math.nan, exc))


@dataclasses.dataclass(frozen=True)
class Curve:
    """The critical ``solve_for`` along ``along``.

    Rows are the grid points and, at every located change of the critical mode, two rows at
    the same x: the end of the branch before and the start of the branch after (kind
    "switch" at a crossing, "end" where the branch before just ends: see :class:`Switch`).
    ``kind`` is "bifurcation" (mode m, n), "threshold" (m = n = -1: the axisymmetric state
    is lost first), "surface" (m = n = -1: the exact short-wave limit m, n -> infinity at a
    face comes first), "switch", "end" or "failed" (value NaN, ``status`` says why).
    ``status`` starts with "ok", or with "inaccurate" where the critical value's error
    estimate exceeds the accuracy asked even after refinement (``inaccurate`` marks those
    rows); a failed row's holds why.
    ``surface`` marks the rows of the short-wave limit; ``short_wave_limit`` holds the limit
    where the scan computed it (NaN elsewhere). ``switches`` lists the crossings, ``ends``
    the branch ends that were located. ``crease`` (bifurcation/curve_crease.py): per row,
    where a free face creases along the same control and whether that comes first
    (``crease.first``; not computed, all NaN, for an interrupted curve's points).
    ``failure``: per row, the kind of a failed row's failure (:class:`CurvePoint`), ""
    for the others. ``surface_face``: per row of the short-wave limit, the face where it
    wrinkles ("inner", "outer", "interface-K"), "" for the others.
    """

    along: str
    solve_for: str
    side: str | None
    x: np.ndarray
    value: np.ndarray
    m: np.ndarray
    n: np.ndarray
    kind: np.ndarray
    status: tuple[str, ...]
    switches: tuple[Switch, ...]
    params: Tube
    surface: np.ndarray
    short_wave_limit: np.ndarray
    ends: tuple[Switch, ...] = ()
    crease: CreaseAlong | None = None
    failure: tuple[str, ...] = ()
    surface_face: tuple[str, ...] = ()
    #: the grid points as computed (CurvePoint, runners-up and all): an interrupted
    #: curve's finished points, which ``critical_curve(..., resume=curve)`` takes back
    grid: tuple[CurvePoint, ...] = dataclasses.field(default=(), repr=False, compare=False)

    def __post_init__(self):
        if self.crease is None:
            object.__setattr__(self, "crease", CreaseAlong.empty(len(self.x)))
        if not self.failure:
            object.__setattr__(self, "failure", ("",) * len(self.x))
        if not self.surface_face:
            object.__setattr__(self, "surface_face", ("",) * len(self.x))

    @property
    def inaccurate(self) -> np.ndarray:
        """Rows whose critical value is not certified to the rtol asked (boolean)."""
        mark = str(Status.INACCURATE)
        return np.array([s.split(";")[0] == mark for s in self.status], dtype=bool)

    def branches(self) -> list[tuple[tuple[int, int], np.ndarray]]:
        """Maximal runs of rows with one mode ((-1, -1): the threshold, or the short-wave
        limit: a run is one of them, ``surface`` tells which), failed rows excluded:
        [((m, n), row indices), ...] in order."""
        out, start = [], None
        for i in range(len(self.x) + 1):
            end = i == len(self.x)
            ok = not end and not _failed_row(self.kind[i])
            if start is not None and (not ok or self._branch_of(i) != self._branch_of(start)):
                out.append(((int(self.m[start]), int(self.n[start])), np.arange(start, i)))
                start = None
            if ok and start is None:
                start = i
        return out

    def _branch_of(self, row: int) -> tuple:
        """What a row's branch is: its mode, and for m = n = -1 the threshold or the
        short-wave limit (at its face)."""
        m, n = int(self.m[row]), int(self.n[row])
        return (m, n) if m >= 0 else (m, n, bool(self.surface[row]), self.surface_face[row])

    def to_xarray(self):
        """The curve as an ``xarray.Dataset``: rows on dimension point (x is the coordinate
        named after ``along``), the located switches on dimension switch (labelled.py)."""
        return curve_dataset(self)

    def _repr_html_(self) -> str:
        return curve_html(self)

    def to_csv(self, path: str | Path) -> Path:
        """Columns <along>, <solve_for>_cr, m, n, kind, surface (0/1), surface_face,
        short_wave_limit, status, and the crease (crease_value, crease_face, crease_trigger,
        crease_error, crease_first 0/1)."""
        path = Path(path)
        with replaced(path, newline="") as fh:  # whole or not at all (atomic.py)
            w = csv.writer(fh)
            w.writerow(
                [
                    self.along,
                    f"{self.solve_for}_cr",
                    "m",
                    "n",
                    "kind",
                    "surface",
                    "surface_face",
                    "short_wave_limit",
                    "status",
                    *CREASE_COLUMNS,
                ]
            )
            crease = self._crease_rows()
            for row, more in zip(
                zip(
                    self.x,
                    self.value,
                    self.m,
                    self.n,
                    self.kind,
                    self.surface,
                    self.surface_face,
                    self.short_wave_limit,
                    self.status,
                ),
                crease,
            ):
                x, v, m, n, kind, surf, face, limit, status = row
                w.writerow(
                    [
                        repr(float(x)),
                        repr(float(v)),
                        int(m),
                        int(n),
                        kind,
                        int(surf),
                        face,
                        repr(float(limit)),
                        status,
                        *more,
                    ]
                )
        return path

    def _crease_rows(self) -> list[tuple]:
        c = self.crease
        assert c is not None  # set in __post_init__
        return [
            (repr(float(v)), face, trigger, repr(float(e)), int(first))
            for v, face, trigger, e, first in zip(c.value, c.face, c.trigger, c.error, c.first)
        ]

    def as_dict(self) -> dict:
        """JSON-ready record (NaN -> None)."""
        num = _finite_or_none
        p = self.params
        rec = p.record()
        fixed = {  # the tube's material(s), its numbers but the curve's own two, and itself
            "material": rec.pop("material", None) or " / ".join(rec.pop("materials", ())),
            "fixed": {k: v for k, v in rec.items() if k not in (self.along, self.solve_for)},
            "tube": p.as_dict(),
        }
        return {
            "along": self.along,
            "solve_for": self.solve_for,
            "side": self.side,
            **fixed,
            "x": num(self.x),
            "value": num(self.value),
            "m": self.m.tolist(),
            "n": self.n.tolist(),
            "kind": self.kind.tolist(),
            "status": list(self.status),
            "failure": list(self.failure),
            "surface": self.surface.tolist(),
            "surface_face": list(self.surface_face),
            "short_wave_limit": num(self.short_wave_limit),
            "switches": [_change_record(s) for s in self.switches],
            "ends": [_change_record(s) for s in self.ends],
            **_crease_record(self.crease),
        }


#: the crease's columns of a curve's table (CreaseAlong.columns)
CREASE_COLUMNS = ("crease_value", "crease_face", "crease_trigger", "crease_error", "crease_first")


def _crease_record(crease) -> dict:
    """The crease's JSON columns (NaN -> None)."""
    out = crease.columns()
    for key in ("crease_value", "crease_error"):
        out[key] = _finite_or_none(out[key])
    return out


def _change_record(s: Switch) -> dict:
    return {
        "x": s.x,
        "value": json_number(s.value),  # NaN on an end's failed side
        "mode_before": list(s.mode_before),
        "mode_after": list(s.mode_after),
        "value_after": json_number(s.value_after),
        "kind": str(s.kind),
        "x_error": json_number(s.x_error),
        "value_error": json_number(s.value_error),
    }


def _scan_point(x: float, res) -> CurvePoint:
    """The CurvePoint of a ScanResult at x (as :func:`curve_point`)."""
    c = res.critical
    mode = (c.m, c.n) if c.kind == Kind.BIFURCATION else NO_MODE
    limit = res.short_wave_limit
    return CurvePoint(
        float(x),
        c.value,
        mode,
        c.kind,
        _accuracy(c),
        tuple((r.m, r.n, r.value) for r in res.runners_up),
        bool(res.surface_instability),
        math.nan if limit is None else float(limit),
        float(c.error_estimate),
        face=(c.face or "") if c.kind == Kind.SURFACE else "",
    )


def _accuracy(c) -> Status:
    """A grid point's status from its CriticalPoint: INACCURATE (not certified to the
    rtol asked) or OK."""
    return Status.INACCURATE if c.status == Status.INACCURATE else Status.OK


def _row(pt: CurvePoint):
    """The table row of a grid point: a failure's status in the kind column, its kind
    last."""
    kind = pt.status if pt.kind == "" else pt.kind
    return (
        pt.x,
        pt.value,
        pt.mode,
        kind,
        _row_status(pt),
        pt.surface,
        pt.short_wave_limit,
        pt.failure,
        pt.face,
    )


def _row_status(pt: CurvePoint) -> str:
    """The status column: a failure's message (a bug's with its remedy), else "ok" or
    "inaccurate", then any note (a switch not located). An ok row said "" before
    2026-12-08, an empty cell a reader could take for a missing value (check round 29);
    ``Curve.inaccurate`` reads both."""
    if pt.kind == "" and pt.status == Status.ERROR:
        return f"{pt.message} ({pt.remedy})"
    if pt.kind == "":
        return pt.message
    mark = str(Status.INACCURATE) if pt.status == Status.INACCURATE else str(Status.OK)
    return "; ".join(filter(None, (mark, pt.message)))


def _not_located(pt: CurvePoint, prev: CurvePoint, exc: Exception) -> CurvePoint:
    """``pt`` (its status kept) noting that the switch from ``prev`` could not be located;
    a bug is named as one ("internal error: ...", with the bug report's remedy)."""
    why = f"switch from {prev.mode} not located: {_message(exc)}"
    return dataclasses.replace(pt, message="; ".join(filter(None, (pt.message, why))))


def _finite_or_none(values) -> list:
    """The floats of ``values`` with NaN and infinities as None (JSON has neither)."""
    return [None if not math.isfinite(v) else float(v) for v in values]
