"""One march over one grid of modes: the scan of fixed ranges (scan.py widens them).

The grid's rows (m, n, family code) and their signs on the unloaded tube come from
:mod:`.scan_grid`; the march (march.first_bifurcations) finds the first ``top`` roots,
the first of which is solved again at the scan's rtol (:func:`finished`). A grid that widens
an earlier one reuses what that march found (:func:`reused`): only its new rows are marched,
and only up to the earlier top-th value.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..incremental.accuracy import SCAN_SIGNS, Accuracy
from ..incremental.targets import Family, ImpedanceTarget
from ..outcomes import NO_MODE, Kind
from .along import TubeAt
from .critical import CriticalPoint, critical_value
from .march import ModeValue, first_bifurcations
from .scan_grid import scan_grid, stable_signs
from .scan_record import ScanResult
from .state_loss import lost_note


def scan_once(
    params, solve_for, side, m_range, n_range, top, rtol, probes, families, known=None
) -> ScanResult:
    """The scan of the grid of these ranges (scan_grid.scan_grid). ``known``: (the grid, the
    result) of an earlier scan of the same tube whose grid this one widens; its modes are
    not marched again (:func:`reused`)."""
    modes = scan_grid(m_range, n_range, probes, families)
    signs = stable_signs(m_range, n_range, probes, families)
    reuse = reused(modes, known, top)
    march = modes if reuse is None else modes[reuse[0]]
    res = first_bifurcations(
        params,
        solve_for,
        side,
        march,
        ImpedanceTarget(SCAN_SIGNS),
        top=top,
        brent_targets=ImpedanceTarget(Accuracy(rtol).runners_up),
        stable_signs=signs if reuse is None else signs[reuse[0]],
        until=None if reuse is None else reuse[2],
    )
    found = res.found
    if reuse is not None:
        old, best = reuse[1], known[1].critical
        sense = -1.0 if side == "compression" else 1.0  # the march's direction
        found = sorted(old + found, key=lambda mv: sense * mv.value)
        if found and (found[0].m, found[0].n, found[0].family) == (best.m, best.n, best.family):
            return ScanResult(best, tuple(found[1:top]), m_range, n_range)
    if not found:  # the march stops at the threshold, so found modes come before it
        crit = CriticalPoint(
            solve_for,
            res.threshold,
            *NO_MODE,
            Kind.THRESHOLD,
            0.0,
            "impedance",
            side,
            params.at(solve_for, res.threshold),
            message=lost_note(TubeAt(params, solve_for), res.threshold),
        )
        return ScanResult(crit, (), m_range, n_range)
    crit = finished(params, solve_for, side, rtol, found[0])
    if crit.kind == Kind.THRESHOLD:
        # the march's root of found[0] was its looser target's alone: solved at rtol the
        # mode reaches the loss of the state first, which is the tube's, not the mode's
        # (the others are checked at rtol as runners-up: runners.with_finished_runners)
        crit = dataclasses.replace(crit, m=NO_MODE[0], n=NO_MODE[1], family=None)
    return ScanResult(crit, tuple(found[1:top]), m_range, n_range)


def reused(modes, known, top):
    """What an earlier scan's result ``known`` = (its grid, its ScanResult) leaves to do on
    the wider grid ``modes``: (the rows to march, the modes it found that are rows of this
    grid, the value the march may stop at), or None (march every row).

    The earlier march found the first ``top`` roots of its modes, up to the top-th value v:
    every mode of both grids that bifurcates before v is among them, so only the new rows
    are marched, and only up to v; merged, the two lists hold every root of this grid
    before v. That is exact only while the kept list is whole: when a found mode is not a
    row here (a probe beyond the new ranges), the roots of the old rows after v would be
    missing, and the whole grid is marched again. So also when the earlier scan found no
    mode (a threshold) or fewer than ``top`` (its march already went to the end: then v is
    the end and the new rows are marched all the way)."""
    if known is None:
        return None
    grid, result = known
    c = result.critical
    if c.kind != Kind.BIFURCATION or result.surface_instability:
        return None
    old = [ModeValue(c.m, c.n, c.value, c.family, c.error_estimate), *result.runners_up]
    rows = {_row_key(r) for r in modes}
    if any(_mode_key(mv) not in rows for mv in old):
        return None
    seen = {_row_key(r) for r in grid}
    new = np.array([_row_key(r) not in seen for r in modes])
    until = old[-1].value if len(old) >= top else None
    return new, old, until


def _row_key(row) -> tuple:
    """A grid row (m, n, family code) as a hashable key."""
    return int(row[0]), int(row[1]), int(row[2])


def _mode_key(mv: ModeValue) -> tuple:
    """The grid row key of a found mode."""
    return mv.m, mv.n, Family(mv.family).code


def finished(params, solve_for, side, rtol, best: ModeValue) -> CriticalPoint:
    """The critical point of the mode ``best`` (its value from a march), solved at ``rtol``
    in a narrow bracket around that value, which is relative: a small value's bracket must
    stay on its side of 0."""
    w = 1e-7 * abs(best.value)
    return critical_value(
        params,
        best.m,
        best.n,
        solve_for,
        family=best.family,
        side=side,
        rtol=rtol,
        bracket=(best.value - w, best.value + w),
    )
