"""March a control parameter from a stable state to the first bifurcation of a set of modes.

Shared by the single-mode solver (bifurcation.critical_value) and the mode scan
(scan.scan_modes). Which sign of the target is stable is read off the unloaded tube
(g = 1, lambda_z = 1, Vbar = 0), stress free and stable in every mode: along any path the
target keeps that sign until the mode's first bifurcation.

The control parameter x moves from its start in steps that grow geometrically (0.4 % of
the scale, doubling up to 5 %; from FAR_FROM scales on, up to FAR of the distance marched
where every mode's own samples allow it) but never beyond 0.7 of the distance at which the linear
extrapolation of any mode's target reaches zero (a mode can be unstable only in a narrow
window, which a long step would jump over; once that zero's prediction has settled below the
finest step, one step goes just past it: docs/derivation.md section 7), and shrink when the
inner stretch lambda_i changes by more than 5 % in one step: near the voltage threshold
lambda_i runs away and modes can lose and regain stability within a tiny interval (a single
mode's march, ONE_MODE_STEPS, predicts lambda_i instead and solves no state it drops). When
the base state is lost between two steps the threshold is located exactly and approached
with shrinking steps. Modes that change sign in a step are narrowed by a shared bisection
and finished with Brent's method; a mode whose target dips towards zero between steps
without crossing, or stays positive at a sample past the zero its last samples predicted (a
window narrower than the step past that zero: :func:`overstepped`), is examined by a bounded
minimisation; a single crossing is finished near its loose root. The loose signs are those
of the caller's tolerance unless they do not resolve this tube's targets at the start
(:func:`calibrated`). The stepping, the prediction and the location are the continuation
engine's (continuation/: MODE_STEPS, EventWatch, first_roots); the march says what a state,
a mode and a lost state are.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from ..basestate import tube as door
from ..basestate.tube import solve_base_state
from ..continuation.events import (
    LATER,
    brent,
    crossed,
    dip_bracket,
    dipped,
    first_roots,
)
from ..continuation.path import ControlPath, Stepper, StepPolicy
from ..continuation.predict import EventWatch
from ..errors import (
    BaseStateError,
    ConvergenceError,
    NoBifurcationBeforeLock,
    NoBifurcationFound,
    Remedy,
    UnstableAtStart,
)
from ..incremental.targets import SIGN_TUBE as SIGN_TUBE  # re-exported: its grids' signs
from ..incremental.targets import ImpedanceTarget, Sample, natural_family, row_family
from ..model.controls import KINDS
from ..model.layers import Tube
from .along import RootRows, Signed, TubeAt
from .problem import DEFAULT_RTOL
from .state_loss import Approach, LockAhead, approach_film, box_note, loss_at_end
from .state_loss import threshold_between as _threshold_between

#: from FAR_FROM scales past the start on, a march's steps, and the waits between a mode's
#: samples, may grow to FAR of the distance marched, as far as every mode's own samples allow
#: (predict.far_waits): a path with no threshold (a stiffening energy's voltage) runs to 1e3
#: scales, 2e4 steps of 5 % of the scale. Within FAR_FROM the steps are as before: a growth
#: path ends 5 scales from its start, a stretch in compression within 1, a voltage with a
#: threshold at 1 (its scale). Only along FAR_CONTROLS: a voltage path that goes past its
#: scale has no threshold, and no state to lose; a pressure or force path may lose its state
#: far out, and a far step past that loss put the loss's bisection deep in the lost range
#: (a pulled trilayer's force march: its states by continuation, not by its loading path)
FAR, FAR_FROM = 0.1, 5.0
FAR_CONTROLS = ("voltage",)
#: the mode march's step control: 0.4 % of the scale doubling up to 5 %, not below 1e-4
MODE_STEPS = StepPolicy(smallest=1e-4, far=FAR, far_from=FAR_FROM)
#: the march of a single mode (critical_value): lambda_i is predicted from the last step, a
#: jump is a bend of 5 % away from that prediction, and no step is proposed over which the
#: prediction moves lambda_i by more than 8 % (a layered state is continued from its
#: neighbour within 10 %: basestate/warm.py), so no state is solved for nothing. Steps stay
#: at most 5 % of the scale, as in a scan: a mode's target can dip below zero over a short
#: window that its prediction does not see coming (a three-layer tube's (0, 1) is unstable
#: for 6 % of its growth only), and longer steps jumped it (tests/bifurcation/
#: test_crease_interface.py's sandwich). The mode is sampled at every step (ONE_MODE_WAIT, the
#: largest step), not only every 0.25 of the scale as a scan's many modes are: a film-lined
#: tube's target dips below zero over 7 % of lambda_z between two samples 0.25 apart
#: (tests/bifurcation/test_march_first_root.py)
ONE_MODE_WAIT = 0.05
ONE_MODE_STEPS = StepPolicy(
    smallest=1e-4,
    predict_monitor=True,
    max_change=0.08,
    max_wait=ONE_MODE_WAIT,
    far=FAR,
    far_from=FAR_FROM,
)
#: a mode is sampled at most this far (times the scale) after it falls due: the largest
#: step of MODE_STEPS, with which the march samples every mode due at its next step
LATE = 0.05

#: a march cut at ``until`` goes this far past it (times the scale): its modes' loose roots
#: (rtol 1e-5) lie up to ~1e-5 of the scale from their fine ones, and a film's modes next to
#: the cut, their fine roots before it, were lost (probe round 6b: (0, 132) 1.22227257 of a
#: skin, cut at 1.22227273)
UNTIL_MARGIN = 1e-3

#: targets(state, modes (k, 2) or (k, 3) array) -> (k,) array of target values
Targets = Callable[[object, np.ndarray], np.ndarray]


@dataclasses.dataclass(frozen=True)
class ModeValue:
    """Critical value of one mode (m, n) of ``family`` (incremental.targets.Family; the
    natural family of (m, n) when not given: prismatic for n = 0, else wrinkle).
    ``error_estimate``: as a CriticalPoint's, once the value is solved at a scan's rtol
    (runners.py); None for a march's root, solved at the march's tolerance."""

    m: int
    n: int
    value: float
    family: str | None = None
    error_estimate: float | None = None

    def __post_init__(self):
        fam = natural_family(self.m, self.n) if self.family is None else self.family
        object.__setattr__(self, "family", str(fam))


def _mode_value(modes, i, value) -> ModeValue:
    """The ModeValue of row i of ``modes`` (m, n[, family code])."""
    return ModeValue(int(modes[i, 0]), int(modes[i, 1]), value, str(row_family(modes[i])))


@dataclasses.dataclass
class MarchResult:
    found: list  # ModeValue, in the order reached
    threshold: float | None  # where the axisymmetric state is lost, if reached first
    #: the threshold is an asymptote, examined up to this state (a root there is it to rtol)
    near: Approach | None = None


def control_path(tube: Tube, solve_for: str, side: str | None):
    """(start, end, scale) of the march for ``solve_for``: its kind's path
    (model/controls.py KINDS) on this tube, read off the base-state door."""
    kind = tube.check_control(solve_for).kind
    return KINDS[kind].path(tube, side == "extension", door)


def unloaded_signs(params, modes: np.ndarray, targets: Targets) -> np.ndarray:
    """Signs of the targets on the unloaded tube (``params.reference()``: g = 1,
    lambda_z = 1, no voltage or pressure)."""
    return np.sign(targets(solve_base_state(params.reference()), modes))


#: a march stops after this many consecutive samples on which the kernel failed for every
#: mode sampled (each went to collocation, incremental/targets.py _retry): the states are
#: past what the kernel resolves (a Fung-type energy's moduli grow like exp((I1 - 3)^2);
#: from g = 3.93 on, a tube's (0, 1) failed at every state, and its march, 40 ms of
#: collocation an evaluation, crept to g = 5.71 in 10 minutes on a tiny target whose loose
#: and fine collocation values disagreed in sign: probe round 8b, D9)
KERNEL_FAILURE_RUN = 8

#: halvings of the gap back to the modes' last samples where states past the path's end
#: are unresolvable: the last look lands within 2^-12 of that gap of the resolvable edge
RETREAT_ROUNDS = 12


def first_bifurcations(
    params: Tube,
    solve_for: str,
    side: str | None,
    modes: np.ndarray,
    targets: Targets,
    *,
    top: int = 1,
    brent_targets: Targets | None = None,
    stable_signs: np.ndarray | None = None,
    steps: StepPolicy = MODE_STEPS,
    at: TubeAt | None = None,
    until: float | None = None,
    rtol: float = DEFAULT_RTOL,
) -> MarchResult:
    """Critical values of the first ``top`` modes of ``modes`` reached by the march.

    ``targets`` is used for signs along the march (it may be loose); ``brent_targets``
    (default ``targets``) for the final roots. ``stable_signs``, the signs of the targets
    on the unloaded tube, are computed unless given (they depend only on the material,
    Rbar_o, L and the modes, so a curve or sweep can reuse them). ``steps``: the step
    control (ONE_MODE_STEPS for a single mode). ``at``: the caller's TubeAt of (params,
    solve_for), whose states the march then shares. ``until``: the march ends there if its
    path reaches it (roots beyond it are not wanted: a widened scan's new modes matter only
    before the top values the scan already has); reaching it with no root found returns an
    empty result, not an error. ``rtol``: the values' accuracy, how near an asymptote the
    march goes where its wall becomes a film (state_loss.approach_film).
    """
    at = TubeAt(params, solve_for) if at is None else at
    if stable_signs is None:
        stable_signs = unloaded_signs(params, modes, targets)
    sref = stable_signs
    path = ControlPath(*control_path(params, solve_for, side))
    asked = until
    if until is not None:  # a margin past it: a loose root there may be a fine one before
        until += path.sense * UNTIL_MARGIN * path.scale
    cut = until is not None and path.sense * (path.end - until) > 0
    if cut:
        path = dataclasses.replace(path, end=until)
    x0, sense = path.start, path.sense
    if solve_for not in FAR_CONTROLS:
        steps = dataclasses.replace(steps, far=0.0)
    state = at.state(x0)
    raw = targets(state, modes)
    targets, raw = calibrated(targets, state, modes, raw)
    g0 = sref * raw
    doubt = np.nonzero(g0 <= 0)[0]
    if doubt.size and brent_targets is not None:  # a loose sign may be wrong: ask again
        g0[doubt] = sref[doubt] * brent_targets(state, modes[doubt])
    if (g0 <= 0).any():
        i = int(np.argmax(g0 <= 0))
        m, n = modes[i, :2].astype(int)
        err = UnstableAtStart(
            f"the tube is already unstable in mode ({m}, {n})"
            f" ({row_family(modes[i])}) at {solve_for} = {x0:g}; start from"
            " a stable state"
        )
        err.row = (int(m), int(n), row_family(modes[i]).code)
        raise err
    fine = brent_targets or targets
    views = Views(
        Signed(at, targets, modes, sref),
        Signed(at, fine, modes, sref),
        RootRows(at, fine, modes, sref),
        RootRows(at, targets, modes, sref),
        np.zeros(len(modes), bool),
    )
    signed = views.signed

    watch = EventWatch(
        x0, g0, sense, path.scale, steps.max_wait, far=steps.far, far_from=steps.far_from,
        late=LATE,
    )  # fmt: skip
    step = Stepper(path, steps, state.lambda_i)
    # unresolved: the error to raise if no mode is found (states past the path's end exist
    # but do not resolve, next to a lock); stop: it ended the path at step.x; film: the wall
    # became a film there (its state runs to an asymptote)
    found, threshold, unresolved, stop, film = [], None, None, False, False
    failing = KernelFailures(solve_for)
    while watch.alive.any():
        done = step.at_end() or len(found) >= top or stop
        if not done:
            due = watch.next_due(step.x)
            x = step.propose(None if due is None else due + sense * LATE * path.scale)
            try:
                state = at.state(x)
            except (BaseStateError, ConvergenceError):  # lost, or unresolved next to a lock
                if step.asymptote is not None:  # established where the states run to:
                    stop = True  # they are not resolved closer to it
                    continue
                if step.far_lost():  # on in the scale's steps, the loss located from there
                    watch.far = 0.0
                    continue
                value, edge, pending = _threshold_between(at, params, step.x, x, side=side)
                if value is not None or threshold is None:  # an established loss stays
                    threshold, unresolved = value, pending
                step.lost(edge)
                continue
            if step.jumped(state.lambda_i):
                continue
            if step.film(state.lambda_i):  # the wall is a film: on toward its asymptote
                film = True
                done = approach_film(at, params, solve_for, side, step, rtol) is None
        if done:  # a last look at every mode not seen at step.x: nothing left behind
            x = step.x
            idx = np.nonzero(watch.alive & (watch.xa != x))[0]
            if idx.size:
                x, g = _last_look(signed, watch, idx, x)
                try:
                    found += _advance(watch, idx, x, g, views, top)
                except ConvergenceError as err:  # as below: the path's end next to a lock
                    where = (idx, watch.xa[idx][np.argmax(sense * watch.xa[idx])], x)
                    more, threshold, unresolved = _unresolved_tables(
                        at, (params, side), views, watch, where, err, top, threshold
                    )
                    found += more
            break
        # on the approach to an asymptote every mode is sampled at every step: a step
        # takes lambda_i twice as far, the watch's predictions do not reach there
        idx = np.nonzero(watch.alive if step.asymptote is not None else watch.needs(x))[0]
        if idx.size:
            try:
                g = failing.sample(targets, state, modes[idx], x) * sref[idx]
                if (doubted := views.doubted[idx]).any():  # their fine values instead
                    g[doubted] = views.fine(x, idx[doubted])
            except ConvergenceError as err:  # the state solves, its tables do not
                # (on the approach to an asymptote: examined up to step.x, say how far)
                unresolved = unresolved if step.asymptote is not None else err
                stop = True
                continue
            try:
                found += _advance(watch, idx, x, g, views, top)
            except ConvergenceError as err:  # a root's refinement met unresolved tables
                more, threshold, unresolved = _unresolved_tables(
                    at, (params, side), views, watch, (idx, step.x, x), err, top, threshold
                )
                found, stop = found + more, True
                continue
            if failing.persistent():  # the states from here on are past the kernel
                unresolved, stop = failing.error(), True
        reach = watch.reach(steps.safety, steps.smallest * path.scale)
        step.accept(x, state.lambda_i, reach / path.scale)
    found.sort(key=lambda mv: sense * mv.value)
    if not found and cut and unresolved is not None and sense * (x - asked) >= 0:
        return MarchResult([], None)  # resolved up to ``until``: only its margin was not
    if not found and isinstance(unresolved, LockAhead) and unresolved.unbounded and x != x0:
        # the control's own threshold is a lock: no state is lost before it (state_loss.py)
        stop = NoBifurcationBeforeLock(
            f"no mode bifurcates for {solve_for} from {x0:.12g} up to {x:.12g}, where"
            f" {unresolved.args[0]}"
        )
        raise stop from unresolved
    if not found and unresolved is not None:  # neither a loss nor a wrinkle is established
        err = ConvergenceError(f"{_unexamined(solve_for, x0, x)}: {unresolved.args[0]}")
        err.remedy = unresolved.remedy if isinstance(unresolved, ConvergenceError) else ""
        raise err from unresolved
    if not found and threshold is None and cut:
        return MarchResult([], None)  # none before ``until``
    near = None
    if not found and threshold is None and step.asymptote is not None:
        # approached to its tolerance: a root there is it
        threshold, near = step.asymptote, Approach(step.x, step.monitor, step.at_end())
    if not found and threshold is None:  # lost at the path's end, or past its film?
        threshold = loss_at_end(at, params, solve_for, side, step.x, step.end, film)
        if threshold is None:
            last = step.x if film else step.end
            raise NoBifurcationFound(
                f"no mode bifurcates for {solve_for} between {x0:g} and {last:g}"
                + (_film_note(step) if film else box_note(params, solve_for, side, step.end))
            )
    return MarchResult(found[:top], threshold, near)


def _film_note(step: Stepper) -> str:
    """Why a march ended where its wall became a film, short of its path's end: the states
    beyond were not examined (check round 19: the note of the box's edge further on read
    as the reason)."""
    return (
        f", where the wall has become a film (its inner radius about {step.policy.film:g}"
        " times its start, at the next step): the march stops there, the states beyond are"
        " not examined"
    )


def _unexamined(solve_for: str, x0: float, x: float) -> str:
    """What a march that ends unresolved at x established: nothing, if x is its start."""
    if x == x0:  # not one step: "from 0 up to 0" would claim a range was examined
        return (
            f"no mode could be examined past {solve_for} = {x0:.12g}: the first states"
            " past it are not resolved"
        )
    return (
        f"no mode bifurcates for {solve_for} from {x0:.12g} up to {x:.12g}, and past it"
        " none is resolved"
    )


#: the loose signs resolve a tube's targets when, on a sample of its modes at the march's
#: start, the 90th percentile of |loose - fine| / |fine| is at most this: then a mode's loose
#: sign is right until it is within ~1e-4 of the path's distance to its root, an ordering
#: the LATER checks of continuation/events.py finish on fine values. Ordinary tubes (the
#: 12 points of benchmarks/bench.py, five layered ones) read 1e-5 at rtol 1e-5 (90th
#: percentile over 443 modes at most 3e-5); a film 1e4 times as stiff as its substrate
#: (h = 1e-3) reads 4e-4 to 2e-2, and its loose signs stayed wrong up to 1e-2 of the path
#: past a root: its scan reported the ring (0, 111) for (0, 110) (probe 9a, D1)
LOOSE_RESOLVES = 1e-4
#: the sample: this many modes spread evenly over the batch (the grid's order spreads m, n)
CALIBRATION_MODES = 16
#: the reference of the calibration, and the floor of a tightened loose tolerance
CALIBRATION_FINE = 1e-12
LOOSE_FLOOR = 1e-9


def calibrated(targets, state, modes: np.ndarray, raw: np.ndarray):
    """(targets, raw): the march's loose ``targets`` and their values ``raw`` of ``modes`` at
    the start ``state``, tightened (x100 steps, down to LOOSE_FLOOR) until they resolve this
    tube's targets (LOOSE_RESOLVES against CALIBRATION_FINE, on CALIBRATION_MODES of the
    modes), then re-read. A target without a kernel tolerance (collocation's) or one already
    at the floor is returned as it is. docs/derivation.md section 7."""
    if not isinstance(targets, ImpedanceTarget) or targets.rtol <= LOOSE_FLOOR:
        return targets, raw
    pick = np.unique(np.linspace(0, modes.shape[0] - 1, CALIBRATION_MODES).astype(int))
    fine = ImpedanceTarget(CALIBRATION_FINE)(state, modes[pick])
    start, loose = targets, raw[pick]
    while targets.rtol > LOOSE_FLOOR and loose_error(loose, fine) > LOOSE_RESOLVES:
        targets = dataclasses.replace(targets, rtol=max(targets.rtol / 100.0, LOOSE_FLOOR))
        loose = targets(state, modes[pick])
    if targets is start:
        return targets, raw
    return targets, targets(state, modes)


def loose_error(loose: np.ndarray, fine: np.ndarray) -> float:
    """The 90th percentile of |loose - fine| / |fine| (finite values only): one or two modes
    of tiny target (a thin tube's probe (0, 60), 1e-3 off at 2e-5) do not tighten a march."""
    rel = np.abs(loose - fine) / np.abs(fine)
    rel = rel[np.isfinite(rel)]
    return float(np.quantile(rel, 0.9)) if rel.size else 0.0


class KernelFailures:
    """The run of consecutive march samples on which the kernel failed for every mode."""

    def __init__(self, solve_for: str):
        self.solve_for, self.run, self.since, self.last, self.reason = solve_for, 0, None, None, ""

    def sample(self, targets, state, modes, x: float) -> np.ndarray:
        """targets(state, modes), counting the run of samples that went to collocation for
        every mode (an isolated failure, or one mode of many, ends the run). A target that
        can fall back says how often it did (incremental.targets.ImpedanceTarget.sample);
        any other never does."""
        ask = getattr(targets, "sample", None)
        got = Sample(targets(state, modes)) if ask is None else ask(state, modes)
        if got.collocated < modes.shape[0]:  # resolved by the kernel, or failed in isolation
            self.run, self.since = 0, None
            return got.values
        self.run, self.last, self.reason = self.run + 1, x, got.reason
        self.since = x if self.since is None else self.since
        return got.values

    def persistent(self) -> bool:
        """Has the kernel failed on KERNEL_FAILURE_RUN consecutive samples?"""
        return self.run >= KERNEL_FAILURE_RUN

    def error(self) -> ConvergenceError:
        """The run, named: where it began and ended, and why the kernel failed last."""
        err = ConvergenceError(
            f"{self.reason}, also at tighter tolerances, at each of {self.run} consecutive"
            f" states from {self.solve_for} = {self.since:.12g} to {self.last:.12g} (the"
            " collocation fallback is for isolated failures)"
        )
        err.remedy = Remedy("")  # no tolerance or method resolves them faster
        return err


def _last_look(signed: Signed, watch, idx, x: float):
    """(x, the signed targets of the modes ``idx`` at x), or, where the targets do not
    resolve at x (the path's end next to a lock, whose moduli carry the rounding of I1
    times 1 / (1 - (I1 - 3) / jm)^2), at the x where they still do, bisected
    (RETREAT_ROUNDS) back towards the modes' last samples: a mode that bifurcates before it
    is found exactly; one in the last 2^-12 of that gap, where no target is computable,
    is not."""
    try:
        return x, signed(x, idx)
    except ConvergenceError as err:
        unresolved = err
    last = watch.xa[idx]
    good, bad, g = last[np.argmax(watch.sense * last)], x, None
    for _ in range(RETREAT_ROUNDS):
        mid = 0.5 * (good + bad)
        try:
            good, g = mid, signed(mid, idx)
        except ConvergenceError:
            bad = mid
    if g is None:  # the modes were last seen at different x: none is known at one x
        raise unresolved
    return good, g


def _unresolved_tables(at: TubeAt, tube_side, views, watch, where, err, top, known=None):
    """(roots, threshold, unresolved) where the refinement of a sign change of the modes
    ``idx`` between their last samples (the latest x_ok) and x met a state whose radial
    tables do not resolve (``err``; next to a lock, where a loose sign jumps: check round 28
    D2, the table's error escaped the march): a mode whose fine sign is negative at the last
    x where the fine targets resolve (:func:`_last_look`) has its root before it, found
    there; else the states end at the ``known`` threshold (a loss the march established
    past x), or where :func:`state_loss.threshold_between` says (a layer's kinematic lock),
    or, where neither is, nothing is established and ``err`` is raised."""
    (params, side), (idx, x_ok, x) = tube_side, where
    try:
        good, g = _last_look(views.fine, watch, idx, x)
        if (g <= 0).any():
            return _advance(watch, idx, good, g, views, top), known, None
    except ConvergenceError:
        pass  # not even the fine signs resolve: the states alone decide
    if known is None:
        known, _, _ = _threshold_between(at, params, x_ok, x, side=side, tables=True)
    return [], known, None if known is not None else err


class Views(NamedTuple):
    """The modes' signed targets along the path, each as one use wants it: the march's
    loose samples, the bounded fine values (a dip's minimisation, the check of LATER
    candidates), and det(M2), analytic where the bounded target is a step (a mode living
    at the inner face: incremental/targets.py), at the fine tolerance (roots) and at the
    loose one (a single candidate's loose root, events._near_root)."""

    signed: Signed
    fine: Signed
    root: RootRows
    loose_root: RootRows
    #: the modes whose loose sign was once wrong (events.first_roots: None), sampled by
    #: their fine values from then on: a target within the loose tolerance of zero reads
    #: noise, and a negative sample's zero, behind x, held every later step at the
    #: smallest (a stiffening tube's short wave along its voltage path: 1e-4 of the scale
    #: from Vbar ~ 35 on); its parabola through noise held its wait at the scale's
    doubted: np.ndarray


def overstepped(watch, idx, x: float, g: np.ndarray) -> np.ndarray:
    """Which modes ``idx``, sampled at x with signed values g, are still positive although x
    is past the zero their last samples predicted (EventWatch: the march steps just past a
    trusted zero to bracket it). A target with a simple root changes sign there; one that
    does not turned within the step: a window of instability narrower than the step's
    overshoot may lie inside it (a short axial wave of a thick tube, (0, 2000) of Rbar_o 3:
    its target falls through zero and comes back within 5e-5, and the step past its
    predicted zero, 0.1 of the distance to it, landed 5e-5 beyond, positive again)."""
    ahead = watch.root_distance()[idx]  # inf where receding or not yet extrapolated
    return (g > 0) & (watch.sense * (x - watch.xa[idx]) >= ahead)


def _advance(watch, idx, x, g, views: Views, need=None) -> list:
    """Record the samples at x; roots of the modes that changed sign or dipped to zero
    (of those that changed sign, the first ``need``, see events.first_roots). A dip is
    looked for on the bounded fine values, roots are refined on det(M2) (``views``)."""
    signed, signed_fine, signed_root = views.signed, views.fine, views.root
    found, modes = [], signed.modes
    passed = overstepped(watch, idx, x, g)  # read before the new samples move the prediction
    hit = crossed(g)
    js = np.nonzero(hit)[0]
    if js.size:  # bisected together from where each mode was last seen
        cand = idx[js]
        roots = first_roots(
            signed,
            signed_root.one,
            cand,
            watch.xa[cand],
            x,
            watch.x0,
            need,
            values=(watch.g[0, cand], g[js]),
            fine_many=signed_fine,
            loose_parts=views.loose_root.parts,
        )
        wrong = []
        for j, root in zip(js, roots):
            if root is None:  # the loose sign was wrong: the mode is not past a root yet
                hit[j] = False
                wrong.append(j)
            elif root is LATER:  # crossed after the first ``need`` roots: not wanted
                pass
            else:
                found.append(_mode_value(modes, idx[j], root))
        if wrong:  # recorded, and sampled from now on, by its fine value (doubted)
            g = g.copy()
            g[wrong] = signed_fine(x, idx[wrong])
            views.doubted[idx[wrong]] = True
    mid, old = watch.g[0, idx], watch.g[1, idx]  # the two samples before x
    dip = dipped(old, mid, g, (watch.x[1, idx] - watch.x[0, idx], watch.x[0, idx] - x))
    dips = np.nonzero(~hit & (dip | passed))[0]
    for j in dips[np.argsort(np.minimum(mid[dips], g[dips]))][:8]:
        i = idx[j]
        # a dip's minimum is near mid (its window on either side); a passed zero's after it
        bracket = dip_bracket(signed_fine.row(i), watch.x[1 if dip[j] else 0, i], x)
        if bracket is not None:
            found.append(_mode_value(modes, i, brent(signed_root.row(i), *bracket)))
            hit[j] = True
        elif not views.doubted[i]:  # the fine values have
            # no zero where the loose ones dipped: fine samples from now on (as ``wrong``:
            # a target at the loose noise dips at every few samples, ~25 states a look)
            views.doubted[i] = True
            g = g.copy()
            g[j] = signed_fine(x, idx[[j]])[0]
    watch.alive[idx[hit]] = False
    watch.record(idx[~hit], x, g[~hit])
    return found
