"""Critical value along a parameter, with the switches of the critical mode located.

A curve is ``x -> value(x)``: the critical ``solve_for`` ("growth", "stretch" or "voltage",
as in :func:`scan.scan_modes`) minimised over the modes (m, n) while the parameter ``along``
(any other control or key of the :class:`Tube`) runs over a grid. Each grid point is one mode
scan (:func:`curve_point`, a pure picklable function, so a process pool's ``map`` can run
them). Between two grid points whose critical modes differ, A at x_a and B at x_b, the
switch is located exactly:

* two wrinkling modes: Brent's method on d(x) = s (v_A(x) - v_B(x)), with v the first
  critical value of one mode (:func:`bifurcation.critical_value`; the threshold value when
  the mode is not reached before it) and s = +1, or -1 for the stretch in compression (there
  the first mode reached is the largest lambda_z). Where a mode's first critical value
  jumps (a window of instability opens), d jumps too and the switch is that jump;
* a mode and the threshold (the axisymmetric state is lost first): bisection on whether the
  mode still bifurcates before the threshold.

A change with equal values on both sides, between two wrinkling modes (or a mode and the
short-wave limit), is a "switch"; one where the value jumps, or the threshold is on one side,
is the "end" of a branch (:class:`Switch`, ``Curve.ends``). The located switch is checked by
a scan there; if a third mode comes first, the interval is
split at it and both halves are located again. If a single-mode solve fails (e.g. the
kernel cannot integrate a high mode next to the threshold), the switch is bisected with
scans instead, to a relative 1e-7 only. A point whose scan fails (e.g. the tube is
already unstable at the start of the march) is kept as kind "failed" with its message (kind
"error": an unexpected exception, a bug; its CurvePoint, an outcomes.Outcome, keeps the
traceback) and is scanned only once. An interrupt (Ctrl-C, SIGTERM) is never a failed
point: it ends the curve with :class:`~electrogrowth.interrupts.Interrupted`, whose
``partial`` holds the grid points computed before it.

By continuation (``follow``, the default with the builtin ``map``), the grid points between
full scans are not scanned: the last scan's critical mode and runners-up are followed
(:class:`_Follower`: each mode's value predicted from its previous points, then one
bracketed solve of the one predicted first; or the exact short-wave limit, if it came
first), and the result is accepted only if every mode of the scan's grid is still on its
stable side (its sign on the unloaded tube, loose targets, as in the scan's march) just
before it, no face is past its short-wave limit (for a mode), and the mode is not on the
edge of the ranges; otherwise, at the ends and every CHECK_EVERY points the point is a
full scan. Switches are located and checked by scans as
before, so the curve equals the curve of full scans.
"""

from __future__ import annotations

import csv
import dataclasses
import functools
import math
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import NamedTuple

import numpy as np

from ..atomic import replaced
from ..basestate.tube import solve_base_state
from ..errors import ElectrogrowthError, ParameterError
from ..incremental.accuracy import SCAN_SIGNS
from ..incremental.targets import impedance_targets
from ..interrupts import Interrupted, interrupt_of, reraise_interrupt
from ..labelled import curve_dataset
from ..model.layers import KEYS_TEXT, Tube
from ..model.params import check_side
from ..outcomes import NO_MODE, Kind, Outcome, Status, remedy, status_of, traceback_of
from ..summary import curve_html
from .critical import critical_value
from .directions import past_surface
from .scan import ScanOptions, scan_grid, scan_modes, stable_signs
from .surface import short_wave_limit

#: The parameters of the paper's tube a curve can run along (Tube.parameter_keys).
ALONG = ("stretch", "voltage", "outer_radius", "length", "growth")
MAX_SPLITS = 6  # depth of the re-location when a third mode intervenes
CHECK_EVERY = 8  # when following modes, a full scan at least every this many points
MAX_POINTS = 10_000  # grid points of a curve (each a mode scan, ~1 s): hours at most


class Switch(NamedTuple):
    """The critical mode changes at ``x`` from ``mode_before`` to ``mode_after`` (m, n), in
    the order of the grid; (-1, -1) stands for the threshold or the short-wave limit.
    ``kind`` "switch": the two are equally critical there (a crossing), ``value`` =
    ``value_after``. ``kind`` "end": the branch before ends there without a crossing, either
    at a jump (a mode's first critical value appears or vanishes discontinuously, e.g. a
    window of instability closes; ``value`` and ``value_after`` are the one-sided limits of
    the critical value) or where one side does not wrinkle (the threshold comes first)."""

    x: float
    value: float
    mode_before: tuple[int, int]
    mode_after: tuple[int, int]
    value_after: float
    kind: str = Kind.SWITCH


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
    refinement, :func:`bifurcation.critical_value`), the runners-up (m, n, value), whether
    the critical point is the short-wave limit (``surface``), and that limit where the
    scan computed it (else NaN). A status given as text ("", "inaccurate") is read as the
    Status. The curve's table writes a failure's status in its kind column (:func:`_row`).
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

    def __post_init__(self):
        object.__setattr__(self, "status", Status(self.status or Status.OK))


def curve_point(
    params: Tube,
    solve_for: str,
    along: str,
    x: float,
    *,
    side: str | None = None,
    options: ScanOptions = ScanOptions(),
) -> CurvePoint:
    """Scan the modes at ``along`` = x; a failure becomes kind "failed" (an electrogrowth
    error) or "error" (any other exception: a bug). Raises only an interrupt (Ctrl-C,
    SIGTERM), also where it comes wrapped by the compiled kernel."""
    try:
        res = scan_modes(params.at(along, x), solve_for, side=side, options=options)
    except Exception as exc:  # noqa: BLE001 -- failures are data in a sweep
        reraise_interrupt(exc)
        return _failed_point(x, exc)
    return _scan_point(x, res)


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
    )


def _failed(pt: CurvePoint) -> bool:
    """A grid point without a value: its scan failed, or hit a bug."""
    return pt.status in (Status.FAILED, Status.ERROR)


def _failed_row(kind) -> bool:
    """A row of a curve's table without a value (its kind column holds the status)."""
    return kind in (Status.FAILED, Status.ERROR)


def _progress_bar(total: int, desc: str, unit: str = "pt"):
    """A tqdm.auto bar (a notebook widget or text on stderr)."""
    from tqdm.auto import tqdm

    return tqdm(total=total, desc=desc, unit=unit)


def _critical_text(pt: CurvePoint) -> str:
    """What is critical at a grid point, in a progress message."""
    if pt.kind == Kind.SURFACE:
        return "the short-wave limit"
    return "the threshold" if pt.mode == NO_MODE else str(pt.mode)


def _changes(prev: CurvePoint, pt: CurvePoint) -> bool:
    """The critical mode changes between two neighbouring grid points: a switch to locate."""
    return not (_failed(prev) or _failed(pt)) and prev.mode != pt.mode


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
    ``status`` starts with "inaccurate" where the critical value's error estimate exceeds
    the accuracy asked even after refinement (``inaccurate`` marks those rows).
    ``surface`` marks the rows of the short-wave limit; ``short_wave_limit`` holds the limit
    where the scan computed it (NaN elsewhere). ``switches`` lists the crossings, ``ends``
    the branch ends that were located.
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

    @property
    def inaccurate(self) -> np.ndarray:
        """Rows whose critical value is not certified to the rtol asked (boolean)."""
        mark = str(Status.INACCURATE)
        return np.array([s.split(";")[0] == mark for s in self.status], dtype=bool)

    def branches(self) -> list[tuple[tuple[int, int], np.ndarray]]:
        """Maximal runs of rows with one mode ((-1, -1): threshold), failed rows excluded:
        [((m, n), row indices), ...] in order."""
        out, start = [], None
        for i in range(len(self.x) + 1):
            end = i == len(self.x)
            ok = not end and not _failed_row(self.kind[i])
            if start is not None and (
                not ok or (self.m[i], self.n[i]) != (self.m[start], self.n[start])
            ):
                out.append(((int(self.m[start]), int(self.n[start])), np.arange(start, i)))
                start = None
            if ok and start is None:
                start = i
        return out

    def to_xarray(self):
        """The curve as an ``xarray.Dataset``: rows on dimension point (x is the coordinate
        named after ``along``), the located switches on dimension switch (labelled.py)."""
        return curve_dataset(self)

    def _repr_html_(self) -> str:
        return curve_html(self)

    def to_csv(self, path: str | Path) -> Path:
        """Columns <along>, <solve_for>_cr, m, n, kind, surface (0/1), short_wave_limit,
        status."""
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
                    "short_wave_limit",
                    "status",
                ]
            )
            for row in zip(
                self.x,
                self.value,
                self.m,
                self.n,
                self.kind,
                self.surface,
                self.short_wave_limit,
                self.status,
            ):
                x, v, m, n, kind, surf, limit, status = row
                w.writerow(
                    [
                        repr(float(x)),
                        repr(float(v)),
                        int(m),
                        int(n),
                        kind,
                        int(surf),
                        repr(float(limit)),
                        status,
                    ]
                )
        return path

    def as_dict(self) -> dict:
        """JSON-ready record (NaN -> None)."""
        num = lambda a: [None if not math.isfinite(v) else float(v) for v in a]  # noqa: E731
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
            "surface": self.surface.tolist(),
            "short_wave_limit": num(self.short_wave_limit),
            "switches": [_change_record(s) for s in self.switches],
            "ends": [_change_record(s) for s in self.ends],
        }


def _change_record(s: Switch) -> dict:
    return {
        "x": s.x,
        "value": s.value,
        "mode_before": list(s.mode_before),
        "mode_after": list(s.mode_after),
        "value_after": s.value_after,
        "kind": str(s.kind),
    }


def check_curve(solve_for: str, along: str, params: Tube) -> None:
    """Raise ParameterError unless ``solve_for`` is a control of ``params`` and ``along``
    is not that control (whether ``along`` is a control or key is checked by :meth:`Tube.at`
    at the curve's values)."""
    control = str(params.check_control(solve_for))
    if along == control:
        raise ParameterError(f"along = {along!r} is the unknown itself; choose another")
    try:
        params.value_of(along)
    except ParameterError as exc:
        raise ParameterError(
            f"along = {along!r}: {exc}; or a key of the tube: {KEYS_TEXT}"
        ) from None


def critical_curve(
    params: Tube,
    solve_for: str,
    along: str,
    values: Iterable[float],
    *,
    side: str | None = None,
    options: ScanOptions = ScanOptions(),
    progress: bool | Callable[[int], object] | None = None,
    mapper: Callable = map,
    follow: bool = True,
) -> Curve:
    """Critical ``solve_for`` as ``along`` runs over ``values``, switches located.

    Parameters
    ----------
    params : Tube
        The fixed parameters; fields ``along`` and ``solve_for`` are overridden.
    solve_for : {"growth", "stretch", "voltage"}
        The unknown, as in :func:`scan.scan_modes` (``side`` for the stretch).
    along : {"stretch", "voltage", "outer_radius", "length", "growth"}
        The parameter of the abscissa; not ``solve_for``.
    values : sequence of float
        Strictly monotone grid of ``along``.
    options : ScanOptions
        Mode ranges of each scan (extended automatically when the optimum is on an edge).
    progress : bool or callable, optional
        True: progress bars (tqdm.auto: a widget in a notebook, text on a terminal), one
        over the grid points, then one over the mode switches to locate; None or False:
        none (default); a callable: called with 1 after each grid point
        (``tqdm(...).update`` fits; the switches are then located silently).
    mapper : callable
        ``map``-like function running :func:`curve_point` over the grid (e.g. a process
        pool's ``map``); the builtin by default.
    follow : bool
        With the builtin ``map``: follow the
        critical mode and its runners-up from point to point, with full scans only where
        the check fails, at the ends and every CHECK_EVERY points (module docstring);
        False: a full scan at every point.

    Returns
    -------
    Curve

    Raises
    ------
    ParameterError
        Unknown ``solve_for``/``along``, equal, a bad ``side``, a non-monotone grid or a grid
        value out of the parameter's range.

    Examples
    --------
    Buckling under axial compression (Vbar = 0, L = 1): thin tubes in mode (1, 1), thicker
    ones in (0, 1), the switch between Rbar_o = 1.2 and 1.3 located exactly:

    >>> c = critical_curve(Tube.uniform(), "stretch", "outer_radius", [1.2, 1.3],
    ...                    side="compression", options=ScanOptions((0, 2), (1, 2)))
    >>> [(s.mode_before, s.mode_after, round(s.x, 6)) for s in c.switches]
    [((1, 1), (0, 1), 1.256361)]
    """
    check_curve(solve_for, along, params)
    solve_for = str(params.check_control(solve_for))
    side = check_side(solve_for, side)
    if side is not None and solve_for not in ("stretch", "pressure", "force"):
        raise ParameterError(
            f"side = {side!r} applies to the stretch, pressure or force only, not {solve_for}"
        )
    xs = np.asarray(list(values), dtype=float)
    if xs.ndim != 1 or not 1 <= xs.size <= MAX_POINTS:
        raise ParameterError(
            f"values must be a non-empty sequence of at most {MAX_POINTS} numbers, got {xs.size}"
        )
    steps = np.diff(xs)
    if xs.size > 1 and not ((steps > 0).all() or (steps < 0).all()):
        raise ParameterError(f"values of {along} must be strictly monotone, got {xs.tolist()}")
    for x in xs:  # the ranges are checked before any work
        params.at(along, x)
    unit = functools.partial(curve_point, params, solve_for, along, side=side, options=options)
    if follow and mapper is map:
        follower = _Follower(params, solve_for, along, side, options, unit)
        computed = (follower.point(x, i in (0, xs.size - 1)) for i, x in enumerate(xs))
    else:
        computed = mapper(unit, xs)
    points = []
    bar = _progress_bar(xs.size, f"{solve_for} along {along}") if progress is True else None
    try:
        for pt in computed:
            points.append(pt)
            if bar is not None:
                bar.update(1)
            elif callable(progress):
                progress(1)
        if bar is not None:
            bar.close()
        loc = _Locator(params, solve_for, along, side, unit)
        rows, switches = _located(points, loc, progress)
    except (KeyboardInterrupt, Exception) as exc:  # an interrupt, maybe wrapped by the kernel:
        stop = interrupt_of(exc)  # hand back the finished grid points, switches not located
        if stop is None:
            raise
        partial = _curve(along, solve_for, side, params, [_row(p) for p in points], [])
        raise Interrupted(stop.signum, str(stop), partial=partial) from None
    finally:
        if bar is not None:
            bar.close()
    return _curve(along, solve_for, side, params, rows, switches)


def _located(points: list[CurvePoint], loc: _Locator, progress=None):
    """The rows of the grid points with the located switches between them, and the
    switches (a progress bar of its own when ``progress`` is True)."""
    rows, switches = [], []
    located = sum(map(_changes, points[:-1], points[1:]))
    bar = None
    if progress is True and located:  # locating can take far longer than the grid
        bar = _progress_bar(located, "locating mode switches", "switch")
    try:
        for i, pt in enumerate(points):
            prev = points[i - 1] if i else None
            if prev is not None and _changes(prev, pt):
                if bar is not None:
                    bar.set_postfix_str(f"between {_critical_text(prev)} and {_critical_text(pt)}")
                try:
                    new_rows, new_switches = loc.between(prev, pt, MAX_SPLITS)
                except Exception as exc:  # noqa: BLE001 -- keep the grid points
                    reraise_interrupt(exc)
                    new_rows, new_switches = [], []
                    pt = _not_located(pt, prev, exc)
                rows += new_rows
                switches += new_switches
                if bar is not None:
                    bar.update(1)
            rows.append(_row(pt))
    finally:
        if bar is not None:
            bar.close()
    return rows, switches


def _curve(along, solve_for, side, params, rows, switches) -> Curve:
    """The Curve of table rows (as :func:`_row`) and switches (and ends)."""
    x, v, modes, kinds, status, surface, limit = zip(*rows) if rows else [()] * 7
    modes = np.array(modes, dtype=int).reshape(-1, 2)
    return Curve(
        along,
        solve_for,
        side,
        np.array(x, dtype=float),
        np.array(v, dtype=float),
        modes[:, 0],
        modes[:, 1],
        np.array(kinds) if kinds else np.array([], dtype=str),
        tuple(status),
        tuple(s for s in switches if s.kind == Kind.SWITCH),
        params,
        np.array(surface, dtype=bool),
        np.array(limit, dtype=float),
        tuple(s for s in switches if s.kind == Kind.END),
    )


class _Follower:
    """Grid points by continuation from the last full scan (module docstring)."""

    def __init__(self, params, solve_for, along, side, options: ScanOptions, unit):
        self.params, self.solve_for, self.along, self.side = params, solve_for, along, side
        self.options, self.unit = options, unit
        self.sense = -1.0 if side == "compression" else 1.0
        self.scan = None  # the last full scan (CurvePoint) and its ScanResult ranges
        self.ranges = None
        self.since = 0
        self.history: dict[tuple[int, int], list[tuple[float, float]]] = {}

    def point(self, x: float, end: bool) -> CurvePoint:
        pt = None
        if not end and self.scan is not None and self.since < CHECK_EVERY:
            try:
                pt = self._follow(float(x))
            except ElectrogrowthError:
                pt = None
        if pt is None:
            pt = self._full(float(x))
        else:
            self.since += 1
        self._record(pt)
        return pt

    def _full(self, x: float) -> CurvePoint:
        at = self.params.at(self.along, x)
        try:
            res = scan_modes(at, self.solve_for, side=self.side, options=self.options)
        except Exception as exc:  # noqa: BLE001 -- the unit keeps the failure as data
            reraise_interrupt(exc)
            self.scan = None
            return _failed_point(x, exc)  # as the unit would, without scanning again
        pt = _scan_point(x, res)
        mode = pt.kind == Kind.BIFURCATION and not pt.surface and math.isnan(pt.short_wave_limit)
        self.scan = pt if mode or pt.kind == Kind.SURFACE else None
        self.ranges = (res.m_range, res.n_range)
        self.since = 0
        return pt

    def _record(self, pt: CurvePoint):
        if pt.kind == Kind.BIFURCATION:
            self.history.setdefault(pt.mode, []).append((pt.x, pt.value))
        for m, n, v in pt.runners_up:
            self.history.setdefault((m, n), []).append((pt.x, v))

    def _predict(self, mode, x) -> tuple[float, float] | None:
        """A bracket around the value of ``mode`` at x extrapolated from its last points."""
        hist = self.history.get(mode, [])
        if not hist:
            return None
        x1, v1 = hist[-1]
        if len(hist) == 1:
            return v1 * (1 - 1e-2), v1 * (1 + 1e-2)
        x0, v0 = hist[-2]
        guess = v1 + (v1 - v0) * (x - x1) / (x1 - x0)
        w = max(abs(guess - v1), 1e-6 * max(1.0, abs(guess)))
        return guess - w, guess + w

    def _follow(self, x: float) -> CurvePoint | None:
        """The followed mode predicted first, solved, or None if the check fails (the
        short-wave limit, if it came first at the last scan)."""
        at = self.params.at(self.along, x)
        if self.scan.kind == Kind.SURFACE:
            limit = short_wave_limit(at, self.solve_for, side=self.side)
            if limit.kind != Kind.SURFACE or not self._all_stable(at, None, limit.value):
                return None
            return CurvePoint(x, limit.value, NO_MODE, Kind.SURFACE, "", (), True, limit.value)
        modes = [self.scan.mode] + [(m, n) for m, n, _ in self.scan.runners_up]
        guesses = [(mode, self._predict(mode, x)) for mode in modes]
        guesses = [(mode, b) for mode, b in guesses if b is not None]
        if not guesses:
            return None
        best, bracket = min(guesses, key=lambda g: self.sense * sum(g[1]))
        c = critical_value(at, *best, self.solve_for, side=self.side, bracket=bracket)
        (m_lo, m_hi), (n_lo, n_hi) = self.ranges
        if c.kind != Kind.BIFURCATION or best[0] == m_hi or best[1] == n_hi:
            return None
        if not self._all_stable(at, best, c.value):
            return None
        if self.options.surface and past_surface(c.params):
            return None
        return CurvePoint(x, c.value, best, Kind.BIFURCATION, _accuracy(c))

    def _all_stable(self, at: Tube, best, value: float) -> bool:
        """Every mode of the scan's grid but ``best`` (None: all) is still on its stable
        side (the sign on the unloaded tube, as in a scan's march; loose targets) just
        before ``value``."""
        o = self.options
        families = (o.prismatic, o.torsional)
        grid = scan_grid(*self.ranges, o.extend, families)
        signs = stable_signs(*self.ranges, o.extend, families)
        other = np.ones(len(grid), bool)
        if best is not None:
            other = ~((grid[:, 0] == best[0]) & (grid[:, 1] == best[1]))
        before = value - self.sense * 1e-9 * max(1.0, abs(value))
        state = solve_base_state(at.at(self.solve_for, before))
        signs = signs[other] * impedance_targets(state, grid[other], rtol=SCAN_SIGNS)
        return bool(np.all(signs > 0))


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
    )


def _accuracy(c) -> Status:
    """A grid point's status from its CriticalPoint: INACCURATE (not certified to the
    rtol asked) or OK."""
    return Status.INACCURATE if c.status == Status.INACCURATE else Status.OK


def _row(pt: CurvePoint):
    """The table row of a grid point: a failure's status in the kind column."""
    kind = pt.status if pt.kind == "" else pt.kind
    return (pt.x, pt.value, pt.mode, kind, _row_status(pt), pt.surface, pt.short_wave_limit)


def _row_status(pt: CurvePoint) -> str:
    """The status column: a failure's message (a bug's with its remedy), else "" or
    "inaccurate", then any note (a switch not located)."""
    if pt.kind == "" and pt.status == Status.ERROR:
        return f"{pt.message} ({pt.remedy})"
    if pt.kind == "":
        return pt.message
    mark = str(Status.INACCURATE) if pt.status == Status.INACCURATE else ""
    return "; ".join(filter(None, (mark, pt.message)))


def _not_located(pt: CurvePoint, prev: CurvePoint, exc: Exception) -> CurvePoint:
    """``pt`` (its status kept) noting that the switch from ``prev`` could not be located;
    a bug is named as one ("internal error: ...", with the bug report's remedy)."""
    why = f"switch from {prev.mode} not located: {_message(exc)}"
    return dataclasses.replace(pt, message="; ".join(filter(None, (pt.message, why))))


class _Locator:
    """Locates the switches between two grid points (see the module docstring)."""

    def __init__(self, params, solve_for, along, side, unit):
        self.params, self.solve_for, self.along, self.side = params, solve_for, along, side
        self.unit = unit  # x -> CurvePoint (a scan)
        self.sense = -1.0 if side == "compression" else 1.0
        self.known: dict[tuple[tuple[int, int], float], tuple[float, str]] = {}

    def _remember(self, pt: CurvePoint):
        if pt.kind == Kind.BIFURCATION:
            self.known[pt.mode, pt.x] = (pt.value, Kind.BIFURCATION)
        for m, n, value in pt.runners_up:
            self.known[(m, n), pt.x] = (value, Kind.BIFURCATION)

    def mode_value(self, mode, x) -> tuple[float, str]:
        """First critical value of ``mode`` at x, by the single-mode march (the threshold,
        kind "threshold", if the base state is lost first: then the mode comes after all)."""
        key = (mode, float(x))
        if key not in self.known:
            at = self.params.at(self.along, x)
            c = critical_value(at, *mode, self.solve_for, side=self.side)
            self.known[key] = (c.value, c.kind)
        return self.known[key]

    def value_of(self, pt: CurvePoint, x) -> float:
        """The critical value at x of what is critical at ``pt``: its mode, or the
        short-wave limit."""
        if pt.kind != Kind.SURFACE:
            return self.mode_value(pt.mode, x)[0]
        key = ("surface", float(x))
        if key not in self.known:
            limit = short_wave_limit(self.params.at(self.along, x), self.solve_for, side=self.side)
            self.known[key] = (limit.value, limit.kind)
        return self.known[key][0]

    def between(self, a: CurvePoint, b: CurvePoint, depth: int):
        """Rows and switches strictly between grid points a and b, in grid order."""
        self._remember(a)
        self._remember(b)
        try:
            kinds = (a.kind, b.kind)
            if Kind.SURFACE in kinds and Kind.THRESHOLD in kinds:  # bisect with scans
                raise ElectrogrowthError("a switch between the short-wave limit and the threshold")
            if Kind.SURFACE in kinds:
                found = self._crossing(a, b)
            elif NO_MODE in (a.mode, b.mode):
                found = self._threshold_switch(a, b)
            else:
                found = self._crossing(a, b)
        except ElectrogrowthError:  # a single-mode solve failed: bisect with scans
            found = self._scan_bisection(a, b)
            if isinstance(found, CurvePoint):
                return self._split(a, found, b, depth)
        if found is None:  # d keeps its sign: a third mode in between; look in the middle
            return self._split(a, self.unit(0.5 * (a.x + b.x)), b, depth)
        x, v_before, v_after = found
        if depth > 0:
            check = self.unit(x)
            first = min(v_before, v_after, key=lambda v: self.sense * v)
            if (
                not _failed(check)
                and check.mode not in (a.mode, b.mode)
                and self.sense * (check.value - first) < -1e-9 * max(1.0, abs(first))
            ):
                return self._split(a, check, b, depth)
        kind = _change_kind(a, b, v_before, v_after)
        rows = [
            (x, v_before, a.mode, kind, "", a.surface, math.nan),
            (x, v_after, b.mode, kind, "", b.surface, math.nan),
        ]
        return rows, [Switch(x, v_before, a.mode, b.mode, v_after, kind)]

    def _split(self, a, mid, b, depth):
        """Locate the switches on both sides of a scanned point ``mid`` (kept as a row)."""
        if depth <= 0 or _failed(mid):
            return [], []
        rows, switches = [], []
        if mid.mode != a.mode:
            rows, switches = self.between(a, mid, depth - 1)
        rows = rows + [_row(mid)]
        if mid.mode != b.mode:
            more_rows, more_switches = self.between(mid, b, depth - 1)
            rows, switches = rows + more_rows, switches + more_switches
        return rows, switches

    def _crossing(self, a, b):
        """(x, value before, value after) where d = s (v_A - v_B) changes sign (Brent), or
        None if it does not. At a jump (a mode's first root appears or vanishes) the two
        values differ: they are taken just before and just after x."""
        from scipy.optimize import brentq

        def d(x):
            return self.sense * (self.value_of(a, x) - self.value_of(b, x))

        if not d(a.x) < 0 < d(b.x):
            return None
        tol = 1e-13 * max(1.0, abs(a.x))
        x = brentq(d, a.x, b.x, xtol=tol, rtol=1e-14, maxiter=100)
        va, vb = self.value_of(a, x), self.value_of(b, x)
        if abs(va - vb) > 1e-9 * max(1.0, abs(va)):  # a jump: one-sided values
            step = math.copysign(4 * tol, b.x - a.x)
            va, vb = self.value_of(a, x - step), self.value_of(b, x + step)
        return x, va, vb

    def _scan_bisection(self, a, b):
        """Fallback: bisect on the mode the scans find, to a relative 1e-7 in x; returns
        (x, value before, value after), or the scanned point where a third mode is first."""
        lo, hi = a, b
        while abs(hi.x - lo.x) > 1e-7 * max(1.0, abs(lo.x)):
            mid = self.unit(0.5 * (lo.x + hi.x))
            if _failed(mid) or mid.mode not in (a.mode, b.mode):
                return mid
            lo, hi = (mid, hi) if mid.mode == a.mode else (lo, mid)
        return 0.5 * (lo.x + hi.x), lo.value, hi.value

    def _threshold_switch(self, a, b):
        """Bisection on 'the non-threshold mode bifurcates before the threshold'."""
        mode = b.mode if a.mode == NO_MODE else a.mode
        good, bad = (b.x, a.x) if a.mode == NO_MODE else (a.x, b.x)
        while abs(bad - good) > 1e-12 * max(1.0, abs(good)):
            mid = 0.5 * (good + bad)
            if self.mode_value(mode, mid)[1] == Kind.BIFURCATION:
                good = mid
            else:
                bad = mid
        value = self.mode_value(mode, good)[0]
        return good, value, value
