"""Savings of a warm critical value that must change nothing (docs/derivation.md section 6):
a root finder's repeated points are not evaluated again, an EventWatch extrapolates once per
set of samples, a mode's stable sign is remembered."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation import critical
from electrogrowth.bifurcation.march import unloaded_signs
from electrogrowth.continuation.events import Remembered, brent, first_roots
from electrogrowth.continuation.predict import EventWatch
from electrogrowth.incremental.accuracy import STABLE_SIGN
from electrogrowth.incremental.targets import ImpedanceTarget, with_family


def test_remembered_evaluates_each_point_once():
    calls = []

    def f(x):
        calls.append(x)
        return np.cos(x) - x

    g = Remembered(f)
    root = brent(g, 0.0, 1.0)
    assert len(calls) == len(set(calls))
    assert g(np.float64(root)) == f(root)  # a repeated point: f's own value
    assert root == brent(f, 0.0, 1.0)  # the same iterates, the same root


def test_first_roots_asks_each_fine_point_once():
    """The shared bisection, then Brent on the fine values: its bracket's ends, checked
    before, are not evaluated again; the root is the bare Brent's on that bracket."""
    roots = np.array([0.31, 0.47])
    asked = []

    def signed(x, idx):
        return roots[idx] - x

    def fine(x, i):
        asked.append((x, i))
        return roots[i] - x + 1e-3 * (roots[i] - x) ** 2

    got = first_roots(signed, fine, np.array([0, 1]), np.zeros(2), 1.0, 0.0)
    assert len(asked) == len(set(asked))
    for i, root in enumerate(got):
        assert fine(root, i) == pytest.approx(0.0, abs=1e-15)


def test_event_watch_extrapolates_the_current_samples():
    """The remembered root_distance is the one of the samples recorded last."""
    rng = np.random.default_rng(1)
    watch = EventWatch(0.0, rng.uniform(1, 2, 5), 1.0, 1.0)
    for x in (0.1, 0.2, 0.3):
        before = watch.root_distance()
        np.testing.assert_array_equal(before, watch._extrapolate())
        idx = np.array([0, 2, 3])
        watch.record(idx, x, rng.uniform(0, 1, 3))
        np.testing.assert_array_equal(watch.root_distance(), watch._extrapolate())


@pytest.mark.parametrize("mode", [(0, 1, "wrinkle"), (3, 2, "wrinkle"), (2, 0, "prismatic")])
def test_stable_sign_is_the_unloaded_tubes(mode):
    tube = Tube.uniform(outer_radius=1.7, length=2.0, voltage=0.3, growth=1.2)
    m, n, fam = mode
    direct = unloaded_signs(tube, with_family(m, n, fam), ImpedanceTarget(STABLE_SIGN))[0]
    assert critical.stable_sign(m, n, tube, family=fam) == direct
    assert critical.stable_sign(m, n, tube.at("growth", 1.5), family=fam) == direct  # remembered
