"""The compiled impedance kernel (incremental/impedance.py) for every kind of tube: against
independent routes (its slow SciPy twin for the paper's tube, collocation and orthonormalised
shooting through layers and pressure), its pole handling, its DOP853 tableau (SciPy's) and its
fitted order of convergence; and the critical values it gives, against exact identities, the
one-layer tube and classical limits (docs/derivation-layered-modes.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from electrogrowth import critical_value, mode_shape
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.errors import ParameterError
from electrogrowth.incremental import dop853
from electrogrowth.incremental.charts import physical_impedance
from electrogrowth.incremental.collocation_impedance import collocation_impedance
from electrogrowth.incremental.impedance import (
    ALL_PAIRS,
    impedance_scale,
    integrate_fixed,
    integrate_one,
    target_batch,
    target_serial,
)
from electrogrowth.incremental.impedance_reference import (
    impedance_reference,
    kept_pairs,
    shooting_target,
    target_reference,
)
from electrogrowth.incremental.radial_table import build_table, stack_tables
from electrogrowth.incremental.targets import U_Z, impedance_targets, mode_pairs, wavenumber
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import mooney_rivlin
from tests.tubes import TUBES

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


LOADS = ("length", "stretch", "voltage", "inner_pressure", "outer_pressure")


def bilayer(**loads) -> Tube:
    """A stiff, hoop-growing inner layer on a softer substrate, with voltage and pressures."""
    inner = Layer(1.15, shear_modulus=5.0, permittivity=2.0, growth=(1.1, 1.3, 1.0))
    outer = Layer(1.8, material=mooney_rivlin(0.3), growth=1.05)
    kw = dict(length=3.0, stretch=1.05, voltage=0.2, inner_pressure=0.15, outer_pressure=0.05)
    kw.update(loads)
    return Tube((inner, outer), **kw)


# -- the kernel against independent routes ------------------------------------------------


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
    f, zc, chart, status, *_ = _kernel(state, m, n)
    assert status == 0 and chart == 0
    k = wavenumber(state.tube, n)
    z = physical_impedance(zc, chart, impedance_scale(m, k, state.r_o))
    z_ref = impedance_reference(state, m, k, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(z, z_ref, rtol=1e-8, atol=1e-9 * np.abs(z_ref).max())
    np.testing.assert_allclose(z, z.T, atol=1e-12 * np.abs(z).max())


@pytest.mark.parametrize(("m", "n"), [(2, 1), (5, 3), (0, 2), (7, 0)])
@pytest.mark.parametrize("tube", [*TUBES.values(), bilayer()], ids=[*TUBES, "pressurised-bilayer"])
def test_kernel_impedance_equals_collocation(tube, m, n):
    """The conditional impedance z(r_o) of every kind of tube (and of a pressurised
    Mooney-Rivlin / neo-Hookean bilayer with anisotropic growth, permittivity contrast and
    voltage): the Riccati kernel (through interfaces, from the pressure's z_P on the inner
    face) against the multi-domain collocation (interface rows, pressure rows), two
    independent discretisations; and z is symmetric (the Lagrangian Grassmannian)."""
    state = solve_base_state(tube)
    k = n * math.pi / state.current_length
    keep = int(mode_pairs(np.array([[m, n]], float))[0])
    f, zc, chart, status, *_ = integrate_one(float(m), k, keep, build_table(state), 1e-13, 20000)
    assert status == 0
    z = physical_impedance(zc, chart, impedance_scale(m, k, state.r_o))
    np.testing.assert_allclose(z, z.T, atol=1e-12 * np.abs(z).max())
    kept = kept_pairs(keep)
    # Collocation has converged by 24 nodes; beyond that its rounding grows like the
    # conditioning of the Chebyshev operators (mode (2, 1) of the bilayer: 6.8e-11 of the
    # largest entry at 24 nodes, 3.6e-10 at 32, 4.7e-9 at 48 with numpy 2.4), so compare
    # at 32.
    col = collocation_impedance(state, m, n, nodes=32, pairs=keep)
    assert np.abs(z[np.ix_(kept, kept)] - col).max() <= 1e-9 * np.abs(col).max()


@pytest.mark.parametrize(("m", "n"), [(2, 1), (5, 3), (0, 2), (7, 0)])
def test_kernel_target_equals_orthonormalised_shooting(m, n):
    """The kernel's pole-free target through layers and pressure equals the slow twin that
    shoots the linear Stroh system with QR re-orthonormalisation (no impedance, no charts):
    the same number, not only its sign."""
    state = solve_base_state(bilayer())
    k = n * math.pi / state.current_length
    keep = int(mode_pairs(np.array([[m, n]], float))[0])
    f = integrate_one(float(m), k, keep, build_table(state), 1e-13, 20000)[0]
    assert f == pytest.approx(shooting_target(state, m, k, pairs=keep), rel=1e-9)


@pytest.mark.parametrize(
    "tube",
    [*TUBES.values(), bilayer(inner_pressure=0.4, outer_pressure=-0.1)],
    ids=[*TUBES, "pressurised-bilayer"],
)
def test_rigid_translation_is_a_zero_mode(tube):
    """u = e_x (m = 1, k = 0, U_th = -U_r) has L = 0, so it satisfies the follower-pressure
    condition Sigma_ri = P du_r/dx_i exactly: its target vanishes for every tube, at any
    pressure. A wrong pressure condition (sign, or a missing m term) makes it non-zero."""
    state = solve_base_state(tube)
    f = integrate_one(1.0, 0.0, ALL_PAIRS & ~U_Z, build_table(state), 1e-13, 20000)[0]
    g = integrate_one(2.0, 0.0, ALL_PAIRS & ~U_Z, build_table(state), 1e-13, 20000)[0]
    assert abs(f) <= 1e-11 and abs(g) > 1e-3


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


# -- poles --------------------------------------------------------------------------------


# Mode (0, 3) of a tube Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0: between g = 2.25 and 2.30
# the paper's impedance z(r_o) has a pole, det z jumps from negative to positive through
# infinity, while the tube does not bifurcate there (it did earlier, near g = 2.17).


def test_pole_of_impedance_is_not_a_root():
    dets, fs = [], []
    for g in (2.25, 2.30):
        state = _state(1.4, 1.0, g, 1.0, 0.0)
        f, zc, chart, status, *_ = _kernel(state, 0, 3)
        k = wavenumber(state.tube, 3)
        dets.append(np.linalg.det(physical_impedance(zc, chart, impedance_scale(0, k, state.r_o))))
        fs.append(f)
    assert dets[0] < 0 < dets[1]  # a naive sign-change search would report a root here
    assert fs[0] < 0 and fs[1] < 0  # the pole-free target does not change sign
    # ... and between them the impedance is unbounded: the SciPy twin cannot pass.
    g_pole = _pole_location()
    assert 2.25 < g_pole < 2.30
    near = _state(1.4, 1.0, g_pole, 1.0, 0.0)
    f, zc, chart, status, *_ = _kernel(near, 0, 3)
    assert status == 0 and chart != 0 and np.isfinite(f) and f < 0


def _pole_location():
    """Where det M1(r_o) = 0, i.e. 1/det z changes sign, by bisection on the kernel."""

    def inv_det(g):
        state = _state(1.4, 1.0, g, 1.0, 0.0)
        f, zc, chart, status, *_ = _kernel(state, 0, 3)
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


@pytest.mark.slow
def test_two_interface_modes_cross_close_together():
    """A stiff grown layer between two soft ones: its two interfaces lose stability near
    g = 2.33 and 2.37 (half-space limit), and the mode (0, 16) crosses twice in between, so
    its target is negative only in a narrow window; kernel and shooting agree on the values
    (and the sign) on both sides of each crossing."""
    tube = Tube((Layer(1.5, shear_modulus=0.2), Layer(2.0), Layer(2.5, shear_modulus=0.2)))
    signs = []
    for g in (2.325, 2.35, 2.375):
        state = solve_base_state(tube.at("growth[2]", g))
        k = 16 * math.pi / state.current_length
        keep = ALL_PAIRS & ~2  # axisymmetric: no torsion
        f = integrate_one(0.0, k, keep, build_table(state), 1e-13, 20000)[0]
        assert f == pytest.approx(shooting_target(state, 0, k, pairs=keep), rel=1e-9)
        signs.append(np.sign(f))
    assert signs == [1.0, -1.0, 1.0]


# -- critical values of layered, pressurised tubes: identities and limits --------------------


@pytest.mark.parametrize(
    ("solve_for", "m", "n", "side"),
    [("growth", 3, 2, None), ("voltage", 3, 2, None), ("stretch", 2, 1, "compression")],
)
def test_identical_layers_equal_one_layer(solve_for, m, n, side):
    params = Tube.uniform(outer_radius=1.6, length=2.0, growth=1.1, stretch=1.0, voltage=0.3)
    layers = (Layer(1.25, growth=1.1), Layer(1.6, growth=1.1))
    tube = Tube(layers, length=2.0, stretch=1.0, voltage=0.3)
    if solve_for == "growth":  # one Tube layer grows like the homogeneous tube
        tube = Tube((Layer(1.6, growth=1.1),), length=2.0, stretch=1.0, voltage=0.3)
    one = critical_value(params, m, n, solve_for, side=side).value
    two = critical_value(tube, m, n, solve_for, side=side).value
    assert two == pytest.approx(one, rel=1e-10)


def test_uniform_isotropic_growth_is_a_rescaling():
    """Every layer grown by g at lambda_z is the ungrown tube at lambda_z / g scaled by g:
    the critical Vbar scales by g (V with the lengths, Vbar per reference thickness), the
    pressures are unchanged (docs/derivation-layered-modes.md)."""
    g = 1.25

    def tube(growth, stretch):
        layers = (Layer(1.2, shear_modulus=4.0, growth=growth), Layer(2.0, growth=growth))
        return Tube(layers, length=2.0, stretch=stretch, inner_pressure=0.1)

    plain = critical_value(tube(1.0, 1.1), 4, 1, "voltage").value
    grown = critical_value(tube(g, 1.1 * g), 4, 1, "voltage").value
    assert grown == pytest.approx(g * plain, rel=1e-10)


def test_axial_growth_is_an_axial_prestretch():
    """(g_r, g_th, g_z; lambda_z, L) == (g_r, g_th, 1; lambda_z / g_z, g_z L) (part 1's
    identity) holds for critical values too."""
    gz = 1.3

    def tube(g3, stretch, length):
        inner = Layer(1.2, shear_modulus=3.0, growth=(1.1, 1.2, g3))
        return Tube((inner, Layer(1.7, growth=(1.0, 1.0, g3))), length=length, stretch=stretch)

    a = critical_value(tube(gz, 1.2, 2.0), 5, 2, "voltage").value
    b = critical_value(tube(1.0, 1.2 / gz, 2.0 * gz), 5, 2, "voltage").value
    assert a == pytest.approx(b, rel=1e-10)


def test_critical_values_of_both_methods_agree_for_a_pressurised_bilayer():
    """Hoop growth of a soft inner layer inside a stiff Mooney-Rivlin one folds it (with a
    stiff inner layer on a soft substrate the tube inflates instead, and nothing folds)."""
    inner = Layer(1.15, permittivity=2.0, growth=(1.1, 1.3, 1.0))
    outer = Layer(1.8, material=mooney_rivlin(0.3), shear_modulus=5.0, growth=1.05)
    tube = bilayer().at("growth[1]", 1.0)
    tube = Tube((inner, outer), **{k: getattr(tube, k) for k in LOADS})
    a = critical_value(tube, 12, 1, "growth[1].theta")
    b = critical_value(tube, 12, 1, "growth[1].theta", method="collocation")
    assert a.value == pytest.approx(b.value, rel=1e-9)
    assert a.params.layers[0].growth[1] == a.value  # only g_theta of layer 1 was varied
    assert a.params.layers[0].growth[::2] == (1.1, 1.0)


def test_superposed_pressure_changes_no_critical_value():
    """Adding c to both face pressures of an incompressible tube shifts p by c and Sigma by
    c L (divergence free), which the follower condition absorbs: an exact identity."""
    a = critical_value(bilayer(), 3, 2, "voltage").value
    b = critical_value(bilayer(inner_pressure=0.65, outer_pressure=0.55), 3, 2, "voltage").value
    assert b == pytest.approx(a, rel=1e-10)


def test_euler_buckling_of_a_slender_tube_under_axial_force():
    """A slender free-ended bilayer under compressive end force buckles in (1, 1) at the
    Euler load pi^2 E I / l^2 (E = 3 mu_k, current I and length l) up to O((r / l)^2): the
    ratio's deficit falls four times per doubling of L, and its Richardson extrapolation
    is 1 (measured 0.999995)."""

    def ratio(length):
        tube = Tube((Layer(1.2, shear_modulus=2.0), Layer(1.5)), length=length, axial_force=0.0)
        cp = critical_value(tube, 1, 1, "force")
        st = solve_base_state(cp.params)
        r = st.radii
        EI = 3.0 * math.pi / 4 * (2.0 * (r[1] ** 4 - r[0] ** 4) + (r[2] ** 4 - r[1] ** 4))
        assert cp.kind == "bifurcation" and cp.value < 0
        return -cp.value / (math.pi**2 * EI / st.current_length**2)

    a, b = ratio(80.0), ratio(160.0)
    assert (1 - a) / (1 - b) == pytest.approx(4.0, rel=0.02)
    assert (4 * b - a) / 3 == pytest.approx(1.0, abs=1e-4)


def test_ring_buckling_under_external_pressure():
    """A thin tube (t / R = 0.04) collapses in the prismatic mode (2, 0) when the pressure
    difference reaches the ring's 3 D / R^3 = mu (t / R)^3 (plane strain, incompressible:
    D = mu t^3 / 3), up to O(t / R)."""
    tube = Tube((Layer(1.04),), length=1.0)
    cp = critical_value(tube, 2, 0, "pressure", side="compression")
    t_over_R = 0.04 / 1.02
    assert cp.value < 0
    assert -cp.value == pytest.approx(t_over_R**3, rel=0.08)


def test_kernel_target_is_identical_for_identical_layers():
    """Splitting a homogeneous wall into two identical layers changes the table, not the
    problem: targets agree to the integration tolerance."""
    one = solve_base_state(Tube((Layer(1.6, growth=1.2),), length=2.0, stretch=1.1))
    two = solve_base_state(
        Tube((Layer(1.25, growth=1.2), Layer(1.6, growth=1.2)), length=2.0, stretch=1.1)
    )
    modes = np.array([[2, 1], [5, 3], [0, 2], [8, 0], [3, 10]], float)
    np.testing.assert_allclose(
        impedance_targets(two, modes), impedance_targets(one, modes), rtol=1e-10
    )


@pytest.mark.parametrize(
    ("solve_for", "message"),
    [
        ("growth", "needs a layer"),
        ("growth[3]", "does not exist"),
        ("growth[1].q", "unknown"),
        ("force", "not a control of this tube"),
    ],
)
def test_controls_a_tube_cannot_vary_are_refused(solve_for, message):
    with pytest.raises(ParameterError, match=message):
        critical_value(bilayer(), 2, 1, solve_for)


@pytest.mark.parametrize(
    "tube, mode, solve_for",
    [
        (Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0))), (4, 1), "growth[1]"),
        (Tube((Layer(1.1, shear_modulus=10.0), Layer(2.0))), (0, 2), "growth[1]"),
        (Tube((Layer(1.3),), inner_pressure=0.1), (3, 2), "growth"),
    ],
    ids=["bilayer-wrinkle", "bilayer-axisymmetric", "pressurised"],
)
def test_impedance_mode_shape_through_layers_is_the_collocation_limit(tube, mode, solve_for):
    """The impedance route (Riccati layer by layer, z continuous at interfaces, the faces'
    follower-pressure impedances) and the multi-domain collocation route are independent:
    the shapes agree to the collocation's own accuracy, which improves spectrally with its
    nodes (to ~1e-8 by 20 nodes, after which its rounding grows), and the impedance shape
    meets the face conditions S = z_P U to 1e-10."""
    crit = critical_value(tube, *mode, solve_for)
    imp = mode_shape(crit, method="impedance", points=41)
    assert imp.route == "impedance" and imp.note == ""
    assert imp.boundary_residual < 1e-10
    diffs = [
        np.abs(mode_shape(crit, method="collocation", points=41, nodes=nodes).eta - imp.eta).max()
        for nodes in (12, 20)
    ]
    assert diffs[1] < 1e-6 and diffs[1] < 1e-2 * diffs[0]
