"""The compiled impedance kernel: against its slow SciPy twin, its pole handling, its DOP853
tableau (SciPy's) and its fitted order of convergence."""

import math

import numpy as np
import pytest

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental import dop853
from electrogrowth.incremental.charts import physical_impedance
from electrogrowth.incremental.impedance import (
    ALL_PAIRS,
    impedance_scale,
    integrate_fixed,
    integrate_one,
    target_batch,
    target_serial,
)
from electrogrowth.incremental.impedance_reference import impedance_reference, target_reference
from electrogrowth.incremental.radial_table import build_table, stack_tables
from electrogrowth.incremental.targets import impedance_targets, mode_pairs, wavenumber
from electrogrowth.model.layers import Tube

CASES = [  # (Rbar_o, L, g, lambda_z, Vbar, m, n)
    (1.4, 1.0, 1.0, 1.0, 0.0, 0, 1),
    (1.4, 1.0, 1.2, 1.0, 0.4, 3, 7),
    (1.4, 1.0, 1.1, 1.3, 0.6, 10, 3),
    (2.0, 1.5, 1.3, 0.9, 0.3, 2, 20),
    (1.4, 1.0, 1.0, 0.8, 0.2, 6, 12),
]


def _state(ro, L, g, lz, V, material=None):
    kw = {} if material is None else {"material": material}
    return solve_base_state(Tube.uniform(ro, L, g, lz, V, **kw))


def _kernel(state, m, n, rtol=1e-12):
    k = wavenumber(state.tube, n)
    return integrate_one(float(m), k, ALL_PAIRS, build_table(state), rtol, 20000)


@pytest.mark.parametrize("case", CASES)
def test_kernel_equals_scipy_reference(case):
    *par, m, n = case
    state = _state(*par)
    f = impedance_targets(state, [(m, n)])[0]
    pairs = int(mode_pairs(np.array([[m, n]], float))[0])  # m = 0: torsion excluded
    ref = target_reference(
        state, m, wavenumber(state.tube, n), pairs=pairs, rtol=1e-12, atol=1e-14
    )
    assert abs(f - ref) <= 1e-8 * abs(ref)


def test_kernel_impedance_is_the_papers_impedance(gent_mat):
    state = _state(1.6, 1.0, 1.15, 1.1, 0.3, material=gent_mat)
    m, n = 4, 5
    f, zc, chart, status, _ = _kernel(state, m, n)
    assert status == 0 and chart == 0
    k = wavenumber(state.tube, n)
    z = physical_impedance(zc, chart, impedance_scale(m, k, state.r_o))
    z_ref = impedance_reference(state, m, k, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(z, z_ref, rtol=1e-8, atol=1e-9 * np.abs(z_ref).max())
    np.testing.assert_allclose(z, z.T, atol=1e-12 * np.abs(z).max())


def test_table_reproduces_base_state():
    state = _state(2.0, 1.0, 1.3, 1.1, 0.5)
    table = build_table(state)
    R = np.linspace(1.0, 2.0, 13)
    x = (2 * R - 3.0) / 1.0
    from numpy.polynomial import chebyshev as C

    want = np.concatenate([state.moduli(R), state.pressure(R)[:, None]], axis=1)
    got = np.stack([C.chebval(x, table.coef[0, table.fmap[0, f]]) for f in range(26)], axis=1)
    assert np.abs(got[:, :24] - want).max() <= 1e-13 * np.abs(want).max()
    r = state.radius(R)  # r^2 = r_i^2 + (g^3 / lambda_z)(R^2 - 1), w = (dr/dR) / r
    # chopped at 8 tol times each function's largest value (tol = 1e-15)
    np.testing.assert_allclose(got[:, 24], r, rtol=0, atol=16e-15 * r.max())
    w = 1.3**3 / 1.1 * R / r**2
    np.testing.assert_allclose(got[:, 25], w, rtol=0, atol=16e-15 * w.max())


def test_batch_equals_one_by_one():
    states = [_state(1.4, 1.0, 1.0, 1.0, 0.4), _state(1.8, 1.0, 1.2, 0.9, 0.2)]
    tables = stack_tables([build_table(s) for s in states])
    assert tables.coef.shape[0] == 2 and tables.n_funcs.dtype == np.int64
    modes = [(0, 1, 0), (3, 7, 1), (5, 2, 0), (1, 15, 1)]
    m = np.array([a for a, _, _ in modes], float)
    idx = np.array([t for _, _, t in modes])
    k = np.array([wavenumber(states[t].tube, n) for _, n, t in modes])
    keep = mode_pairs(np.array([(mm, n) for mm, n, _ in modes], float))
    f, status, steps = target_batch(m, k, keep, idx, tables, 1e-12, 20000)
    one = [impedance_targets(states[t], [(mm, n)])[0] for mm, n, t in modes]
    assert (status == 0).all() and (steps > 0).all()
    np.testing.assert_array_equal(f, one)
    serial = target_serial(m, k, keep, idx, tables, 1e-12, 20000)
    for a, b in zip(serial, (f, status, steps)):
        np.testing.assert_array_equal(a, b)


def test_dop853_tableau_is_scipys():
    """Our DOP853 coefficients are SciPy's, bit for bit (the package never imports these)."""
    from scipy.integrate._ivp import dop853_coefficients as ref

    ns = ref.N_STAGES
    assert dop853.N_STAGES == ns
    for ours, theirs in [
        (dop853.A, ref.A[:ns, :ns]),
        (dop853.B, ref.B),
        (dop853.C, ref.C[:ns]),
        (dop853.E3, ref.E3),
        (dop853.E5, ref.E5),
    ]:
        assert ours.shape == theirs.shape
        assert ours.tobytes() == theirs.tobytes()


def test_riccati_integration_is_of_order_8():
    """Fixed steps h = (Rbar_o - 1) / N: the error of z~(Rbar_o) falls like h^p, p = 8.

    Mode (0, 1) stays in chart J = {} and is smooth on the scale of the wall, so the window
    N = 10..24 has errors from 2e-10 down to 2e-13, all far above round-off (~1e-15). The
    next term of the error, O(h^9), lowers the slope fitted there to about 7.7 (the local
    slopes climb from 7.6 to 7.8 towards 8), hence the band 7.4 <= p <= 8.5. A wrong
    tableau falls far outside: the embedded 5th- and 3rd-order weights as B fit p = 5.0 and
    3.0, and one entry of A off by 1e-4 relative fits p = 1.0. The converged impedance is
    also the SciPy twin's.
    """
    state = _state(1.4, 1.0, 1.2, 1.0, 0.4)
    table = build_table(state)
    m, k = 0.0, wavenumber(state.tube, 1)
    exact = integrate_fixed(m, k, ALL_PAIRS, table, 512)
    N = np.array([10, 12, 14, 16, 20, 24])
    err = [np.linalg.norm(integrate_fixed(m, k, ALL_PAIRS, table, int(n)) - exact) for n in N]
    p = -np.polyfit(np.log(N), np.log(err), 1)[0]
    assert 7.4 <= p <= 8.5, p
    z = physical_impedance(exact, 0, impedance_scale(m, k, state.r_o))
    z_ref = impedance_reference(state, m, k, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(z, z_ref, rtol=1e-9, atol=1e-10 * np.abs(z_ref).max())


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
        k = wavenumber(state.tube, 3)
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
        k = wavenumber(state.tube, 3)
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
    f = impedance_targets(state, [(0, 3)])[0]  # axisymmetric: the torsion pair left out
    ref = target_reference(state, 0, 3 * math.pi, pairs=0b1101, rtol=1e-12, atol=1e-14)
    assert abs(f - ref) <= 1e-8 * abs(ref)
