"""Where the critical mode of a curve changes between two grid points (bifurcation/curves.py).

Between two wrinkling modes A and B: Brent's method (continuation.events.brent, tolerance
SWITCH) on d(x) = s (v_A(x) - v_B(x)), v a mode's first critical value (or the short-wave
limit); where d jumps (a window of instability opens) the switch is that jump. Between a
mode and the threshold: bisection (continuation.events.bisect, MODE_EDGE) on whether the
mode still bifurcates before the threshold. A located switch is checked by a scan there;
a third mode found first splits the interval. A mode with no root before the end of the
march is read as coming after all (+-inf in d). If a single-mode solve fails, the switch is
bisected with scans, to a relative 1e-7 only.

Between a grid point whose scan failed (the tube already unstable at the control's start,
no base state, ...) and one whose scan succeeded, on request (``critical_curve(...,
edges=True)``, the design's mode sequence): the end of the valid range, by bisection on
"the scan succeeds" to the switches' tolerance (SWITCH), kept as an "end" from or to no
mode; then the switches between that end and the valid grid point, as above.
"""

from __future__ import annotations

import math

from ..continuation.events import MODE_EDGE, SWITCH, bisect, brent
from ..errors import ElectrogrowthError, NoBifurcationFound
from ..outcomes import NO_MODE, Kind
from .curve_record import CurvePoint, Switch, _change_kind, _failed, _row

#: the value recorded on the failed side of a located edge of the valid range
NO_VALUE = math.nan


class _Locator:
    """Locates the switches between two grid points (see the module docstring)."""

    def __init__(self, params, solve_for, along, side, unit, *, solve, limit):
        self.params, self.solve_for, self.along, self.side = params, solve_for, along, side
        self.unit = unit  # x -> CurvePoint (a scan)
        self.critical_value, self.short_wave_limit = solve, limit  # from curves.py
        self.sense = -1.0 if side == "compression" else 1.0
        self.known: dict[tuple[tuple[int, int], float], tuple[float, str]] = {}

    def _remember(self, pt: CurvePoint):
        if pt.kind == Kind.BIFURCATION:
            self.known[pt.mode, pt.x] = (pt.value, Kind.BIFURCATION)
        for m, n, value in pt.runners_up:
            self.known[(m, n), pt.x] = (value, Kind.BIFURCATION)

    def mode_value(self, mode, x) -> tuple[float, str]:
        """First critical value of ``mode`` at x, by the single-mode march (the threshold,
        kind "threshold", if the base state is lost first: then the mode comes after all;
        +-inf in the march's direction, kind "none", if it has no root before the end of
        the march)."""
        key = (mode, float(x))
        if key not in self.known:
            at = self.params.at(self.along, x)
            try:
                c = self.critical_value(at, *mode, self.solve_for, side=self.side)
                self.known[key] = (c.value, c.kind)
            except NoBifurcationFound:
                # Not a failure: the mode comes after every other, which is all the sign of
                # d (Brent's bracket) needs, as in design/margins.py. Falling back to scans
                # here located a regular crossing to 1e-7 only, as an "end" (probe 8b, D3).
                self.known[key] = (self.sense * math.inf, Kind.NONE)
        return self.known[key]

    def value_of(self, pt: CurvePoint, x) -> float:
        """The critical value at x of what is critical at ``pt``: its mode, or the
        short-wave limit."""
        if pt.kind != Kind.SURFACE:
            return self.mode_value(pt.mode, x)[0]
        key = ("surface", float(x))
        if key not in self.known:
            limit = self.short_wave_limit(
                self.params.at(self.along, x), self.solve_for, side=self.side
            )
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

    def edge(self, a: CurvePoint, b: CurvePoint, depth: int):
        """Rows and changes strictly between neighbours a and b of which exactly one
        failed: the last failed and the first valid scan of a bisection on "the scan
        succeeds" (SWITCH's tolerance), the "end" between them (at the valid one, NaN on
        the failed side) and the switches from there to the valid grid point."""
        good, bad = (b, a) if _failed(a) else (a, b)
        scanned = {good.x: good, bad.x: bad}

        def succeeds(x):
            scanned[x] = self.unit(x)
            return not _failed(scanned[x])

        x_good, x_bad = bisect(succeeds, good.x, bad.x, SWITCH)
        end, last_failed = scanned[x_good], scanned[x_bad]
        rows, switches = [], []
        if end is not good and end.mode != good.mode:
            rows, switches = self.between(*((end, good) if good is b else (good, end)), depth)
        inner = [_row(p) for p in (last_failed, end) if p is not bad and p is not good]
        if good is b:  # failed before, valid after: the valid range starts at x_good
            rows = inner + rows
            change = Switch(x_good, NO_VALUE, NO_MODE, end.mode, end.value, Kind.END)
        else:
            rows = rows + inner[::-1]
            change = Switch(x_good, end.value, end.mode, NO_MODE, NO_VALUE, Kind.END)
        return rows, sorted(switches + [change], key=lambda s: (b.x - a.x) * s.x)

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

        def d(x):
            return self.sense * (self.value_of(a, x) - self.value_of(b, x))

        if not d(a.x) < 0 < d(b.x):
            return None
        tol = SWITCH.at(a.x)
        x = brent(d, a.x, b.x, SWITCH, named=False)
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

        def bifurcates(x):
            return self.mode_value(mode, x)[1] == Kind.BIFURCATION

        good, _ = bisect(bifurcates, good, bad, MODE_EDGE)
        value = self.mode_value(mode, good)[0]
        return good, value, value
