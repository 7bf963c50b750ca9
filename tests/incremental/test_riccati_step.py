"""One step of the impedance kernel (incremental/riccati_step.py).

A step evaluates the base state at its eleven stage radii together (their Clenshaw
recurrences side by side) and keeps the last, R + h, for the next step's first slope.
Both must give the bits of the plain route, one radius at a time through ``_rhs``: the
same arithmetic in the same order, only scheduled differently.
"""

from __future__ import annotations

import numpy as np
import pytest

from electrogrowth import Tube, solve_base_state
from electrogrowth.incremental.charts import chart_setup
from electrogrowth.incremental.dop853 import N_STAGES, A, B, C
from electrogrowth.incremental.impedance import ALL_PAIRS
from electrogrowth.incremental.radial_table import build_table
from electrogrowth.incremental.riccati_step import _new_work, _rhs, _step, next_slope
from electrogrowth.model.layers import Layer


def _plain_step(R, h, z, m, k, table, seg, work, K, rate0):
    """The step stage by stage through ``_rhs``, the sums in the kernel's order; and the
    step's increment of log|det U~| from the stages' rates, by the weights B."""
    K = K.copy()
    rates = [rate0]
    for st in range(1, N_STAGES):
        acc = np.zeros((4, 4))
        for q in range(st):
            acc = acc + A[st, q] * K[q]
        rates.append(_rhs(R + C[st] * h, z + h * acc, m, k, table, seg, work, K[st]))
    acc = np.zeros((4, 4))
    for q in range(N_STAGES):
        acc = acc + B[q] * K[q]
    znew = z + h * acc
    _rhs(R + h, znew, m, k, table, seg, work, K[N_STAGES])
    return znew, K, h * float(np.dot(B, rates))


def _tables():
    paper = Tube.uniform(1.4, 1.0, growth=1.2, voltage=0.4)
    film = Tube(
        (Layer(1.02, growth=(1.0, 1.03, 1.0), shear_modulus=50.0), Layer(2.0, growth=1.1)),
        length=1.0, stretch=1.05, voltage=0.1, inner_pressure=0.02,
    )  # fmt: skip
    return [build_table(solve_base_state(t)) for t in (paper, film)]


@pytest.mark.parametrize("chart", [0, 0b0101, 0b1111])
def test_a_step_is_the_plain_route_to_the_bit(chart):
    rng = np.random.default_rng(chart)
    for table in _tables():
        work = _new_work(table)
        for seg in range(table.coef.shape[0]):
            a, b = table.bounds[seg], table.bounds[seg + 1]
            for m, k in [(0.0, 3.1), (2.0, 0.0), (7.0, 12.5), (300.0, 40.0)]:
                chart_setup(chart, max(1.0, np.hypot(m, k * b)), ALL_PAIRS, work.perm, work.mult)
                z = rng.standard_normal((4, 4))
                z = z + z.T
                R, h = a + 0.1 * (b - a), 0.37 * (b - a)
                K = np.empty((N_STAGES + 1, 4, 4))
                rate0 = _rhs(R, z, m, k, table, seg, work, K[0])
                want_z, want_K, want_grow = _plain_step(R, h, z, m, k, table, seg, work, K, rate0)
                znew = np.empty((4, 4))
                grow = _step(R, h, z, m, k, table, seg, work, K, np.empty((4, 4)), znew, rate0)
                np.testing.assert_array_equal(znew, want_z)
                np.testing.assert_array_equal(K, want_K)
                # the same stage rates, summed in another order
                tol = 1e-13 * abs(h * rate0)
                np.testing.assert_allclose(grow, want_grow, rtol=1e-13, atol=tol)
                # the next step's first slope (and rate) from the blocks the last stage left
                got, want = np.empty((4, 4)), np.empty((4, 4))
                got_rate = next_slope(znew, work, got)
                want_rate = _rhs(R + h, znew, m, k, table, seg, work, want)
                np.testing.assert_array_equal(got, want)
                np.testing.assert_array_equal(got_rate, want_rate)
