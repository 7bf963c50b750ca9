"""The compiled zero-distance extrapolation (continuation/extrapolate_kernel.py) is
EventWatch's NumPy route to the last bit: on random samples with every special case of the
formulas (fresh functions with NaN samples, equal abscissae, straight lines with zero
curvature, receding functions, a zero discriminant, infinities) and both senses."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.continuation.extrapolate_kernel import root_distances
from electrogrowth.continuation.predict import EventWatch


def _watch(x, g, sense):
    w = EventWatch(x[0, 0], g[0], sense, 1.0)
    w.x, w.g = x, g
    return w


def _samples(rng, n):
    """(3, n) samples x (newest first, moving along +1) and g, with special cases mixed in."""
    x = np.cumsum(rng.uniform(1e-4, 0.1, size=(3, n)), axis=0)[::-1].copy()
    g = rng.normal(size=(3, n)) * 10.0 ** rng.integers(-8, 2, size=(3, n))
    kind = rng.integers(0, 9, size=n)
    g[:, kind == 1] = np.abs(g[:, kind == 1])  # all positive
    x[2, kind == 2] = g[2, kind == 2] = np.nan  # two samples only
    x[1:, kind == 3] = g[1:, kind == 3] = np.nan  # one sample only
    x[1, kind == 4] = x[0, kind == 4]  # equal abscissae
    line = kind == 5  # a straight line: zero curvature
    g[1, line], g[2, line] = g[0, line] + 0.5, g[0, line] + 1.0
    g[:, kind == 6] = 0.0
    g[0, kind == 7] = np.inf
    both = kind == 8  # a double root of the parabola: zero discriminant
    g[0, both], g[1, both], g[2, both] = 1.0, 4.0, 9.0
    x[0, both], x[1, both], x[2, both] = 1.0, 0.0, -1.0
    return x, g


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_compiled_distances_equal_numpy(seed, sense):
    x, g = _samples(np.random.default_rng(seed), 400)
    if sense < 0:
        x = -x
    got = root_distances(x, g, sense)
    want = _watch(x, g, sense)._extrapolate_numpy()
    assert got.tobytes() == want.tobytes()


def test_watch_uses_the_same_distances_on_a_march():
    """A watch fed a march's samples predicts the same zeros by either route."""
    rng = np.random.default_rng(1)
    w = EventWatch(1.0, rng.uniform(0.5, 1.0, 50), 1.0, 1.0)
    idx = np.arange(50)
    for step in range(1, 8):
        w.record(idx, 1.0 + 0.01 * step, rng.uniform(0.1, 1.0, 50) / step)
        assert w.root_distance().tobytes() == w._extrapolate_numpy().tobytes()
