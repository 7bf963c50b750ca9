"""Grid points of a curve by continuation from the last full scan (bifurcation/curves.py).

Along the grid (the control of this path is the curve's abscissa, its unknowns the
critical values of the followed modes), the last scan's critical mode and runners-up are
followed: each mode's value is predicted from its last two points
(continuation.predict.secant_bracket), and the one predicted first is solved in that
bracket; or the exact short-wave limit is solved, if it came first. The point is accepted
only if every mode of the scan's grid is still on its stable side just before it, no face
is past its short-wave limit and the mode is not on the edge of the scan's ranges, and the
tube at the control's start is as stable as a scan's march requires (its grid's modes on
their stable side, no face past its short-wave limit); otherwise, at the ends and every
CHECK_EVERY points it is a full scan.
"""

from __future__ import annotations

import math

import numpy as np

from ..basestate.tube import solve_base_state
from ..continuation.path import Point
from ..continuation.predict import secant_bracket
from ..errors import ElectrogrowthError
from ..incremental.accuracy import SCAN_SIGNS
from ..incremental.targets import ImpedanceTarget
from ..interrupts import reraise_interrupt
from ..model.layers import Tube
from ..outcomes import NO_MODE, Kind
from .curve_record import CurvePoint, _accuracy, _failed_point, _scan_point
from .directions import past_surface, surface_past
from .march import calibrated, control_path
from .scan import ScanOptions
from .scan_grid import every_mode_ranges, scan_grid, stable_signs

CHECK_EVERY = 8  # when following modes, a full scan at least every this many points


class _Follower:
    """Grid points by continuation from the last full scan (module docstring). The solves
    come from curves.py: ``scan`` (scan_modes), ``solve`` (critical_value) and ``limit``
    (short_wave_limit)."""

    def __init__(
        self, params, solve_for, along, side, options: ScanOptions, unit, *, scan, solve, limit
    ):
        self.params, self.solve_for, self.along, self.side = params, solve_for, along, side
        self.options, self.unit = options, unit
        self.scan_modes, self.critical_value, self.short_wave_limit = scan, solve, limit
        self.sense = -1.0 if side == "compression" else 1.0
        self.scan = None  # the last full scan (CurvePoint) and its ScanResult ranges
        self.ranges = None
        self.since = 0
        self.history: dict[tuple[int, int], list[Point]] = {}  # (x, value) of each mode

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
            res = self.scan_modes(at, self.solve_for, side=self.side, options=self.options)
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
            self.history.setdefault(pt.mode, []).append(Point(pt.x, pt.value))
        for m, n, v in pt.runners_up:
            self.history.setdefault((m, n), []).append(Point(pt.x, v))

    def _predict(self, mode, x) -> tuple[float, float] | None:
        """A bracket around the value of ``mode`` at x extrapolated from its last points."""
        return secant_bracket(self.history.get(mode, []), x)

    def _follow(self, x: float) -> CurvePoint | None:
        """The followed mode predicted first, solved, or None if the check fails (the
        short-wave limit, if it came first at the last scan)."""
        at = self.params.at(self.along, x)
        if not self._stable_at_start(at):  # the full scan says why
            return None
        if self.scan.kind == Kind.SURFACE:
            limit = self.short_wave_limit(at, self.solve_for, side=self.side)
            if limit.kind != Kind.SURFACE or not self._all_stable(at, None, limit.value):
                return None
            return CurvePoint(x, limit.value, NO_MODE, Kind.SURFACE, "", (), True, limit.value,
                              float(limit.error_estimate), face=limit.face or "")  # fmt: skip
        modes = [self.scan.mode] + [(m, n) for m, n, _ in self.scan.runners_up]
        guesses = [(mode, self._predict(mode, x)) for mode in modes]
        guesses = [(mode, b) for mode, b in guesses if b is not None]
        if not guesses:
            return None
        best, bracket = min(guesses, key=lambda g: self.sense * sum(g[1]))
        c = self.critical_value(at, *best, self.solve_for, side=self.side, bracket=bracket)
        (m_lo, m_hi), (n_lo, n_hi) = self.ranges
        if c.kind != Kind.BIFURCATION or best[0] == m_hi or best[1] == n_hi:
            return None
        if not self._all_stable(at, best, c.value):
            return None
        if self.options.surface and past_surface(c.params):
            return None
        return CurvePoint(  # no runners-up: only the mode predicted first was solved
            x, c.value, best, Kind.BIFURCATION, _accuracy(c), error_estimate=c.error_estimate
        )

    def _stable_at_start(self, at: Tube) -> bool:
        """The tube at the control's start: no face past its short-wave instability and
        every mode of the scan's grid on its stable side, as a full scan requires there. A
        voltage held past the inner face's limit, whose growth restabilised the short waves
        before the critical value, was followed as (2, 1), status ok (check round 20, D1)."""
        x0 = control_path(at, self.solve_for, self.side)[0]
        try:
            return surface_past(at.at(self.solve_for, x0)) is None and self._grid_stable(
                at, None, x0
            )
        except ElectrogrowthError:
            return False

    def _all_stable(self, at: Tube, best, value: float) -> bool:
        """Every mode of the scan's grid but ``best`` (None: all) is still on its stable
        side (the sign on the unloaded tube, as in a scan's march; loose targets, tightened
        as a march's where they do not resolve this tube's targets: march.calibrated)
        just before ``value``."""
        before = value - self.sense * 1e-9 * max(1.0, abs(value))
        return self._grid_stable(at, best, before)

    def _grid_stable(self, at: Tube, best, x: float) -> bool:
        """Every mode of the scan's grid but ``best`` (None: all) on its stable side at
        ``x`` (:meth:`_all_stable`)."""
        o = self.options
        families = (o.prismatic, o.torsional)
        ranges = every_mode_ranges(*self.ranges)  # beyond 2000 the scan searched rows only
        grid = scan_grid(*ranges, o.extend, families)
        signs = stable_signs(*ranges, o.extend, families)
        other = np.ones(len(grid), bool)
        if best is not None:
            other = ~((grid[:, 0] == best[0]) & (grid[:, 1] == best[1]))
        state = solve_base_state(at.at(self.solve_for, x))
        rows, loose = grid[other], ImpedanceTarget(SCAN_SIGNS)
        _, f = calibrated(loose, state, rows, loose(state, rows))
        return bool(np.all(signs[other] * f > 0))
