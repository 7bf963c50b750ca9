"""EventWatch's compiled arithmetic (continuation/watch_kernel.py) is its NumPy route to the
last bit: the zero distances on random samples with every special case of the formulas
(fresh functions with NaN samples, equal abscissae, straight lines with zero curvature,
receding functions, a zero discriminant, infinities), and which functions are due, where the
next falls due, how far a step may go and a sample's bookkeeping on random watches (dead
functions, NaN moves, infinite distances), both senses."""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth.continuation import watch_kernel
from electrogrowth.continuation.predict import EventWatch
from electrogrowth.continuation.watch_kernel import root_distances


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


def _random_watch(rng, n, sense):
    """A watch part way along a march: samples, some functions dead, moves with NaN and inf,
    due points on both sides of x = 1."""
    x, g = _samples(rng, n)
    w = _watch(sense * x, g, sense)
    w.alive = rng.uniform(size=n) < 0.7
    w.moved = np.where(rng.uniform(size=n) < 0.2, np.inf, rng.uniform(0, 0.05, n))
    w.moved[rng.uniform(size=n) < 0.1] = np.nan
    w.due = sense * (1.0 + rng.uniform(-0.2, 0.2, n))
    return w


@pytest.mark.parametrize("seed", range(30))
@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_watch_questions_equal_numpy(seed, sense):
    rng = np.random.default_rng(seed)
    n = int(rng.choice([1, 2, 5, 300]))
    w = _random_watch(rng, n, sense)
    if seed % 5 == 0:
        w.alive[:] = False  # nothing live: reach inf, nothing due
    for x in sense * np.array([0.9, 1.0, 1.05, 1.3]):
        assert w.needs(x).tolist() == w.needs_numpy(x).tolist()
        assert w.next_due(x) == w.next_due_numpy(x)
    for safety, finest in ((0.7, 1e-4), (0.5, 0.1), (0.9, 0.0)):
        got, want = w.reach(safety, finest), w.reach_numpy(safety, finest)
        assert got == want or (np.isnan(got) and np.isnan(want))


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_record_equals_numpy(seed, sense, monkeypatch):
    rng = np.random.default_rng(100 + seed)
    n = int(rng.choice([1, 3, 200]))
    compiled = _random_watch(rng, n, sense)
    twin = _watch(compiled.x.copy(), compiled.g.copy(), sense)
    for name in ("alive", "moved", "due"):
        setattr(twin, name, getattr(compiled, name).copy())
    steps = []
    for k in range(4):
        idx = np.sort(rng.choice(n, size=max(1, n // 2), replace=False))
        steps.append((idx, sense * (1.1 + 0.01 * k), rng.normal(size=idx.size)))
    for idx, x, g in steps:
        compiled.record(idx, x, g)
    monkeypatch.setattr("electrogrowth.continuation.predict._compiled", lambda: None)
    for idx, x, g in steps:
        twin.record(idx, x, g)
    for name in ("x", "g", "moved", "due"):
        assert getattr(compiled, name).tobytes() == getattr(twin, name).tobytes(), name


def test_the_kernel_is_used_once_numba_is_loaded():
    from electrogrowth.continuation import predict

    assert predict._compiled() is watch_kernel


def test_record_takes_a_mask_and_one_value_for_all(monkeypatch):
    """EventWatch.record, a public method, takes what NumPy indexing takes: a boolean mask
    of the functions and one value for all of them, compiled as in NumPy, to the last bit."""
    rng = np.random.default_rng(7)
    compiled = _random_watch(rng, 5, 1.0)
    twin = _watch(compiled.x.copy(), compiled.g.copy(), 1.0)
    for name in ("alive", "moved", "due"):
        setattr(twin, name, getattr(compiled, name).copy())
    mask = np.array([True, False, True, True, False])
    compiled.record(mask, 1.2, 0.25)
    monkeypatch.setattr("electrogrowth.continuation.predict._compiled", lambda: None)
    twin.record(mask, 1.2, 0.25)
    for name in ("x", "g", "moved", "due"):
        assert getattr(compiled, name).tobytes() == getattr(twin, name).tobytes(), name
    assert compiled.x[0].tolist() == [1.2, compiled.x[0, 1], 1.2, 1.2, compiled.x[0, 4]]
