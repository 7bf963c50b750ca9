"""The first mode along one design variable: intervals of one pattern and the switches.

``mode_sequence`` runs :func:`bifurcation.critical_curve` over a grid of the design variable
``key`` (any key the tube's ``.at`` accepts) and reads the curve as a sequence of intervals,
each with the pattern that comes first there: a mode (m, n), the exact short-wave limit
("surface") or the loss of the axisymmetric state ("threshold"). The switch between two
intervals is the curve's own location (bifurcation/curves.py): Brent's method on the
two-mode condition s (v_A(x) - v_B(x)) = 0, each v the critical value of one fixed mode, to
an x tolerance of 1e-13 relative, with the error estimate that the values' own give x
(``x_error``: far above the tolerance between neighbouring folds, docs/design.md); it is not
computed a second time here. Where a grid
point's scan fails (the tube already unstable at the control's start, no state) next to
one that succeeds, the curve also locates the end of the valid range (``edges=True``:
bisection on "the scan succeeds" to the same tolerance), an "end" to or from no mode, so
an interval next to a failed one is not cut at the grid point; and between a tube already
unstable at the control's start and one that wrinkles in no mode before its end, the valid
window in which the critical value runs through the control's range is searched.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..bifurcation.curves import Curve, check_curve, critical_curve
from ..bifurcation.scan import ScanOptions
from ..errors import ElectrogrowthError, NoBifurcationFound, ParameterError
from ..model.controls import parse_control
from ..model.keys import layer_key
from ..model.layers import KEYS_TEXT
from ..outcomes import NO_MODE, Kind, Status, json_number

MIN_POINTS, MAX_POINTS = 2, 2001


@dataclasses.dataclass(frozen=True)
class Interval:
    """``key`` in [lo, hi] (in the order of the grid, lo < hi) has ``mode`` (m, n) first,
    kind "bifurcation"; or kind "surface" (the short-wave limit), "threshold" (no mode
    before the axisymmetric state is lost) or "failed" (mode (-1, -1)). ``lo_edge`` and
    ``hi_edge`` say whether an end is the end of the searched range (else a located switch,
    also one located at the range's end, a tie there: next to a failed interval, the
    located end of the valid range, a switch to "no design"). A failed interval's
    ``failure`` is the kind of its scans' failure (the error's class: "UnstableAtStart",
    the tube already unstable at the control's start; "NoBifurcationFound", no mode
    before the control's end; "BaseStateError", no state; ...) and ``reason`` the first
    one's message; failures of two kinds are two intervals (the change between them
    located where they bound a valid window, bifurcation/curve_switches.py, else not: a
    gap between the two)."""

    lo: float
    hi: float
    mode: tuple[int, int]
    kind: str
    lo_edge: bool = False
    hi_edge: bool = False
    failure: str = ""
    reason: str = ""

    def contains(self, x: float) -> bool:
        return self.lo <= x <= self.hi

    def as_dict(self) -> dict:
        finite = self.kind == Kind.BIFURCATION
        return {
            "lo": self.lo,
            "hi": self.hi,
            "mode": list(self.mode) if finite else None,
            "kind": str(self.kind),
            "lo_edge": self.lo_edge,
            "hi_edge": self.hi_edge,
            "failure": self.failure or None,
            "reason": self.reason or None,
        }


@dataclasses.dataclass(frozen=True)
class SequenceSwitch:
    """The first pattern changes at ``x`` from ``mode_before`` to ``mode_after`` (grid
    order; (-1, -1): the short-wave limit or the threshold). ``kind`` "switch": both are
    equally critical there, at ``value``; "end": the branch before ends without a crossing
    (a jump: ``value`` and ``value_after`` are the one-sided limits, or the threshold).
    ``x_error``, ``value_error``: their error estimates (NaN: not known; the curve's
    :class:`~electrogrowth.bifurcation.curve_record.Switch`)."""

    x: float
    mode_before: tuple[int, int]
    mode_after: tuple[int, int]
    value: float
    value_after: float
    kind: str
    x_error: float = math.nan
    value_error: float = math.nan

    def as_dict(self) -> dict:
        return {
            "x": self.x,
            "mode_before": list(self.mode_before),
            "mode_after": list(self.mode_after),
            "value": json_number(self.value),  # NaN on an end's failed side
            "value_after": json_number(self.value_after),
            "kind": str(self.kind),
            "x_error": json_number(self.x_error),
            "value_error": json_number(self.value_error),
        }


@dataclasses.dataclass(frozen=True)
class ModeSequence:
    """Result of :func:`mode_sequence`: the intervals of ``key`` in [lo, hi] with their first
    pattern, in increasing ``key``, the switches between them, and the underlying curve."""

    key: str
    lo: float
    hi: float
    solve_for: str
    side: str | None
    intervals: tuple[Interval, ...]
    switches: tuple[SequenceSwitch, ...]
    curve: Curve

    def interval_at(self, x: float) -> Interval | None:
        """The (first) interval holding x, or None."""
        return next((iv for iv in self.intervals if iv.contains(x)), None)

    def sides(self, change: SequenceSwitch) -> tuple[Interval, Interval]:
        """The intervals just before and just after ``change``, one of the ``switches``
        (an end's failed side begins or ends at the last failed scan, within SWITCH of it:
        the first interval from its x on that holds its mode after)."""
        after = [k for k, iv in enumerate(self.intervals) if k and iv.lo >= change.x]
        k = next((k for k in after if self.intervals[k].mode == change.mode_after), None)
        k = k if k is not None else (after[0] if after else len(self.intervals) - 1)
        return self.intervals[max(k - 1, 0)], self.intervals[k]

    def as_dict(self) -> dict:
        return {
            "key": self.key,
            "range": [self.lo, self.hi],
            "solve_for": self.solve_for,
            "side": self.side,
            "intervals": [iv.as_dict() for iv in self.intervals],
            "switches": [s.as_dict() for s in self.switches],
        }

    def to_xarray(self):
        """Intervals (dimension interval) and switches (dimension switch) as an
        ``xarray.Dataset`` (needs xarray, the ``sweep`` extra)."""
        from ..labelled import xarray

        xr = xarray()
        key = {"units": "1", "long_name": f"design variable {self.key}"}
        value = {"units": "1", "long_name": f"critical {self.solve_for} at the switch"}
        mode = {"units": "1", "long_name": "(m, n); (-1, -1): no finite mode"}
        return xr.Dataset(
            {
                "lo": ("interval", [iv.lo for iv in self.intervals], key),
                "hi": ("interval", [iv.hi for iv in self.intervals], key),
                "mode": (
                    ("interval", "mn"),
                    np.array([iv.mode for iv in self.intervals], int).reshape(-1, 2),
                    mode,
                ),
                "kind": ("interval", [str(iv.kind) for iv in self.intervals]),
                "switch_x": ("switch", [s.x for s in self.switches], key),
                "switch_value": ("switch", [s.value for s in self.switches], value),
                "switch_mode_before": (
                    ("switch", "mn"),
                    np.array([s.mode_before for s in self.switches], int).reshape(-1, 2),
                    mode,
                ),
                "switch_mode_after": (
                    ("switch", "mn"),
                    np.array([s.mode_after for s in self.switches], int).reshape(-1, 2),
                    mode,
                ),
                "switch_kind": ("switch", [str(s.kind) for s in self.switches]),
                "switch_x_error": (
                    "switch",
                    [s.x_error for s in self.switches],
                    {**key, "long_name": f"error estimate of {self.key} at the switch"},
                ),
                "switch_value_error": (
                    "switch",
                    [s.value_error for s in self.switches],
                    {**value, "long_name": "error estimate of the critical value at the switch"},
                ),
            },
            attrs={"key": self.key, "solve_for": self.solve_for, "side": self.side or ""},
        )


def check_vary(vary, tube=None, solve_for: str | None = None) -> tuple[str, float, float]:
    """(key, lo, hi) with lo < hi finite, or ParameterError; with ``tube`` and
    ``solve_for`` also a key of the tube other than the unknown, at both ends in range."""
    if not isinstance(vary, (tuple, list)) or len(vary) != 3 or not isinstance(vary[0], str):
        raise ParameterError(f"vary = {vary!r} is invalid; give (key, lo, hi)")
    key, lo, hi = vary
    ok = all(
        not isinstance(v, bool) and isinstance(v, (int, float)) and math.isfinite(v)
        for v in (lo, hi)
    )
    if not ok or not lo < hi:
        raise ParameterError(
            f"vary range {lo!r} to {hi!r} of {key} is invalid; need finite numbers lo < hi"
        )
    if tube is not None:
        try:
            tube.value_of(key)
        except (ParameterError, AttributeError):
            raise ParameterError(
                f"vary key {key!r} is not a key of this tube; valid: a control (growth[K],"
                f" growth[K].theta, stretch, voltage, pressure, force) or {KEYS_TEXT}"
            ) from None
        if solve_for is not None:
            check_curve(solve_for, key, tube)
        tube.at(key, lo)
        tube.at(key, hi)
    return key, float(lo), float(hi)


def shared_variable(tube, key_x: str, key_y: str) -> str | None:
    """The number of ``tube`` that the keys ``key_x`` and ``key_y`` both set, as
    :meth:`Tube.at <electrogrowth.model.layers.Tube.at>` resolves them, or None: a map over
    one number under two names (``outer_radius`` and ``layers[N].outer_radius``, ``growth``
    and ``growth[1].theta``) has no effect along one axis and reports a design that
    contradicts itself (probe 10b D3), so the names, not the strings, must differ."""
    common = _numbers_set(tube, key_x) & _numbers_set(tube, key_y)
    return min(common) if common else None


def _numbers_set(tube, key: str) -> set[str]:
    """The tube's numbers ``tube.at(key, v)`` sets, each by one name."""
    n = len(tube.layers)
    if key == "outer_radius":  # Tube.at's alias, for any number of layers
        return {f"layers[{n}].outer_radius"}
    k_field = layer_key(key)
    if k_field is not None:
        k, field = k_field
        if (k, field) == (n, "thickness"):  # the outermost layer's sets the outer radius
            field = "outer_radius"  # (an inner one's also moves the layers outside it)
        return {f"layers[{k}].{field}"}
    try:
        c = parse_control(key)
    except ParameterError:  # a key (length, outer_pressure): its own name
        return {key}
    if c.kind != "growth":
        return {c.kind}
    comps = c.components or ("r", "theta", "z")  # growth alone sets every component
    return {f"growth[{c.layer or 1}].{comp}" for comp in comps}


def check_points(points) -> int:
    if isinstance(points, bool) or not isinstance(points, int):
        raise ParameterError(f"points = {points!r} is not an integer")
    if not MIN_POINTS <= points <= MAX_POINTS:
        raise ParameterError(
            f"points = {points} is out of range; valid range: {MIN_POINTS} to {MAX_POINTS}"
        )
    return points


def mode_sequence(
    tube,
    solve_for: str,
    vary: tuple[str, float, float],
    *,
    side: str | None = None,
    options: ScanOptions = ScanOptions(),
    points: int = 9,
    progress=None,
    resume: Curve | None = None,
) -> ModeSequence:
    """The first pattern as the design variable runs over [lo, hi], switches located.

    Parameters
    ----------
    tube : Tube
        The tube; ``solve_for`` is the unknown, ``vary[0]`` is overridden.
    solve_for : str
        The control whose critical value decides which pattern comes first (as in
        :func:`scan_modes`; ``side`` for the stretch, pressure and force).
    vary : (key, lo, hi)
        The design variable: any control or key ``tube.at`` accepts (outer_radius,
        length, growth, stretch, voltage, layers[K].thickness, ... see :meth:`Tube.at`),
        and its range.
    options : ScanOptions
        The modes each scan examines.
    points : int
        Grid points, evenly spaced on [lo, hi], scanned (or followed) before the switches
        between them are located; an interval narrower than the spacing can be missed.
        Next to a grid point whose scan fails, the end of the valid range is located (an
        "end" switch to or from no mode, mode (-1, -1)).
    resume : Curve, optional
        The ``partial`` curve of an interrupted sequence of the same tube and grid: its
        finished scans are taken as computed (:func:`~electrogrowth.critical_curve`).

    Returns
    -------
    ModeSequence

    Examples
    --------
    >>> from electrogrowth import ScanOptions, Tube
    >>> seq = mode_sequence(Tube.uniform(), "stretch", ("outer_radius", 1.2, 1.3),
    ...                     side="compression", points=2, options=ScanOptions((0, 2), (1, 2)))
    >>> [(iv.mode, round(iv.lo, 6), round(iv.hi, 6)) for iv in seq.intervals]
    [((1, 1), 1.2, 1.256361), ((0, 1), 1.256361, 1.3)]
    """
    key, lo, hi = check_vary(vary, tube, solve_for)
    points = check_points(points)
    xs = np.linspace(lo, hi, points)
    curve = critical_curve(
        tube, solve_for, key, xs, side=side, options=options, progress=progress, edges=True,
        resume=resume,
    )  # fmt: skip
    return from_curve(curve, key, lo, hi)


def _label(curve: Curve, i: int) -> tuple[tuple[int, int], str, str]:
    """The pattern of row i: (mode, kind, failure) with kind bifurcation, surface,
    threshold or failed (and then the failure's kind); a switch or end row takes its
    mode's kind."""
    mode = (int(curve.m[i]), int(curve.n[i]))
    if curve.kind[i] == Status.FAILED:
        return NO_MODE, str(Status.FAILED), curve.failure[i]
    if bool(curve.surface[i]):
        return NO_MODE, str(Kind.SURFACE), ""
    if mode == NO_MODE:
        return NO_MODE, str(Kind.THRESHOLD), ""
    return mode, str(Kind.BIFURCATION), ""


def from_curve(curve: Curve, key: str, lo: float, hi: float) -> ModeSequence:
    """The intervals of constant first pattern (and kind of failure) of a curve, and its
    located changes."""
    runs: list[list] = []  # [(mode, kind, failure), x_first, x_last, reason]
    for i, x in enumerate(curve.x):
        label = _label(curve, i)
        if runs and runs[-1][0] == label:
            runs[-1][2] = float(x)
        else:
            runs.append([label, float(x), float(x), str(curve.status[i]) if label[2] else ""])
    changes = sorted(curve.switches + curve.ends, key=lambda s: s.x)
    # a switch located at an end of the range (a tie there) bounds its interval as a switch
    located = {float(s.x) for s in changes}
    intervals = tuple(
        Interval(
            a,
            b,
            mode,
            kind,
            a == lo and a not in located,
            b == hi and b not in located,
            failure,
            reason,
        )
        for (mode, kind, failure), a, b, reason in runs
    )
    switches = tuple(
        SequenceSwitch(
            s.x,
            s.mode_before,
            s.mode_after,
            s.value,
            s.value_after,
            s.kind,
            s.x_error,
            s.value_error,
        )
        for s in changes
    )
    return ModeSequence(key, lo, hi, curve.solve_for, curve.side, intervals, switches, curve)


def no_design_ends(sequence: ModeSequence) -> frozenset:
    """The located ends of the valid range: the ends of the intervals next to a failed
    one (beyond them the tube is already unstable at the control's start, or has no
    state: a switch to "no design"). Not an end beyond which no mode bifurcates before the
    control's end: there the target's onset rises to that end, not down to the start, and
    the room up to it is the gap (design/margins.py M_e)."""
    ivs = sequence.intervals
    out = set()
    for a, b in zip(ivs, ivs[1:]):
        failed = a if a.kind == Status.FAILED else b
        if (a.kind == Status.FAILED) != (b.kind == Status.FAILED) and (
            failed.failure != NoBifurcationFound.__name__
        ):
            out.add(b.lo if failed is a else a.hi)
    return frozenset(out)


def mode_values(tube, solve_for: str, key: str, modes, xs, *, side: str | None = None) -> dict:
    """{(m, n): array of the first critical value of that mode at each ``key`` = x of
    ``xs``} (NaN where the mode does not wrinkle before the threshold, or fails): the
    competing branches behind a :class:`ModeSequence`, e.g. for its plot."""
    from ..bifurcation.critical import critical_value

    out = {}
    for mode in modes:
        vals = []
        for x in xs:
            try:
                c = critical_value(tube.at(key, x), mode[0], mode[1], solve_for, side=side)
                vals.append(c.value if c.kind == Kind.BIFURCATION else math.nan)
            except ElectrogrowthError:
                vals.append(math.nan)
        out[tuple(mode)] = np.array(vals)
    return out
