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
