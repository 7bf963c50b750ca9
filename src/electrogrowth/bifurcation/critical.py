"""Critical growth factor, axial stretch or voltage of one wrinkling mode (m, n).

The tube wrinkles in mode (m, n), k = n pi / (lambda_z L), when the incremental problem
has a non-trivial solution: det z(r_o) = 0 (paper eq. dispersion-eq). A mode belongs to a
family (incremental.targets.Family): the paper's ansatz ("wrinkle", m >= 0, n >= 1, the
torsion excluded at m = 0), "prismatic" (n = 0, m >= 2) or "torsional" (m = 0, n >= 1);
each has its own block of the incremental problem. We use the pole-free
target f of the impedance kernel (impedance.py) or of the collocation method
(collocation.py); both change sign exactly at bifurcation. Which sign is stable is read
off the unloaded tube (g = 1, lambda_z = 1, Vbar = 0), stress free and stable in every
mode: along any path of parameters f keeps that sign until the first bifurcation.

A critical value is found by marching the control parameter from the stable start
(march.py), then converging with Brent's method. If the axisymmetric base state ceases to
exist first (the voltage threshold), that is reported instead.

Every value carries an error estimate, the distance to the root of the same target at 100
times looser accuracy (searched only inside the march's path: a probe never leaves the
control's domain). A value whose estimate exceeds CERTIFIED rtol |value| (the looser root
more than 100 times its own tolerance away; incremental.accuracy.certified) is solved again
at rtol / 100 (down to the smallest rtol), and if it still misses it is returned with the status
INACCURATE (outcomes.Status), never silently.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import TYPE_CHECKING

import numpy as np

from ..basestate.tube import solve_base_state
from ..continuation.events import Remembered, brent
from ..errors import (
    CHECK_WITH_IMPEDANCE,
    ConvergenceError,
    ElectrogrowthError,
    NoBifurcationBeforeLock,
    NoBifurcationFound,
    Remedy,
)
from ..incremental.accuracy import CERTIFIED, RTOL_RANGE, STABLE_SIGN, Accuracy, certified
from ..incremental.targets import (
    CollocationTarget,
    Family,
    Method,
    check_method,
    check_mode,
    coarse_targets_for,
    natural_family,
    targets_for,
    with_family,
)
from ..model.controls import check_side, natural_scale
from ..model.layers import Tube
from ..outcomes import Kind, Outcome, Status
from ..summary import critical_html
from .along import TubeAt, root_mode
from .error_estimate import achieved_floor, collocation_floor, second_resolution
from .march import (
    ONE_MODE_STEPS,
    ONE_MODE_WAIT,
    MarchResult,
    ModeValue,
    control_path,
    first_bifurcations,
)
from .problem import Problem, as_problem
from .state_loss import asymptote_error, asymptote_note, lost_note
from .torsion_onset import torsional_onset

if TYPE_CHECKING:
    from .verdict import Verdict

#: an uncertified value is solved again at rtol / REFINE, down to the smallest rtol
REFINE = 100.0


@dataclasses.dataclass(frozen=True)
class CriticalPoint(Outcome):
    """Result of :func:`critical_value`.

    ``kind`` is BIFURCATION (wrinkling in mode (m, n) of ``family``, see
    incremental.targets.Family), THRESHOLD (the axisymmetric base
    state is lost first, at ``value``) or, from a scan, SURFACE: the short-wave limit
    m, k -> infinity at ``face`` ("inner" or "outer") with the wave direction ``psi``
    (radians; tan psi = k r / m: 0 wrinkles along theta, pi/2 along z). (m, n) is
    NO_MODE unless the kind is BIFURCATION; ``as_dict`` gives null there. ``status`` is
    OK, or INACCURATE when the error estimate exceeds the accuracy asked even after
    refinement (module docstring): the value then has only the digits the estimate supports;
    ``message`` then says by how much and ``remedy`` what to try. An
    :class:`~electrogrowth.outcomes.Outcome` (``unwrap``, ``outcome_dict``).

    ``verdict`` (computed when first read: it marches the crease criterion along the same
    control, bifurcation/verdict.py) says what comes first of this wrinkle, a crease of a
    free face (crease.py) and the loss of the axisymmetric state; ``kind`` stays the
    linear result's.
    """

    solve_for: str
    value: float
    m: int
    n: int
    kind: str
    error_estimate: float
    method: str
    side: str | None
    params: Tube
    face: str | None = None
    psi: float | None = None
    family: str | None = None
    status: Status = Status.OK
    message: str = ""
    remedy: str = ""

    def __post_init__(self):
        if self.family is None and self.kind == Kind.BIFURCATION:
            object.__setattr__(self, "family", natural_family(self.m, self.n))

    def as_dict(self) -> dict:
        mode = self.kind == Kind.BIFURCATION
        return {
            "solve_for": self.solve_for,
            "value": self.value,
            "m": self.m if mode else None,
            "n": self.n if mode else None,
            "family": str(self.family) if mode and self.family else None,
            "face": self.face,
            "psi": self.psi,
            "kind": self.kind,
            "error_estimate": self.error_estimate,
            "method": self.method,
            "side": self.side,
            "status": str(self.status),
            **self.params.as_dict(),
        }

    @functools.cached_property
    def verdict(self) -> Verdict:
        """What comes first: this linear result, a crease or the threshold (verdict.py)."""
        from .verdict import verdict_of  # here: a critical value alone never loads the crease

        return verdict_of(self, one_mode=True)

    def _repr_html_(self) -> str:
        return critical_html(self)


def critical_value(
    params: Tube | Problem,
    m: int,
    n: int,
    solve_for: str | None = None,
    *,
    family: str | None = None,
    side: str | None = None,
    method: str = "impedance",
    rtol: float | None = None,
    bracket: tuple[float, float] | None = None,
) -> CriticalPoint:
    """Critical value of ``solve_for`` for mode (m, n), the other parameters fixed.

    ``critical_value(problem, m, n)`` takes the control, side and accuracy from a
    :class:`~.problem.Problem`; ``critical_value(tube, m, n, solve_for, side=...,
    rtol=...)`` builds that problem from the keywords.

    Parameters
    ----------
    params : Tube or Problem
        The tube (one homogeneous layer, or a layered Tube with its loads); the value of
        the control ``solve_for`` is ignored (it is the unknown). Or a Problem (then
        ``solve_for``, ``side`` and ``rtol`` are left out).
    m, n : int
        Circumferential wavenumber m >= 0 and axial half-wavenumber n >= 0 (k = n pi /
        (lambda_z L); n = 0: a prismatic mode, m >= 2).
    solve_for : str
        Growth: smallest g > 1. Stretch: the lambda_z nearest to lambda_z = g on ``side``
        ("compression", default, or "extension"). Voltage: smallest Vbar > 0. For a layered
        Tube also ``"growth[K]"``, ``"growth[K].theta"`` (one layer, some components),
        ``"pressure"`` (P_i from P_o, up or, ``side="compression"``, down) and ``"force"``
        (the axial force from 0, down by default); see model/controls.py.
    family : {"wrinkle", "prismatic", "torsional"}, optional
        The mode family (incremental.targets.Family); default the natural one of (m, n):
        prismatic for n = 0, else wrinkle (the paper's ansatz; axisymmetric at m = 0).
        Torsional (m = 0, n >= 1: u_th = U(r) cos kz) must be named.
    method : {"impedance", "collocation"}
        The compiled Riccati kernel or the independent spectral collocation.
    rtol : float
        Local accuracy of the integration (default 1e-12, valid 1e-14 to 1e-4); the value is
        converged to a few rtol, and its error estimate is at least 5 rtol |value|
        (error_estimate.achieved_floor). A value whose
        error estimate exceeds CERTIFIED rtol |value| is solved again at rtol / 100,
        and returned with status INACCURATE if it still does.
    bracket : (float, float), optional
        A known sign-change interval (e.g. from a mode scan); the march is skipped when
        the target does change sign on it; where it does not, the march from the control's
        start finds the first root and ``message`` says so (layered collocation never
        marches: then ConvergenceError).

    Returns
    -------
    CriticalPoint
        With an error estimate from a second solve at 100 times looser accuracy, and a
        status (OK or INACCURATE).

    Raises
    ------
    ParameterError, NoBifurcationFound, ConvergenceError
    """
    fam = check_mode(m, n, family)
    problem = as_problem(params, solve_for, side=side, rtol=rtol)
    params, solve_for, side, rtol = problem.tube, problem.control, problem.side, problem.rtol
    # layered collocation never marches on its own (its determinant has sign changes of its
    # own, docs/derivation-layered-modes.md L.3): it solves a root in a bracket
    layered = check_method(method) is Method.COLLOCATION and not params.is_uniform
    kernel = None
    if bracket is None and layered:
        kernel, bracket = _kernel_bracket(params, m, n, solve_for, fam, side, rtol)
        if bracket is None:
            return kernel  # the state is lost first (a base-state property: any method)
    solve = functools.partial(
        _solve, params, m, n, solve_for, fam, side, method, march=not layered
    )
    point = solve(rtol, bracket)
    tight = rtol
    certain = functools.partial(is_certified, rtol=rtol, tube=params)
    while not certain(point) and tight / REFINE >= RTOL_RANGE[0] * (1 - 1e-9):
        tight /= REFINE
        if kernel is not None:  # more nodes at the finer rtol: the bracket is theirs to find
            bracket = _collocation_bracket(params, m, n, solve_for, fam, kernel.value, tight)
        try:
            point = solve(tight, bracket)
        except NoSignChange as exc:  # the point at the looser rtol stands, not certified
            return _inaccurate(point, rtol, f"; at rtol = {tight:g} {exc}")
    if certain(point):
        return point
    return _inaccurate(point, rtol, f" even at rtol / {REFINE:g}")


def _inaccurate(point: CriticalPoint, rtol: float, why: str) -> CriticalPoint:
    """``point`` marked INACCURATE: its estimate exceeds the certified bound, and ``why``."""
    return dataclasses.replace(
        point,
        status=Status.INACCURATE,
        message=f"error estimate {point.error_estimate:.1e} exceeds {CERTIFIED:g} rtol"
        f" |value| (rtol = {rtol:g}){why}",
        remedy=CHECK_WITH_IMPEDANCE
        if point.method == Method.COLLOCATION
        else ConvergenceError.remedy,
    )


class NoSignChange(ConvergenceError):
    """Layered collocation has no sign change on its bracket (it does not march instead);
    certify reads it as the other method's refusal, not as an error of the value."""


#: relative half-widths tried around the kernel's root for layered collocation's bracket
KERNEL_BRACKETS = (1e-7, 1e-5, 1e-3)


def _kernel_bracket(params, m, n, solve_for, fam, side, rtol):
    """(the kernel's point, a bracket around its root where collocation changes sign), or
    (the kernel's point, None) where the state is lost first.

    Collocation with one domain per layer has sign changes of its own, where no method
    bifurcates (docs/derivation-layered-modes.md L.3: mode (0, 8) of a three-layer tube at
    g = 2.033, which the kernel and the shooting twin do not see; a collapse pressure of
    -222.57 against their -3030.66). So on a layered tube it does not march: it solves the
    root the kernel's march found, in a bracket of 1e-7 to 1e-3 of it, and says so if it has
    none there (ConvergenceError)."""
    kernel = _solve(params, m, n, solve_for, fam, side, "impedance", rtol, None)
    if kernel.kind != Kind.BIFURCATION:
        return kernel, None
    bracket = _collocation_bracket(params, m, n, solve_for, fam, kernel.value, rtol)
    if bracket is not None:
        return kernel, bracket
    raise ConvergenceError(
        f"collocation finds no root of mode ({m}, {n}) within {KERNEL_BRACKETS[-1]:g} |value| of"
        f" the impedance kernel's {solve_for} = {kernel.value:.12g} on this layered tube (its"
        " determinant has sign changes of its own: docs/derivation-layered-modes.md L.3); use"
        " the impedance method, or give collocation a bracket"
    )


def _collocation_bracket(params, m, n, solve_for, fam, v, rtol):
    """The narrowest of the KERNEL_BRACKETS about ``v`` on which collocation at ``rtol`` (its
    node count) changes sign, or None."""
    colloc, mode = CollocationTarget(rtol), with_family(m, n, fam)
    for width in KERNEL_BRACKETS:
        w = width * max(abs(v), 1e-300)  # relative: a small value's bracket keeps its side
        ends = [colloc(solve_base_state(params.at(solve_for, x)), mode)[0] for x in (v - w, v + w)]
        if ends[0] * ends[1] < 0:
            return v - w, v + w
    return None


def is_certified(point: CriticalPoint, rtol: float, tube: Tube) -> bool:
    """Is the error estimate of ``point`` (a critical value of ``tube``) within CERTIFIED
    rtol |value| (incremental.accuracy.certified)? A threshold or a limit has no second
    resolution to miss."""
    if point.kind != Kind.BIFURCATION:
        return True
    natural = natural_scale(tube, tube.check_control(point.solve_for).kind)
    return certified(point.error_estimate, point.value, rtol, natural)


def _solve(
    params, m, n, solve_for, fam, side, method, rtol, bracket, *, march=True
) -> CriticalPoint:
    """One solve of :func:`critical_value` at ``rtol`` (checked arguments); without
    ``march``, only in ``bracket`` (NoSignChange if the target keeps its sign there)."""
    mode = with_family(m, n, fam)
    acc = Accuracy(rtol)
    doubt, onset_read = "", False  # why a torsional root is not known to be the first
    fine, coarse = targets_for(method, acc.fine), coarse_targets_for(method, acc.fine)
    sref = stable_sign(m, n, params, method, family=fam)
    at = TubeAt(params, solve_for)
    along = root_mode(at, fine, mode, sref)  # along the control, stable > 0
    # remembered: Brent's method starts from a bracket's ends, which the check of its sign
    # change (here, or _root_before's) has just paid for; the same values, the same root
    g = Remembered(along)
    note = ""
    if bracket is not None:
        bracket = _after_start(bracket, control_path(params, solve_for, side)[:2])
    if bracket is not None and g(bracket[0]) * g(bracket[1]) < 0:
        value = brent(g, *bracket)
    elif not march:
        where = "no bracket" if bracket is None else f"no sign change on {bracket}"
        raise NoSignChange(
            f"{method} has {where} for mode ({m}, {n}) on this layered tube, and does not"
            " march on its own there (its determinant has sign changes of its own:"
            " docs/derivation-layered-modes.md L.3)"
        )
    else:
        if bracket is not None:  # a value outside the caller's bracket says why (probe 14a)
            note = f"no sign change on the bracket {tuple(bracket)}: the march's first root"
        loose = targets_for(method, acc.march_signs)
        try:
            res = first_bifurcations(
                params,
                solve_for,
                side,
                mode,
                loose,
                brent_targets=fine,
                stable_signs=np.array([sref]),  # the sign read above, not read again
                steps=ONE_MODE_STEPS,
                at=at,  # the error estimate's first state is the value's, solved by the march
                rtol=acc.fine,
            )
        except NoBifurcationFound as exc:
            # a torsional mode first bifurcates where its moduli vanish: no window to look for
            if fam is Family.TORSIONAL:
                root, doubt = _torsional_first(params, at, solve_for, side, None)
                onset_read = True
            else:
                root = _surface_window(params, (m, n), solve_for, side, g)
            if root is None:
                _no_bifurcation(exc, solve_for, m, n, fam)
            res = MarchResult([ModeValue(int(m), int(n), root, str(fam))], None)
        if not res.found:
            return _threshold_point(params, at, res, solve_for, (m, n), fam, method, side, acc)
        value = res.found[0].value
        if fam is Family.TORSIONAL and not onset_read:  # the march's root: the first?
            value, doubt = _torsional_first(params, at, solve_for, side, value)
    path = control_path(params, solve_for, side)[:2]
    estimate = second_resolution(root_mode(at, coarse, mode, sref), value, path)
    if check_method(method) is Method.COLLOCATION:
        estimate = max(estimate, collocation_floor(Remembered(along), value, path))
    estimate = max(estimate, achieved_floor(value, acc.fine))  # the two may share an error
    return CriticalPoint(
        solve_for,
        value,
        int(m),
        int(n),
        Kind.BIFURCATION,
        estimate,
        method,
        side,
        params.at(solve_for, value),
        family=fam,
        status=Status.INACCURATE if doubt else Status.OK,
        message=doubt or note,
        remedy=TORSION_REMEDY if doubt else "",
    )


def _threshold_point(params, at, res, solve_for, mn, fam, method, side, acc) -> CriticalPoint:
    """The CriticalPoint of a mode whose march lost the state first (``res.threshold``).
    Its error estimate: 0 where the loss was located, what rtol achieves where it is an
    asymptote examined up to the value's tolerance short of it (a root there is it)."""
    value, near = res.threshold, res.near
    if near is None:
        err, note = 0.0, lost_note(at, value)
    else:
        err = asymptote_error(value, near, acc.fine)
        note = asymptote_note(solve_for, value, near, f"mode {mn} does not bifurcate")
    m, n = mn
    return CriticalPoint(
        solve_for,
        value,
        int(m),
        int(n),
        Kind.THRESHOLD,
        err,
        method,
        side,
        params.at(solve_for, value),
        family=fam,
        message=note,
    )


TORSION_REMEDY = Remedy(
    "solve the mode in Python with critical_value(..., bracket=(onset, value)): its first"
    " root lies between the two (shorter torsional waves bifurcate nearer the onset)",
    python="pass bracket=(onset, value) to critical_value: the first root lies between the"
    " two (shorter torsional waves bifurcate nearer the onset)",
)


def _torsional_first(params, at: TubeAt, solve_for, side, found: float | None):
    """(value, doubt) of a torsional mode whose march found the root ``found`` (None: no
    root up to the path's end): the first zero of its moduli along the path before it
    (torsion_onset.py) where that is an exact root of every torsional mode; else ``found``,
    with why it is not known to be the first root where the moduli vanish before it (past
    that point the roots come densely, the march steps over them); a ConvergenceError
    where no root was found past such a point."""
    start, end = control_path(params, solve_for, side)[:2]
    onset = torsional_onset(at, start, end if found is None else found, 1e-12)
    if onset is None:
        return found, ""
    if onset.exact:
        return onset.value, ""
    where = (
        f"the wall's torsional shear modulus (gamma_12 or A3232) vanishes at {solve_for} ="
        f" {onset.value:.12g}: past it the torsional problem is not elliptic and a mode's"
        " roots come densely"
    )
    if found is None:
        err = ConvergenceError(f"{where}; none was found up to {end:g}")
        err.remedy = TORSION_REMEDY
        raise err
    return found, f"{where}; the first root lies between it and this one, not located"


def _after_start(bracket: tuple[float, float], path: tuple[float, float]):
    """``bracket`` cut at the path's start (start, end): a root before the start is no
    onset, the tube is unstable at its start, which the march then says. A scan's bracket
    about its march's root (relative 1e-7 wide, grid_scan.finished) reached past g = 1
    where the march's loose sign at the start read stable: it returned g_cr = 0.9999999
    where a single-mode solve said "already unstable" (probe 14d, D1)."""
    start, end = path
    sense = math.copysign(1.0, end - start)
    near, far = sorted(bracket, key=lambda x: sense * x)
    if sense * (near - start) < 0 < sense * (far - start):
        near = start
    return (near, far) if near <= far else (far, near)


def _no_bifurcation(exc: NoBifurcationFound, solve_for: str, m: int, n: int, fam) -> None:
    """Raise the march's ``exc`` with its remedy (and why, for a torsional mode); one that
    stopped next to its control's lock keeps its own."""
    if not isinstance(exc, NoBifurcationBeforeLock):
        exc.remedy = no_bifurcation_remedy(solve_for, mode=(m, n))
    if fam is not Family.TORSIONAL:
        raise exc
    stop = NoBifurcationFound(
        f"{exc}: torsional modes never bifurcate while the shear moduli gamma_12 and"
        " A3232 are positive (docs/derivation-families.md)"
    )
    stop.remedy = exc.remedy
    raise stop from None


#: the search around the short-wave limit x_s for an unstable state: first this far from it
#: (times the path's scale), then SURFACE_WIDEN times as far, up to the march's longest step
#: (ONE_MODE_WAIT: a wider window has a sample of the march in it)
SURFACE_FIRST = 1e-7
SURFACE_WIDEN = 4.0


def _surface_window(params, mode, solve_for, side, g) -> float | None:
    """The first bifurcation of ``mode`` (m, n) in its window next to the short-wave limit
    x_s of its ray (modes (j m, j n), surface.ray_limit), when the
    march found none: None where the mode g (stable > 0) is stable within one march step of
    x_s (or the path has no surface value).

    A short wave's critical value tends to x_s (like 1 / wavenumber) from either side, and
    near the cap of the modes it can be unstable only in a window next to x_s narrower than
    the march's steps: a film ring's (0, 2000) on [1.7643, 1.779] around x_s = 1.7678, whose
    bounded target keeps its size through both roots (its sign is det(M2)'s: nothing tells a
    march sampling every 0.05 that the window is there). The unstable state nearest to x_s
    (earlier side first) is looked for in widening steps, then the stable one before it."""
    from .surface import ray_limit  # the half-space march: only where a march failed

    try:
        limit = ray_limit(params, mode[0], mode[1], solve_for, side=side, estimate=False)
    except ElectrogrowthError:  # no surface value on this path: the march's answer stands
        return None
    if limit.kind is not Kind.SURFACE:
        return None
    start, end, scale = control_path(params, solve_for, side)
    xs, sense = limit.value, math.copysign(1.0, end - start)
    width, widest = SURFACE_FIRST * scale, ONE_MODE_WAIT * scale
    unstable = xs if not g(xs) > 0 else None
    while unstable is None and width <= widest:
        near = [xs - sense * width, xs + sense * width]
        unstable = next((x for x in near if _inside(x, start, end) and not g(x) > 0), None)
        width *= SURFACE_WIDEN
    return None if unstable is None else _root_before(g, unstable, start, scale)


def _inside(x: float, start: float, end: float) -> bool:
    """Is x strictly past the path's start and not past its end?"""
    return (x - start) * (end - x) >= 0 and x != start


def _root_before(g, bad: float, start: float, scale: float) -> float:
    """The root of g between ``bad`` (g <= 0) and the nearest stable state before it, found in
    widening steps back towards the start (stable: the march checked it)."""
    sense, width = math.copysign(1.0, bad - start), SURFACE_FIRST * scale
    while True:
        a = bad - sense * width
        if sense * (a - start) <= 0:
            a = start
        if a == start or g(a) > 0:
            return brent(g, *sorted((a, bad)))
        width *= SURFACE_WIDEN


def no_bifurcation_remedy(solve_for: str, *, mode: tuple[int, int] | None = None) -> Remedy:
    """The remedy of a NoBifurcationFound in the terms of what was asked: one mode (then
    --m-max / --n-max change nothing) or a scan; the other --side only for a control that
    has one (the stretch, the pressure, the force)."""
    sided = check_side(solve_for, None) is not None
    side, side_py = (", try the other --side", ", try the other side=") if sided else ("", "")
    if mode is not None:
        return Remedy(
            f"mode {tuple(mode)} has no root in the searched range: scan every mode (leave out"
            f" --mode){side}, or solve for another control parameter",
            python=f"mode {tuple(mode)} has no root in the searched range: scan every mode"
            f" (scan_modes){side_py}, or solve for another control parameter",
        )
    return Remedy(
        f"raise --m-max / --n-max{side}, or solve for another control parameter",
        python=f"widen ScanOptions(m_range=..., n_range=...){side_py}, or solve for another"
        " control parameter",
    )


def control_name(params: Tube, solve_for) -> str:
    """The canonical name of the control ``solve_for`` of ``params`` (model/controls.py,
    checked against the tube)."""
    return str(params.check_control(solve_for))


def stable_sign(
    m: int, n: int, params: Tube, method: str = "impedance", *, family: str | None = None
) -> float:
    """Sign of the target of mode (m, n) of ``family`` (default: the natural one) on the
    unloaded tube (g = 1, lambda_z = 1, Vbar = 0)."""
    fam = check_mode(m, n, family)
    return _stable_sign(params.reference(), int(m), int(n), fam, str(check_method(method)))


@functools.lru_cache(maxsize=1024)
def _stable_sign(reference: Tube, m: int, n: int, fam: Family, method: str) -> float:
    """:func:`stable_sign` on the unloaded tube ``reference``, remembered: a curve or a
    sweep of one tube's growth, stretch or voltage asks for the same sign again."""
    targets = targets_for(method, STABLE_SIGN)
    f = float(targets(solve_base_state(reference), with_family(m, n, fam))[0])
    if f == 0.0 or not math.isfinite(f):
        raise ConvergenceError(
            f"target undefined on the unloaded tube for mode ({m}, {n}) ({fam})"
        )
    return math.copysign(1.0, f)
