"""The one stepper: how a march moves along its control, from a stable start to its events.

A path is a one-parameter family of solutions: its state is a :class:`Point` (the control
value, the unknowns solved there: a base state, the critical values of some modes, a
branch's load). Every march of the package is natural-parameter continuation: the step is
taken in the control, and the unknowns are solved at the new value (:class:`Path`).

The step control is one object per march, :class:`StepPolicy`: steps start at ``first`` of
the path's scale and at most double (``growth``) up to ``largest``, never beyond ``safety``
of the distance at which the march's predictor (continuation.predict) expects the next
event, and never below ``smallest`` (1e-4 for the mode march, 1e-6 for the short-wave
march); from ``far_from`` scales past the start, ``largest`` grows to ``far`` of the
distance marched (a path with no threshold runs to 1e3 scales), as far as the march's event
functions allow (continuation.predict.far_waits). A step is halved when the monitored
unknown (lambda_i, the inner stretch) changes by more than ``max_jump`` (with
``predict_monitor``: bends that far away from its linear prediction, and a step is proposed
only as far as the prediction moves it by ``max_change``): near the voltage threshold
lambda_i runs away and modes lose and regain stability within a tiny interval. When the
state is lost between two steps the threshold is located
(continuation.events.threshold_between) and approached with shrinking steps. A wall thinned
to a film (lambda_i grown ``film``-fold) runs to an asymptote of the control (an inflation's
pressure, a held voltage's threshold): the march goes on toward it
(:meth:`Stepper.approach`) in steps that grow geometrically in lambda_i (``film_growth``
each, the gap to the asymptote falling by the power its observed order gives), until the gap
is below what the value's tolerance can tell. :class:`Stepper` holds this,
:class:`GeometricGrid` the fixed geometric steps of a base-state branch (in r_i, past its
folds).

Arc-length continuation (post-buckling branches, which turn back in the control) plugs in
beside :class:`Stepper`: a stepper whose ``propose`` returns a predicted :class:`Point`
(control and unknowns along the tangent) and whose ``accept`` takes the corrected one, on
a :class:`Path` that also gives its residual and Jacobian (the pseudo-arclength
corrector); it shares :class:`StepPolicy` and the events. Its place is
``continuation/arclength.py``.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator
from typing import Any, NamedTuple, Protocol

import numpy as np


class Point(NamedTuple):
    """A state of a path: the control value and the unknowns solved there."""

    control: float
    unknowns: Any


class Path(Protocol):
    """A one-parameter family of solutions.

    ``solve(control)`` returns the unknowns at a control value (natural-parameter
    continuation), raising the path's error (e.g. BaseStateError) where there are none.
    Arc-length continuation adds ``residual(point)`` and ``jacobian(point)``."""

    def solve(self, control: float) -> Any: ...


@dataclasses.dataclass(frozen=True)
class ControlPath:
    """Where a march runs: from ``start`` towards ``end``, steps in units of ``scale``."""

    start: float
    end: float
    scale: float

    @property
    def sense(self) -> float:
        return 1.0 if self.end > self.start else -1.0


@dataclasses.dataclass(frozen=True)
class StepPolicy:
    """The constants of a march's step control (module docstring); steps are fractions of
    the path's scale."""

    smallest: float
    first: float = 0.004
    largest: float = 0.05
    growth: float = 2.0  # a step at most doubles
    safety: float = 0.7  # of the predicted distance to the next event
    max_jump: float = 0.05  # relative change of the monitored unknown (lambda_i) per step
    jump_shrink: float = 2.0
    jump_floor: float = 1e-12  # a step this small is taken whatever the jump
    lost_shrink: float = 4.0  # after the state was lost within a step
    edge_gap: float = 1e-12  # stop this far (times the scale) before a lost state
    film: float = 50.0  # lambda_i grown this much: the wall is a film, near its asymptote
    #: past a film, lambda_i grows this much per step toward the asymptote (a root there
    #: lies at lambda_i ~ 1.2 / Vbar for an inflated tube under voltage: 50 .. 1e3)
    film_growth: float = 2.0
    #: the state solver failed (not lost): retry shorter until the step is this small
    unresolved_floor: float = 1e-5
    #: predict the monitor linearly from the last accepted step: a jump is then a change
    #: ``max_jump`` away from that prediction (a runaway bends the monitor; a steady change
    #: does not), and no step is proposed over which the prediction changes the monitor by
    #: more than ``max_change`` (relative). Without it a jump is any change beyond
    #: ``max_jump``: a monitor growing steadily with the control limits every step, and a
    #: step doubles until it is dropped (its state solved for nothing), then halves.
    predict_monitor: bool = False
    max_change: float = math.inf
    #: an event function is sampled at least this often (times the scale): see
    #: predict.EventWatch; a window of instability narrower than it may be missed
    max_wait: float = 0.25
    #: from ``far_from`` scales past the start on, the largest step is ``far`` of the
    #: distance marched, if that is more (0: never): a path with no threshold runs to 1e3
    #: scales. The caller's event functions say how much of it a step may take (they fall
    #: due no later than their own samples allow: predict.EventWatch far waits)
    far: float = 0.0
    far_from: float = math.inf

    def __post_init__(self):
        if not 0 < self.smallest <= self.first <= self.largest:
            raise ValueError(f"steps {self.smallest}, {self.first}, {self.largest} not ordered")

    def next(self, step: float, limit: float, marched: float = 0.0) -> float:
        """The step after an accepted one, ``marched`` scales from the start: ``limit`` (a
        predictor's, relative to the scale) clipped to [smallest, min(growth step,
        largest there)]."""
        # np.clip's minimum(maximum(...)) in plain floats (NaN stays NaN): one per step
        top = min(self.growth * step, self.largest_at(marched))
        return float(min(max(limit, self.smallest), top))

    def largest_at(self, marched: float) -> float:
        """The largest step ``marched`` scales from the start: ``largest``, and from
        ``far_from`` on ``far`` of the distance marched if that is more."""
        if marched >= self.far_from:
            return max(self.largest, self.far * marched)
        return self.largest

    def limit(self, distance: float, scale: float) -> float:
        """The step limit ``safety`` of a predicted distance to the next event."""
        return self.safety * distance / scale


class Stepper:
    """Natural-parameter continuation along a :class:`ControlPath` with a
    :class:`StepPolicy`; ``x`` is the last accepted control value, ``step`` the next step
    (relative to the scale), ``end`` the end of the path (cut where the state is lost).
    The monitored unknown (lambda_i) is given to :meth:`jumped` and :meth:`accept`."""

    def __init__(self, path: ControlPath, policy: StepPolicy, monitor0: float):
        self.policy, self.scale, self.sense = policy, path.scale, path.sense
        self.x, self.end, self.start = path.start, path.end, path.start
        self.step = policy.first
        self.monitor0 = self.monitor = monitor0
        self.rate = 0.0  # d monitor / dx over the last accepted step (0: none yet)
        self.taken = self.step  # the step of the last proposal (a cap may shorten it)
        self.proposed = self.x  # the last proposal
        #: past a film: the control's asymptote (lambda_i -> inf) and the observed order p
        #: of the gap to it, asymptote - x ~ lambda_i^-p (approach)
        self.asymptote: float | None = None
        self.order = 2.0

    def at_end(self) -> bool:
        """Has the march reached the end of its path?"""
        return (self.end - self.x) * self.sense <= 0

    def propose(self, until: float | None = None) -> float:
        """The next control value: one step on, not beyond the end, nor beyond ``until``
        (where the caller next needs a state; a step still covers ``smallest``), nor where
        the monitor is predicted to jump (``jump_foresight``)."""
        sense, p = self.sense, self.policy
        if self.asymptote is not None:  # lambda_i grows film_growth-fold
            left = self.asymptote - self.x
            x = self.asymptote - left * p.film_growth**-self.order
            self.proposed = min(x, self.end, key=lambda v: sense * v)
            return self.proposed
        step = self.step
        if until is not None:
            step = min(step, max(sense * (until - self.x) / self.scale, p.smallest))
        if p.predict_monitor and self.rate != 0.0:
            room = p.max_change * abs(self.monitor / self.rate) / self.scale
            step = min(step, max(room, p.jump_floor))
        self.taken = step
        self.proposed = min(self.x + sense * step * self.scale, self.end, key=lambda v: sense * v)
        return self.proposed

    def lost(self, threshold: float) -> bool:
        """The state was lost within the step, at ``threshold``: the path ends just before
        it, the step shrinks. True if nothing is left of the path."""
        self.end = threshold - self.sense * self.policy.edge_gap * self.scale
        self.step /= self.policy.lost_shrink
        return abs(self.end - self.x) <= self.policy.edge_gap * self.scale

    def far_lost(self) -> bool:
        """The state was lost within a far step (longer than ``largest``): the march goes on
        from where it was in the scale's steps, far steps no more, and the loss is located
        from a step of that length (True). False for a step of the old length, whose loss
        is located now. A far step past a loss (a pulled trilayer's force march, 0.1 of 243
        scales) put the bisection's points deep in the lost range, where each cold solve
        walks a whole threshold (minutes, where the old steps took 25 s)."""
        if self.taken <= self.policy.largest or self.asymptote is not None:
            return False
        self.policy = dataclasses.replace(self.policy, far=0.0)
        self.step = self.policy.largest
        return True

    def unresolved(self) -> bool:
        """The state solver failed at the proposed value: shorten the step (True), or
        False if it is already below ``unresolved_floor``."""
        if self.step <= self.policy.unresolved_floor or self.asymptote is not None:
            return False
        self.step /= self.policy.lost_shrink
        return True

    def jumped(self, monitor: float) -> bool:
        """Did the monitored unknown at the proposal jump (change by more than ``max_jump``,
        from its linear prediction with ``predict_monitor``)? Then the step is shortened and
        the proposal should be dropped (True). Never on the approach to an asymptote, whose
        steps are meant to grow lambda_i."""
        p = self.policy
        if self.asymptote is not None:
            return False
        expected = self.monitor
        if p.predict_monitor:
            expected += self.rate * (self.proposed - self.x)
        if abs(monitor / expected - 1) > p.max_jump and self.step > p.jump_floor:
            self.step = min(self.step, self.taken) / p.jump_shrink
            return True
        return False

    def film(self, monitor: float) -> bool:
        """Has the monitored unknown grown ``film``-fold since the start (and the march not
        yet been sent on toward the asymptote)?"""
        return self.asymptote is None and monitor > self.policy.film * self.monitor0

    def approach(self, asymptote: float, gap: float) -> None:
        """The wall is a film whose state runs to ``asymptote`` (lambda_i -> inf): march on
        toward it, the path ending ``gap`` short of it (or where it ended before, if that is
        nearer). A root within ``gap`` of the asymptote cannot be told from it: ``gap`` is
        the value's tolerance. Each accepted step reads the order of the gap (accept; 2
        until one is read)."""
        self.asymptote = asymptote
        near = asymptote - self.sense * gap
        self.end = min(self.end, near, key=lambda v: self.sense * v)

    def accept(self, x: float, monitor: float, limit: float | None = None) -> None:
        """Move to x; with a predictor's ``limit``, choose the next step (on the approach to
        an asymptote: read the order of the gap to it instead)."""
        if self.asymptote is not None:
            self._read_order(x, monitor)
        elif limit is not None:
            marched = self.sense * (x - self.start) / self.scale
            self.step = self.policy.next(self.step, limit, marched)
        if x != self.x:
            self.rate = (monitor - self.monitor) / (x - self.x)
        self.x, self.monitor = x, monitor

    def _read_order(self, x: float, monitor: float) -> None:
        """p of asymptote - x ~ monitor^-p from the step to x, kept in [0.5, 8] (a step's
        gap falls by at most film_growth^8: 256-fold for lambda_i doubling)."""
        before, after = self.asymptote - self.x, self.asymptote - x
        if before * after > 0 and abs(after) < abs(before) and monitor > self.monitor > 0:
            p = math.log(before / after) / math.log(monitor / self.monitor)
            self.order = min(max(p, 0.5), 8.0)


@dataclasses.dataclass(frozen=True)
class GeometricGrid:
    """Fixed geometric steps x0 ratio^(sign k), k = 1, 2, ... up to a factor ``span``, in
    batches of ``batch`` (evaluated together: a vectorised path)."""

    ratio: float
    span: float
    batch: int = 8

    def batches(self, x0: float, sign: int) -> Iterator[np.ndarray]:
        kmax = math.ceil(math.log(self.span, self.ratio))
        for k in range(1, kmax + 1, self.batch):
            yield x0 * self.ratio ** (sign * np.arange(k, min(k + self.batch, kmax + 1)))
