"""The runners-up of a scan, solved again at the scan's rtol, each with its error estimate.

The march (march.py) finds the roots of a scan's modes with the kernel at
``Accuracy(rtol).runners_up`` = max(rtol, 1e-9); only the critical mode was then solved
again at rtol (grid_scan.finished). The runners-up kept the march's roots, with no estimate,
yet were printed to 10 digits: a film's force (6.3e-5) 1.4e-6 relative off, a film's
growth 2.3e-9 (probe 9a, D2). Each is now solved at rtol near its march root, and carries
the estimate of a critical value: the distance to the root at 100 times looser accuracy
(error_estimate.second_resolution). On the twelve scans of benchmarks/bench.py that is
+3 % (warm, best of two; 0.19 s against 5.9 s of scans), 1-4 % of a film's scan.

Solved at rtol, a runner-up may come before the critical mode (a film's rings lie 2.7e-10
apart, the march's roots 2.3e-9 from the fine ones): it is the critical mode then
(:func:`with_finished_runners`).
"""

from __future__ import annotations

import dataclasses

from ..continuation.events import Remembered, brent, widening_windows
from ..errors import BaseStateError, ConvergenceError
from ..incremental.accuracy import Accuracy
from ..incremental.targets import Family, coarse_targets_for, targets_for, with_family
from ..outcomes import Kind
from .along import TubeAt, root_mode
from .critical import stable_sign
from .error_estimate import achieved_floor, second_resolution
from .grid_scan import finished
from .march import ModeValue, control_path
from .scan_record import ScanResult

#: the first window about a march root in which its root at rtol is looked for, times the
#: march's tolerance max(1, |value|): the march's roots were up to 2.6 times that tolerance
#: from the fine ones (a film's growth and force, probe 9a)
WINDOW = 10.0
#: windows widened 4 times each round: the last is 4^5 WINDOW times the march's tolerance
ROUNDS = 6


def with_finished_runners(params, solve_for, side, rtol, result: ScanResult) -> ScanResult:
    """``result`` with its runners-up solved at ``rtol`` (:func:`finished_runner`), in the
    order of their values; the earliest becomes the critical mode where it comes before it
    (a finite critical mode only: a surface result's runners-up are all after it)."""
    if not result.runners_up:
        return result
    sense = -1.0 if side == "compression" else 1.0  # the march's direction
    at = TubeAt(params, solve_for)  # shared: a layered state continues from its neighbour
    if result.critical.kind == Kind.THRESHOLD:
        return _before_the_loss(params, solve_for, side, rtol, result, at, sense)
    runners = sorted(
        (finished_runner(at, side, rtol, r) for r in result.runners_up),
        key=lambda mv: sense * mv.value,
    )
    c = result.critical
    first = runners[0]
    if c.kind != Kind.BIFURCATION or sense * (first.value - c.value) >= 0:
        return dataclasses.replace(result, runners_up=tuple(runners))
    demoted = ModeValue(c.m, c.n, c.value, c.family, c.error_estimate)
    runners = sorted([*runners[1:], demoted], key=lambda mv: sense * mv.value)
    crit = finished(params, solve_for, side, rtol, first)
    return dataclasses.replace(result, critical=crit, runners_up=tuple(runners))


def _before_the_loss(params, solve_for, side, rtol, result: ScanResult, at, sense):
    """``result``, whose critical point is the loss of the state (a threshold), with its
    runners-up checked: the march stops at the loss, so each comes before it, and is kept
    only where its root at ``rtol`` is found (:func:`fine_runner`). A root of the march's
    looser target alone is no bifurcation: next to a Gent lock the targets saturate
    (~1e259) and the loose ones flip sign where the fine ones keep theirs (probe 11a, Q1:
    (4, 1) and (10, 2) listed 2.6e-6 before a lock they do not reach). The first mode kept,
    if any, bifurcates before the loss: it is the critical mode, the others its runners-up."""
    c = result.critical
    fine = (fine_runner(at, side, rtol, r) for r in result.runners_up)
    kept = sorted(
        (mv for mv in fine if mv is not None and sense * (mv.value - c.value) < 0),
        key=lambda mv: sense * mv.value,
    )
    for i, first in enumerate(kept):
        crit = finished(params, solve_for, side, rtol, first)
        if crit.kind == Kind.BIFURCATION:
            return dataclasses.replace(result, critical=crit, runners_up=tuple(kept[i + 1 :]))
    return dataclasses.replace(result, runners_up=())


def finished_runner(at: TubeAt, side, rtol: float, mv: ModeValue) -> ModeValue:
    """The runner-up ``mv`` (its value the march's root) solved at ``rtol`` near that root,
    with its error estimate. One with an estimate (a critical point's, moved among the
    runners-up by a surface result or a search) is already finished.

    Where no root at rtol is found near the march's (no sign change in the widest window,
    or states there that do not resolve), the march's root stands with that window's
    half-width as its estimate: the fine root is at least that far."""
    fine = fine_runner(at, side, rtol, mv)
    if fine is None:
        tol = Accuracy(rtol).runners_up * max(1.0, abs(mv.value))
        return dataclasses.replace(mv, error_estimate=_widest(tol))
    return fine


def fine_runner(at: TubeAt, side, rtol: float, mv: ModeValue) -> ModeValue | None:
    """:func:`finished_runner`, or None where no root at ``rtol`` is found near the
    march's."""
    if mv.error_estimate is not None:
        return mv
    fam = Family(mv.family)
    mode = with_family(mv.m, mv.n, fam)
    sign = stable_sign(mv.m, mv.n, at.tube, family=fam)
    path = control_path(at.tube, at.control, side)[:2]
    march = Accuracy(rtol).runners_up
    tol = march * max(1.0, abs(mv.value))
    try:
        fine = root_mode(at, targets_for("impedance", rtol), mode, sign)
        # at rtol >= 1e-9 the march's root is already the root of this target (Brent's)
        value = mv.value if march <= rtol else _root_near(fine, mv.value, WINDOW * tol, path)
        if value is None:
            return None
        coarse = root_mode(at, coarse_targets_for("impedance", rtol), mode, sign)
        # at least what the solve achieves (a critical value's floor: critical._solve)
        estimate = max(second_resolution(coarse, value, path), achieved_floor(value, rtol))
    except (BaseStateError, ConvergenceError):
        return None
    return dataclasses.replace(mv, value=value, error_estimate=estimate)


def _root_near(g, value: float, width: float, path) -> float | None:
    """The root of ``g`` (stable > 0) in the first of the windows about ``value`` (half-width
    ``width``, widened ROUNDS times, clipped to the march's ``path``) where g changes sign,
    or None. Brent's method starts from the window's ends, whose values the sign check has
    just paid for: remembered, not computed again (two fine solves of the mode's det(M2)
    per runner-up, the same values, so the same root to the bit)."""
    g = Remembered(g)
    bounds = (min(path), max(path))
    for lo, hi, _ in widening_windows(value, width, ROUNDS, bounds=bounds):
        if lo < hi and g(lo) * g(hi) < 0:
            return brent(g, lo, hi)
    return None


def _widest(tol: float) -> float:
    """The half-width of the widest window :func:`_root_near` searches (march tolerance
    ``tol``)."""
    return WINDOW * tol * 4.0 ** (ROUNDS - 1)
