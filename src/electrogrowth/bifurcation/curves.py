"""Critical value along a parameter, with the switches of the critical mode located.

A curve is ``x -> value(x)``: the critical ``solve_for`` ("growth", "stretch" or "voltage",
as in :func:`scan.scan_modes`) minimised over the modes (m, n) while the parameter ``along``
(any other control or key of the :class:`Tube`) runs over a grid. Each grid point is one mode
scan (:func:`curve_point`, a pure picklable function, so a process pool's ``map`` can run
them). Between two grid points whose critical modes differ, A at x_a and B at x_b, the
switch is located exactly (bifurcation/curve_switches.py):

* two wrinkling modes: Brent's method on d(x) = s (v_A(x) - v_B(x)), with v the first
  critical value of one mode (:func:`bifurcation.critical_value`; the threshold value when
  the mode is not reached before it) and s = +1, or -1 for the stretch in compression (there
  the first mode reached is the largest lambda_z). Where a mode's first critical value
  jumps (a window of instability opens), d jumps too and the switch is that jump;
* a mode and the threshold (the axisymmetric state is lost first): bisection on whether the
  mode still bifurcates before the threshold;
* the exact short-wave limit and the threshold (neither a mode, both m = n = -1): bisection
  on whether the limit's march meets a face's instability before the state is lost.

A change with equal values on both sides, between two wrinkling modes (or a mode and the
short-wave limit), is a "switch"; one where the value jumps, or the threshold is on one side,
is the "end" of a branch (:class:`Switch`, ``Curve.ends``). The located switch is checked by
a scan there; if a third mode comes first, the interval is
split at it and both halves are located again. If a single-mode solve fails (e.g. the
kernel cannot integrate a high mode next to the threshold), the switch is bisected with
scans instead, to a relative 1e-7 only. A point whose scan fails (e.g. the tube is
already unstable at the start of the march) is kept as kind "failed" with its message (kind
"error": an unexpected exception, a bug); with ``edges=True`` (the design's mode sequence)
the end of the valid range next to it is located too, by bisection on "the scan
succeeds", and kept as an "end" to or from no mode; failures of different kinds are kept
apart, and between a tube already unstable at the control's start and one with no mode
before the control's end the valid window is searched (curve_switches.py). An interrupt
(Ctrl-C, SIGTERM) is never a failed point: it ends the curve with
:class:`~electrogrowth.interrupts.Interrupted`, whose ``partial`` holds the grid points
computed before it.

By continuation (``follow``, the default with the builtin ``map``), the grid points between
full scans are not scanned: the last scan's critical mode and runners-up are followed
(bifurcation/curve_follow.py: each mode's value predicted from its previous points, then one
bracketed solve of the one predicted first; or the exact short-wave limit, if it came
first), and the result is accepted only if every mode of the scan's grid is still on its
stable side (its sign on the unloaded tube, loose targets, as in the scan's march) just
before it, no face is past its short-wave limit (for a mode), and the mode is not on the
edge of the ranges; otherwise, at the ends and every CHECK_EVERY points the point is a
full scan. Switches are located and checked by scans as
before, so the curve equals the curve of full scans. Last, at every row, where a free face
creases along the same control and whether that comes before the wrinkle
(bifurcation/curve_crease.py: the crease criterion's march, cheap next to a scan). The
records (grid point, switch, curve and its CSV) are in bifurcation/curve_record.py.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable

import numpy as np

from ..errors import ParameterError
from ..interrupts import Interrupted, interrupt_of, reraise_interrupt
from ..model.controls import SIDED, check_side
from ..model.layers import KEYS_TEXT, Tube
from ..outcomes import NO_MODE, Kind
from .critical import critical_value
from .curve_crease import crease_along
from .curve_follow import CHECK_EVERY, _Follower
from .curve_record import (
    Curve,
    CurvePoint,
    Switch,
    _changes,
    _edge,
    _failed,
    _failed_point,
    _not_located,
    _row,
    _scan_point,
)
from .curve_switches import _Locator
from .problem import DEFAULT_RTOL, Problem, as_problem
from .scan import ScanOptions, scan_modes
from .surface import short_wave_limit

__all__ = [
    "CHECK_EVERY",
    "MAX_POINTS",
    "Curve",
    "CurvePoint",
    "Switch",
    "check_curve",
    "critical_curve",
    "curve_point",
]

MAX_SPLITS = 6  # depth of the re-location when a third mode intervenes
MAX_POINTS = 10_000  # grid points of a curve (each a mode scan, ~1 s): hours at most


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


def _progress_bar(total: int, desc: str, unit: str = "pt"):
    """A tqdm.auto bar (a notebook widget or text on stderr)."""
    from tqdm.auto import tqdm

    return tqdm(total=total, desc=desc, unit=unit)


def _critical_text(pt: CurvePoint) -> str:
    """What is critical at a grid point, in a progress message."""
    if _failed(pt):
        return "a failed scan"
    if pt.kind == Kind.SURFACE:
        return "the short-wave limit"
    return "the threshold" if pt.mode == NO_MODE else str(pt.mode)


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
    params: Tube | Problem,
    solve_for: str,
    along: str | Iterable[float],
    values: Iterable[float] | None = None,
    *,
    side: str | None = None,
    options: ScanOptions | None = None,
    progress: bool | Callable[[int], object] | None = None,
    mapper: Callable = map,
    follow: bool = True,
    edges: bool = False,
    resume: Curve | None = None,
) -> Curve:
    """Critical ``solve_for`` as ``along`` runs over ``values``, switches located.

    ``critical_curve(problem, along, values)`` takes the tube, the control, the side and
    the scan options from a :class:`~.problem.Problem` (at the default accuracy, the
    curve's); ``critical_curve(tube, solve_for, along, values, side=..., options=...)``
    is the keyword form.

    Parameters
    ----------
    params : Tube or Problem
        The fixed parameters; fields ``along`` and ``solve_for`` are overridden. Or a
        Problem (then ``solve_for`` is left out, ``side`` and ``options`` too).
    solve_for : {"growth", "stretch", "voltage"}
        The unknown, as in :func:`scan.scan_modes` (``side`` for the stretch).
    along : {"stretch", "voltage", "outer_radius", "length", "growth"}
        The parameter of the abscissa; not ``solve_for``.
    values : sequence of float
        Strictly monotone grid of ``along``.
    options : ScanOptions, optional
        Mode ranges of each scan (extended automatically when the optimum is on an edge;
        default ScanOptions()).
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
    edges : bool
        Also locate, between a failed grid point and a valid neighbour, where the scans
        start to succeed (bisection to the switches' tolerance, some 40 scans per edge):
        an "end" in ``Curve.ends`` whose failed side has mode (-1, -1) and value NaN, with
        the last failed and the first valid scan as rows; and between a tube already
        unstable at the control's start and one with no mode before the control's end
        (two grid points, or two scans of that bisection: ``Curve.failure``) the valid
        window where the critical value runs through the control's range, and its ends
        (curve_switches.py). False (default): the valid range ends at the grid point.
    resume : Curve, optional
        An earlier curve of the same tube, control and side (e.g. the ``partial`` of an
        :class:`~electrogrowth.interrupts.Interrupted` one): its grid points (``grid``)
        at the leading ``values`` are taken as computed, the rest computed (the first of
        them by a full scan), and the switches located over the whole grid.

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
    if isinstance(params, Problem):
        if values is not None:
            raise ParameterError(
                "critical_curve(problem, along, values): solve_for is the problem's"
            )
        problem, along, values = as_problem(params, side=side, options=options), solve_for, along
        if problem.rtol != DEFAULT_RTOL:
            raise ParameterError(
                f"rtol = {problem.rtol!r}: critical_curve runs at the default {DEFAULT_RTOL:g}"
            )
        params, solve_for, side, options = (
            problem.tube,
            problem.control,
            problem.side,
            problem.options,
        )
    if values is None:
        raise ParameterError("critical_curve(tube, solve_for, along, values): values missing")
    options = ScanOptions() if options is None else options
    check_curve(solve_for, along, params)
    solve_for = str(params.check_control(solve_for))
    side = check_side(solve_for, side)
    if side is not None and solve_for not in SIDED:
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
    points = _resumed(resume, xs, (along, solve_for, side, params))
    rest = xs[len(points) :]
    if follow and mapper is map:
        solvers = dict(scan=scan_modes, solve=critical_value, limit=short_wave_limit)
        follower = _Follower(params, solve_for, along, side, options, unit, **solvers)
        ends = (0, rest.size - 1)  # a full scan first: a resumed grid has no scan to follow
        computed = (follower.point(x, i in ends) for i, x in enumerate(rest))
    else:
        computed = mapper(unit, rest)
    bar = _progress_bar(xs.size, f"{solve_for} along {along}") if progress is True else None
    if bar is not None:
        bar.update(len(points))
    try:
        for pt in computed:
            points.append(pt)
            if bar is not None:
                bar.update(1)
            elif callable(progress):
                progress(1)
        if bar is not None:
            bar.close()
        loc = _Locator(
            params, solve_for, along, side, unit, solve=critical_value, limit=short_wave_limit
        )
        rows, switches = _located(points, loc, progress, edges)
        xs_rows, values = [r[0] for r in rows], [r[1] for r in rows]
        crease = crease_along(params, solve_for, along, side, xs_rows, values)
    except (KeyboardInterrupt, Exception) as exc:  # an interrupt, maybe wrapped by the kernel:
        stop = interrupt_of(exc)  # hand back the finished grid points, switches not located
        if stop is None:
            raise
        partial = grid_curve(along, solve_for, side, params, points)
        raise Interrupted(stop.signum, str(stop), partial=partial) from None
    finally:
        if bar is not None:
            bar.close()
    return _curve(along, solve_for, side, params, rows, switches, crease, grid=points)


def grid_curve(along: str, solve_for: str, side, params: Tube, points) -> Curve:
    """The curve of grid points alone (no switch located, no crease): what an interrupted
    curve hands back, and what ``critical_curve(..., resume=...)`` takes (the control's
    name and side as critical_curve reads them)."""
    solve_for = str(params.check_control(solve_for))
    side, points = check_side(solve_for, side), list(points)
    return _curve(along, solve_for, side, params, [_row(p) for p in points], [], grid=points)


def _resumed(resume: Curve | None, xs: np.ndarray, what: tuple) -> list[CurvePoint]:
    """The grid points of ``resume`` at the leading values of ``xs`` (the same numbers),
    after checking it is a curve of the same (along, solve_for, side, tube)."""
    if resume is None:
        return []
    if (resume.along, resume.solve_for, resume.side, resume.params) != what:
        raise ParameterError(
            "resume is a curve of another tube, control or side: "
            f"{resume.solve_for} along {resume.along} (side {resume.side}), not"
            f" {what[1]} along {what[0]} (side {what[2]}) of this tube"
        )
    done = []
    for pt, x in zip(resume.grid, xs):
        if pt.x != x:
            break
        done.append(pt)
    return done


def _located(points: list[CurvePoint], loc: _Locator, progress=None, edges: bool = False):
    """The rows of the grid points with the located switches between them (and, with
    ``edges``, the ends of the valid range next to failed points), and the switches (a
    progress bar of its own when ``progress`` is True)."""
    rows, switches = [], []
    pairs = list(zip(points[:-1], points[1:]))
    located = sum(_changes(a, b) or (edges and _edge(a, b)) for a, b in pairs)
    bar = None
    if progress is True and located:  # locating can take far longer than the grid
        bar = _progress_bar(located, "locating mode switches", "switch")
    try:
        for i, pt in enumerate(points):
            prev = points[i - 1] if i else None
            edge = edges and prev is not None and _edge(prev, pt)
            if prev is not None and (_changes(prev, pt) or edge):
                if bar is not None:
                    bar.set_postfix_str(f"between {_critical_text(prev)} and {_critical_text(pt)}")
                try:
                    locate = loc.edge if edge else loc.between
                    new_rows, new_switches = locate(prev, pt, MAX_SPLITS)
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


def _curve(along, solve_for, side, params, rows, switches, crease=None, grid=()) -> Curve:
    """The Curve of table rows (as :func:`_row`) and switches (and ends), with the crease
    at each row (None: not computed) and the ``grid`` points they were made of."""
    x, v, modes, kinds, status, surface, limit, failure, face = zip(*rows) if rows else [()] * 9
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
        crease,
        tuple(failure),
        tuple(face),
        tuple(grid),
    )
