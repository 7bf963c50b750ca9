"""Where the critical mode of a curve changes between two grid points (bifurcation/curves.py).

Between two wrinkling modes A and B: Brent's method (continuation.events.brent, tolerance
SWITCH) on d(x) = s (v_A(x) - v_B(x)), v a mode's first critical value (or the short-wave
limit); where d jumps (a window of instability opens) the switch is that jump. Between a
mode and the threshold: bisection (continuation.events.bisect, MODE_EDGE) on whether the
mode still bifurcates before the threshold; between the short-wave limit and the threshold
(both m = n = -1: what is critical is compared, ``curve_record._critical``), the same
bisection on whether the limit's march meets a face's instability first (an "end": the
threshold wrinkles in no mode). A located switch is checked by a scan there;
a third mode found first splits the interval (at most MAX_SPLITS times; then the switch is
bisected with scans, or the point says it was not located: never dropped). The sign of d
at the grid points is that of the scans' values, and where they show no sign change, that
of single-mode solves: two modes that tie at a grid point (TIE) switch there. A mode with
no root before the end of the march is read as coming after all (+-inf in d). If a
single-mode solve fails, the switch is bisected with scans, to a relative 1e-7 only.

Each change carries error estimates (``Switch.x_error``, ``value_error``): at a crossing,
Brent's tolerance plus (e_A + e_B) / |d'| (the two values' own estimates move the root of d
that much; between nearly parallel neighbouring folds, far more than the tolerance: check
round 16c), d' the secant of the values already solved nearest to x on either side above
that noise; the value's, the larger estimate plus the values' slope times the x error. A
crossing of two modes whose x error is above REFINE_ABOVE is refined once the scan there
confirms it: the two modes solved again at the finest rtol either side of x, and the root
of the line through them. A
bisection's change: its last bracket, and the value's own estimate.

Between a grid point whose scan failed (the tube already unstable at the control's start,
no base state, no mode before the control's end, ...) and one whose scan succeeded, on
request (``critical_curve(..., edges=True)``, the design's mode sequence): the end of the
valid range, by bisection on "the scan succeeds" to the switches' tolerance (SWITCH), kept
as an "end" from or to no mode; then the switches between that end and the valid grid
point, as above. Failures of different kinds are kept apart (``CurvePoint.failure``), and
between a tube already unstable at the control's start and one that wrinkles in no mode
before the control's end, where the critical value runs through the control's whole
range, the valid window is searched: bisection on the kind of failure until a scan
succeeds, whose two ends are then located as above (probe 14d, D1: the two failures were
taken for one, the window missed).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..continuation.events import MODE_EDGE, SWITCH, bisect, brent
from ..errors import ConvergenceError, ElectrogrowthError, NoBifurcationFound
from ..incremental.accuracy import RTOL_RANGE
from ..outcomes import NO_MODE, Kind, Status
from .curve_record import (
    CurvePoint,
    Switch,
    _change_kind,
    _changes,
    _critical,
    _edge,
    _failed,
    _fails_alike,
    _row,
    _window_between,
)
from .start_edge import start_root

#: the value recorded on the failed side of a located edge of the valid range
NO_VALUE = math.nan
#: two single-mode critical values this close (relative) at a grid point, in the wrong order,
#: tie there: the switch is the grid point (each is converged to ~10 rtol = 1e-11; in probe
#: 9b's D1 they were 5e-16 apart, the scan's runner-up 5e-12 off)
TIE = 1e-9
#: a secant of d for the x error spans values whose |d| is this many times their noise
#: (e_A + e_B): its slope is then good to ~25 %, as an error estimate needs
ABOVE_NOISE = 8.0
#: a crossing whose x_error exceeds this (relative to |x|, or 1e-6 of the grid's spacing
#: where x is near 0) is refined: its two
#: modes solved again at FINEST (between neighbouring folds x_error ~1e-7 at the default
#: rtol, ~1e-9 after)
REFINE_ABOVE = 1e-9
FINEST = RTOL_RANGE[0]
#: the distance (relative to |x|, as REFINE_ABOVE) of the scan whose secant carries an end's value
#: to its located x (:meth:`_Locator._end_at`)
SECANT = 1e-4


class Located(NamedTuple):
    """A change located between two grid points: at ``x`` (+- ``x_error``), the critical
    value just before and just after (+- ``value_error``)."""

    x: float
    before: float
    after: float
    x_error: float = math.nan
    value_error: float = math.nan
    #: a crossing by Brent's method inside the interval, refined once it is confirmed
    refine: bool = False


class _Locator:
    """Locates the switches between two grid points (see the module docstring)."""

    def __init__(self, params, solve_for, along, side, unit, *, solve, limit):
        self.params, self.solve_for, self.along, self.side = params, solve_for, along, side
        self.unit = unit  # x -> CurvePoint (a scan)
        self.critical_value, self.short_wave_limit = solve, limit  # from curves.py
        self.sense = -1.0 if side == "compression" else 1.0
        # (mode or "surface", x) -> (value, kind, error estimate): every value solved
        self.known: dict[tuple, tuple[float, str, float]] = {}

    def _remember(self, pt: CurvePoint):
        if pt.kind == Kind.BIFURCATION:
            self.known[pt.mode, pt.x] = (pt.value, Kind.BIFURCATION, pt.error_estimate)
        for m, n, value in pt.runners_up:
            self.known[(m, n), pt.x] = (value, Kind.BIFURCATION, math.nan)

    def mode_value(self, mode, x) -> tuple[float, str, float]:
        """First critical value of ``mode`` at x, by the single-mode march, its kind and
        error estimate (the threshold, kind "threshold", if the base state is lost first:
        then the mode comes after all; +-inf in the march's direction, kind "none", if it
        has no root before the end of the march)."""
        key = (mode, float(x))
        if key not in self.known:
            at = self.params.at(self.along, x)
            try:
                c = self.critical_value(at, *mode, self.solve_for, side=self.side)
                self.known[key] = (c.value, c.kind, c.error_estimate)
            except NoBifurcationFound:
                # Not a failure: the mode comes after every other, which is all the sign of
                # d (Brent's bracket) needs, as in design/margins.py. Falling back to scans
                # here located a regular crossing to 1e-7 only, as an "end" (probe 8b, D3).
                self.known[key] = (self.sense * math.inf, Kind.NONE, math.nan)
        return self.known[key]

    def value_of(self, pt: CurvePoint, x) -> float:
        """The critical value at x of what is critical at ``pt``: its mode, or the
        short-wave limit."""
        return self._solved(pt, x)[0]

    def error_of(self, pt: CurvePoint, x) -> float:
        """The error estimate of :meth:`value_of` (NaN: a scan's runner-up, not known)."""
        return self._solved(pt, x)[2]

    def _solved(self, pt: CurvePoint, x) -> tuple[float, str, float]:
        if pt.kind != Kind.SURFACE:
            return self.mode_value(pt.mode, x)
        return self.limit_value(x)

    def limit_value(self, x) -> tuple[float, str, float]:
        """The short-wave limit at x: its value, kind ("surface", or "threshold" where the
        base state is lost first) and error estimate."""
        key = ("surface", float(x))
        if key not in self.known:
            limit = self.short_wave_limit(
                self.params.at(self.along, x), self.solve_for, side=self.side
            )
            self.known[key] = (limit.value, limit.kind, limit.error_estimate)
        return self.known[key]

    def between(self, a: CurvePoint, b: CurvePoint, depth: int):
        """Rows and switches strictly between grid points a and b, in grid order."""
        self._remember(a)
        self._remember(b)
        try:
            kinds = (a.kind, b.kind)
            if Kind.SURFACE in kinds and Kind.THRESHOLD in kinds:
                found = self._limit_threshold_switch(a, b)
            elif Kind.SURFACE in kinds:
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
        if depth > 0:
            check = self.unit(found.x)
            first = min(found.before, found.after, key=lambda v: self.sense * v)
            if (
                not _failed(check)
                and _critical(check) not in (_critical(a), _critical(b))
                and self.sense * (check.value - first) < -1e-9 * max(1.0, abs(first))
            ):
                return self._split(a, check, b, depth)
        if found.refine:  # confirmed: no third mode first there
            found = self._refined(a, b, found, *sorted((a.x, b.x)))
        return _switch_at(a, b, found)

    def edge(self, a: CurvePoint, b: CurvePoint, depth: int):
        """Rows and changes strictly between neighbours a and b of which one failed and the
        other not, or both failed in different ways (:func:`_edge`).

        One failed: bisection on "the scan succeeds" (SWITCH's tolerance): the last failed
        and the first valid scan are rows, the "end" between them (at the valid one, NaN on
        the failed side), then the switches from there to the valid neighbour. The failed
        scans of the bisection are points of the curve too where their kind of failure
        changes, and between a tube unstable at the control's start and one with no mode
        before its end the window is searched (:meth:`_window`): the bisection took two
        such failures for one and missed the window between them (probe 14d, D1). Both
        failed: that window, where their kinds bound one; else nothing (two failures, the
        change between them not located)."""
        if _failed(a) and _failed(b):
            return self._window(a, b, depth) if _window_between(a, b) else ([], [])
        good, bad = (b, a) if _failed(a) else (a, b)
        scanned = {good.x: good, bad.x: bad}

        def succeeds(x):
            scanned[x] = self.unit(x)
            return not _failed(scanned[x])

        x_good, x_bad = bisect(succeeds, good.x, bad.x, SWITCH)
        end, last_failed = scanned[x_good], scanned[x_bad]
        rows, switches = [], []
        if end is not good and _critical(end) != _critical(good):
            rows, switches = self.between(*((end, good) if good is b else (good, end)), depth)
        sense = b.x - a.x  # the grid's order
        failed = sorted((p for p in scanned.values() if _failed(p)), key=lambda p: sense * p.x)
        more_rows, more_switches = self._chain(_kind_changes(failed), depth)
        x_end, value, errors = self._end_at(end, last_failed, scanned, (good.x, bad.x))
        # the rows of the two last scans, each on its side of the located end (a scan's
        # start check reads loose signs: next to the root either can be past it, then its
        # row is at the end, as a crossing's two rows are)
        inner = []
        if last_failed is not bad:
            at = last_failed.x if _between(last_failed.x, bad.x, x_end) else x_end
            inner.append((at, *_row(last_failed)[1:]))
        if end is not good:  # the end's row where the end was located
            inner.append((x_end, value, *_row(end)[2:]))
        if good is b:  # failed before, valid after: the valid range starts at x_good
            rows = more_rows + inner + rows
            change = Switch(x_end, NO_VALUE, NO_MODE, end.mode, value, Kind.END, *errors)
        else:
            rows = rows + inner[::-1] + more_rows
            change = Switch(x_end, value, end.mode, NO_MODE, NO_VALUE, Kind.END, *errors)
        changes = switches + more_switches + [change]
        return rows, sorted(changes, key=lambda s: sense * s.x)

    def _end_at(self, end: CurvePoint, failed: CurvePoint, scanned: dict, grid: tuple):
        """(x, value, (x_error, value_error)) of the end of the valid range found by the
        bisection between ``end`` (the last valid scan) and ``failed``: the bracket and the
        end's own value, or where the failed scan names the mode unstable at the control's
        start, that mode's root there (bifurcation/start_edge.py), the value carried to it
        along the secant of the valid scans of the same mode (``grid``: the valid and the
        failed grid point; a root not between them is not taken)."""
        x_error = abs(failed.x - end.x)  # the end lies in the last bracket
        found = None
        if failed.unstable_row and end.x != grid[0]:
            found = start_root(
                self.params, self.along, self.solve_for, self.side, failed.unstable_row,
                end.x, failed.x,
            )  # fmt: skip
        if found is None or not _between(found[0], *grid):
            return end.x, end.value, (x_error, end.error_estimate)
        x, x_error = found
        same = [
            p
            for p in scanned.values()
            if p.mode == end.mode and p.kind == end.kind and p is not end
        ]
        if not same:  # no secant: the end's value where it was scanned, its distance an error
            return end.x, end.value, (abs(x - end.x) + x_error, end.error_estimate)
        # a secant over ~SECANT (the bisection's scans halve the distance: one is within a
        # factor 2): the values' noise (~1e-11) and the curvature both small there
        gap = SECANT * max(abs(end.x), 1e-6 * abs(grid[1] - grid[0]))  # as _refined's scale
        near = min(same, key=lambda p: abs(math.log(abs(p.x - end.x) / gap)))
        slope = (near.value - end.value) / (near.x - end.x)
        value_error = end.error_estimate + abs(slope) * x_error
        return x, end.value + slope * (x - end.x), (x_error, value_error)

    def _window(self, a: CurvePoint, b: CurvePoint, depth: int):
        """Rows and changes between a tube unstable at the control's start and one with no
        mode before its end (a and b, either way round): the critical value runs through
        the control's whole range in between, so a window where the scans succeed lies
        there. Bisection on "the scan fails as a's does" until a scan succeeds (the window:
        its two ends are then located as ends, :meth:`edge`) or the bracket is SWITCH's
        tolerance (the two failures meet: its two scans are rows)."""
        lo, hi = a, b
        while abs(hi.x - lo.x) > SWITCH.at(hi.x):
            mid = self.unit(0.5 * (lo.x + hi.x))
            if _fails_alike(mid, a):
                lo = mid
            elif _fails_alike(mid, b):
                hi = mid
            else:  # valid, or a failure of a third kind: the changes on either side
                return self._chain([a, mid, b], depth)
        return [_row(p) for p in (lo, hi) if p is not a and p is not b], []

    def _chain(self, points: list[CurvePoint], depth: int):
        """Rows and changes between consecutive ``points`` (grid order), the rows of the
        points inside the chain included, as between grid points: a switch where two valid
        ones differ, an end or a window where one failed (or both, in different ways)."""
        rows, switches = [], []
        for i, (p, q) in enumerate(zip(points, points[1:])):
            if _changes(p, q):
                new_rows, new_switches = self.between(p, q, depth)
            elif _edge(p, q) and depth > 0:
                new_rows, new_switches = self.edge(p, q, depth - 1)
            else:
                new_rows, new_switches = [], []
            rows += new_rows + ([_row(q)] if i + 2 < len(points) else [])
            switches += new_switches
        return rows, switches

    def _split(self, a, mid, b, depth):
        """Locate the switches on both sides of a scanned point ``mid`` (kept as a row)."""
        if _failed(mid):
            return [], []
        if depth <= 0:  # out of halvings: the change of mode is still located, not dropped
            return self._last_resort(a, b)
        rows, switches = [], []
        if _critical(mid) != _critical(a):
            rows, switches = self.between(a, mid, depth - 1)
        rows = rows + [_row(mid)]
        if _critical(mid) != _critical(b):
            more_rows, more_switches = self.between(mid, b, depth - 1)
            rows, switches = rows + more_rows, switches + more_switches
        return rows, switches

    def _crossing(self, a, b) -> Located | None:
        """Where d = s (v_A - v_B) changes sign (Brent), or None if it does not. At a jump
        (a mode's first root appears or vanishes) the two values differ: they are taken
        just before and just after x, and x is as good as Brent's tolerance. An end where
        the two single-mode values tie (TIE) is itself the switch."""

        def d(x):
            return self.sense * (self.value_of(a, x) - self.value_of(b, x))

        if not d(a.x) < 0 < d(b.x):
            # The ends' values are the scans' (remembered), good to ~1e-11 only: a range
            # that starts at a switch saw v_B 5e-12 before v_A at a, "no sign change", and
            # its switch was dropped (probe 9b, D1). Judge the ends by single-mode solves.
            self._forget_scans(a, b)
            tie = self._tie_at_end(a, b, d)
            if tie is not None:
                return tie
            if not d(a.x) < 0 < d(b.x):
                return None
        tol = SWITCH.at(a.x)
        x = brent(d, a.x, b.x, SWITCH, named=False)
        va, vb = self.value_of(a, x), self.value_of(b, x)
        if abs(va - vb) > 1e-9 * max(1.0, abs(va)):  # a jump: one-sided values
            step = math.copysign(4 * tol, b.x - a.x)
            before, after = x - step, x + step
            va, vb = self.value_of(a, before), self.value_of(b, after)
            error = max(self.error_of(a, before), self.error_of(b, after))
            return Located(x, va, vb, SWITCH.at(x) + abs(step), error)
        return self._crossed(a, b, x, d, SWITCH.at(x))._replace(refine=True)

    def _refined(self, a, b, found: Located, lo: float, hi: float) -> Located:
        """A crossing of two modes whose x_error is above REFINE_ABOVE (relative): their
        values solved again at the finest rtol an x_error either side of x (within [lo,
        hi]: the root lies between where the estimate holds), the root of the line through
        them (d is linear on that scale) and the errors of those values; kept as found
        where they bracket no root or a solve fails. Relative to the design variable's own
        scale, |x| or 1e-6 of the grid's spacing where x is near 0: a film's thickness ~1e-3 kept
        x_error 5.5e-8 of it (max(1, |x|) = 1 took 5.5e-11 as small), where its two modes
        tie 4e-12 of it away (check round 22)."""
        x, h = found.x, found.x_error
        scale = max(abs(x), 1e-6 * (hi - lo))  # the spacing's share: x near 0
        if not REFINE_ABOVE * scale < h < math.inf or Kind.SURFACE in (a.kind, b.kind):
            return found
        ends = (max(x - h, lo), min(x + h, hi))
        try:
            (a0, b0), (a1, b1) = ((self._finest(a, xi), self._finest(b, xi)) for xi in ends)
        except ElectrogrowthError:
            return found
        d0, d1 = (self.sense * (u.value - w.value) for u, w in ((a0, b0), (a1, b1)))
        if not d0 * d1 < 0 or any(c.kind != Kind.BIFURCATION for c in (a0, b0, a1, b1)):
            return found
        width = ends[1] - ends[0]
        t = d0 / (d0 - d1)
        root = ends[0] + t * width
        noise = max(a0.error_estimate + b0.error_estimate, a1.error_estimate + b1.error_estimate)
        x_error = SWITCH.at(root) + noise * width / abs(d1 - d0)
        slope_v = max(abs(a1.value - a0.value), abs(b1.value - b0.value)) / width
        va, vb = (u.value + t * (w.value - u.value) for u, w in ((a0, a1), (b0, b1)))
        errors = (a0.error_estimate, b0.error_estimate, a1.error_estimate, b1.error_estimate)
        return Located(root, va, vb, x_error, max(errors) + slope_v * x_error)

    def _finest(self, pt: CurvePoint, x: float):
        """The critical value of pt's mode at x at the finest rtol (a refined crossing)."""
        at = self.params.at(self.along, x)
        return self.critical_value(at, *pt.mode, self.solve_for, side=self.side, rtol=FINEST)

    def _crossed(self, a, b, x: float, d, tol: float) -> Located:
        """The crossing of a's and b's values at x (a root of d to ``tol``), with its errors
        (the module docstring): the values' estimates e_A + e_B and the residual |d(x)|
        over the slope of d, its secant through the values solved nearest to x on either
        side (x itself where one side has none) whose |d| is above ABOVE_NOISE times that
        noise (else the farthest: a secant in the noise makes the x error as large as the
        interval, as it is). No value is solved for it but a scan's runner-up at x, which
        has no estimate (Brent's root at a grid point: a tie there)."""
        for pt in (a, b):
            if math.isnan(self.error_of(pt, x)) and pt.kind == Kind.BIFURCATION:
                self.known.pop(_key(pt, x))
        va, vb = self.value_of(a, x), self.value_of(b, x)
        ea, eb = self.error_of(a, x), self.error_of(b, x)
        noise = ea + eb
        solved = sorted(
            xi for xi in {xi for _, xi in self.known} if xi != x and self._both(a, b, xi)
        )
        left = [xi for xi in solved if xi < x][::-1]  # nearest first
        right = [xi for xi in solved if xi > x]

        def secant_end(side: list[float]) -> float:
            above = [xi for xi in side if abs(d(xi)) > ABOVE_NOISE * noise]
            return above[0] if above else side[-1]

        p = secant_end(left) if left else x
        q = secant_end(right) if right else x
        if p == q:  # nothing else solved: no slope, no estimate
            return Located(x, va, vb)
        slope_d = abs(d(q) - d(p)) / (q - p)
        slope_v = max(abs(self.value_of(o, q) - self.value_of(o, p)) for o in (a, b)) / (q - p)
        residual = abs(va - vb)
        x_error = tol + ((noise + residual) / slope_d if slope_d > 0 else math.inf)
        return Located(x, va, vb, x_error, max(ea, eb) + slope_v * x_error)

    def _both(self, a, b, x) -> bool:
        """Both a's and b's values at x are solved and are critical values (finite, not the
        threshold or a mode with no root, which say only which comes first)."""
        pair = [self.known.get(_key(o, x)) for o in (a, b)]
        return all(
            v is not None and math.isfinite(v[0]) and v[1] not in (Kind.THRESHOLD, Kind.NONE)
            for v in pair
        )

    def _forget_scans(self, a, b):
        """Drop the scans' values of the two modes at the two ends, so that they are solved
        mode by mode (the surface limit is not a scan's value: kept)."""
        for pt in (a, b):
            if pt.kind != Kind.SURFACE:
                for end in (a.x, b.x):
                    self.known.pop((pt.mode, float(end)), None)

    def _tie_at_end(self, a, b, d) -> Located | None:
        """The crossing at the end x of [a, b] where d (single-mode values) is zero or of
        the wrong sign by no more than TIE relative: the two modes tie there, a switch at
        the grid point itself; None otherwise."""
        for end, wrong in ((a.x, d(a.x) >= 0), (b.x, d(b.x) <= 0)):
            va, vb = self.value_of(a, end), self.value_of(b, end)
            if wrong and abs(va - vb) <= TIE * max(1.0, abs(va)):
                return self._crossed(a, b, end, d, 0.0)
        return None

    def _last_resort(self, a, b):
        """The switch between a and b by bisection with scans (1e-7 relative) where the
        halvings ran out: a silent gap in the sequence is worse than a coarse switch; a third
        mode met there is a ConvergenceError (the point's message), never dropped."""
        found = self._scan_bisection(a, b)
        if isinstance(found, CurvePoint):
            raise ConvergenceError(
                f"the switch from mode {a.mode} to {b.mode} between {a.x:.12g} and {b.x:.12g}"
                f" was not located: a third pattern is first at {found.x:.12g}, and the"
                " interval was halved as often as allowed"
            )
        return _switch_at(a, b, found)

    def _scan_bisection(self, a, b):
        """Fallback: bisect on the mode the scans find, to a relative 1e-7 in x; returns
        the Located change (its errors: half the last bracket, and the values' estimates
        with their difference across it), or the scanned point where a third mode is
        first."""
        lo, hi = a, b
        while abs(hi.x - lo.x) > 1e-7 * max(1.0, abs(lo.x)):
            mid = self.unit(0.5 * (lo.x + hi.x))
            if _failed(mid) or _critical(mid) not in (_critical(a), _critical(b)):
                return mid
            lo, hi = (mid, hi) if _critical(mid) == _critical(a) else (lo, mid)
        spread = abs(hi.value - lo.value) + max(lo.error_estimate, hi.error_estimate)
        return Located(0.5 * (lo.x + hi.x), lo.value, hi.value, 0.5 * abs(hi.x - lo.x), spread)

    def _threshold_switch(self, a, b):
        """Bisection on 'the non-threshold mode bifurcates before the threshold'."""
        mode = b.mode if a.mode == NO_MODE else a.mode
        good, bad = (b.x, a.x) if a.mode == NO_MODE else (a.x, b.x)

        def bifurcates(x):
            return self.mode_value(mode, x)[1] == Kind.BIFURCATION

        good, bad = bisect(bifurcates, good, bad, MODE_EDGE)
        value, _, error = self.mode_value(mode, good)
        return Located(good, value, value, abs(bad - good), error)

    def _limit_threshold_switch(self, a, b):
        """Between the short-wave limit and the threshold (neither a mode): bisection, as
        for a mode and the threshold, on 'the limit's own march meets a face's instability
        before the base state is lost'. At the last x where it does, the limit's value and
        estimate; on the other side of the last bracket, the threshold's."""
        limit_first = a.kind == Kind.SURFACE
        good, bad = (a.x, b.x) if limit_first else (b.x, a.x)

        def surface_first(x):
            return self.limit_value(x)[1] == Kind.SURFACE

        good, bad = bisect(surface_first, good, bad, MODE_EDGE)
        limit, _, error = self.limit_value(good)
        threshold = self.limit_value(bad)[0]
        before, after = (limit, threshold) if limit_first else (threshold, limit)
        return Located(good, before, after, abs(bad - good), error)


def _kind_changes(failed: list[CurvePoint]) -> list[CurvePoint]:
    """The first and last of the ``failed`` points (grid order) and those next to a point
    that failed in another way: where the kind of failure changes (one kind: the first
    and the last alone)."""
    last = len(failed) - 1
    return [
        p
        for i, p in enumerate(failed)
        if i in (0, last)
        or not (_fails_alike(p, failed[i - 1]) and _fails_alike(p, failed[i + 1]))
    ]


def _key(pt: CurvePoint, x) -> tuple:
    """The key of the value at x of what is critical at ``pt`` (its mode, or the short-wave
    limit) among a locator's solved values."""
    return ("surface" if pt.kind == Kind.SURFACE else pt.mode, float(x))


def _between(x: float, a: float, b: float) -> bool:
    """x strictly between a and b."""
    return min(a, b) < x < max(a, b)


def _switch_at(a: CurvePoint, b: CurvePoint, found: Located):
    """The two rows (a's mode, b's mode at x) and the Switch of a located change."""
    x, v_before, v_after = found.x, found.before, found.after
    kind = _change_kind(a, b, v_before, v_after)
    rows = [
        (x, v_before, a.mode, kind, str(Status.OK), a.surface, math.nan, "", a.face),
        (x, v_after, b.mode, kind, str(Status.OK), b.surface, math.nan, "", b.face),
    ]
    errors = (found.x_error, found.value_error)
    return rows, [Switch(x, v_before, a.mode, b.mode, v_after, kind, *errors)]
