"""The short-wave (surface) limit of wrinkling, from the half-space problem at the faces.

A mode (m, n) with m, k -> infinity along a ray tan psi = k r / m sees, at a face, a
half-space with the frozen local moduli and field (incremental/halfspace.py). Its
critical value tends to that of the half-space like 1/m (the curvature of the wall and
the gradients of the base state enter at the next order). The short-wave critical value
of a control parameter x (growth g > 1, stretch lambda_z on one side, voltage Vbar > 0)
is the first x, marching from the stable start, at which for SOME face and SOME
direction psi in [0, pi/2] the half-space target f vanishes:

    h(x) = min_{face} min_{psi} s_face f(state(x), face, psi),

with s_face = sign of f on the unloaded tube (g = 1, lambda_z = 1, Vbar = 0), which is
stable; h > 0 until the first surface instability. For a layered Tube the minimum runs over
every face (with its follower pressure) and every interface ("interface-K", between layers
K and K + 1; halfspace.surfaces), and the control is any of the tube's (params.at);
docs/derivation-layered-modes.md. min over psi: f on a grid of psi
(endpoints psi = 0 and pi/2 included) and a bounded 1-D minimisation around the lowest
grid minima, compared with the exact endpoint values. h is continuous (a minimum of
continuous functions), so once the march brackets its first sign change Brent's method
converges to rounding level; f near an interior minimiser is quadratic in psi, so the
psi-accuracy ~1e-10 costs nothing in the value.

The march (surface_march.py: steps of 0.4 % of the scale doubling up to 5 %, limited by 0.7
of the linear extrapolation of h to zero; the psi minimum refined only where the grid
minimum is below MARCH_REFINE; a bounded minimisation where h dips between samples) reports
kind "threshold" if the base state is lost first, located as the mode march locates it
(state_loss.py: the voltage threshold falls to the applied voltage, the state search fails,
or a layer locks kinematically; a state that exists but does not resolve, or lies within
along.LOCK_MARGIN of a lock, is no loss, and where nothing else is established the march
raises ConvergenceError; a wall become a film is marched on toward its asymptote, lambda_i
doubling a step, to 5 rtol of it: a face wrinkles there under a voltage), and kind
"ellipticity" if the half-space stops being strongly elliptic first (then there is no
decaying split to impose the face conditions on; the value is where that happens). The
error estimate is the distance to the root found at a second, coarser resolution (psi grid
13 instead of 25, psi tolerance 1e-7, base state at 100 rtol), at least the precision rtol
achieves (error_estimate.achieved_floor).
Derivation and measured numbers: docs/derivation-surface.md.
"""

from __future__ import annotations

import dataclasses
import math

from ..basestate.tube import solve_base_state
from ..continuation import events
from ..continuation.events import Remembered
from ..errors import BaseStateError, ConvergenceError, ParameterError
from ..incremental.halfspace import surfaces
from ..model.controls import KINDS, check_side
from ..model.layers import Tube
from ..outcomes import Kind, Outcome, Status
from .along import SampleValue, StateAt, TubeAt
from .directions import (
    HALF_PI,
    MARCH_REFINE,
    FixedDirection,
    RayDirection,
    Resolution,
    reference_signs,
    sampler,
)
from .error_estimate import achieved_floor
from .march import control_path
from .problem import DEFAULT_RTOL, Problem, as_problem
from .state_loss import asymptote_error, asymptote_note
from .surface_march import locate


@dataclasses.dataclass(frozen=True)
class SurfaceLimit(Outcome):
    """Result of :func:`short_wave_limit` and :func:`ray_limit`.

    kind : "surface" (the half-space at ``face`` bifurcates in direction ``psi`` at
        ``value``), "threshold" (the axisymmetric base state is lost first, at ``value``),
        "ellipticity" (strong ellipticity is lost first at ``face``, direction ``psi``,
        at ``value``: the half-space problem is not defined beyond) or "none" (nothing
        up to the end of the march; value NaN, params as given).
    psi : wave direction in the face in radians, tan psi = k r / m (0: wrinkles along
        theta, pi/2: along z); ``ratio`` = k r / m = tan psi, None at psi = pi/2.
    error_estimate : |value - value at a second, coarser resolution|, at least the
        precision rtol achieves (error_estimate.achieved_floor: the two may agree to the
        bit, which is no exactness); for a threshold at an asymptote (a film's state runs
        to it: the march stops 5 rtol |value| short of it) that floor, 5 rtol |value| (a
        root closer is the threshold to rtol); 0 for any other value that is not a root;
        NaN if the base state is lost within the search for the coarser root.
    params : the parameters (Tube) at ``value``.
    face : the surface: "inner", "outer" or, in a layered tube, "interface-K" (between
        layers K and K + 1).
    status, message, remedy : always OK and "" (a failure raises); the message "" but for
        a threshold at an asymptote (how near it the faces were examined); with them a
        SurfaceLimit is an :class:`~electrogrowth.outcomes.Outcome` like every result.
    """

    solve_for: str
    value: float
    face: str | None
    psi: float | None
    ratio: float | None
    kind: str
    error_estimate: float
    params: Tube
    side: str | None = None
    status: Status = Status.OK
    message: str = ""
    remedy: str = ""

    def as_dict(self) -> dict:
        return {
            "solve_for": self.solve_for,
            "value": self.value,
            "kind": self.kind,
            "face": self.face,
            "psi": self.psi,
            "ratio": self.ratio,
            "error_estimate": self.error_estimate,
            "side": self.side,
            **self.params.as_dict(),
        }


#: what a threshold at an asymptote says was examined up to the last state (its message)
NO_FACE = "no face wrinkles"


# -- input checks ---------------------------------------------------------------------------


def _check(params, solve_for, side, faces, rtol) -> tuple[str, str | None, tuple[str, ...]]:
    """(canonical control, side, surfaces) after checking the input."""
    if not isinstance(params, Tube):
        raise ParameterError(f"params = {params!r} is not a Tube")
    control = params.check_control(solve_for)
    solve_for = str(control)
    side = check_side(control.kind, side)
    # as critical_value: a side only for the stretch, pressure or force (ignored otherwise)
    side = side if KINDS[control.kind].sided else None
    valid = surfaces(params)
    faces = valid if faces is None else (faces,) if isinstance(faces, str) else tuple(faces)
    if not faces or any(f not in valid for f in faces) or len(set(faces)) != len(faces):
        raise ParameterError(
            f"faces = {faces!r} is invalid; choose a non-empty subset of {valid!r}"
        )
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not 0 < rtol <= 1e-3:
        raise ParameterError(f"rtol = {rtol!r} is out of range; valid range: 0 < rtol <= 1e-3")
    return solve_for, side, faces


def _second_resolution(value_coarse, value: float, path: tuple[float, float]) -> float:
    """|root of the coarser h near value - value|, looked for within the march's ``path``
    (start, end): a root next to an asymptote has no states 1e-8 past it (NaN if the base
    state is lost before the coarse target changes sign: a surface instability at the
    threshold itself). Brent's method starts from the window's ends, whose coarse samples
    (a state and a direction search each) the sign check has just paid for: remembered."""
    value_coarse = Remembered(value_coarse)
    width, bounds = 1e-8 * max(1.0, abs(value)), tuple(sorted(path))
    for lo, hi, _ in events.widening_windows(value, width, 14, bounds=bounds):
        try:
            flo, fhi = value_coarse(lo), value_coarse(hi)
        except (BaseStateError, ConvergenceError):
            return math.nan
        if flo * fhi < 0:
            return abs(
                events.brent(value_coarse, lo, hi, events.SECOND, ref=value, named=False) - value
            )
    raise ConvergenceError(f"no root of the coarse half-space target near {value}")


def _solve(
    params, solve_for, side, faces, rtol, direction, until=None, estimate=True
) -> SurfaceLimit:
    solve_for, side, faces = _check(params, solve_for, side, faces, rtol)
    signs = reference_signs(params)
    fine = Resolution(25, 1e-10, rtol)
    coarse = Resolution(13, 1e-7, min(1e-3, 100 * rtol))
    h = sampler(faces, signs, fine, direction)
    hm = sampler(faces, signs, fine, direction, refine_below=MARCH_REFINE)
    hc = sampler(faces, signs, coarse, direction)
    at = TubeAt(params, solve_for, as_float=True)
    kind, value, bracket, near = locate(params, solve_for, side, h, rtol, hm, until)
    if kind in (Kind.THRESHOLD, Kind.NONE):
        # at an asymptote, a root within the march's gap to it is this value to rtol
        err = 0.0 if near is None else asymptote_error(value, near, rtol)
        return SurfaceLimit(
            solve_for,
            value,
            None,
            None,
            None,
            kind,
            err,
            at(value) if kind == Kind.THRESHOLD else params,
            side,
            message="" if near is None else asymptote_note(solve_for, value, near, NO_FACE),
        )
    if kind == Kind.ELLIPTICITY:
        s = h(solve_base_state(at(value), rtol=rtol))
        return SurfaceLimit(
            solve_for, value, s.face, s.psi, _ratio(s.psi), kind, 0.0, at(value), side
        )
    value_of = SampleValue(h, StateAt(at, rtol))
    value = events.brent(value_of, *bracket, events.surface_tolerance(rtol))
    coarse_of = SampleValue(hc, StateAt(at, coarse.rtol))
    path = control_path(params, solve_for, side)[:2]
    err = _second_resolution(coarse_of, value, path) if estimate else math.nan
    # the two resolutions can share their error (a closed-form state's roots agree to the
    # bit): never less than what rtol achieves, as every critical value (critical.py)
    err = max(err, achieved_floor(value, rtol)) if math.isfinite(err) else err
    s = h(solve_base_state(at(value), rtol=rtol))
    return SurfaceLimit(
        solve_for, value, s.face, s.psi, _ratio(s.psi), Kind.SURFACE, err, at(value), side
    )


def _ratio(psi):
    if psi is None or abs(psi - HALF_PI) <= 1e-12:
        return None
    return math.tan(psi)


# -- public entry points --------------------------------------------------------------------


def short_wave_limit(
    params: Tube | Problem,
    solve_for: str | None = None,
    *,
    side: str | None = None,
    faces=None,
    psi: float | None = None,
    rtol: float | None = None,
    until: float | None = None,
    estimate: bool = True,
) -> SurfaceLimit:
    """Critical value of ``solve_for`` for wrinkles of vanishing wavelength (m, k -> inf).

    Parameters
    ----------
    params : Tube or Problem
        The tube (one homogeneous layer, or a layered, pressurised Tube); the control named
        by ``solve_for`` is the unknown (``params.at(solve_for, x)``). Or a
        :class:`~.problem.Problem`, which gives ``solve_for``, ``side`` and ``rtol``.
    solve_for : str
        Growth: smallest g > 1 (march 1 -> 6). Stretch: the lambda_z nearest to
        lambda_z = g on ``side`` ("compression", default, march to 0.05 g; or "extension",
        to 8 g). Voltage: smallest Vbar > 0 (march to the threshold). For a Tube any of
        its controls (model/controls.py: "growth[K]", "growth[K].theta", "pressure",
        "force", ...), on the path of bifurcation.march.control_path.
    faces : iterable of surface names, optional
        The surfaces whose half-spaces are examined: "inner", "outer" and, for a layered
        Tube, "interface-1", ... (default all of them, halfspace.surfaces).
    psi : float, optional
        Examine only this wave direction (radians in [0, pi/2]) instead of the worst one:
        the directional critical value, whose infimum over psi is the default result.
    rtol : float, optional
        Accuracy of the base state and of Brent's method (default 1e-12, 0 < rtol <= 1e-3).
    until : float, optional
        March only this far (a scan asks whether the limit comes before its best finite
        mode): kind "none" when nothing is met before it.
    estimate : bool
        Also the error estimate (a second root at a coarser resolution, a fifth of the
        cost); False: ``error_estimate`` NaN (a design's margin needs the value only).

    Returns
    -------
    SurfaceLimit
        With the face and the worst wave direction psi (the infimum over psi of the
        directional critical values), or kind "threshold" / "ellipticity" / "none".

    Raises
    ------
    ParameterError
        Bad input, or the start of the march is not stable.
    ConvergenceError
        A root could not be converged.
    """
    if isinstance(params, Problem):
        problem = as_problem(params, solve_for, side=side, rtol=rtol)
        params, solve_for, side, rtol = problem.tube, problem.control, problem.side, problem.rtol
    elif rtol is None:
        rtol = DEFAULT_RTOL
    if psi is None:
        return _solve(params, solve_for, side, faces, rtol, None, until, estimate)
    if isinstance(psi, bool) or not isinstance(psi, (int, float)) or not 0 <= psi <= HALF_PI:
        raise ParameterError(f"psi = {psi!r} is out of range; valid range: 0 <= psi <= pi/2")
    fixed = float(psi)
    direction = FixedDirection(fixed)
    return _solve(params, solve_for, side, faces, rtol, direction, until, estimate)


def ray_limit(
    params: Tube,
    m: float,
    n: float,
    solve_for: str,
    *,
    side: str | None = None,
    faces=None,
    rtol: float = 1e-12,
    estimate: bool = True,
) -> SurfaceLimit:
    """Limit j -> infinity of the critical value of the modes (j m, j n).

    Along the ray the direction at a face of radius r is tan psi = k r / m with
    k = n pi / (lambda_z L); it follows the state (lambda_z and r change with the
    control). The limit is the first control value at which the half-space at one of
    ``faces`` bifurcates in that direction. m = 0 gives psi = pi/2, n = 0 gives psi = 0.
    Without ``estimate`` the error estimate (a second, coarser solve) is NaN, as for
    :func:`short_wave_limit`.
    """
    for name, v in (("m", m), ("n", n)):
        if (
            isinstance(v, bool)
            or not isinstance(v, (int, float))
            or not (math.isfinite(v) and v >= 0)
        ):
            raise ParameterError(f"ray {name} = {v!r} is invalid; need 0 <= {name} < inf")
    if m == 0 and n == 0:
        raise ParameterError("ray (m, n) = (0, 0) is invalid; need m > 0 or n > 0")
    return _solve(params, solve_for, side, faces, rtol, RayDirection(m, n), estimate=estimate)
