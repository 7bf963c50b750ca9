"""The two-variable design's maximiser (prescribe_map._maximise) on closed forms of the
margin M(u) over the unit square: a kinked maximum inside, on a side and at a corner. Each
margin of a real design is single-mode solves (~0.1 s), so the evaluations are counted:
bounded to the square, the simplex does not pay for vertices past a side, where M (taken
at the clipped design) is flat (206 and 109 evaluations before, on the side and corner)."""

import sys

import numpy as np
import pytest

import electrogrowth.design.prescribe_map  # noqa: F401 -- the module, not the function

maximiser = sys.modules["electrogrowth.design.prescribe_map"]


class ClosedForm:
    """Margins of a closed form, every design it was asked at recorded; no scan adds a
    competitor."""

    def __init__(self, margin):
        self.f, self.asked = margin, []

    def margin(self, mode, others, u):
        self.asked.append(np.array(u, dtype=float))
        return self.f(u), None

    def ranked(self, u):
        return []


CASES = {  # M(u), the maximiser, the most evaluations
    "a side": (lambda u: min(u[1], 2.0 - u[1]) - abs(u[0] - 0.3), (0.3, 1.0), 160),
    "a corner": (lambda u: min(u[0] + 0.2 * u[1], 3 * u[1] - 0.1 * u[0]), (1.0, 1.0), 30),
    "a kink inside": (
        lambda u: min(0.5 + u[0] - 0.5 * u[1], 1.2 - u[0] + 0.5 * u[1]) - abs(u[1] - 0.4),
        (0.55, 0.4),
        200,
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_the_maximiser_finds_the_design_inside_the_square(name):
    margin, best, most = CASES[name]
    margins = ClosedForm(margin)
    u, _ = maximiser._maximise(margins, (1, 1), (), np.array([0.5, 0.5]), set())
    assert u == pytest.approx(best, abs=1e-6)
    asked = np.array(margins.asked)
    assert ((asked >= 0.0) & (asked <= 1.0)).all()
    assert len(asked) <= most


class TwoCompetitors:
    """The target's value 1 and two competitors' 1 + a(u), 1 + b(u): M = min(a, b), a ridge
    along their tie (critical values, as the ridge follower asks for)."""

    sense = 1.0

    def __init__(self, a, b):
        self.f = {
            (1, 1): lambda u: 1.0,
            (2, 1): lambda u: 1.0 + a(u),
            (3, 1): lambda u: 1.0 + b(u),
        }

    def value(self, mode, u):
        return self.f[mode](np.clip(u, 0.0, 1.0))

    def margin(self, mode, others, u):
        v = self.value(mode, u)
        return min((self.value(o, u) - v) / abs(v) for o in others), None

    def ranked(self, u):
        return []


def test_the_maximiser_follows_a_ridge_of_two_competitors_to_the_side():
    """A thin film's (200, 0) over thickness x modulus: M ~ 2.6e-7 is set by (200, 1) and
    (199, 0), tied along a line across which M falls steeply and along which it rises by
    1e-4 of itself to the box's side; Nelder-Mead stopped 0.024 of the box short (M 1.2e-4
    low, check round 22). The same shape: the tie u1 = 0.5 + 0.25 u0, M rising along it by
    1e-5 of itself to u0 = 1, falling 1e4 times as steeply across it (Nelder-Mead alone:
    u0 = 0.3175)."""
    tie = lambda u: 1e-3 * (0.25 * u[0] + 0.5 - u[1])  # noqa: E731
    rise = lambda u: 2.6e-7 * (1.0 + 1e-5 * u[0])  # noqa: E731
    margins = TwoCompetitors(lambda u: rise(u) + tie(u), lambda u: rise(u) - tie(u))
    others = ((2, 1), (3, 1))
    u, _ = maximiser._maximise(margins, (1, 1), others, np.array([0.3, 0.55]), set())
    best = margins.margin((1, 1), others, (1.0, 0.75))[0]
    assert margins.margin((1, 1), others, u)[0] >= best - 1e-15 * best  # M to rounding
    assert u[0] > 0.999
