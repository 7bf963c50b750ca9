"""Certification of a critical value by the other method, and of a scan's choice of mode.

A bifurcation value found by one method (impedance or collocation) is certified when the
other method's root, searched in a narrow window around it, agrees to ``rtol``. A scan's
choice of mode is certified when no scanned mode is already unstable just before the
critical value by both methods: a mode is unstable there by a method when its target has
changed sign from the unloaded tube (``params.reference()``, where every mode is stable).
Both are asked because on a layered Tube the collocation determinant may change sign without
a bifurcation where the layers differ strongly (docs/derivation-layered-modes.md L.3): a
root lies before the critical value only if the impedance kernel's sign (at a tight
tolerance) has changed too. So the kernel reads every scanned mode first, in batches, and
collocation only the modes whose kernel sign has changed: a film's scan covers m to 2000
and n to 30, 62 059 modes at ~50 ms each by collocation (not done in 600 s); on a loaded
machine the kernel took 940 s at 1e-12, 139 s as :func:`kernel_signs` reads them. The
kernel's signs on the unloaded tube are one per family block (:func:`unloaded_signs`), read
at a few modes, not at every mode twice more: a film folding at m = 922 is scanned to
m = 2000, n = 240 (482 000 modes), and four reads a mode ran past 13 minutes (probe 8a, D5).

A surface (short-wave) result is certified by recomputing the exact half-space value at a
tighter tolerance, and its best finite runner-up, if any, by the other method.
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Callable

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import CollocationTooLarge, ConvergenceError, ParameterError, Remedy
from ..incremental.accuracy import CERTIFY_RTOL
from ..incremental.modes import ALL_PAIRS, U_Z, mode_pairs
from ..incremental.targets import (
    collocation_targets,
    impedance_targets,
    natural_family,
    resolving_nodes,
    row_family,
)
from ..outcomes import Kind, Status
from .beyond import read_rows, searched_rows
from .critical import NoSignChange, critical_value
from .error_estimate import achieved_floor
from .march import control_path
from .msearch import geometric_samples
from .options import EVERY_M
from .problem import Problem
from .scan_grid import every_mode_ranges, scan_grid
from .surface import short_wave_limit

SURFACE_RTOL = 1e-14  # the half-space value is recomputed at this tolerance
SIGN_RTOL = 1e-12  # the impedance kernel decides a mode's sign this tightly
LOOSE_SIGN = 1e-9  # ... where its resolutions at this and 100 times looser do not agree


@dataclasses.dataclass(frozen=True)
class Certificate:
    """What :func:`certify` established.

    certified : whether the value (and, for a scan, the choice of its mode) is certified.
    by : the method that certified the value ("collocation", "impedance", "halfspace").
    value : the value that method gives; difference : its relative difference.
    modes_checked : scanned modes found stable before the critical value (None: no scan).
    message : one line saying what was certified and how, or why not.
    """

    certified: bool
    by: str | None
    value: float | None
    difference: float | None
    modes_checked: int | None
    message: str

    def as_dict(self) -> dict:
        """The keys ``electrogrowth critical --certify --json`` prints."""
        out = {
            "certified": self.certified,
            "certified_by": self.by,
            "certified_value": self.value,
            "certification_difference": self.difference,
        }
        if self.modes_checked is not None:
            out["certified_modes"] = self.modes_checked
        if self.by == "halfspace" or not self.certified:
            out["certification"] = self.message
        return out


def certify(
    params,
    crit,
    *,
    scan=None,
    options=None,
    rtol: float = CERTIFY_RTOL,
    progress: Callable[[int, int], None] | None = None,
) -> Certificate:
    """Certify the critical point ``crit`` (of ``params``) by the other method.

    Parameters
    ----------
    params : Tube or Problem
        The tube ``crit`` was solved for, or its Problem (whose options are the scan's
        unless ``options`` is given).
    crit : CriticalPoint
        A bifurcation (``critical_value`` or ``scan.critical``) or a surface result.
    scan : ScanResult, optional
        The scan that chose ``crit``: its choice of mode is certified as well.
    options : ScanOptions, optional
        The scan's options (default ScanOptions()): which families it covered.
    rtol : float
        The relative agreement required of the two methods.
    progress : callable(done, total), optional
        Called after each scanned mode is checked.

    Returns
    -------
    Certificate
        For a surface result, ``certified`` False with the reason when it is not.

    Raises
    ------
    ConvergenceError
        "not certified: ..." when the two methods disagree about a bifurcation, or a
        scanned mode comes before the critical one.
    ParameterError
        ``crit`` is neither a bifurcation nor a surface result (a threshold, none).
    """
    if isinstance(params, Problem):
        params, options = params.tube, params.options if options is None else options
    if crit.kind == Kind.SURFACE:
        return _surface(params, crit, scan, rtol)
    if crit.kind != Kind.BIFURCATION:
        raise ParameterError(
            f"crit.kind = {crit.kind}: certify takes a bifurcation or a surface result"
        )
    mode = (crit.m, crit.n, crit.family)
    other, value, diff = _other_method(params, crit, mode, crit.value, crit.error_estimate, rtol)
    families = (True, True) if options is None else (options.prismatic, options.torsional)
    checked = None
    if scan is not None:
        checked = _certify_choice(params, crit, scan, families, progress, abs(value - crit.value))
    message = f"certified by {other}: {value:.12g} (relative difference {diff:.1e})"
    return Certificate(True, other, value, diff, checked, message)


def _other_method(params, crit, mode, value, error, rtol, method=None):
    """(other method, its value, relative difference) for ``mode`` = (m, n, family) of the
    control of ``crit``, found by ``method`` (default crit.method) at ``value`` (error
    estimate ``error``); raises ConvergenceError "not certified: ..." beyond ``rtol``, or
    where the other method finds no root near the value (:func:`_other_root`)."""
    method = method or crit.method
    other = "collocation" if method == "impedance" else "impedance"
    try:
        check = _other_root(params, crit, mode, value, error, other)
    except CollocationTooLarge as exc:  # the value stands, printed, but unchecked (exit 3)
        raise _unchecked(exc, f"{method}'s {value:.12g}") from exc
    diff = abs(check.value - value) / abs(value)
    if diff > rtol:
        own = _own(value, error, rtol)  # the value to tighten first, then the judge
        raise ConvergenceError(
            f"not certified: {method} gives {value:.12g}{own}, {other} gives"
            f" {check.value:.12g} (relative difference {diff:.2e} > {rtol:g})"
            f"{'' if own else _unresolved(check, method, other)}"
        )
    return other, check.value, diff


def _unchecked(exc: CollocationTooLarge, what: str) -> ConvergenceError:
    """ "not certified: ..." where collocation cannot be run for the mode of ``what``."""
    return ConvergenceError(f"not certified: {exc}, so it cannot check {what} here")


def _own(value, error, rtol) -> str:
    """Where the value's own error estimate exceeds rtol |value|, the value is the one off:
    a value solved at rtol 1e-4 (estimate 5.2e-4) disagreed with collocation by 6.6e-7,
    and the refusal blamed collocation, which agreed with the value at rtol 1e-12 to 2.2e-10
    (probe 12b, D4)."""
    if not error > rtol * abs(value):
        return ""
    return (
        f" with its own error estimate {error:.1e}, above {rtol:g} |value|: the value is"
        f" not accurate enough to be certified to {rtol:g} (solve it at a tighter --rtol,"
        " e.g. 1e-12)"
    )


def _unresolved(check, method, other) -> str:
    """Which one is off: the judge that did not meet its own accuracy says so."""
    if check.status is not Status.INACCURATE:
        return ""
    return (
        f"; {other} did not resolve this mode to its tolerance (its own error estimate"
        f" {check.error_estimate:.1e}), so it cannot judge {method} here"
    )


#: the half-widths (relative to the value) of the brackets where layered collocation's root
#: is looked for after the first, as critical._collocation_bracket looks around the kernel's
OTHER_BRACKETS = (1e-5, 1e-3)


def _other_root(params, crit, mode, value, error, other):
    """The other method's critical point of ``mode`` near ``value``: in +-max(1e-6 |value|,
    10 ``error``), then in the wider OTHER_BRACKETS (layered collocation solves only in a
    bracket, and its own error can exceed the first: a film's pressure of -1.7e-5 known to
    1e-12 has collocation's root 4e-9 away, probe 12b D8). Where it has none, or fails,
    ConvergenceError "not certified: {other} cannot resolve this mode near the value (...)":
    the value is printed, refused (not an error of the solve, exit 2)."""
    m, n, family = mode
    widths = [max(1e-6 * abs(value), 10 * error)]
    widths += [r * abs(value) for r in OTHER_BRACKETS if r * abs(value) > widths[0]]
    for w in widths:
        try:
            return critical_value(
                params,
                m,
                n,
                crit.solve_for,
                family=family,
                side=crit.side,
                method=other,
                bracket=(value - w, value + w),
            )
        except NoSignChange as exc:
            why = exc
        except CollocationTooLarge:  # no bracket makes it smaller: _other_method says so
            raise
        except ConvergenceError as exc:
            why = exc
            break
    raise ConvergenceError(
        f"not certified: {other} cannot resolve this mode near the value ({value:.12g} +-"
        f" {w:.1e}: {' '.join(str(why).split())})"
    )


#: the choice is read this many times the two methods' disagreement (or the error
#: estimate) before the critical value: there collocation puts the critical mode itself on
#: its stable side, and a mode whose root lies between is seen
CHOICE_MARGIN = 10.0


def _certify_choice(params, crit, scan, families, progress, disagreement: float) -> int:
    """The number of scanned modes found stable just before the critical value; raises
    ConvergenceError naming a mode unstable there by both methods (module docstring). Just
    before: CHOICE_MARGIN times the larger of the two methods' ``disagreement`` about the
    critical mode and its error estimate (not 1e-6 of the value, the window of the value's
    own check: a film's modes lie 1e-7 to 1e-8 apart, and a ring 7e-8 before the critical
    one was certified stable, probe round 6b)."""
    start, end, _ = control_path(params, crit.solve_for, crit.side)
    sense = 1.0 if end > start else -1.0
    gap = max(disagreement, crit.error_estimate, 1e-13 * max(1.0, abs(crit.value)))
    before = crit.value - sense * CHOICE_MARGIN * gap
    modes = choice_modes(scan, crit, families)
    state = solve_base_state(params.at(crit.solve_for, before))
    reference = solve_base_state(params.reference())
    stable = unloaded_signs(reference, modes)
    f = _in_batches(functools.partial(kernel_signs, state), modes, progress) * stable
    suspects = np.flatnonzero(~(f > 0))  # changed sign, or no sign (NaN, 0)
    for i in suspects[np.argsort(f[suspects])]:  # the most unstable-looking first
        if _collocation_stable(state, reference, modes[i]):
            continue  # the kernel's sign changed alone: not both methods
        m, n = (int(x) for x in modes[i, :2])
        err = ConvergenceError(
            f"not certified: by collocation and impedance mode ({m}, {n}) is already"
            f" unstable at {crit.solve_for} = {before:.12g}, before the scan's critical"
            f" mode ({crit.m}, {crit.n}) at {crit.value:.12g}"
        )
        err.remedy = choice_remedy(crit, m, n, str(row_family(modes[i])))
        raise err
    return int(len(modes))


def choice_modes(scan, crit, families) -> np.ndarray:
    """The modes whose signs certify a scan's choice: every mode of its ranges up to M_CAP,
    N_CAP (scan_grid.every_mode_ranges) and, where the ranges reach beyond (a thin layer's
    caps, options.mode_caps), the rows its searches follow and its read beyond the ranges
    reads (beyond.searched_rows, read_rows) at their geometric samples and every index
    within EVERY_M of the critical mode's. Every mode to 64064 of 30 rows would be
    1.9 million reads (an hour); these are a few hundred."""
    ranges = every_mode_ranges(scan.m_range, scan.n_range)
    grid = [scan_grid(*ranges, False, families)]
    finite = crit if crit.kind == Kind.BIFURCATION else None
    for axis, (_, edge) in zip("mn", ranges, strict=True):
        grid.append(_rows_past(scan, finite, families[0], axis, edge))
    return np.unique(np.vstack([g.reshape(-1, 3) for g in grid]), axis=0)


def _rows_past(scan, finite, prismatic: bool, axis: str, edge: int) -> np.ndarray:
    """The modes past ``edge`` along ``axis`` up to the scan's range on the rows its search
    follows and its read (beyond.searched_rows, read_rows) reads, at the indices of
    :func:`_past_every_mode` (``finite``: the critical mode, or None)."""
    top = scan.m_range[1] if axis == "m" else scan.n_range[1]
    if top <= edge:
        return np.zeros((0, 3))
    rows = searched_rows(finite, scan.m_range, scan.n_range, prismatic, axis)
    first = ((finite,) if finite is not None else ()) + tuple(scan.runners_up)
    rows |= set(read_rows(first, scan.m_range, scan.n_range, prismatic, axis))
    ks = _past_every_mode(edge, top, None if finite is None else getattr(finite, axis))
    if axis == "m":
        return np.array([(k, n, code) for k in ks for n, code in sorted(rows)], float)
    return np.array([(m, k, code) for k in ks for m, code in sorted(rows)], float)


def _past_every_mode(edge: int, top: int, at: int | None) -> list[int]:
    """Indices past ``edge`` up to ``top``: geometric samples, and every one within EVERY_M
    of ``at`` (the critical mode's, if finite)."""
    out = set(geometric_samples(edge + 1, top))
    if at is not None:
        out |= set(range(max(edge + 1, at - EVERY_M), min(top, at + EVERY_M) + 1))
    return sorted(out)


def choice_remedy(crit, m: int, n: int, family: str) -> Remedy:
    """What to do where the scan chose the wrong mode: solve the mode that comes first alone.
    Not ConvergenceError's "loosen rtol": the value of the scan's mode may be exact, and no
    tolerance of certify makes it the first (probe 9a, D5: that advice came with rtol 1e-6)."""
    natural = family == natural_family(m, n)
    flag = "" if natural else f" --family {family}"
    args = ("" if natural else f", family={family!r}") + (
        "" if crit.side is None else f", side={crit.side!r}"
    )
    why = (
        f"the scan passed over mode ({m}, {n}), which bifurcates before its mode"
        f" ({crit.m}, {crit.n}): the critical value is that mode's or an earlier one's"
    )
    return Remedy(
        f"solve mode ({m}, {n}) alone with --mode {m} {n}{flag} ({why})",
        python=f"solve mode ({m}, {n}) alone with critical_value(tube, {m}, {n},"
        f" {crit.solve_for!r}{args}) ({why})",
    )


def _collocation_stable(state, reference, row) -> bool:
    """Has collocation's target of mode ``row`` at ``state`` its sign on the unloaded
    ``reference`` (positive for one layer), with the nodes that resolve the mode there?"""
    nodes = resolving_nodes(state, row[0], row[1], CERTIFY_RTOL)
    try:
        now = collocation_targets(state, row[None, :], nodes=nodes)[0]
    except CollocationTooLarge as exc:  # the kernel's sign changed, collocation cannot say
        raise _unchecked(
            exc, f"the kernel's sign change of mode ({int(row[0])}, {int(row[1])})"
        ) from exc
    if len(state.tube.layers) == 1:
        return bool(now > 0)
    return bool(
        np.sign(now) == np.sign(collocation_targets(reference, row[None, :], nodes=nodes)[0])
    )


#: modes of a family block whose sign on the unloaded tube is read, besides its extremes
SAMPLES = 16


def unloaded_signs(reference, modes) -> np.ndarray:
    """The kernel's sign of every row of ``modes`` on the unloaded tube ``reference``: one
    sign per family block (the Stroh pairs a row keeps, :func:`mode_pairs`), read at
    SIGN_RTOL at the block's extreme modes and SAMPLES spread over it.

    Why one: on a stress-free tube no mode of a block has a non-trivial solution for any
    real (m, k) of the block's domain (m >= 1, k > 0 for the wrinkles; m = 0 the rings and
    the torsion, k = 0 the prismatic m >= 2): the incremental energy is positive definite
    and no rigid motion has the form U(r) exp(i (m theta + k z)) there. The target is
    continuous in (m, k) (f exp(log_norm) is det M2, analytic), so it keeps one sign over
    the block (the argument of scan_grid.stable_signs, along modes instead of tubes); it is
    +1 in every mode of eight tubes read at 1e-12 (one to four layers, dielectric, Gent,
    Mooney-Rivlin, a film to m = 2000, n = 120). A block whose samples disagree (a kernel
    misread: a chart's pole once gave -0.7 at 1e-9, docs/reliability.md) is read mode by
    mode, as :func:`kernel_signs` reads the state; so is a row outside those domains (a
    hand-made range with n = 0 reaches the rigid motions at k = 0).
    """
    pairs, signs = mode_pairs(modes), np.zeros(len(modes))
    prismatic = pairs == ALL_PAIRS & ~U_Z
    block_of = np.where(np.where(prismatic, modes[:, 0] >= 2, modes[:, 1] >= 1), pairs, -1)
    for p in np.unique(block_of):
        block = np.flatnonzero(block_of == p)
        s = _block_sign(reference, modes[block]) if p >= 0 else 0.0
        signs[block] = s if s != 0 else kernel_signs(reference, modes[block])
    return signs


def _block_sign(reference, rows) -> float:
    """The one sign of a block's ``rows`` on the unloaded ``reference`` where its sampled
    modes agree on it at SIGN_RTOL, else 0 (no sign assumed)."""
    s = np.sign(impedance_targets(reference, rows[_spread(rows)], rtol=SIGN_RTOL))
    return float(s[0]) if s[0] != 0 and np.all(s == s[0]) else 0.0


def _spread(rows) -> np.ndarray:
    """Indices of ``rows``: its extremes in m, n and m + n, and SAMPLES evenly spread."""
    m, n = rows[:, 0], rows[:, 1]
    ends = [f(x) for x in (m, n, m + n) for f in (np.argmin, np.argmax)]
    even = np.linspace(0, len(rows) - 1, min(SAMPLES, len(rows))).astype(int)
    return np.unique(np.concatenate([ends, even]))


def kernel_signs(state, rows) -> np.ndarray:
    """The signs of the impedance kernel's targets of ``rows`` at ``state``: read at
    LOOSE_SIGN and taken where the second resolution (100 LOOSE_SIGN) is nearer to it than
    half its size, else read at SIGN_RTOL. A film's modes to m = 2000 cost ~0.3 ms each at
    1e-9 and 1e-7, ~6 ms at 1e-12."""
    f = impedance_targets(state, rows, rtol=LOOSE_SIGN)
    coarse = impedance_targets(state, rows, rtol=100.0 * LOOSE_SIGN)
    doubt = ~(np.abs(f - coarse) < 0.5 * np.abs(f))  # NaN too
    if doubt.any():
        f[doubt] = impedance_targets(state, rows[doubt], rtol=SIGN_RTOL)
    return np.nan_to_num(np.sign(f))


#: modes per batch of the kernel's signs (a progress report after each)
BATCH = 2048


def _in_batches(target, modes, progress) -> np.ndarray:
    """``target`` of the rows of ``modes`` in batches of BATCH (reported to ``progress``)."""
    f = []
    for lo in range(0, len(modes), BATCH):
        f.append(target(modes[lo : lo + BATCH]))
        if progress is not None:
            progress(min(lo + BATCH, len(modes)), len(modes))
    return np.concatenate(f) if f else np.zeros(0)


def _surface(params, crit, scan, rtol) -> Certificate:
    """The half-space value recomputed at SURFACE_RTOL (and the best finite runner-up by the
    other method), or certified False with the reason."""
    limit = short_wave_limit(params, crit.solve_for, side=crit.side, rtol=SURFACE_RTOL)
    if limit.kind != Kind.SURFACE:
        msg = f"not certified: at rtol {SURFACE_RTOL:g} the short-wave limit is {limit.kind}"
        return Certificate(False, "halfspace", None, None, None, msg)
    # the same method at a tighter rtol: agreeing to the bit is no exactness, so the
    # difference is at least the precision achieved at SURFACE_RTOL (achieved_floor)
    floor = achieved_floor(limit.value, SURFACE_RTOL) / abs(crit.value)
    diff = max(abs(limit.value - crit.value) / abs(crit.value), floor)
    if diff > rtol:
        msg = (
            f"not certified: the half-space value {crit.value:.12g} is {limit.value:.12g} at"
            f" rtol {SURFACE_RTOL:g} (relative difference {diff:.2e} > {rtol:g})"
        )
        return Certificate(False, "halfspace", limit.value, diff, None, msg)
    shown = f"{diff:.1e}" if diff > floor else f"up to {diff:.1e}, the precision achieved there"
    msg = (
        f"half-space value recomputed at rtol {SURFACE_RTOL:g}: {limit.value:.12g}"
        f" (relative difference {shown})"
    )
    runners = [] if scan is None else list(scan.runners_up)
    if not runners:
        msg += "; no finite mode was reached before the end of the march, none to certify"
        return Certificate(True, "halfspace", limit.value, diff, None, msg)
    r = runners[0]
    try:
        mode = (r.m, r.n, r.family)
        other, value, rdiff = _other_method(params, crit, mode, r.value, 0.0, rtol, "impedance")
    except ConvergenceError as exc:
        msg += f"; the first scanned finite mode ({r.m}, {r.n}) at {r.value:.12g} is {exc}"
        return Certificate(False, "halfspace", limit.value, diff, None, msg)
    msg += (
        f"; the first scanned finite mode ({r.m}, {r.n}) at {r.value:.12g} certified by {other}"
        f" ({value:.12g}, relative difference {rdiff:.1e}): it comes after the surface"
    )
    return Certificate(True, "halfspace", limit.value, diff, None, msg)
