"""The compiled impedance kernel against its slow SciPy twin, and its pole handling."""

import math

import numpy as np
import pytest

from electrogrowth.bifurcation.critical import impedance_targets, wavenumber
from electrogrowth.incremental.impedance import (integrate_one, physical_impedance, impedance_scale,
                                     target_batch)
from electrogrowth.incremental.impedance_reference import impedance_reference, target_reference
from electrogrowth.model.params import TubeParameters
from electrogrowth.incremental.radial_table import build_table, stack_tables
from electrogrowth.basestate.tube import solve_base_state

CASES = [  # (Rbar_o, L, g, lambda_z, Vbar, m, n)
    (1.4, 1.0, 1.0, 1.0, 0.0, 0, 1),
    (1.4, 1.0, 1.2, 1.0, 0.4, 3, 7),
    (1.4, 1.0, 1.1, 1.3, 0.6, 10, 3),
    (2.0, 1.5, 1.3, 0.9, 0.3, 2, 20),
    (1.4, 1.0, 1.0, 0.8, 0.2, 6, 12),
]


def _state(ro, L, g, lz, V, material=None):
    kw = {} if material is None else {"material": material}
    return solve_base_state(TubeParameters(ro, L, g, lz, V, **kw))


def _kernel(state, m, n, rtol=1e-12):
    table = stack_tables([build_table(state)])
    k = wavenumber(state.params, n)
    return integrate_one(float(m), k, *(a[0] for a in table), rtol, 20000)


@pytest.mark.parametrize("case", CASES)
def test_kernel_equals_scipy_reference(case):
    *par, m, n = case
    state = _state(*par)
    f = impedance_targets(state, [(m, n)])[0]
    ref = target_reference(state, m, wavenumber(state.params, n), rtol=1e-12, atol=1e-14)
    assert abs(f - ref) <= 1e-8 * abs(ref)


def test_kernel_impedance_is_the_papers_impedance(gent_mat):
    state = _state(1.6, 1.0, 1.15, 1.1, 0.3, material=gent_mat)
    m, n = 4, 5
    f, zc, chart, status, _ = _kernel(state, m, n)
    assert status == 0 and chart == 0
    k = wavenumber(state.params, n)
    z = physical_impedance(zc, chart, impedance_scale(m, k, state.r_o))
    z_ref = impedance_reference(state, m, k, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(z, z_ref, rtol=1e-8, atol=1e-9 * np.abs(z_ref).max())
    np.testing.assert_allclose(z, z.T, atol=1e-12 * np.abs(z).max())


def test_table_reproduces_base_state():
    state = _state(2.0, 1.0, 1.3, 1.1, 0.5)
    coef, degree, fmap, geom = stack_tables([build_table(state)])
    R = np.linspace(1.0, 2.0, 13)
    x = (2 * R - 3.0) / 1.0
    from numpy.polynomial import chebyshev as C
    want = np.concatenate([state.moduli(R), state.pressure(R)[:, None]], axis=1)
    got = np.stack([C.chebval(x, coef[0, fmap[0, f], :degree[0, fmap[0, f]]])
                    for f in range(24)], axis=1)
    assert np.abs(got - want).max() <= 1e-13 * np.abs(want).max()


def test_batch_equals_one_by_one():
    states = [_state(1.4, 1.0, 1.0, 1.0, 0.4), _state(1.8, 1.0, 1.2, 0.9, 0.2)]
    coef, degree, fmap, geom = stack_tables([build_table(s) for s in states])
    modes = [(0, 1, 0), (3, 7, 1), (5, 2, 0), (1, 15, 1)]
    m = np.array([a for a, _, _ in modes], float)
    idx = np.array([t for _, _, t in modes])
    k = np.array([wavenumber(states[t].params, n) for _, n, t in modes])
    f = np.empty(4)
    status = np.empty(4, np.int64)
    steps = np.empty(4, np.int64)
    target_batch(m, k, idx, coef, degree, fmap, geom, 1e-12, 20000, f, status, steps)
    one = [impedance_targets(states[t], [(mm, n)])[0] for mm, n, t in modes]
    assert (status == 0).all()
    np.testing.assert_array_equal(f, one)


def test_target_converges_with_tolerance():
    state = _state(1.4, 1.0, 1.2, 1.0, 0.4)
    f = [impedance_targets(state, [(4, 9)], rtol=tol)[0] for tol in (1e-8, 1e-10, 1e-12)]
    assert abs(f[1] - f[2]) < abs(f[0] - f[2]) or f[0] == f[2]
    assert abs(f[1] - f[2]) <= 1e-7 * abs(f[2])


# Mode (0, 3) of a tube Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0: between g = 2.25 and 2.30
# the paper's impedance z(r_o) has a pole, det z jumps from negative to positive through
# infinity, while the tube does not bifurcate there (it did earlier, near g = 2.17).


def test_pole_of_impedance_is_not_a_root():
    dets, fs = [], []
    for g in (2.25, 2.30):
        state = _state(1.4, 1.0, g, 1.0, 0.0)
        f, zc, chart, status, _ = _kernel(state, 0, 3)
        k = wavenumber(state.params, 3)
        dets.append(np.linalg.det(physical_impedance(zc, chart, impedance_scale(0, k, state.r_o))))
        fs.append(f)
    assert dets[0] < 0 < dets[1]  # a naive sign-change search would report a root here
    assert fs[0] < 0 and fs[1] < 0  # the pole-free target does not change sign
    # ... and between them the impedance is unbounded: the SciPy twin cannot pass.
    g_pole = _pole_location()
    assert 2.25 < g_pole < 2.30
    near = _state(1.4, 1.0, g_pole, 1.0, 0.0)
    f, zc, chart, status, _ = _kernel(near, 0, 3)
    assert status == 0 and chart != 0 and np.isfinite(f) and f < 0


def _pole_location():
    """Where det M1(r_o) = 0, i.e. 1/det z changes sign, by bisection on the kernel."""
    def inv_det(g):
        state = _state(1.4, 1.0, g, 1.0, 0.0)
        f, zc, chart, status, _ = _kernel(state, 0, 3)
        k = wavenumber(state.params, 3)
        z = physical_impedance(zc, chart, impedance_scale(0, k, state.r_o))
        return 1.0 / np.linalg.det(z)
    a, b = 2.25, 2.30
    for _ in range(30):
        c = 0.5 * (a + b)
        if inv_det(a) * inv_det(c) <= 0:
            b = c
        else:
            a = c
    return 0.5 * (a + b)


def test_kernel_agrees_before_the_pole():
    state = _state(1.4, 1.0, 2.25, 1.0, 0.0)
    f = impedance_targets(state, [(0, 3)])[0]
    ref = target_reference(state, 0, 3 * math.pi, rtol=1e-12, atol=1e-14)
    assert abs(f - ref) <= 1e-8 * abs(ref)
