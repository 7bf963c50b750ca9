"""Fewer evaluations in a march, the same roots (docs/derivation.md section 6): a monitor
predicted from its last step, steps that end where a function falls due, a trusted zero
bracketed by one step just past it, a single crossing finished near its loose root."""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth.continuation.events import NEAR, first_roots
from electrogrowth.continuation.path import ControlPath, Stepper, StepPolicy
from electrogrowth.continuation.predict import EventWatch

PREDICTING = StepPolicy(smallest=1e-4, largest=0.25, predict_monitor=True, max_change=0.08)


def test_a_steady_monitor_is_no_jump_a_bending_one_is():
    """lambda_i = 1 + 2x changes by more than 5 % per step but along its linear prediction:
    no step is dropped, each is capped at 8 % of predicted change; a monitor that bends away
    from the prediction by more than 5 % is a jump."""
    step = Stepper(ControlPath(0.0, 1.0, 1.0), PREDICTING, 1.0)
    x = 0.0
    for _ in range(12):
        x = step.propose()
        assert not step.jumped(1.0 + 2.0 * x)
        step.accept(x, 1.0 + 2.0 * x, math.inf)
    change = [2.0 * s / (1.0 + 2.0 * x0) for x0, s in [(x - step.taken, step.taken)]]
    assert change[0] <= 0.08 * (1 + 1e-12)
    x1 = step.propose()
    assert step.jumped((1.0 + 2.0 * x1) * 1.06)  # 6 % off the line
    plain = Stepper(ControlPath(0.0, 1.0, 1.0), StepPolicy(smallest=1e-4), 1.0)
    assert plain.jumped(1.06)  # without prediction any 5 % change is a jump


def test_a_step_ends_where_asked():
    step = Stepper(ControlPath(0.0, 1.0, 1.0), PREDICTING, 1.0)
    step.step = 0.25
    assert step.propose(until=0.1) == pytest.approx(0.1)
    assert step.propose(until=1e-9) == pytest.approx(1e-4)  # never below the finest step
    assert step.propose() == pytest.approx(0.25)


def _watch_on(g, xs):
    watch = EventWatch(xs[0], np.array([g(xs[0])]), 1.0, 1.0)
    for x in xs[1:]:
        watch.record(np.array([0]), x, np.array([g(x)]))
    return watch


def test_a_settled_zero_is_bracketed_by_one_step():
    """g = (0.5 - x)(1 + x) sampled close to its zero: the prediction has settled, so the
    step may end just past it (at most the finest step beyond); where the prediction still
    moves, 0.7 of the distance."""

    def g(x):
        return (0.5 - x) * (1.0 + x)

    near = _watch_on(g, [0.48, 0.49, 0.495, 0.4985])
    dist = near.root_distance()[0]
    assert dist == pytest.approx(0.5 - 0.4985, rel=1e-2)
    assert dist < near.reach(0.7, 1e-4) <= dist + 1e-4
    wavy = _watch_on(lambda x: g(x) + 0.01 * math.sin(40 * x), [0.0, 0.1, 0.2, 0.3])
    d = wavy.root_distance()[0]
    assert wavy.reach(0.7, 1e-4) == pytest.approx(0.7 * d)


def _one_crossing(signed, fine, loose_parts=None):
    """first_roots of one candidate that crossed between 0.2 and 0.4, its loose values at
    both ends known."""
    return first_roots(
        signed,
        fine,
        np.array([0]),
        np.array([0.2]),
        0.4,
        0.0,
        values=(signed(0.2, 0), signed(0.4, 0)),
        loose_parts=loose_parts,
    )


def test_one_crossing_is_finished_near_its_loose_root():
    """One candidate with its loose values: the fine root to the last bits in ~4 fine
    evaluations; a loose root off by more than the first bracket in the second; off by more
    than that, the bisection."""
    c = 0.3141592653589793

    def fine(x, i):
        asked.append(x)
        return (c - x) * (2.0 + x)

    for shift, most in ((1e-12, 4), (30 * NEAR[0], 8), (30 * NEAR[-1], 14)):
        asked = []

        def signed(x, idx, shift=shift):
            return np.array([(c + shift - x) * (2.0 + x)])

        got = _one_crossing(signed, fine)
        assert got[0] == pytest.approx(c, rel=2e-15, abs=0)
        assert len(asked) <= most


def test_a_loose_root_on_a_step_is_refined_on_the_determinant():
    """A short wave living at the inner face: its bounded target f is a step (+-1e-9), its
    size log_norm carries the zero and grows like 60 x. Brent's method on f bisects (~30
    evaluations to 1e-10); after its first iterations, det(M2) = f exp(log_norm), divided by
    exp of the line through log_norm at the ends, converges in a few. A smooth target keeps
    Brent's method on f, with no evaluation more."""
    c = 0.3141592653589793

    def parts(x, i):
        asked.append(x)
        return math.copysign(1e-9, c - x), math.log(abs(c - x) + 1e-300) + 60.0 * x + 20.0

    def signed(x, idx):
        return np.array([parts(x, 0)[0]])

    def fine(x, i):
        return (c - x) * math.exp(60.0 * x)

    for loose_parts, least, most in ((None, 25, 40), (parts, 0, 22)):
        asked = []
        got = _one_crossing(signed, fine, loose_parts)
        assert got[0] == pytest.approx(c, rel=2e-15, abs=0)
        assert least <= len(asked) <= most, len(asked)


def test_a_smooth_loose_root_costs_no_more_with_the_determinant_at_hand():
    """Brent's method on a smooth bounded target converges within LOOSE_FIRST: det(M2) is
    never asked, and the loose evaluations are those of the route without it."""
    c = 0.3141592653589793
    counts = []
    for with_parts in (False, True):
        asked = []

        def signed(x, idx, asked=asked):
            asked.append(x)
            return np.array([(c - x) * (2.0 + x)])

        def parts(x, i):
            raise AssertionError("det(M2) asked for a smooth target")

        _one_crossing(signed, lambda x, i: (c - x) * (2.0 + x), parts if with_parts else None)
        counts.append(len(asked))
    assert counts[0] == counts[1]
