"""The compiled root of (NH-6) (basestate/nh_root_kernel.py) is brent.brentq's on
neo_hookean.nh_square to the last bit, on random tubes and voltage ratios up to the asymptote
(where brentq falls back to bisection), and the base states built on it are unchanged."""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth.basestate import neo_hookean
from electrogrowth.basestate.nh_root_kernel import nh_root
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.brent import brentq
from electrogrowth.model.layers import Tube


def _python_root(k, target):
    f = lambda y: neo_hookean.nh_square(y, k) - target  # noqa: E731
    return brentq(f, 0.0, 1.0, xtol=1e-300, rtol=neo_hookean._RTOL_MIN, maxiter=500)


@pytest.mark.parametrize("seed", range(20))
def test_compiled_root_is_brentq(seed):
    rng = np.random.default_rng(seed)
    for _ in range(50):
        k = rng.uniform(1.01, 100.0) ** 2 - 1.0
        ratio = rng.choice([rng.uniform(0.0, 1.0), 1.0 - 10.0 ** rng.uniform(-15, -1), 1e-9])
        y, ok = nh_root(k, ratio * ratio, 1e-300, neo_hookean._RTOL_MIN, 500)
        assert ok and y == _python_root(k, ratio * ratio)


def test_compiled_root_defers_where_brentq_fails():
    """No sign change (a target above 1) and a NaN: not ok, so nh_lambda_i's brentq raises."""
    assert not nh_root(3.0, 1.5, 1e-300, neo_hookean._RTOL_MIN, 500)[1]
    assert not nh_root(math.nan, 0.25, 1e-300, neo_hookean._RTOL_MIN, 500)[1]
    with pytest.raises(ValueError, match="different signs"):
        neo_hookean.nh_lambda_i(1.4, 1.0, 1.0, 1.5)


def test_states_equal_with_and_without_the_compiled_root(monkeypatch):
    rng = np.random.default_rng(4)
    tubes = [
        Tube.uniform(outer_radius=rng.uniform(1.05, 3.0), growth=rng.uniform(1.0, 1.5),
                     stretch=rng.uniform(0.8, 1.3), voltage=rng.uniform(0.0, 0.5))
        for _ in range(30)
    ]  # fmt: skip
    compiled = [solve_base_state(t) for t in tubes]
    monkeypatch.setattr(neo_hookean, "_compiled_root", lambda: None)
    for tube, state in zip(tubes, compiled):
        twin = solve_base_state(tube)
        assert (state.lambda_i, state.charge, state.axial_force) == (
            twin.lambda_i, twin.charge, twin.axial_force,
        )  # fmt: skip
