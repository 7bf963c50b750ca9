"""Where a march's base state is lost: a load's threshold, the edge of the states, a lock.

Shared by the mode march (march.py) and the short-wave march (surface_march.py): when a
march's state fails at x_bad after one at x_ok, :func:`threshold_between` says where the state
ends between them, and whether that end is established. A march that loses no state on its
way is lost at its end (:func:`loss_at_end`): a path that ends at the control's own threshold
(:func:`own_threshold`: the voltage's, an inflation's pressure) ends there, and a wall thinned
to a film runs to an asymptote, where the threshold of a load held fixed falls to that load
(:func:`held_loads`: the inflation threshold of a tube pulled at a fixed inner pressure). Past
a film the march goes on toward that asymptote (:func:`approach_film`), to the value's
tolerance short of it: a root there (a face under voltage, a short mode) is found.

A state that is lost (the state search fails: BaseStateError, from cold and continued from
the march's nearest state) right after one that solves ends the path there; a search that
meets a layer's lock first (LockedSearch, even at the finest Gauss rule) is no loss by itself,
as below. A state that exists but does not resolve (ConvergenceError: its profile
needs more than the largest Chebyshev degree, or it lies within LOCK_MARGIN of a lock,
along.clear_of_lock) ends nothing by itself: a stiffening layer's state goes on, closer and
closer to its lock (docs/reliability.md). The loss there is established only kinematically:
with the axial stretch prescribed, every state has I1 >= lambda_e^2 + 2 / lambda_e and
I2 >= 2 lambda_e + 1 / lambda_e^2 (lambda_e = lambda_z / g_z, the elastic axial stretch;
equality for equal in-plane stretches), so past the lambda_e where the energy at those least
invariants stops being finite no state can exist. For Gent's energy that is the root of
lambda_e^2 + 2 / lambda_e - 3 = jm; for an energy text, whose domain is taken to be bounded
in I1 and I2 from above (Gent's, Gent-Gent's), the edge of its finite values, bisected.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..basestate.ellipticity import softest, wall_shear, why_lost
from ..basestate.thresholds import LockedSearch, Threshold
from ..basestate.tube import load_in_box, solve_base_state, threshold
from ..continuation.events import EDGE, FULL, LOCK, THRESHOLD, Tolerance, bisect, brent
from ..continuation.events import threshold_between as _lost_between
from ..errors import (
    NEAR_LOCK,
    BaseStateError,
    BranchNotFollowed,
    ConvergenceError,
    ElectrogrowthError,
    ParameterError,
    Remedy,
)
from ..model.controls import parse_control
from ..model.layers import Tube
from ..model.params import SUPPORTED
from .along import (
    LoadMargin,
    TubeAt,
    bounded_energy,
    clear_of_lock,
    has_lock,
    nearest_lock,
)
from .error_estimate import achieved_floor

#: the fates of a point where no state was found (_fate)
_NO_STATE = ("lost", "locked")
#: what a margin's evaluation may raise where it cannot be read (no state to start from)
_UNREADABLE = (ValueError, BaseStateError, ConvergenceError)


def own_threshold(params: Tube, solve_for: str, side: str | None) -> Threshold | None:
    """The threshold of the control's own branch, where its march's path ends
    (model/controls.py): the voltage's, or the pressure's of an inflation (side not
    "compression"); None for any other control."""
    kind = _own_kind(solve_for, side)
    if kind is None or load_in_box(params, kind) is not None:
        return None  # none, or the path ends where lambda_z leaves the box: no loss there
    return threshold(params, kind)


def _own_kind(solve_for: str, side: str | None) -> str | None:
    """The kind of the control's own branch ("voltage", "pressure" of an inflation)."""
    kind = parse_control(solve_for).kind
    return kind if kind == "voltage" or (kind == "pressure" and side != "compression") else None


def box_note(params: Tube, solve_for: str, side: str | None, end: float) -> str:
    """Why a march's path ended at ``end`` before its branch's threshold: a force-controlled
    tube's lambda_z leaves the supported box there (model/controls.py paths); "" where the
    path ends elsewhere."""
    kind = _own_kind(solve_for, side)
    box = None if kind is None else load_in_box(params, kind)
    if box is None or box != end:
        return ""
    lo, hi = SUPPORTED[5:7]
    return (
        f" (its {kind} threshold lies beyond the supported range {lo:g} to {hi:g} of the"
        f" elastic axial stretch lambda_z / g_z, which its branch leaves past {solve_for} ="
        f" {box:.6g})"
    )


def held_loads(at: TubeAt, params: Tube, solve_for: str) -> LoadMargin | None:
    """The margin of the loads the path holds fixed, the control aside: the voltage where
    Vbar > 0, the inner pressure where it inflates (P_i > P_o); None where neither is."""
    kind = parse_control(solve_for).kind
    loads = []
    if params.voltage > 0 and kind != "voltage":
        loads.append(("voltage", params.voltage))
    if params.inner_pressure > params.outer_pressure and kind != "pressure":
        loads.append(("pressure", params.inner_pressure))
    return LoadMargin(at, tuple(loads)) if loads else None


def loss_at_end(
    at: TubeAt, params: Tube, solve_for: str, side: str | None, x: float, end: float, film: bool
) -> float | None:
    """Where the state is lost when a march lost none on its way and stopped at x: the
    control's own threshold (its path ends there); else, where the wall became a film
    (``film``), the first root past x of the held loads' margin, bracketed in steps that
    double from 1e-6 of the distance to ``end`` (the asymptote lies close past a film); None
    where neither is established."""
    own = own_threshold(params, solve_for, side)
    if own is not None:
        return own.value if math.isfinite(own.value) else None
    margin = held_loads(at, params, solve_for) if film else None
    if margin is None:
        return None
    try:
        lo, m_lo = x, margin(x)
        if not m_lo > 0:
            return None
        for k in range(21):
            hi = x + (end - x) * min(1e-6 * 2.0**k, 1.0)
            m_hi = margin(hi)
            if m_hi <= 0:
                return brent(margin, *sorted((lo, hi)), THRESHOLD, named=False)
            lo = hi
    except _UNREADABLE:
        return None
    return None


class Approach(NamedTuple):
    """The last state a march examined on its way to an asymptote, where it stopped:
    ``resolved`` if within the value's tolerance of it (else the states closer failed)."""

    x: float
    lambda_i: float
    resolved: bool


def asymptote_note(solve_for: str, value: float, near: Approach, what: str) -> str:
    """What a threshold at an asymptote stands for (a result's message): ``what`` (e.g. "no
    face wrinkles") up to the last state the march examined; within the value's tolerance
    of it, a root closer is the same value to rtol (under a voltage one is there: the field
    at a face grows with lambda_i); else the states closer were not resolved (a half-space's
    decay rates ~ 1 / lambda_i^2 below its split's margin) and a root in the gap is not
    excluded (:func:`asymptote_error`)."""
    where = f"up to {near.x:.15g} (lambda_i = {near.lambda_i:.4g})"
    if near.resolved:
        tail = "within the value's tolerance of it: a root closer to it, if any, is this value"
        tail += " to rtol"
    else:
        gap = abs(value - near.x)
        tail = f"not resolved closer to it: a root within {gap:.2g} of it is not excluded"
    return (
        f"the state runs to its asymptote {solve_for} = {value:.12g} (lambda_i -> inf);"
        f" {what} {where}, {tail}"
    )


def asymptote_error(value: float, near: Approach, rtol: float) -> float:
    """The error estimate of a threshold at an asymptote: what rtol achieves (the march came
    that close), or the gap to the last state examined where it stopped short of it."""
    return max(achieved_floor(value, rtol), abs(value - near.x))


def approach_film(
    at: TubeAt, params: Tube, solve_for: str, side: str | None, step, rtol: float
) -> float | None:
    """The wall became a film at ``step.x`` (lambda_i grown ``film``-fold): where its state
    runs to (:func:`loss_at_end`, as the march would report it), with ``step`` sent on toward
    it (Stepper.approach) up to the value's tolerance short of it, ACHIEVED rtol |x| (no
    less than the path's edge gap): a root closer than that is the threshold to rtol (an
    inflated tube under Vbar = 0.01 wrinkles at its inner face at lambda_i = 120, 3.4e-9
    short of its pressure asymptote). None (the march stops there) where no loss is
    established."""
    asymptote = loss_at_end(at, params, solve_for, side, step.x, step.end, True)
    if asymptote is not None:
        gap = max(achieved_floor(asymptote, rtol), step.policy.edge_gap * step.scale)
        step.approach(asymptote, gap)
    return asymptote


class LockAhead(ConvergenceError):
    """The states past a march's last one are next to a layer's lock and not resolved.
    ``unbounded``: the control's own threshold is that lock (kind "locking": its load grows
    without bound towards it), so no state is lost on the way: the march's answer is that
    no mode bifurcates up to its last state (march.py), not that the loss is unknown."""

    def __init__(self, *args, unbounded: bool = False):
        super().__init__(*args)
        self.unbounded = unbounded
        self.remedy = NEAR_LOCK


#: next to a lock the states past a march's last one may exist and not resolve, and every
#: look at one is a cold solve that walks its branch for seconds before it fails: their
#: edge is bisected this many times at most (to 2^-LOCK_LOOKS of the step), not to EDGE
#: (37 looks, 383 s: check round 35b); a look that finds the state lost is still located
#: to EDGE, a loss's exact value
LOCK_LOOKS = 4


def lock_note(at: TubeAt, x: float) -> str:
    """How near the Gent layer nearest its lock is at the march's last state x, in words;
    "" where no Gent layer is (an energy text's edge has no such margin)."""
    try:
        near = nearest_lock(at.solved(x))
    except ElectrogrowthError:
        near = None
    if near is None:
        return ""
    k, margin = near
    return f"the Gent layer {k} is next to its lock, 1 - (I1 - 3)/jm = {margin:.2g}"


def own_lock(params: Tube, solve_for: str, side: str | None) -> Threshold | None:
    """The control's own threshold where it is a lock whose load grows without bound
    (kind "locking", value inf: the state is never lost on the way), else None."""
    own = own_threshold(params, solve_for, side)
    if own is None or own.kind != "locking" or math.isfinite(own.value):
        return None
    return own


def _lock_ahead(at: TubeAt, x_ok: float, lock: Threshold) -> LockAhead:
    """The answer of a march whose states stop resolving at x_ok on the way to its
    control's own lock (:func:`own_lock`)."""
    where = lock_note(at, x_ok) or "a layer is next to its lock"
    return LockAhead(
        f"{where}, and the {lock.control} grows without bound towards the lock at lambda_i ="
        f" {lock.lambda_i:.6g} (the {lock.control}'s threshold is that lock: no state is lost"
        " before it); the states closer to it are not resolved",
        unbounded=True,
    )


def threshold_between(
    at: TubeAt,
    params: Tube,
    x_ok: float,
    x_bad: float,
    rtol=1e-12,
    *,
    side: str | None = None,
    tables: bool = False,
):
    """Where the base state is lost between x_ok and x_bad (no state, or none resolved, at
    x_bad): (value, the last x the march may step to, None). Where the voltage threshold
    falls to the applied voltage, or the inflation threshold to the inner pressure, if that
    brackets it (:func:`held_loads`), else the edge of the states that solve at ``rtol``
    (whichever of the tube's loads reaches its threshold), bisected. ``tables``: the state
    at x_bad solves but its radial tables do not resolve (a root's refinement met it): it
    is unresolved, and the edge is x_bad itself.

    Next to a locking stretch the states past the edge may exist and yet not resolve: the
    edge is then a loss only where a layer locks kinematically before the first state that
    is lost, or within one more step of it (the search failed within LOCK_MARGIN of the
    lock), or, where x_bad is not lost, within one more step of x_bad (the march came
    within LOCK_MARGIN of the lock), and the value is that lock. Else the answer is (None,
    the last resolved x, the error to raise if nothing is found before it). Where the
    control's own threshold (on ``side``, None the control's default) is a lock with its
    load unbounded (:func:`own_lock`), no state is lost: nothing is looked at, the answer
    is (None, x_ok, :class:`LockAhead`). Next to a lock, the edge of the states that
    resolve is bisected LOCK_LOOKS times only, unless a look finds the state lost."""
    margin = held_loads(at, params, at.control)
    if margin is not None:
        # no sign change (ValueError), or no branch to read at x_bad: bisect instead
        x = _lost_between(x_ok, x_bad, margin=margin, tolerate=_UNREADABLE)
        if x is not None:
            return x, x, None
    own = own_lock(params, at.control, side) if has_lock(params) else None
    if own is not None:
        return None, x_ok, _lock_ahead(at, x_ok, own)
    fates: dict[float, str] = {}

    def fate(x: float) -> str:  # each look once: a cold solve next to a lock costs seconds
        if x not in fates:
            fates[x] = _fate(at, x, rtol)
        return fates[x]

    fate_bad = "unresolved" if tables else fate(x_bad)
    if fate_bad == "solved":  # the failure was the march's alone: no edge here
        return (
            None,
            x_ok,
            ConvergenceError(
                f"the base state at {x_bad:.12g} was not resolved continued from its neighbour"
                " (it solves on its own)"
            ),
        )
    if tables:  # every state up to x_bad solves: the edge is where the tables fail
        ok, bad = x_ok, x_bad
    else:
        few = fate_bad == "unresolved" and has_lock(params) and not _lock_ahead_of(at, x_ok, x_bad)
        ok, bad = _edge(fate, x_ok, x_bad, few)
        if fate(bad) == "lost":
            return ok, ok, None
    beyond = x_bad if fate_bad in _NO_STATE else _lost_past_lock(at, x_ok, x_bad, rtol)
    lost_from = ""
    if beyond is not None:
        _, lost = bisect(lambda x: fate(x) not in _NO_STATE, bad, beyond, EDGE)
        # the search may fail short of the lock, within LOCK_MARGIN of it: one more step on
        ahead = _lost_past_lock(at, ok, lost, rtol)
        lock = kinematic_lock(at, ok, lost if ahead is None else ahead)
        if lock is not None:  # past it no state can exist: the loss is established, exactly
            return lock, ok, None
        lost_from = f", and the state search fails from {lost:.12g}"
    locks = has_lock(at(x_ok))
    if locks:
        note = lock_note(at, ok)
        near = f"{note} at {ok:.12g}" if note else "a layer next to its locking stretch?"
    else:
        near = _why_unresolved(at, ok, bad, rtol)
    unresolved = ConvergenceError(
        f"the states from {bad:.12g} are not resolved ({near}){lost_from}: whether the"
        " state is lost there is not established"
    )
    # neither a looser rtol (the states' is fixed) nor collocation helps: a lock's remedy,
    # or none (a charged film under suction: "loosen --rtol" failed the same at 1e-8,
    # probe 12b D7)
    unresolved.remedy = NEAR_LOCK if locks else Remedy("")
    return None, ok, unresolved


def _lock_ahead_of(at: TubeAt, x_ok: float, x_bad: float) -> bool:
    """Does a layer lock kinematically within one more step past x_bad? Then the edge of the
    states that solve is where the march's path ends, next to that lock (a loss): bisected
    to EDGE, not LOCK_LOOKS times."""
    try:
        return kinematic_lock(at, x_ok, x_bad + (x_bad - x_ok)) is not None
    except ParameterError:  # one more step leaves the control's range
        return kinematic_lock(at, x_ok, x_bad) is not None


def _edge(fate, x_ok: float, x_bad: float, near_lock: bool) -> tuple[float, float]:
    """(ok, bad): the edge of the states that solve between x_ok and x_bad, bisected to EDGE;
    ``near_lock`` (x_bad unresolved next to a lock no kinematic loss is near), LOCK_LOOKS
    times only, unless a look finds the state lost (a loss is located to EDGE)."""
    looks: list[str] = []

    def solved(x: float) -> bool:
        looks.append(fate(x))
        return looks[-1] == "solved"

    if near_lock:
        few = Tolerance(abs(x_bad - x_ok) * 2.0**-LOCK_LOOKS, maxiter=LOCK_LOOKS, scale="absolute")
        x_ok, x_bad = bisect(solved, x_ok, x_bad, few)
        if "lost" not in looks:
            return x_ok, x_bad
    return bisect(solved, x_ok, x_bad, EDGE)


#: a wall whose smallest shear modulus (basestate/ellipticity.py) is below this share of its
#: stiffness at the last resolved state is said to be losing strong ellipticity there
SOFT_SHEAR = 1e-2


def lost_note(at: TubeAt, x: float) -> str:
    """Why a march's states end at x (its threshold, where no mode bifurcated before), for
    the result's message: a shear modulus vanishing there (basestate/ellipticity.py), else
    '' (a load's threshold, or the edge of the states found, says itself)."""
    try:
        return why_lost(at.solved(x))
    except ElectrogrowthError:
        return ""


def _why_unresolved(at: TubeAt, x_ok: float, x_bad: float, rtol: float) -> str:
    """What is known of why the states past x_ok are not resolved: a shear modulus of the
    wall vanishing there (the material losing strong ellipticity: an energy text whose W_1
    falls to 0, check round 21), else what the first unresolved state's search observed at
    x_bad: which check failed and by how much (its error; check round 24 read "why is not
    known" for a stress scale asked for more than a scale needs)."""
    try:
        state = at.solved(x_ok, rtol)
        low = wall_shear(state).min()
    except ElectrogrowthError:
        low = math.inf
    if low < SOFT_SHEAR:
        return (
            f"the wall's shear modulus {softest(state)} there: the material is losing"
            " strong ellipticity"
        )
    try:
        clear_of_lock(_solved(at, x_bad, rtol))  # as _fate read it
    except ElectrogrowthError as exc:
        return f"at {x_bad:.12g}: {' '.join(str(exc).split())}"
    return "they solve on their own, not continued from the march's states"


def _lost_past_lock(at: TubeAt, x_ok: float, x_bad: float, rtol: float) -> float | None:
    """x_bad unresolved, or the first x where the search fails: a point one more step
    (x_bad - x_ok) on, if a layer locks kinematically before it and no state is found there
    (else None)."""
    ahead = x_bad + (x_bad - x_ok)
    try:
        if kinematic_lock(at, x_bad, ahead) is None or _fate(at, ahead, rtol) not in _NO_STATE:
            return None
    except ParameterError:  # one more step leaves the control's range
        return None
    return ahead


def kinematic_lock(at: TubeAt, a: float, b: float) -> float | None:
    """Where the axial stretch alone locks a layer, if that is between a and b (the first
    such x from a, over the layers: module docstring). None under force control or where
    no layer locks in [a, b] (a lock approached under a load is approached, not reached:
    no loss)."""
    if at(a).axial_force is not None:
        return None
    locks = [x for x in (_gent_lock(at, a, b), _domain_lock(at, a, b)) if x is not None]
    return min(locks, key=lambda x: abs(x - a)) if locks else None


def _gent_lock(at: TubeAt, a: float, b: float) -> float | None:
    """The root of lambda_e^2 + 2 / lambda_e - 3 = jm of the first Gent layer to lock
    between a and b, by Brent."""

    def excess(x) -> float:
        tube = at(x)
        worst = -math.inf
        for layer in tube.layers:
            energy = layer.material.definition  # a BuiltinEnergy, or an expression
            if getattr(energy, "family", None) == "gent" and not layer.graded:
                le = tube.stretch / layer.growth[2]
                worst = max(worst, le * le + 2.0 / le - 3.0 - energy.parameter)
        return worst

    fa, fb = excess(a), excess(b)
    if not (math.isfinite(fa) and fa < 0.0 <= fb):
        return None
    return float(brent(excess, *sorted((a, b)), FULL))


def _domain_lock(at: TubeAt, a: float, b: float) -> float | None:
    """The last x (from a) where every energy text is finite at the least invariants of its
    elastic axial stretch, if it stops being so before b: bisected to 1e-14 relative."""

    def admissible(x) -> bool:
        tube = at(x)
        for layer in tube.layers:
            omega = bounded_energy(layer)
            if omega is not None and not layer.graded:
                le = tube.stretch / layer.growth[2]
                if not _finite(omega, le * le + 2.0 / le, 2.0 * le + 1.0 / (le * le)):
                    return False
        return True

    if not any(bounded_energy(layer) for layer in at(a).layers):
        return None
    if not admissible(a) or admissible(b):
        return None
    return bisect(admissible, a, b, LOCK)[0]


def _finite(omega, i1: float, i2: float) -> bool:
    """Is the energy finite at (I1, I2) with no field (I4 = I5 = I6 = 0)?"""
    with np.errstate(all="ignore"):
        try:
            return math.isfinite(float(omega(i1, i2, 0.0, 0.0, 0.0)))
        except (ArithmeticError, ValueError):
            return False


def _fate(at: TubeAt, x: float, rtol: float = 1e-12) -> str:
    """The base state at x: "solved"; "lost" (BaseStateError: no state found); "locked"
    (LockedSearch: the search met a layer's lock before any state, even with the finest
    Gauss rule: a loss only where :func:`kinematic_lock` establishes it); or "unresolved"
    (it exists, but its profile is not resolved, or it lies within LOCK_MARGIN of a lock:
    ConvergenceError; or it may exist on a branch not followed, BranchNotFollowed)."""
    try:
        clear_of_lock(_solved(at, x, rtol))
    except LockedSearch:
        return "locked"
    except BranchNotFollowed:  # it may exist, on a branch the package does not follow
        return "unresolved"
    except BaseStateError:
        return "lost"
    except ConvergenceError:
        return "unresolved"
    return "solved"


def _solved(at: TubeAt, x: float, rtol: float):
    """The state at x from cold, as every bisection; where that search fails, continued
    from the nearest state the march solved (basestate/warm.py: the same root, checked), so
    that a failure of the search alone is never read as the loss of a state."""
    tube = at(x)
    try:
        return solve_base_state(tube, rtol=rtol)
    except BaseStateError:
        if tube.is_uniform:  # continuation is the layered solver's (basestate/warm.py)
            raise
        from ..basestate.layered import LayeredState, solve_continued  # a layered tube's

        near, guess = at.neighbours.nearest(x, rtol)
        if near is None or not isinstance(near, LayeredState):
            raise
        state = solve_continued(tube, near, rtol, guess)
        if state is None:
            raise
        return state
