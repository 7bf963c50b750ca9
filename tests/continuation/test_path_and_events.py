"""The continuation engine on functions whose roots, dips and steps are known."""

import math

import numpy as np
import pytest

from electrogrowth.continuation.events import (
    EDGE,
    FULL,
    LATER,
    LOCK,
    THRESHOLD,
    Tolerance,
    bisect,
    brent,
    crossed,
    dip_bracket,
    dipped,
    first_roots,
    reached,
    threshold_between,
    turned,
    widening_windows,
)
from electrogrowth.continuation.path import (
    ControlPath,
    GeometricGrid,
    Point,
    Stepper,
    StepPolicy,
)
from electrogrowth.continuation.predict import EventWatch, secant_bracket
from electrogrowth.errors import ConvergenceError

# -- Brent and bisection ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("f", "a", "b", "root"),
    [
        (math.cos, 1.0, 2.0, math.pi / 2),
        (lambda x: x**3 - 2.0, 0.0, 2.0, 2.0 ** (1 / 3)),
        (lambda x: math.exp(x) - 10.0, 0.0, 5.0, math.log(10.0)),
    ],
)
def test_brent_finds_known_roots_to_full_precision(f, a, b, root):
    assert brent(f, a, b, FULL) == pytest.approx(root, rel=4e-15, abs=0)


def test_brent_names_its_failure_or_lets_it_pass():
    with pytest.raises(ConvergenceError, match=r"failed on \[0.0, 1.0\]"):
        brent(lambda x: x + 1.0, 0.0, 1.0)
    with pytest.raises(ValueError):
        brent(lambda x: x + 1.0, 0.0, 1.0, named=False)


def test_tolerance_scales():
    assert Tolerance(1e-13).at(50.0) == pytest.approx(5e-12, rel=1e-15)
    assert Tolerance(1e-13).at(0.5) == 1e-13  # max(1, |x|)
    assert Tolerance(1e-14, scale="relative").at(-0.5) == 5e-15
    assert THRESHOLD.at(1e6) == 1e-14  # absolute


def test_bisection_halves_to_the_edge():
    """holds(x) = x <= 0.3: the edge to EDGE relative to max(1, |good|), good side kept."""
    good, bad = bisect(lambda x: x <= 0.3, 0.0, 1.0, EDGE)
    assert good <= 0.3 < bad and bad - good <= 1e-13
    # near the bad end and relative (LOCK): |bad - good| <= 1e-14 |bad|
    good, bad = bisect(lambda x: x <= 300.0, 100.0, 1000.0, LOCK, near_bad=True)
    assert good <= 300.0 < bad and bad - good <= 1e-14 * bad
    # at most maxiter halvings: 3 halvings of [0, 1]
    assert bisect(lambda x: x <= 0.3, 0.0, 1.0, Tolerance(0.0, maxiter=3)) == (0.25, 0.375)


def test_widening_windows_clip_to_bounds():
    windows = list(widening_windows(1.1, 0.1, 3, bounds=(1.0, 6.0)))
    assert [w for *_, w in windows] == pytest.approx([0.1, 0.4, 1.6])
    assert windows[0][:2] == pytest.approx((1.0, 1.2))
    assert windows[2][:2] == pytest.approx((1.0, 2.7))


def test_threshold_between_a_margin_and_an_edge():
    # a margin with a root: Brent to THRESHOLD
    assert threshold_between(0.0, 1.0, margin=lambda x: 0.4 - x) == pytest.approx(0.4, abs=1e-14)
    # no sign change: tolerated, then the edge of the states (last "ok" or first "bad")
    exists = lambda x: x < 0.7  # noqa: E731
    ok = threshold_between(0.0, 1.0, margin=lambda x: 1.0, exists=exists, tolerate=(ValueError,))
    bad = threshold_between(0.0, 1.0, exists=exists, last="bad")
    assert ok < 0.7 <= bad and bad - ok <= 1e-13
    assert threshold_between(0.0, 1.0, margin=lambda x: 1.0, tolerate=(ValueError,)) is None
    with pytest.raises(ValueError):  # not tolerated: SciPy's error passes
        threshold_between(0.0, 1.0, margin=lambda x: 1.0)


# -- events -----------------------------------------------------------------------------------


def test_a_dip_between_samples_is_found():
    """f = (x - 1.1)^2 - 1e-4 has the double root pair 1.09, 1.11 between the samples 1.0,
    1.15 and 1.3, all positive: the middle sample is low enough to look, the bounded
    minimisation brackets the first root and Brent finds it."""
    f = lambda x: (x - 1.1) ** 2 - 1e-4  # noqa: E731
    xs = [1.0, 1.15, 1.3]
    old, mid, new = map(f, xs)
    assert min(old, mid, new) > 0 and not crossed(new)
    assert dipped(old, mid, new)
    bracket = dip_bracket(f, xs[0], xs[2])
    assert bracket is not None and bracket[0] == 1.0 and f(bracket[1]) <= 0
    assert brent(f, *bracket) == pytest.approx(1.09, rel=1e-14)
    # lifted by 2e-4 the pair is gone: no dip
    assert dip_bracket(lambda x: f(x) + 2e-4, 1.0, 1.3) is None


def test_a_dip_after_an_uneven_pair_of_steps_is_examined():
    """A narrow window (roots 0.4220, 0.4263) passed by a long step that lands just beyond
    it, then a short step: the middle sample is 0.37 of the next one, above DIP_RATIO, but
    the secant from the next sample through it reaches zero within the long step (check
    round 16, D1, its samples as they were); the window is then bracketed and found."""
    f = lambda x: 0.0107 * abs(x - 0.424166) - 0.0107 * 0.002156  # noqa: E731
    xs = [0.46849, 0.42069, 0.41837]
    old, mid, new = map(f, xs)
    assert min(old, mid, new) > 0 and not dipped(old, mid, new)  # the ratio alone
    assert dipped(old, mid, new, (xs[0] - xs[1], xs[1] - xs[2]))
    bracket = dip_bracket(f, xs[0], xs[2])
    assert bracket is not None and brent(f, *bracket) == pytest.approx(0.426322, rel=1e-12)
    # evenly stepped about a smooth minimum at 0.6 of its neighbours' height: no dip
    g = lambda x: 1.5 + (x - 1.0) ** 2  # noqa: E731
    assert not dipped(g(0.0), g(1.0), g(2.0), (1.0, 1.0))


def test_reached_and_turned():
    assert reached(2.0, 2.0, 1) and not reached(1.9, 2.0, 1) and reached(1.9, 2.0, -1)
    assert turned(3.0, 2.9, 1) and not turned(3.0, 3.1, 1) and turned(3.0, 3.1, -1)


def test_first_roots_of_many_events_at_once():
    """g_i(x) = c_i - x, all positive at 0, sampled last at 0 and crossed by x = 1: roots
    c_i; with need = 2 only the first two are finished, the others come LATER."""
    c = np.array([0.9, 0.35, 0.6, 0.5, 0.7])
    signed = lambda x, idx: c[idx] - x  # noqa: E731
    fine = lambda x, i: float(c[i] - x)  # noqa: E731
    cand = np.arange(c.size)
    roots = first_roots(signed, fine, cand, np.zeros(c.size), 1.0, 0.0)
    assert roots == pytest.approx(c.tolist(), rel=1e-15)
    some = first_roots(signed, fine, cand, np.zeros(c.size), 1.0, 0.0, need=1)
    assert sum(r is LATER for r in some) >= 1
    finished = [r for r in some if r is not LATER]
    assert min(finished) == pytest.approx(0.35, rel=1e-15)


@pytest.mark.parametrize(
    ("spread", "x", "most"), [((0.05, 0.95), 1.0, 3.1), ((0.02, 0.03), 0.15, 6.7)]
)
def test_a_pack_is_found_before_its_brackets_are_narrowed(spread, x, most):
    """300 candidates crossing in one step (roots spread over the step, or a cluster at its
    start, as a film's folds): the first three roots exactly, in at most ``most`` loose
    samples a candidate. The pack is bisected first (each sample only where a candidate's
    bracket holds it), and the shared rounds then narrow its few members alone: 604 and 1652
    samples, against 1180 and 3147 when the shared rounds came first, over all 300; then one
    sample more of each of the other 297 at the third root (events._later_before: loose
    signs chose the pack, the fine ones check the rest), 900 and 1948."""
    c = np.random.default_rng(1).uniform(*spread, 300)
    samples = []

    def signed(y, idx):
        samples.append(len(idx))
        return c[idx] - y

    out = first_roots(
        signed, lambda y, i: float(c[i] - y), np.arange(c.size), np.zeros(c.size), x, 0.0, need=3
    )
    got = sorted(r for r in out if r is not LATER)
    assert got[:3] == pytest.approx(sorted(c)[:3], rel=1e-15)
    assert sum(samples) <= most * c.size


# -- steps ------------------------------------------------------------------------------------


def test_a_step_policy_reproduces_its_sequence():
    """No event predicted: 0.4 % of the scale doubling to 5 %; a near event: the limit,
    never below the smallest step."""
    policy = StepPolicy(smallest=1e-4)
    step = Stepper(ControlPath(1.0, 6.0, 1.0), policy, 1.0)
    xs = []
    for _ in range(7):
        x = step.propose()
        step.accept(x, 1.0, math.inf)
        xs.append(x)
    assert xs == pytest.approx([1.004, 1.012, 1.028, 1.06, 1.11, 1.16, 1.21], rel=1e-15)
    step.accept(step.propose(), 1.0, 0.7 * 0.01)  # an event 1 % ahead: 0.7 of it
    assert step.step == pytest.approx(0.007)
    step.accept(step.propose(), 1.0, 1e-9)
    assert step.step == 1e-4  # the smallest step of this policy
    assert StepPolicy(smallest=1e-6).next(0.004, 1e-9) == 1e-6


def test_the_stepper_shrinks_for_jumps_and_stops_before_a_lost_state():
    step = Stepper(ControlPath(0.0, 1.0, 1.0), StepPolicy(smallest=1e-4), 1.0)
    assert step.jumped(1.2) and step.step == 0.002  # lambda_i +20 %: halved
    assert not step.jumped(1.01)
    assert not step.lost(0.5) and step.end == pytest.approx(0.5 - 1e-12)
    assert step.step == 0.0005  # quartered
    assert step.propose() == pytest.approx(0.0005)
    step.accept(0.5 - 1e-12, 1.0)
    assert step.at_end()
    assert step.film(50.1) and not step.film(49.0)
    down = Stepper(ControlPath(1.0, 0.05, 1.0), StepPolicy(smallest=1e-4), 1.0)
    assert down.sense == -1.0 and down.propose() == pytest.approx(0.996)


def test_a_geometric_grid_in_batches():
    grid = GeometricGrid(ratio=1.08, span=1e3, batch=8)
    batches = list(grid.batches(2.0, -1))
    xs = np.concatenate(batches)
    kmax = math.ceil(math.log(1e3, 1.08))
    assert len(xs) == kmax and all(b.size <= 8 for b in batches)
    assert xs == pytest.approx(2.0 * 1.08 ** -np.arange(1, kmax + 1), rel=1e-15)


# -- predictors -------------------------------------------------------------------------------


def test_the_event_watch_extrapolates_to_the_zero():
    """Two linear events g = 1 - x and g = 2 - x/2 sampled at 0 and 0.1: zeros 1 and 4."""
    watch = EventWatch(0.0, np.array([1.0, 2.0]), 1.0, 1.0)
    watch.record(np.arange(2), 0.1, np.array([0.9, 1.95]))
    assert watch.root_distance() == pytest.approx([0.9, 3.9], rel=1e-12)
    assert watch.distance() == pytest.approx(0.9, rel=1e-12)
    assert watch.needs(1.0).tolist() == [True, True]  # the first predicted crossed, both due


def test_the_secant_bracket_of_a_followed_value():
    assert secant_bracket([], 1.0) is None
    assert secant_bracket([Point(0.0, 2.0)], 1.0) == pytest.approx((1.98, 2.02))
    lo, hi = secant_bracket([Point(0.0, 1.0), Point(1.0, 2.0)], 2.0)
    assert (lo, hi) == pytest.approx((2.0, 4.0))  # guess 3, widened by its change
