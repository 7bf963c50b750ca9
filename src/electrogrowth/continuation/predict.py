"""Predictors: where a path's events are expected, and where a followed value goes next.

:class:`EventWatch` keeps the last samples of many signed event functions (a march's
modes) and extrapolates each to its zero, which both limits the step
(continuation.path.StepPolicy) and says which functions need a new sample.
:func:`secant_bracket` extrapolates a followed value (a mode's critical value along a
curve) from its last two points: the natural-parameter form of arc-length continuation's
tangent predictor.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

import numpy as np

#: an event function is sampled at least every MAX_WAIT of the path's scale
MAX_WAIT = 0.25
#: a zero is trusted where its prediction moved by at most TRUST of the distance to it, and
#: of the finest step, between the last two samples; a step may then go OVERSHOOT of that
#: distance (or twice the move, if more; never more than the finest step) beyond it, to
#: bracket the zero instead of creeping up on it
TRUST = 0.25
OVERSHOOT = 0.1


class EventWatch:
    """Last three samples (x, signed value) of every event function, and when each is due.

    A function is extrapolated to its zero, by the line through its last two samples and
    the parabola through its last three, whichever reaches zero first (near Vbar = 0
    targets fall like Vbar^2, which a line overestimates). The function is sampled again
    once the march has covered half that distance, and at least every MAX_WAIT of the
    scale (a function may dip below zero and return between two distant samples), so
    functions far from zero cost a few evaluations, not one per step. From ``far_from``
    scales past the start, that wait grows to ``far`` of the distance marched where the
    function's own last three samples allow it (:func:`far_waits`).
    """

    def __init__(
        self, x0, g0, sense, scale, max_wait: float = MAX_WAIT, *, far=0.0, far_from=np.inf,
        late=0.0,
    ):  # fmt: skip
        n = g0.size
        self.sense, self.scale = sense, scale
        self.wait = max_wait * scale  # the longest a function goes unsampled
        # far waits (:meth:`_far_waits`): ``far`` of the distance marched, from ``far_from``
        # scales on; a function due is sampled up to ``late`` (times the scale) after
        self.far, self.far_from, self.late = far, far_from * scale, late * scale
        self.x = np.full((3, n), np.nan)  # rows: newest, previous, oldest
        self.g = np.full((3, n), np.nan)
        self.x[0], self.g[0] = x0, g0
        self.alive = np.ones(n, bool)
        self.due = np.full(n, x0)
        self.moved = np.full(n, np.inf)  # how far the predicted zero moved at the last sample
        self.x0 = x0
        self._distance = None  # root_distance() of the current samples, once computed

    @property
    def xa(self):
        return self.x[0]

    def root_distance(self):
        """Extrapolated distance from the newest sample to the zero (inf if receding);
        computed once per set of samples (each step asks which functions are due and how
        far the nearest zero is)."""
        if self._distance is None:
            self._distance = self._extrapolate()
            self._distance.setflags(write=False)
        return self._distance

    # Each question below is answered by watch_kernel.py once numba is loaded (the same
    # bits: ~1 us against 5-45 us for NumPy's small-array operations), else by its
    # ``*_numpy`` twin.

    def _extrapolate(self):
        """:meth:`root_distance` from the samples."""
        kernel = _compiled()
        if kernel is None:
            return self._extrapolate_numpy()
        return kernel.root_distances(self.x, self.g, float(self.sense))

    def _extrapolate_numpy(self):
        """:meth:`root_distance` from the samples, in NumPy."""
        (xa, xb, xc), (ga, gb, gc) = self.x, self.g
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            slope = (ga - gb) / (xa - xb)
            line = np.where(slope * self.sense < 0, -ga / slope * self.sense, np.inf)
            curv = ((ga - gb) / (xa - xb) - (gb - gc) / (xb - xc)) / (xa - xc)
            # g(xa + sense t) = ga + s t + c t^2 with s = slope sense, c = curv
            s_, c_ = slope * self.sense, curv
            disc = s_ * s_ - 4 * c_ * ga
            t = (-s_ - np.sqrt(np.maximum(disc, 0))) / (2 * c_)
            t2 = (-s_ + np.sqrt(np.maximum(disc, 0))) / (2 * c_)
            t = np.where((t > 0) & (disc >= 0), t, np.where((t2 > 0) & (disc >= 0), t2, np.inf))
        return np.fmin(np.where(np.isnan(line), np.inf, line), np.where(np.isnan(t), np.inf, t))

    def needs(self, x):
        """Live functions to sample at x: due, or predicted to have reached zero by x; far
        from the start, once half their wait has passed (:meth:`_due`)."""
        due = self._due(x)
        kernel = _compiled()
        if kernel is None:
            return self.needs_numpy(x, due)
        dist = self.root_distance()
        return kernel.needs(self.alive, due, dist, self.xa, float(x), float(self.sense))

    def _due(self, x):
        """Where each function is sampled: its due point, and from ``far_from`` on the
        midpoint of its wait. A sample taken early is never a risk, and it keeps the due
        points together: a step ends at most ``late`` past the next one due, and a scan's
        ~1000 modes, each falling due at its own point, ended a step each (3,000 steps from
        300 to 1000 voltage scales of a stiffening tube). Half the wait, not more: a wait is
        at most twice the last sample spacing (:func:`far_waits`), so it does not shrink."""
        if self.far and self.sense * (x - self.x0) >= self.far_from:
            return 0.5 * (self.xa + self.due)
        return self.due

    def needs_numpy(self, x, due=None):
        """:meth:`needs` in NumPy (``due``: :meth:`_due`)."""
        due = self.due if due is None else due
        reach = self.sense * (x - self.xa)
        return self.alive & ((self.sense * (x - due) >= 0) | (reach >= self.root_distance()))

    def record(self, idx, x, g):
        """New samples g (one per function, or one for all) of the functions ``idx`` (their
        indices, or a mask) at x: each one's samples one row older, its zero extrapolated
        again, how far that moved and when it falls due."""
        kernel = _compiled()
        idx = np.asarray(idx)
        idx = np.flatnonzero(idx) if idx.dtype == bool else idx.astype(np.int64, copy=False)
        if kernel is None:
            self._record_numpy(idx, x, g)
        else:
            g = np.broadcast_to(np.asarray(g, dtype=float), idx.shape).copy()  # its type
            dist = kernel.record(
                idx, float(x), g, self.x, self.g, float(self.sense), self.root_distance(),
                self.moved, self.due, self.wait,
            )  # fmt: skip
            dist.setflags(write=False)
            self._distance = dist
        if self.far and self.sense * (x - self.x0) >= self.far_from:
            self._far_waits(idx, x)

    def _far_waits(self, idx, x):
        """The functions ``idx``, sampled at x far from the start, fall due up to ``far`` of
        the distance marched later, as far as their own samples allow (:func:`far_waits`),
        still at most half their predicted distance to zero. A path with no threshold runs
        to 1e3 scales, which MAX_WAIT of the scale samples 4e3 times."""
        longest = self.far * self.sense * (x - self.x0)
        wait = far_waits(self.x[:, idx], self.g[:, idx], self.sense, longest, self.wait,
                         self.late)  # fmt: skip
        self.due[idx] = x + self.sense * np.minimum(0.5 * self.root_distance()[idx], wait)

    def _record_numpy(self, idx, x, g):
        """:meth:`record` in NumPy (before the far waits)."""
        before = self.x[0, idx] + self.sense * self.root_distance()[idx]  # the zero predicted
        self._distance = None  # new samples, new extrapolation
        for rows in (self.x, self.g):  # each sample one row older
            rows[2, idx] = rows[1, idx]
            rows[1, idx] = rows[0, idx]
        self.x[0, idx], self.g[0, idx] = x, g
        self._settle_numpy(idx, x, before)

    def _settle_numpy(self, idx, x, before):
        """The end of :meth:`record` in NumPy: how far each new sample moved its predicted
        zero from ``before``, and when it falls due."""
        dist = self.root_distance()[idx]
        with np.errstate(invalid="ignore"):
            self.moved[idx] = np.abs(x + self.sense * dist - before)  # inf - inf: NaN
        wait = np.minimum(0.5 * dist, self.wait)
        self.due[idx] = x + self.sense * wait

    def reach(self, safety: float, finest: float) -> float:
        """How far the next step may go: ``safety`` of the distance to the nearest predicted
        zero, or just beyond a trusted zero (TRUST, OVERSHOOT), the least over the live
        functions (inf if none). ``finest`` is the march's smallest step (absolute): a
        function creeping up on its zero by ``safety`` ends with steps of that size, and a
        window in which it dips below zero and returns is seen if it is wider. So is it
        here: the zero is trusted only once its prediction has settled to TRUST of
        ``finest``, and the step ends at most ``finest`` beyond it."""
        kernel = _compiled()
        if kernel is None:
            return self.reach_numpy(safety, finest)
        return kernel.reach(self.alive, self.root_distance(), self.moved, float(safety),
                            float(finest), TRUST, OVERSHOOT)  # fmt: skip

    def reach_numpy(self, safety: float, finest: float) -> float:
        """:meth:`reach` in NumPy."""
        live = self.alive
        dist, moved = self.root_distance()[live], self.moved[live]
        if not dist.size:
            return np.inf
        with np.errstate(invalid="ignore"):
            trusted = moved <= TRUST * np.minimum(dist, finest)
        past = np.minimum(np.maximum(2.0 * moved, OVERSHOOT * dist), finest)
        return float(np.where(trusted, dist + past, safety * dist).min())

    def next_due(self, x) -> float | None:
        """The nearest point beyond x where a live function falls due (None if none is
        ahead): a step that ends before it samples nothing (:meth:`needs`)."""
        kernel = _compiled()
        if kernel is None:
            return self.next_due_numpy(x)
        found, due = kernel.next_due(self.alive, self.due, float(x), float(self.sense))
        return due if found else None

    def next_due_numpy(self, x) -> float | None:
        """:meth:`next_due` in NumPy."""
        ahead = self.alive & (self.sense * (self.due - x) > 0)
        if not ahead.any():
            return None
        due = self.due[ahead]
        return float(due.min() if self.sense > 0 else due.max())

    def distance(self) -> float:
        """The smallest extrapolated distance to a zero of a live function (inf if none)."""
        dist = self.root_distance()[self.alive]
        return dist.min() if dist.size else np.inf


def far_waits(x, g, sense, longest, base, late=0.0):
    """How long each function (columns of its (3, k) samples x, g, newest first, g > 0) may
    go unsampled: ``longest``, at most twice its last sample spacing (the parabola through
    its samples is read no further than twice their span), halved while the parabola through
    the three samples closes more than half the gap to zero over that wait (plus ``late``,
    the march's lateness: :func:`closes_half`); ``base`` where it does down to ``base`` (and
    where fewer than three samples say nothing). A target that turns back toward zero, or
    curves toward it, is sampled at the old rate again."""
    wait = np.minimum(longest, 2.0 * sense * (x[0] - x[1]))  # NaN: no second sample
    ok = np.zeros(wait.shape, bool)
    with np.errstate(invalid="ignore"):
        trial = wait > base
        while trial.any():
            ok[trial] = ~closes_half(x[:, trial], g[:, trial], sense, wait[trial] + late)
            wait[trial & ~ok] *= 0.5
            trial = ~ok & (wait > base)
    return np.where(ok, wait, base)


def closes_half(x, g, sense, span):
    """Does the parabola through the three samples (x, g) of each function (newest first)
    come closer to zero than half its newest value anywhere within ``span`` ahead of its
    newest sample (in ``sense``)? True also where the samples give no parabola (NaN)."""
    t1, t0 = sense * (x[1] - x[0]), sense * (x[2] - x[0])  # t = sense (x - newest) < 0
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        a = (g[0] - g[1]) / -t1  # q(t) = g0 + a t + c t (t - t1) through all three
        c = (a - (g[1] - g[2]) / (t1 - t0)) / -t0
        at_end = a * span + c * span * (span - t1)
        vertex = np.clip(0.5 * (t1 - a / c), 0.0, span)  # a minimum's, where c > 0
        at_vertex = a * vertex + c * vertex * (vertex - t1)
        lowest = np.where(c > 0, np.minimum(at_end, at_vertex), at_end)
        return ~(lowest >= -0.5 * g[0])


def _compiled():
    """The module watch_kernel once the compiled kernels have loaded numba, else None: a
    path alone does not import it. Remembered once loaded: every step asks several times."""
    global _WATCH_KERNEL
    if _WATCH_KERNEL is None and "numba" in sys.modules:
        from . import watch_kernel

        _WATCH_KERNEL = watch_kernel
    return _WATCH_KERNEL


_WATCH_KERNEL = None


def secant_bracket(
    history: Sequence[tuple[float, float]], x: float, *, first: float = 1e-2, least: float = 1e-6
) -> tuple[float, float] | None:
    """A bracket around a followed value at x, from its last points (x_k, v_k): the secant
    through the last two extrapolated to x, widened by the change it predicts (at least
    ``least`` max(1, |guess|)); from one point, that value +- ``first`` of it; None
    without points."""
    if not history:
        return None
    x1, v1 = history[-1]
    if len(history) == 1:
        return v1 * (1 - first), v1 * (1 + first)
    x0, v0 = history[-2]
    guess = v1 + (v1 - v0) * (x - x1) / (x1 - x0)
    w = max(abs(guess - v1), least * max(1.0, abs(guess)))
    return guess - w, guess + w
