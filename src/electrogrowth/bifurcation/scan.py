"""Which mode comes first: the critical value over m in [m_lo, m_hi], n in [n_lo, n_hi].

The modes of every family (incremental.targets.Family) are in one batch: the paper's
wrinkles (m, n), n >= 1 (axisymmetric at m = 0, the torsion excluded); the prismatic
modes (m, 0), m >= 2, plane-strain wrinkles (ScanOptions.prismatic); the torsional modes
(0, n), u_th = U(r) cos kz (ScanOptions.torsional). A row of the batch is (m, n, family
code); the kernel keeps each family's own block of the Stroh system. The batch's rows and
their signs on the unloaded tube are in :mod:`.scan_grid`; the result, :class:`ScanResult`
(re-exported here), in :mod:`.scan_record`.

The scan is organised around the batch kernel. The base state does not depend on the
mode, so the march (march.py) evaluates every mode at once on one base state per step
(impedance.target_batch, parallel over modes), at a loose tolerance that only has to get
signs right; the modes that change sign in a step are narrowed together by bisection and
finished by Brent's method at full accuracy. Marching on yields the runner-up modes.

When the best mode sits on the edge of the range the range is doubled in that direction
(every m up to EVERY_M = 64, n up to the cap). Beyond m = 64 (an optimum on that edge, a
probe beyond it, or an m range asked for beyond it) the best m is searched coarse-to-
fine along family rows up to the tube's m cap (options.mode_caps: M_CAP = 2000, or the
folds of its thinnest layer, m ~ FOLD_KH R / h; msearch.py, docs/derivation-film.md): a
thin stiff film folds at a finite m of tens to hundreds, a soft lining 1e-3 thick at m in
the thousands to ten thousands, which the search brackets. The
infimum over all modes may be the short-wave limit m, k -> infinity, a surface
instability of a face: it is computed exactly from the half-space problem (surface.py)
when the best finite mode sits on the edge at the cap, when no finite mode bifurcates
before the threshold (or at all), or when a face is already past its half-space
instability at the best finite value. If it comes first, and no mode beyond the scan is
unstable at it along either axis (a soft lining on a stiffer tube reaches its face's limit
from below: :func:`_folds_before_limit`), it is the result (kind SURFACE, with the face and
the wave direction) and the best finite mode is the first runner-up.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import (
    ConvergenceError,
    ElectrogrowthError,
    NoBifurcationBeforeLock,
    NoBifurcationFound,
    UnstableAtStart,
)
from ..incremental.modes import MODE_MAX, row_family
from ..incremental.targets import impedance_targets
from ..model.layers import Tube
from ..outcomes import NO_MODE, Kind, Status
from .beyond import searched_rows, unstable_beyond, unstable_past_cap
from .certify import kernel_signs
from .critical import CriticalPoint, critical_value, no_bifurcation_remedy
from .directions import past_surface, surface_past
from .grid_scan import finished, scan_once
from .march import ModeValue, control_path
from .msearch import search_m, search_n
from .options import EVERY_M, ScanOptions, mode_caps
from .options import TOP_MAX as TOP_MAX  # re-exported: the CLI checks --top against it
from .problem import Problem, as_problem
from .runners import with_finished_runners
from .scan_grid import scan_grid, stable_signs
from .scan_record import ScanResult
from .surface import short_wave_limit

# widen a range mode by mode at most this often (m up to EVERY_M, n up to the n cap); an m
# optimum still on its edge is then searched for up to the m cap (msearch.py, scan_caps)
DOUBLINGS = 2


def _surface_point(limit, side) -> CriticalPoint:
    """The short-wave limit as the critical point of a scan."""
    return CriticalPoint(
        limit.solve_for,
        limit.value,
        *NO_MODE,
        Kind.SURFACE,
        limit.error_estimate,
        "halfspace",
        side,
        limit.params,
        face=limit.face,
        psi=limit.psi,
    )


def scan_modes(
    params: Tube | Problem,
    solve_for: str | None = None,
    *,
    side: str | None = None,
    options: ScanOptions | None = None,
    rtol: float | None = None,
) -> ScanResult:
    """Critical value of ``solve_for`` minimised (first reached) over all modes.

    Parameters
    ----------
    params : Tube or Problem
        The tube; the control named by ``solve_for`` is the unknown. Or a
        :class:`~.problem.Problem`, which gives every keyword below.
    solve_for : str
        As in :func:`bifurcation.critical_value` (growth, stretch, voltage; for a layered
        Tube also growth[K].component, pressure, force).
    side : {"compression", "extension"}, optional
        For the stretch, the pressure and the force (defaults: compression, extension
        (inflation), compression).
    options : ScanOptions, optional
        The mode ranges (extended automatically while the optimum sits on an upper edge),
        the number of modes reported, and whether to extend (default ScanOptions()).
    rtol : float, optional
        Accuracy of the critical value (default 1e-12, 1e-14 to 1e-4; incremental/accuracy.py).

    Returns
    -------
    ScanResult
    """
    problem = as_problem(params, solve_for, side=side, rtol=rtol, options=options)
    params, solve_for, side = problem.tube, problem.control, problem.side
    options, rtol = problem.options, problem.rtol
    _stable_short_waves_at_start(params, solve_for, side)
    try:
        result, at_cap, limit = _widened_scan(params, solve_for, side, options, rtol)
        if options.extend:
            found = _beyond_searched(params, solve_for, side, result, options, rtol, at_cap, limit)
            result, at_cap = found
    except NoBifurcationFound as exc:
        if not isinstance(exc, NoBifurcationBeforeLock):  # the lock's own stands
            exc.remedy = no_bifurcation_remedy(solve_for)  # not the remedy of one mode's solve
        result, at_cap, limit = _no_scanned_mode(params, solve_for, side, options, rtol, exc)
    if options.surface:
        result = _with_short_waves(params, solve_for, side, result, options, rtol, at_cap, limit)
    else:
        result = _windows_without_surface(params, solve_for, side, result, options, rtol, limit)
    # the runners-up were the march's roots (max(rtol, 1e-9)): solved at rtol (runners.py)
    caps = scan_caps(params, options)
    result = _capped(with_finished_runners(params, solve_for, side, rtol, result), caps)
    return dataclasses.replace(_past_caps(params, solve_for, options, result), caps=caps)


def scan_caps(params, options: ScanOptions) -> tuple[int, int]:
    """The largest m and n the scan of ``params`` searches: the tube's (options.mode_caps,
    chosen by its thinnest layer), or the ranges asked for where they reach beyond."""
    m_cap, n_cap = mode_caps(params)
    return max(m_cap, options.m_range[1]), max(n_cap, options.n_range[1])


def _stable_short_waves_at_start(params, solve_for, side) -> None:
    """UnstableAtStart where a face or interface is past its short-wave instability at the
    control's start: every short wave there is unstable before the control moves. The
    march reads only the scanned modes at its start, and the limit is weighed only against
    a later critical value: a tube held at a voltage past its inner face's limit, whose
    growth restabilises the short waves, was scanned as wrinkling in (2, 1) at g = 1.38,
    status ok, where (0, 40) is unstable at g = 1 (check round 20, D1)."""
    x0 = control_path(params, solve_for, side)[0]
    try:
        face = surface_past(params.at(solve_for, x0))
    except ElectrogrowthError:  # no state or no reading at the start: the march says why
        return
    if face is not None:
        where = face.replace("-", " ") if face.startswith("interface") else f"{face} face"
        raise UnstableAtStart(
            f"the tube is already unstable at {solve_for} = {x0:g}: its {where} is past its"
            " short-wave (half-space) instability there; start from a stable state"
        )


def _capped(result: ScanResult, caps: tuple[int, int]) -> ScanResult:
    """``result``, its critical point INACCURATE where the mode sits at a cap (``caps``,
    scan_caps): the scan did not look beyond, and a layer folding past the cap does so
    with a lower value (when every cap was 2000, a film 2e-4 thick, 10 times stiffer,
    under hoop growth: (2000, 0) at 1.13838 while its flat film's folds are near m = 3300;
    its own cap is now 320000). The value is that mode's, exact; it is the tube's critical
    value only if no mode beyond the cap comes first."""
    c = result.critical
    over = [
        f"{name} = {cap}"
        for name, value, cap in (("m", c.m, caps[0]), ("n", c.n, caps[1]))
        if value >= cap
    ]
    if c.kind != Kind.BIFURCATION or not over or c.status != Status.OK:
        return result
    message = (
        f"the critical mode ({c.m}, {c.n}) sits at the largest {' and '.join(over)} the scan"
        " searched: a mode beyond it may bifurcate first"
    )
    if result.short_wave_limit is not None:  # computed, and later (else it is the result)
        message += f" (the exact short-wave limit comes later, at {result.short_wave_limit:.6g})"
    remedy = (
        f"scan further (--m-max / --n-max, up to {MODE_MAX}); a film this thin folds as"
        " the flat film on its substrate (docs/derivation-film.md)"
    )
    crit = dataclasses.replace(c, status=Status.INACCURATE, message=message, remedy=remedy)
    return dataclasses.replace(result, critical=crit)


def _widened_scan(params, solve_for, side, options: ScanOptions, rtol):
    """The scan of the finite modes, its ranges widened towards short waves; whether its
    optimum still sits on the edge of a range at the cap; and the exact short-wave limit
    if it was computed (else None).

    Widening only looks for a finite optimum beyond the ranges, so it stops (as at the
    cap) once the exact short-wave limit comes before the best finite mode found: shorter
    waves tend to that limit, which is then the result unless a mode beyond the scan is
    unstable at it (_with_short_waves reads both axes there: _folds_before_limit).
    Every m is scanned up to EVERY_M (or m_max, if smaller); m beyond it, of an m range
    reaching past EVERY_M or of an optimum on the m edge there (or a probe beyond it), are
    examined by the coarse-to-fine search along family rows (:func:`_searched`), which
    brackets the best m or ends at m_max (the m cap, scan_caps, when extending)."""
    n_range, top, extend = options.n_range, options.top, options.extend
    m_lo, m_max = options.m_range
    cap_m, cap_n = scan_caps(params, options)  # this tube's (its thinnest layer's)
    m_range = (m_lo, min(m_max, max(m_lo, EVERY_M)))  # scanned mode by mode
    grown = {"m": 0, "n": 0}
    probes = extend
    limit, sense = None, -1.0 if side == "compression" else 1.0

    def limit_first(c) -> bool:
        nonlocal limit
        if not options.surface or c.kind != Kind.BIFURCATION:
            return False
        # only as far as the finite mode: past it the march may meet a lock it cannot
        # resolve (a Gent core under a folding film), and the answer is no longer asked
        limit = limit or short_wave_limit(params, solve_for, side=side, rtol=rtol, until=c.value)
        return limit.kind == Kind.SURFACE and (limit.value - c.value) * sense < 0

    def limit_stands(result) -> tuple[ScanResult, bool]:
        """The limit comes before the scanned modes: widening stops, and the result is
        flagged as at the cap, so that _with_short_waves weighs the limit, reading the modes
        beyond the scan at it first (_folds_before_limit)."""
        assert limit is not None  # limit_first computed it
        return result, True

    def search(result, m_top=cap_m, axis="m"):
        rows = _search_rows(result, options, axis, ())
        edge = result.m_range[1] if axis == "m" else result.n_range[1]
        return _searched(params, solve_for, side, result, options, rtol, m_top, axis, rows, edge)

    def search_beyond(result, beyond):
        """Searched along n, then m, from the edges the doublings left the optimum on."""
        at_n = at_m = False
        if beyond["n"]:
            result, at_n = search(result, cap_n, "n")
        if beyond["m"]:
            result, at_m = search(result)
        return result, at_n or at_m

    known = None  # the last grid scanned and its result
    while True:
        families = (options.prismatic, options.torsional)
        result = scan_once(
            params, solve_for, side, m_range, n_range, top, rtol, probes, families, known
        )
        known = (scan_grid(m_range, n_range, probes, families), result)
        c = result.critical
        if probes and c.kind == Kind.BIFURCATION and (c.m > m_range[1] or c.n > n_range[1]):
            if limit_first(c):
                return (*limit_stands(result), limit)
            if c.m > max(m_range[1], EVERY_M):  # a probe beyond the every-m scan wins
                return (*search(result), limit)
            # a probe beyond the range wins: the optimum is a short wave, widen to it once
            grown = {"m": int(c.m > m_range[1]), "n": int(c.n > n_range[1])}
            m_range = (m_range[0], max(m_range[1], c.m))
            n_range = (n_range[0], max(n_range[1], c.n))
            probes = False
            continue
        probes = False
        edge = {
            "m": c.kind == Kind.BIFURCATION and c.m == m_range[1],
            "n": c.kind == Kind.BIFURCATION and c.n == n_range[1],
        }
        grow = {
            "m": edge["m"] and m_range[1] < EVERY_M and grown["m"] < DOUBLINGS,
            "n": edge["n"] and n_range[1] < cap_n and grown["n"] < DOUBLINGS,
        }
        beyond = {
            "m": extend and edge["m"] and not grow["m"] and m_range[1] < cap_m,
            "n": extend and edge["n"] and not grow["n"] and n_range[1] < cap_n,
        }
        if not extend or not (any(grow.values()) or any(beyond.values())):
            break
        if limit_first(c):
            return (*limit_stands(result), limit)
        if not any(grow.values()):  # on an edge the doublings cannot widen: searched
            return (*search_beyond(result, beyond), limit)
        if grow["m"]:
            m_range, grown["m"] = (m_range[0], min(2 * m_range[1] + 1, EVERY_M)), grown["m"] + 1
        if grow["n"]:
            n_range, grown["n"] = (n_range[0], min(2 * n_range[1], cap_n)), grown["n"] + 1
    at_cap = extend and any(edge.values()) and not (c.m == 0 and not edge["n"])
    if m_max > m_range[1]:  # the m asked for beyond the mode-by-mode scan
        result, at_m_cap = search(result, cap_m if extend else m_max)
        c = result.critical
        at_cap = at_m_cap or (extend and c.kind == Kind.BIFURCATION and c.n == n_range[1])
    return result, at_cap, limit


def _beyond_searched(params, solve_for, side, result, options, rtol, at_cap, limit):
    """``result``, searched along each axis where a mode beyond its ranges is past its root
    at the critical value or, for a layered tube, at the last runner-up's value (beyond.py):
    a thin film's folds at m or n in the hundreds, which neither an edge nor a probe pointed
    to, come before a low mode of the whole tube (Euler buckling, a collapse). And whether
    the search ended at its cap. Where the search for runners-up runs into states that do
    not resolve (next to a lock), the list stands as scanned; for the critical mode that is
    an error (:func:`_beyond_value` says when the check applies)."""
    scanned = {"m": result.m_range, "n": result.n_range}  # marched mode by mode
    searched: dict[str, set] = {"m": set(), "n": set()}
    for runner in (False, True):
        for _ in range(READS):
            value = _beyond_value(params, side, result, options, limit, runner)
            if value is None:
                break
            read = (value, runner)
            found = _rows_searched(
                params, solve_for, side, result, options, rtol, read, scanned, searched
            )
            if found is None:
                break
            result, top = found
            at_cap = at_cap or top
    return result, at_cap


#: reads beyond the ranges at most, at each value (critical, last runner-up): each search
#: changes the scan's first modes, and with them the rows read next (module docstring)
READS = 4


def _rows_searched(params, solve_for, side, result, options, rtol, read, scanned, searched):
    """``result`` searched along the rows beyond the ``scanned`` ranges that are past their
    roots at the value of ``read`` (value, whether it is the last runner-up's) and not yet
    ``searched`` (updated), and whether the search ended at its cap; None where no such
    row turned. The rows are read beyond the ranges scanned,
    not those a search widened: a search follows some rows to the cap, and the runners-up
    may lie on others (check round 36a: (16, 3), tied with (11, 5), after the search for
    (15, 4) on the row n = 4). They are those of the scan's first modes (beyond.read_rows):
    after a search its critical mode (15, 3) has another n than the (11, 1) scanned, and
    (15, 4), (14, 5) lie on rows read only then (round 36a's W1t). Where the search for
    runners-up runs into states that do not resolve, the list stands; for the critical
    mode that is an error."""
    value, runner = read
    first = (result.critical, *result.runners_up)  # a finite critical mode (_beyond_value)
    turned = unstable_beyond(
        params, solve_for, value, scanned["m"], scanned["n"], options.prismatic, modes=first
    )
    at_cap, any_searched = False, False
    for axis, cap in zip(("n", "m"), reversed(scan_caps(params, options)), strict=True):
        if not set(turned[axis]) - searched[axis]:
            continue
        rows = _search_rows(result, options, axis, turned[axis]) - searched[axis]
        try:
            result, top = _searched(
                params, solve_for, side, result, options, rtol, cap, axis, rows, scanned[axis][1]
            )
        except ConvergenceError:
            if not runner:
                raise
            continue
        finally:
            searched[axis] |= rows
        at_cap, any_searched = at_cap or top, True
    return (result, at_cap) if any_searched else None


def _search_rows(result: ScanResult, options: ScanOptions, axis: str, turned) -> set:
    """The rows searched along ``axis``: those ``turned`` (read past their roots beyond
    the ranges, beyond.py) and those every search follows (beyond.searched_rows)."""
    c = result.critical
    finite = c if c.kind == Kind.BIFURCATION else None
    rows = searched_rows(finite, options.m_range, options.n_range, options.prismatic, axis)
    return rows | set(turned)  # a wrinkle (15, 4) of a film in a thin wall: neither row


def _beyond_value(params, side, result, options, limit, runner: bool) -> float | None:
    """The value at which modes beyond the ranges are read: the critical value, or (
    ``runner``) the last runner-up's; None where that check does not apply.

    Not for the runners-up of a uniform tube: its modes beyond the ranges tend to its faces'
    short-wave limits, which the scan computes when they matter (its runners-up are those of
    its grid; the search would only list short waves approaching the limit), nor when the
    march ended short of ``top`` modes. Not when the short-wave limit comes first (``limit``
    if computed, or a face already past its half-space instability): every short wave is
    then unstable at the finite value; the modes beyond are read at the limit instead, where
    it would become the result (:func:`_folds_before_limit`)."""
    c, runners = result.critical, result.runners_up
    if runner and (params.is_uniform or not runners or len(runners) < options.top - 1):
        return None
    if c.kind != Kind.BIFURCATION or past_surface(c.params):
        return None
    sense = -1.0 if side == "compression" else 1.0
    if limit is not None and limit.kind == Kind.SURFACE and (limit.value - c.value) * sense < 0:
        return None
    return runners[-1].value if runner else c.value


def _searched(
    params,
    solve_for,
    side,
    result: ScanResult,
    options: ScanOptions,
    rtol,
    top: int,
    axis: str,
    rows: set,
    edge: int,
):
    """``result`` merged with the coarse-to-fine search (msearch.py) of m (or n, ``axis``)
    from ``edge`` up to ``top`` along the family ``rows`` (:func:`_search_rows`): the
    earlier of the search's best and the scan's critical mode is the critical mode, the
    others the runners-up; and whether the critical index is ``top`` (the edge of the
    search)."""
    c, sense = result.critical, -1.0 if side == "compression" else 1.0
    searcher = search_m if axis == "m" else search_n
    ranges = {"m": result.m_range, "n": result.n_range}
    ranges[axis] = (ranges[axis][0], top)
    # along n, the runners-up include the neighbouring m rows of the scanned m range
    more = {} if axis == "m" else {"m_span": (options.m_range[0], result.m_range[1])}
    try:
        found = searcher(
            params, solve_for, side, sorted(rows), edge, top, rtol, options.top, **more
        )
    except NoBifurcationFound:  # no mode beyond the scan bifurcates first: the scan stands
        return dataclasses.replace(result, m_range=ranges["m"], n_range=ranges["n"]), False
    best, others = found.best, {(v.m, v.n, v.family): v for v in found.found}
    others.update({(v.m, v.n, v.family): v for v in result.runners_up})
    if c.kind == Kind.BIFURCATION:
        others[(c.m, c.n, c.family)] = ModeValue(c.m, c.n, c.value, c.family, c.error_estimate)
    if c.kind == Kind.BIFURCATION and sense * c.value <= sense * best.value:
        crit = c
    else:
        crit = finished(params, solve_for, side, rtol, best)
    others.pop((crit.m, crit.n, crit.family), None)
    runners = sorted(others.values(), key=lambda v: sense * v.value)[: options.top - 1]
    at_top = crit.kind == Kind.BIFURCATION and getattr(crit, axis) == top
    return ScanResult(crit, tuple(runners), ranges["m"], ranges["n"]), at_top


def _no_scanned_mode(params, solve_for, side, options: ScanOptions, rtol, exc):
    """No scanned mode bifurcates (``exc``): the scan's result, its critical point the
    exact short-wave limit of a face, for _with_short_waves to weigh against the modes
    beyond the scan (a soft lining's folds (1028, 0) come 3.7e-4 before its face's limit,
    which a scan of m <= 12, n <= 2 returned unchecked: probe 13b, D1); and at_cap and the
    limit, as _widened_scan gives them. Re-raises ``exc`` where no face has a limit.

    Without ``options.surface`` the limit is not a result, but it is where those folds are
    read (each short wave is unstable past it), so it is computed all the same; a fold
    found beyond the scan is the result, else ``exc`` is raised."""
    limit = short_wave_limit(params, solve_for, side=side, rtol=rtol, estimate=options.surface)
    if limit.kind != Kind.SURFACE:
        raise exc
    m_lo, m_max = options.m_range
    m_range = (m_lo, min(m_max, max(m_lo, EVERY_M)))  # as scanned (_widened_scan)
    crit, error = _surface_point(limit, side), limit.error_estimate
    result = ScanResult(crit, (), m_range, options.n_range, True, limit.value, error)
    if not options.surface:
        result, _ = _folds_before_limit(params, solve_for, side, result, options, rtol, limit)
        if result.critical.kind != Kind.BIFURCATION:
            result = _with_windows(params, solve_for, side, result, options, rtol, limit)
        if result is None:
            raise exc
        result = dataclasses.replace(
            result, surface_instability=False, short_wave_limit=None, short_wave_error=None
        )
    return result, True, limit


def _with_short_waves(
    params, solve_for, side, result: ScanResult, options, rtol: float, at_cap: bool, limit=None
) -> ScanResult:
    """``result``, or the exact short-wave limit (``limit`` if already computed) if it
    comes first (module docstring) and no mode beyond the scan comes before it
    (:func:`_folds_before_limit`). ``result``'s critical point is a finite mode, or the
    limit itself where no scanned mode bifurcates (:func:`_no_scanned_mode`)."""
    c = result.critical
    if c.kind == Kind.BIFURCATION and not at_cap and not past_surface(c.params):
        return result
    limit = limit or short_wave_limit(params, solve_for, side=side, rtol=rtol)
    if limit.kind != Kind.SURFACE:
        return result
    result = dataclasses.replace(
        result, short_wave_limit=limit.value, short_wave_error=limit.error_estimate
    )
    if _before(c, limit.value, side):
        return result
    # the one place a limit becomes the result: not before the folds beyond the scan
    result, turned = _folds_before_limit(params, solve_for, side, result, options, rtol, limit)
    c = result.critical
    if _before(c, limit.value, side):
        return result
    windowed = _with_windows(params, solve_for, side, result, options, rtol, limit)
    if windowed is not None:
        return windowed
    crit = _surface_point(limit, side)
    if turned:  # a mode beyond is past its root at the limit, yet no root was found before it
        crit = dataclasses.replace(crit, status=Status.INACCURATE, **_UNFOUND)
    return dataclasses.replace(
        result,
        critical=crit,
        surface_instability=True,
        runners_up=(_as_runner(c) + result.runners_up)[: options.top - 1],
    )


#: at most this many scanned modes that changed sign before the limit are solved alone
STEPPED_OVER = 16
#: the kernel's tolerance of a first reading of every scanned mode at the limit (the
#: march's own loose samples': an ordinary tube's targets to ~1e-5)
LOOSE_READING = 1e-5


def _windows_without_surface(params, solve_for, side, result: ScanResult, options, rtol, limit):
    """``result`` of a scan without the short-wave limit as a result, with the windows of
    its modes before the limit all the same: they lie just before it (_stepped_over; check
    round 18: "no mode bifurcates" where (0, 1) does, 1e-4 before an interface's limit).
    The limit is computed only where a face is past it at the scan's finite mode (as
    _with_short_waves decides), and marched only as far as that mode; where it cannot be
    computed the result stands, as the window check adds no check then."""
    c = result.critical
    if c.kind == Kind.BIFURCATION and not past_surface(c.params):
        return result
    if limit is None:
        until = c.value if c.kind == Kind.BIFURCATION else None
        try:
            limit = short_wave_limit(
                params, solve_for, side=side, rtol=rtol, until=until, estimate=False
            )
        except ElectrogrowthError:
            return result
    if limit.kind != Kind.SURFACE or _before(c, limit.value, side):
        return result
    windowed = _with_windows(params, solve_for, side, result, options, rtol, limit)
    return result if windowed is None else windowed


def _with_windows(params, solve_for, side, result: ScanResult, options, rtol, limit):
    """``result`` led by the scanned modes whose roots before ``limit`` the march stepped
    over (:func:`_stepped_over`), its own finite mode among the runners-up; None where
    there are none."""
    stepped = _stepped_over(params, solve_for, side, result, options, rtol, limit)
    if not stepped:
        return None
    first, *more = stepped
    found = [r for x in (*more, result.critical) for r in _as_runner(x)]
    sense = -1.0 if side == "compression" else 1.0
    runners = sorted(found + list(result.runners_up), key=lambda r: sense * r.value)
    return dataclasses.replace(
        result, critical=first, runners_up=tuple(runners[: options.top - 1])
    )


def _as_runner(c: CriticalPoint) -> tuple[ModeValue, ...]:
    """``c`` as a runner-up of a scan (none where it is no finite mode)."""
    if c.kind != Kind.BIFURCATION:
        return ()
    return (ModeValue(c.m, c.n, c.value, c.family, c.error_estimate),)


def _stepped_over(params, solve_for, side, result: ScanResult, options, rtol, limit):
    """The scanned modes whose first roots come before the limit although the scan's march
    did not find them, earliest first (CriticalPoints). The march samples a scan's modes
    every 0.25 of the control's scale; a mode unstable in a narrower window (two
    interfaces of a thin stiff layer: one turns the target's sign, the other back) is
    stepped over, and the limit was the answer, status ok (check round 18, D1 and D2:
    (0, 1) 1e-3 and 1e-4 before an interface's limit). Every mode scanned mode by mode is
    read just before the limit (as ``certify`` reads them before a critical value); those
    past their roots (in grid order, at most STEPPED_OVER) are solved alone, by the
    single-mode march that samples at every step."""
    sense = -1.0 if side == "compression" else 1.0
    error = limit.error_estimate if np.isfinite(limit.error_estimate) else 0.0  # NaN: none
    gap = 10.0 * max(error, 1e-13 * max(1.0, abs(limit.value)))
    families = (options.prismatic, options.torsional)
    m_range = (result.m_range[0], min(result.m_range[1], max(result.m_range[0], EVERY_M)))
    modes = scan_grid(m_range, result.n_range, False, families)
    stable = stable_signs(m_range, result.n_range, False, families)
    try:  # a state or a reading that fails there adds no check (the scan's result stands)
        state = solve_base_state(params.at(solve_for, limit.value - sense * gap))
        # read as the march reads its modes (loosely), the modes that look past their roots
        # then as certify reads them: a full sign reading costs a third of a surface scan
        loose = impedance_targets(state, modes, rtol=LOOSE_READING) * stable
        doubt = np.flatnonzero(~(loose > 0))
        if not doubt.size:
            return []
        past = doubt[~(kernel_signs(state, modes[doubt]) * stable[doubt] > 0)]
    except ElectrogrowthError:
        return []
    found = []
    for i in past[:STEPPED_OVER]:
        m, n = (int(x) for x in modes[i, :2])
        try:
            c = critical_value(
                params, m, n, solve_for, family=row_family(modes[i]), side=side, rtol=rtol
            )
        except ElectrogrowthError:  # no root after all (the sign's own doubt): not first
            continue
        if _before(c, limit.value, side):
            found.append(c)
    return sorted(found, key=lambda c: sense * c.value)


_UNFOUND = {
    "message": "a mode beyond the scanned ranges is past its root at this short-wave limit,"
    " but the search beyond them found no root before it: a finite mode may come first",
    "remedy": "scan the single modes beyond the ranges (--mode M N) near the limit",
}


def _past_caps(params, solve_for, options, result: ScanResult) -> ScanResult:
    """``result``, its critical point INACCURATE where a mode beyond the caps is past its
    root at its value (beyond.unstable_past_cap): the tube then wrinkles first in waves
    shorter than the scan resolves, and the value is only an upper bound on its critical
    value. Read at a face's short-wave limit, and at a finite mode of a layered tube (a
    thin layer's folds); not at a uniform tube's finite mode, whose wall has no layer thin
    against the caps (and whose scans would pay ~25 ms for it)."""
    c = result.critical
    finite = c.kind == Kind.BIFURCATION and not params.is_uniform
    if not options.extend or c.status != Status.OK or not (c.kind == Kind.SURFACE or finite):
        return result
    past = unstable_past_cap(params, solve_for, c.value, options.prismatic)
    if past is None:
        return result
    what = "short-wave limit" if c.kind == Kind.SURFACE else "value"
    m_cap, n_cap = scan_caps(params, options)
    message = (
        f"mode {past}, beyond the largest m = {m_cap} and n = {n_cap} the scan resolves, is"
        f" past its root at this {what}: the tube wrinkles before it, in shorter waves than"
        " the scan resolves (the value is an upper bound on the critical value)"
    )
    remedy = (
        "take the value as an upper bound; the folds of a layer this thin are those of the"
        " flat layer on its substrate (docs/derivation-film.md)"
    )
    crit = dataclasses.replace(c, status=Status.INACCURATE, message=message, remedy=remedy)
    return dataclasses.replace(result, critical=crit)


def _before(c: CriticalPoint, value: float, side) -> bool:
    """Whether ``c`` is a finite mode reached no later than ``value`` along the march."""
    sense = -1.0 if side == "compression" else 1.0  # the direction of the march
    return c.kind == Kind.BIFURCATION and (value - c.value) * sense >= 0


def _folds_before_limit(params, solve_for, side, result: ScanResult, options, rtol, limit):
    """``result`` searched along each axis (n, then m, up to its cap) whose modes beyond the
    ranges are past their roots at the limit's value (beyond.py); and whether one was.

    Shorter waves tend to a face's limit, but not always from above: the flat film never
    comes before Biot's limit, while a soft lining on a stiffer tube reaches it from below,
    through its O(1/k) corrections (curvature, the stress gradient across the lining). So
    folds far beyond the scan ((m, 0), m ~ 800-1030; rings (0, n), n ~ 300-340) come 2.5e-4
    to 3.2e-3 before the limit, and the limit was returned unchecked, or checked along m
    only (probe 13b, D1-D3). Not without ``options.extend``: the ranges are then as asked."""
    if not options.extend:
        return result, False
    # the fold rows only (beyond.read_rows of no modes): at the limit every
    # short wave of every row is past its root, and each row read would be searched
    turned = unstable_beyond(
        params, solve_for, limit.value, result.m_range, result.n_range, options.prismatic
    )
    if not any(turned.values()):
        return result, False
    for axis, cap in zip(("n", "m"), reversed(scan_caps(params, options)), strict=True):
        if turned[axis]:  # a mode at the cap is then the result: _capped says so
            rows = _search_rows(result, options, axis, turned[axis])
            edge = result.m_range[1] if axis == "m" else result.n_range[1]
            result, _ = _searched(
                params, solve_for, side, result, options, rtol, cap, axis, rows, edge
            )
    # the search's result is a scan's: the limit computed is kept (a finite mode leads)
    limit_kept = {"short_wave_limit": limit.value, "short_wave_error": limit.error_estimate}
    return dataclasses.replace(result, surface_instability=False, **limit_kept), True
