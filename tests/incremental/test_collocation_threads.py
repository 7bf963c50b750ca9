"""The collocation's dense algebra runs with BLAS on one thread (dense_algebra.one_blas_thread):
OpenBLAS's threads, spinning against other processes on a busy machine, made one evaluation
15-50x slower; the value must not depend on it."""

import contextlib

import numpy as np
import pytest
import scipy.linalg
from threadpoolctl import threadpool_info

from electrogrowth import Tube
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental import collocation
from electrogrowth.incremental.collocation import collocation_target
from electrogrowth.incremental.dense_algebra import one_blas_thread


def _blas_threads():
    return [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]


def test_one_thread_inside_and_restored_after():
    before = _blas_threads()
    with one_blas_thread() as linalg:
        assert linalg is scipy.linalg
        inside = _blas_threads()
    assert inside and set(inside) == {1}  # numpy's and scipy's OpenBLAS both
    assert _blas_threads() == before


@pytest.mark.parametrize(("m", "n"), [(0, 1), (4, 2), (12, 0)])
def test_value_does_not_depend_on_the_threads(monkeypatch, m, n):
    state = solve_base_state(Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4))
    one = collocation_target(state, m, n, nodes=40)

    @contextlib.contextmanager
    def as_they_are():
        yield scipy.linalg

    monkeypatch.setattr(collocation, "one_blas_thread", as_they_are)
    assert collocation_target(state, m, n, nodes=40) == pytest.approx(one, rel=1e-12, abs=1e-15)
    assert np.isfinite(one) and one != 0
