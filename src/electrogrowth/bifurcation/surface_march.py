"""The short-wave march: the control from its stable start to the first zero of the
half-space target h (surface.py), or to the loss of the state or of strong ellipticity.

Steps of 0.4 % of the scale doubling up to 5 %, limited by 0.7 of the linear extrapolation of
h to zero (SURFACE_STEPS); a bounded minimisation where h dips between samples. Where the
state fails, the loss is located as the mode march locates it (state_loss.py): a held load's
threshold, the state search failing, or a kinematic lock, and at the path's end or past a
film, the control's own threshold or a held load's; a state that exists but does not
resolve, or lies within along.LOCK_MARGIN of a lock, is no loss. A wall become a film runs to
an asymptote (lambda_i -> inf): the march goes on toward it in steps that double lambda_i
(state_loss.approach_film), up to the value's tolerance short of it, so that a face that
wrinkles there (an inflated tube under Vbar = 0.01 at lambda_i = 120) is found, and a
threshold reported there is right to that tolerance. Where h turns NaN the half-space has
stopped being strongly elliptic: that edge is bisected.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from ..continuation import events
from ..continuation.path import ControlPath, Stepper, StepPolicy
from ..continuation.predict import far_waits
from ..errors import BaseStateError, ConvergenceError, ParameterError, UnstableAtStart
from ..outcomes import Kind
from .along import Elliptic, NearLock, SampleValue, StateAt, TubeAt, has_lock
from .march import FAR, FAR_CONTROLS, FAR_FROM, control_path
from .state_loss import Approach, approach_film, loss_at_end, own_lock, threshold_between

#: the short-wave march's step control: as the mode march's, but down to 1e-6 of the scale
#: (h is one continuous function: its zero may be approached closer); from FAR_FROM scales
#: on, steps up to FAR of the distance marched where h's last three samples allow it
SURFACE_STEPS = StepPolicy(smallest=1e-6, far=FAR, far_from=FAR_FROM)


def locate(params, solve_for, side, h: Callable, rtol: float, h_march=None, until=None):
    """March to the first zero of h (not past ``until``, if given); returns (kind, value,
    bracket or None, Approach or None: how near a threshold at an asymptote was examined).

    h_march (default h) is used for the steps: it may be cheaper where h is far from 0
    but must agree with h wherever either is <= MARCH_REFINE."""
    fine_h, h = h, (h_march or h)
    at = TubeAt(params, solve_for, as_float=True)
    state_at = StateAt(at, rtol)
    path = ControlPath(*control_path(params, solve_for, side))
    if until is not None and (until - path.start) * path.sense > 0:
        path = dataclasses.replace(
            path,
            end=path.start + path.sense * min(abs(until - path.start), abs(path.end - path.start)),
        )
    x0, scale = path.start, path.scale
    try:
        state = state_at(x0)
    except BaseStateError as exc:
        raise ParameterError(
            f"no base state at the start of the march, {solve_for} = {x0:g}: {exc}"
        ) from None
    s0 = h(state)
    if math.isnan(s0.value):
        raise UnstableAtStart(
            f"the half-space at the {s0.face} face is not strongly "
            f"elliptic at {solve_for} = {x0:g}; start from a stable state"
        )
    if s0.value <= 0:
        raise UnstableAtStart(
            f"the {s0.face} face is already unstable (psi = {s0.psi:.6g})"
            f" at {solve_for} = {x0:g}; start from a stable state"
        )
    value_of, fine_of = SampleValue(h, state_at), SampleValue(fine_h, state_at)
    xs, hs = [x0], [s0.value]
    policy = SURFACE_STEPS  # far steps only along a path with no state to lose (march.py)
    if solve_for not in FAR_CONTROLS:
        policy = dataclasses.replace(SURFACE_STEPS, far=0.0)
    step = Stepper(path, policy, state.lambda_i)
    # unresolved: the error to raise if nothing is found (states past the path's end exist
    # but do not resolve, next to a lock: state_loss.threshold_between)
    threshold, unresolved, film = None, None, False
    # on the way to the control's own lock (its load unbounded) a state that fails is next
    # to it, as the mode march reads it: no shorter steps, each a walk of seconds that
    # fails (a three-layer tube inflated towards a Gent layer's lock: 18 of them, 70 s)
    bound = None  # read at the first failure: a walk of the control's threshold
    while not step.at_end():
        x_prev = step.x
        x = step.propose()
        try:
            state = state_at(x)
        except (BaseStateError, ConvergenceError) as exc:  # lost, or unresolved
            if step.asymptote is not None:  # where the states run to is established:
                break  # they are not resolved closer to it (a shear modulus ~1e-8)
            if bound is None:
                bound = has_lock(params) and own_lock(params, solve_for, side) is not None
            if _retry(exc) and not bound and step.unresolved():
                continue  # the solver failed here, not next to a lock: step shorter first
            value, edge, pending = threshold_between(at, params, x_prev, x, rtol, side=side)
            if value is not None or threshold is None:  # an established loss stays
                threshold, unresolved = value, pending
            if step.lost(edge):
                break
            continue
        if step.jumped(state.lambda_i):
            continue
        s = h(state)
        if math.isnan(s.value) and step.asymptote is not None:
            break  # a face's decay rates ~ 1 / lambda_i^2 fall below the split's: unresolved
        if math.isnan(s.value):  # ellipticity lost in (x_prev, x]
            elliptic = Elliptic(value_of)
            edge = events.Tolerance(1e-13 * scale, maxiter=60, scale="absolute")
            lo, hi = events.bisect(elliptic, x_prev, x, edge)
            if fine_of(lo) <= 0:  # a surface instability just before
                return Kind.SURFACE, None, _bracket(xs, lo, fine_of), None
            return Kind.ELLIPTICITY, 0.5 * (lo + hi), None, None
        if s.value <= 0:
            return Kind.SURFACE, None, _bracket(xs, x, fine_of), None
        steps = (xs[-2] - xs[-1], xs[-1] - x) if len(hs) >= 2 else None
        if steps and events.dipped(hs[-2], hs[-1], s.value, steps):  # a dip between samples?
            dip = events.dip_bracket(value_of, xs[-2], x)
            if dip is not None:
                return Kind.SURFACE, None, _bracket(xs[:-1], float(dip[1]), fine_of), None
        xs.append(x)
        hs.append(s.value)
        slope = (hs[-1] - hs[-2]) / (xs[-1] - xs[-2]) * path.sense
        limit = SURFACE_STEPS.safety * hs[-1] / -slope / scale if slope < 0 else math.inf
        step.accept(x, state.lambda_i, min(limit, _far_room(xs, hs, path, policy) / scale))
        if step.film(state.lambda_i):  # the wall is a film: on toward its asymptote
            film = True
            if approach_film(at, params, solve_for, side, step, rtol) is None:
                break
    if threshold is None and unresolved is not None:  # neither a loss nor a root established
        err = ConvergenceError(
            f"no surface instability for {solve_for} from {x0:.12g} up to {step.x:.12g}, and"
            f" the base states past it are not resolved: {unresolved.args[0]}"
        )
        err.remedy = unresolved.remedy
        raise err from unresolved
    near = None
    if threshold is None and step.asymptote is not None:  # approached to its tolerance
        threshold, near = step.asymptote, Approach(step.x, step.monitor, step.at_end())
    if threshold is None:  # lost at the path's end, or past its film?
        threshold = loss_at_end(at, params, solve_for, side, step.x, step.end, film)
    if threshold is not None:
        return Kind.THRESHOLD, threshold, None, near
    return Kind.NONE, math.nan, None, None


def _far_room(xs, hs, path: ControlPath, steps: StepPolicy) -> float:
    """How far past its last sample h may go unsampled, from ``far_from`` scales on: ``far``
    of the distance marched as far as the parabola through its last three samples allows
    (predict.far_waits, as a mode's far wait), else the largest step; inf before."""
    marched = path.sense * (xs[-1] - path.start)
    if not steps.far or len(xs) < 3 or marched < steps.far_from * path.scale:
        return math.inf
    x, h = np.array(xs[:-4:-1])[:, None], np.array(hs[:-4:-1])[:, None]
    base = steps.largest * path.scale
    return float(far_waits(x, h, path.sense, steps.far * marched, base)[0])


def _retry(exc: Exception) -> bool:
    """Is ``exc`` a failure of the state solver that a shorter step may avoid (not a loss of
    the state, nor a state next to a lock)?"""
    return isinstance(exc, ConvergenceError) and not isinstance(exc, NearLock)


def _bracket(xs, x_bad, value_of) -> tuple[float, float]:
    """(x_ok, x_bad) with the fine h > 0 at x_ok: the newest sample where it is (the
    march start always is)."""
    for x in reversed(xs):
        if value_of(x) > 0:
            return x, x_bad
        x_bad = x
    raise ConvergenceError("the half-space target is not positive at the start")
