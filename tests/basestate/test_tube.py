"""The axisymmetric base state (basestate/tube.py) against closed forms, limits and twins.

The neo-Hookean closed forms below are written here, independently of the package, from
docs/derivation-base-state.md; the "slow twins" integrate with scipy.integrate.quad in the
current radius r instead of Gauss-Legendre / Chebyshev in R. The package's own neo-Hookean
closed-form route (the fast path) is checked against its generic quadrature route, reached by
writing the same energy in a form the package does not recognise.
"""

import dataclasses
import doctest
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from electrogrowth.basestate import neo_hookean
from electrogrowth.basestate import voltage as tube
from electrogrowth.basestate.tube import (
    neo_hookean_asymptote,
    solve_base_state,
    voltage_curve,
    voltage_threshold,
)
from electrogrowth.errors import BaseStateError
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import I1, I4, I5, I6, Material, gent, mooney_rivlin

CASES = [  # (Rbar_o, g, lambda_z, Vbar)
    (2.0, 1.0, 1.0, 0.5),
    (2.0, 1.1, 0.9, 0.9),
    (2.0, 1.2, 1.2, 1.0),
    (1.3, 0.9, 1.1, 0.4),
    (4.0, 1.05, 0.8, 1.4),
    (2.0, 1.0, 1.2, 0.84),
]
KNOWLES = Material("knowles-1/2", (sp.sqrt(1 + 2 * (I1 - 3)) - 1) / 2 + I5 / 2)  # softening
NON_IDEAL = [
    Material("nh+I6/10", (I1 - 3) / 2 + I5 / 2 + I6 / 10, check_units=False),
    Material("nh+I4/5", (I1 - 3) / 2 + I5 / 2 + I4 / 5, check_units=False),
]
# the ideal neo-Hookean energy in disguise: equal on I1 >= 3, but takes the generic route
NH_TWINS = [
    Material("nh-trig", (I1 - 3) / 2 * (sp.cos(I1) ** 2 + sp.sin(I1) ** 2) + I5 / 2),
    Material("nh-rational", (I1**2 - 9) / (2 * (I1 + 3)) + I5 / 2),
]


def params(Ro, g, lz, V, material=None):
    extra = {} if material is None else {"material": material}
    return Tube.uniform(outer_radius=Ro, growth=g, stretch=lz, voltage=V, **extra)


# -- independent neo-Hookean closed forms (docs/derivation-base-state.md, eqs. NH-1 .. NH-5) --


def nh_geometry(p, lam_i):
    b = p.growth**3 / p.stretch
    r_o = math.sqrt(lam_i**2 + b * (p.outer_radius**2 - 1))
    return b, r_o, r_o / p.outer_radius


def nh_voltage(p, lam_i):
    g, lz, Ro = p.growth, p.stretch, p.outer_radius
    b, r_o, lam_o = nh_geometry(p, lam_i)
    x = b * (Ro**2 - 1) / lam_i**2  # (r_o / r_i)^2 - 1, free of cancellation at large lambda_i
    log_ratio = 0.5 * math.log1p(x)  # ln(r_o / r_i)
    radicand = (2 * g * lz * (math.log(Ro) - log_ratio) - g**4 * (lam_i**-2 - lam_o**-2)) / x
    return r_o * log_ratio / (lz * (Ro - 1)) * math.sqrt(radicand)


def nh_stresses(p, lam_i, c, R):
    g, lz = p.growth, p.stretch
    b, r_o, lam_o = nh_geometry(p, lam_i)
    r = np.sqrt(lam_i**2 + b * (R**2 - 1))
    lam = r / R
    srr = (
        g
        / lz
        * (
            np.log(lam_i / lam)
            + np.log(lam_i / lam_o) * r_o**2 * (lam_i**2 - r**2) / (r**2 * (r_o**2 - lam_i**2))
        )
    )
    l2, l3 = lam / g, lz / g
    l1sq = 1 / (l2 * l3) ** 2
    return srr, srr + l2**2 - l1sq - c**2 / r**2, srr + l3**2 - l1sq - c**2 / r**2


def nh_axial_force(p, lam_i, c):
    g, lz, Ro = p.growth, p.stretch, p.outer_radius
    b, r_o, _ = nh_geometry(p, lam_i)
    A, delta, log_r = lam_i**2 - b, r_o**2 - lam_i**2, math.log(r_o / lam_i)
    return math.pi * (
        lz**2 * delta / g**2
        - c**2 * log_r
        - g**4 / lz**2 * ((Ro**2 - 1) / 2 - A / b * log_r)
        - b / g**2 * (A * math.log(Ro) + delta / 2)
    )


def mechanical_lambda_i(p):
    """Vbar = 0 neo-Hookean state: the radicand of nh_voltage vanishes."""

    def radicand(lam_i):
        _, _, lam_o = nh_geometry(p, lam_i)
        return 2 * p.growth * p.stretch * math.log(lam_i / lam_o) - p.growth**4 * (
            lam_i**-2 - lam_o**-2
        )

    return brentq(radicand, 0.2, 5.0, xtol=1e-15, rtol=1e-15)


# -- slow twins in the current radius r --------------------------------------------------------


def twin_integrals(state):
    """(int (tau_2 - tau_1) dr / r, int E_r dr, int (|tau_1| + |tau_2|) dr / r) by quad in r."""
    p, mat = state.tube, state.tube.material
    b = p.growth**3 / p.stretch

    def local(r):
        R = math.sqrt(1 + (r**2 - state.r_i**2) / b)
        l2 = r / (p.growth * R)
        l3 = p.stretch / p.growth
        return (1 / (l2 * l3), l2, l3), state.charge / r

    def hoop(r):
        tau = mat.stress(*local(r)[0], local(r)[1])
        return (tau[1] - tau[0]) / r

    def size(r):
        tau = mat.stress(*local(r)[0], local(r)[1])
        return (abs(tau[1]) + abs(tau[0])) / r

    def field(r):
        return float(mat.electric_field(*local(r)[0], local(r)[1]))

    # the hoop integral vanishes: an absolute tolerance, the others relative
    return tuple(
        quad(f, state.r_i, state.r_o, epsabs=tol, epsrel=1e-13, limit=200)[0]
        for f, tol in ((hoop, 1e-13), (field, 0), (size, 0))
    )


# -- closed forms vs the generic quadrature route ------------------------------------------------


@pytest.mark.parametrize("Ro, g, lz, V", CASES)
def test_neo_hookean_state_matches_closed_forms(Ro, g, lz, V):
    p = params(Ro, g, lz, V)
    s = solve_base_state(p)
    assert nh_voltage(p, s.lambda_i) == pytest.approx(V, rel=1e-12)
    assert s.charge * math.log(s.r_o / s.r_i) == pytest.approx(V * (Ro - 1), rel=1e-12)
    R = np.linspace(1, Ro, 41)
    exact = nh_stresses(p, s.lambda_i, s.charge, R)
    scale = max(np.abs(e).max() for e in exact)
    for got, want in zip(s.stresses(R), exact):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-11 * scale)
    np.testing.assert_allclose(s.sigma_rr(R), exact[0], rtol=0, atol=1e-12 * scale)
    assert s.axial_force == pytest.approx(nh_axial_force(p, s.lambda_i, s.charge), rel=1e-11)
    assert s.lambda_o == pytest.approx(s.r_o / Ro, rel=1e-15)
    assert s.voltage_threshold == pytest.approx(neo_hookean_asymptote(p), rel=1e-15)


@pytest.mark.parametrize("Ro, g, lz, V", CASES)
def test_neo_hookean_voltage_curve_matches_closed_form(Ro, g, lz, V):
    p = params(Ro, g, lz, 0.0)
    lam0 = mechanical_lambda_i(p)
    lam = lam0 * np.geomspace(1.001, 300.0, 25)
    want = np.array([nh_voltage(p, x) for x in lam])
    np.testing.assert_allclose(voltage_curve(p, lam), want, rtol=1e-12)


@pytest.mark.parametrize("Ro, g, lz", [(2.0, 1.0, 1.0), (2.0, 1.2, 0.9), (1.5, 1.1, 1.3)])
def test_neo_hookean_asymptote_is_the_limit_of_the_closed_form(Ro, g, lz):
    p = params(Ro, g, lz, 0.0)
    # Vbar_inf - Vbar(lambda_i) = O(lambda_i^-4): one Richardson step lands on the limit
    v1, v2 = nh_voltage(p, 200.0), nh_voltage(p, 400.0)
    assert abs(v2 - neo_hookean_asymptote(p)) > 2e-12
    assert (16 * v2 - v1) / 15 == pytest.approx(neo_hookean_asymptote(p), rel=2e-13)
    assert neo_hookean_asymptote(params(Ro, 1.0, 1.0, 0.0)) == pytest.approx(
        math.sqrt((Ro**2 - 1) * math.log(Ro) / 2) / (Ro - 1), rel=1e-15
    )


# -- equilibrium, boundary conditions, limits ---------------------------------------------------


@pytest.mark.parametrize(
    "material",
    [None, gent(97.2), KNOWLES, NON_IDEAL[0]],
    ids=["neo-hookean", "gent", "knowles", "non-ideal"],
)
def test_equilibrium_and_traction_free_faces(material):
    s = solve_base_state(params(2.0, 1.1, 0.95, 0.6, material))
    R = np.linspace(1.05, 1.95, 19)
    h = 1e-4  # 4th-order central difference of sigma_rr(R), then d/dr = (d/dR) / (dr/dR)
    dsdR = (
        -s.sigma_rr(R + 2 * h)
        + 8 * s.sigma_rr(R + h)
        - 8 * s.sigma_rr(R - h)
        + s.sigma_rr(R - 2 * h)
    ) / (12 * h)
    r = s.radius(R)
    drdR = s.tube.growth**3 * R / (s.tube.stretch * r)
    srr, stt, _ = s.stresses(R)
    np.testing.assert_allclose(dsdR / drdR, (stt - srr) / r, rtol=0, atol=1e-9 * np.abs(stt).max())
    assert s.sigma_rr(1.0) == 0.0
    assert abs(s.sigma_rr(2.0)) <= 1e-13 * np.abs(stt).max()
    prof = s.profiles(11)
    np.testing.assert_allclose(
        prof["p"],
        s.tube.material.stress(*s.elastic_stretches(prof["R"]), prof["D_r"])[0] - prof["sigma_rr"],
        rtol=1e-14,
    )
    assert set(prof) == {"R", "r", "lambda", "sigma_rr", "sigma_tt", "sigma_zz", "p", "D_r", "E_r"}
    assert all(np.all(np.isfinite(v)) for v in prof.values())


def test_zero_voltage_is_the_mechanical_state():
    p = params(2.0, 1.1, 0.9, 0.0)
    s = solve_base_state(p)
    assert s.lambda_i == pytest.approx(mechanical_lambda_i(p), rel=1e-13)
    assert s.charge == 0.0 and np.all(s.electric_field(np.linspace(1, 2, 5)) == 0)
    # lambda_i - lambda_i0 = O(Vbar^2) as Vbar -> 0
    d1, d2 = (
        solve_base_state(dataclasses.replace(p, voltage=v)).lambda_i - s.lambda_i
        for v in (1e-3, 2e-3)
    )
    assert d2 / d1 == pytest.approx(4.0, rel=1e-3)


def test_growth_matched_by_axial_stretch_is_stress_free():
    s = solve_base_state(params(2.0, 1.15, 1.15, 0.0, gent(97.2)))
    assert s.lambda_i == pytest.approx(1.15, rel=1e-14)
    srr, stt, szz = s.stresses(np.linspace(1, 2, 7))
    assert max(np.abs(srr).max(), np.abs(stt).max(), np.abs(szz).max()) < 1e-13
    assert abs(s.axial_force) < 1e-12


@pytest.mark.parametrize(
    "material", [None, gent(97.2), KNOWLES], ids=["neo-hookean", "gent", "knowles"]
)
@pytest.mark.parametrize("g, lz, V", [(1.1, 1.0, 0.5), (1.25, 0.9, 0.7), (0.9, 1.2, 0.3)])
def test_growth_is_a_rescaling_of_the_ungrown_tube(material, g, lz, V):
    """(g, lambda_z, Vbar) == (1, lambda_z/g, Vbar/g) in a tube g times larger."""
    grown = solve_base_state(params(2.0, g, lz, V, material))
    ref = solve_base_state(params(2.0, 1.0, lz / g, V / g, material))
    assert grown.lambda_i == pytest.approx(g * ref.lambda_i, rel=1e-12)
    assert grown.charge == pytest.approx(g * ref.charge, rel=1e-11)
    assert grown.axial_force == pytest.approx(g**2 * ref.axial_force, rel=1e-10, abs=1e-12)
    R = np.linspace(1, 2, 9)
    for a, b in zip(grown.stresses(R), ref.stresses(R)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-11 * np.abs(b).max())
    thr, kind, lam = voltage_threshold(grown.tube)
    thr1, kind1, lam1 = voltage_threshold(ref.tube)
    assert kind == kind1 and thr == pytest.approx(g * thr1, rel=1e-12)
    assert lam == pytest.approx(g * lam1, rel=1e-9)


# -- the threshold -------------------------------------------------------------------------------


@pytest.mark.parametrize("g, lz", [(1.0, 1.0), (1.2, 0.9), (1.1, 1.2)])
def test_asymptote_is_approached_from_below_and_never_exceeded(g, lz):
    p = params(2.0, g, lz, 0.0)
    thr, kind, lam = voltage_threshold(p)
    assert kind == "asymptote" and lam == math.inf
    assert thr == pytest.approx(g**2 / lz * math.sqrt(3 * math.log(2) / 2), rel=1e-15)
    v = voltage_curve(p, np.geomspace(mechanical_lambda_i(p), 1e3, 300))
    assert np.all(np.diff(v) > 0) and v[-1] < thr
    far = voltage_curve(p, [1e2, 1e3, 1e6])
    assert np.all(far[:2] < thr) and far[2] <= thr * (1 + 4e-16)
    # the lambda_i^-2 term cancels exactly (docs): Vbar_inf - Vbar = O(lambda_i^-4)
    assert (thr - far[1]) / (thr - far[0]) == pytest.approx(1e-4, rel=1e-3)
    near = solve_base_state(dataclasses.replace(p, voltage=thr * (1 - 1e-10)))
    assert near.lambda_i > 100 and near.quadrature_error < 1e-12


def test_softening_energy_has_a_limit_point_below_the_neo_hookean_asymptote():
    p = params(2.0, 1.1, 0.9, 0.0, KNOWLES)
    thr, kind, lam = voltage_threshold(p)
    assert kind == "limit point" and thr < neo_hookean_asymptote(p)
    lam0 = solve_base_state(p).lambda_i  # Vbar = 0
    res = minimize_scalar(
        lambda x: -voltage_curve(p, x),
        bounds=(lam0 * 1.01, 10.0),
        method="bounded",
        options={"xatol": 1e-11},
    )
    assert thr == pytest.approx(-res.fun, rel=1e-14)
    assert lam == pytest.approx(res.x, rel=1e-8)
    branch = voltage_curve(p, np.linspace(lam0, lam, 200))
    assert np.all(np.diff(branch) > 0) and branch.max() <= thr
    s = solve_base_state(dataclasses.replace(p, voltage=thr * (1 - 1e-9)))
    assert s.lambda_i < lam  # the branch continuous from Vbar = 0, not the one past the peak


@pytest.mark.parametrize("jm", [20.0, 97.2])
def test_gent_voltage_rises_without_bound_to_the_locking_stretch(jm):
    """Stiffening removes the neo-Hookean asymptote: no limit point, Vbar -> inf at locking."""
    p = params(2.0, 1.1, 1.0, 0.0, gent(jm))
    thr, kind, lam_lock = voltage_threshold(p)
    assert kind == "locking" and thr == math.inf
    l2, l3 = lam_lock / 1.1, 1.0 / 1.1  # locking: I1 = 3 + jm on the inner face
    assert l2**2 + l3**2 + 1 / (l2 * l3) ** 2 == pytest.approx(3 + jm, rel=1e-12)
    lam = np.linspace(solve_base_state(p).lambda_i * 1.001, lam_lock * (1 - 1e-6), 300)
    v = voltage_curve(p, lam)
    assert np.all(np.diff(v) > 0) and v[-1] > 2 * neo_hookean_asymptote(p)
    assert np.all(v >= voltage_curve(params(2.0, 1.1, 1.0, 0.0), lam))  # stiffer than nH
    with pytest.raises(BaseStateError, match="beyond locking"):
        voltage_curve(p, lam_lock * 1.01)


def test_gent_tends_to_neo_hookean_as_jm_grows():
    nh = solve_base_state(params(2.0, 1.1, 1.0, 1.1))
    gaps = [
        nh.lambda_i - solve_base_state(params(2.0, 1.1, 1.0, 1.1, gent(jm))).lambda_i
        for jm in (1e3, 1e4, 1e5)
    ]
    assert gaps[0] > 0  # stiffening: less inflation at the same voltage
    assert gaps[0] / gaps[1] == pytest.approx(10, rel=0.05)  # O(1/jm)
    assert gaps[1] / gaps[2] == pytest.approx(10, rel=0.01)


@pytest.mark.parametrize("alpha", [0.5, 0.3])
def test_richardson_asymptote_matches_the_mooney_rivlin_closed_form(alpha):
    """Vbar_inf = Vbar_inf^nH sqrt(alpha + (1 - alpha) (lambda_z / g)^2) (see the docs)."""
    p = params(2.0, 1.2, 1.3, 0.0, mooney_rivlin(alpha))
    thr, kind, _ = voltage_threshold(p)
    want = neo_hookean_asymptote(p) * math.sqrt(alpha + (1 - alpha) * (1.3 / 1.2) ** 2)
    assert kind == "asymptote" and thr == pytest.approx(want, rel=1e-13)
    assert tube.threshold_info(p).error < 1e-13


@pytest.mark.parametrize(
    "Ro, g, lz, V", [(2.0, 1.0, 1.0, 1.02), (2.0, 1.1, 1.2, 1.3), (2.0, 1.0, 1.0, 1e6)]
)
def test_voltage_at_or_above_threshold_is_an_error(Ro, g, lz, V):
    p = params(Ro, g, lz, V)
    with pytest.raises(BaseStateError) as err:
        solve_base_state(p)
    msg = str(err.value)
    assert "\n" not in msg and f"Vbar = {V:.12g}" in msg
    assert f"{neo_hookean_asymptote(p):.12g}" in msg
    with pytest.raises(BaseStateError):  # exactly at the threshold too
        solve_base_state(dataclasses.replace(p, voltage=neo_hookean_asymptote(p)))


def test_voltage_curve_rejects_lambda_below_the_mechanical_state():
    p = params(2.0, 1.0, 1.0, 0.0)
    with pytest.raises(BaseStateError, match="below"):
        voltage_curve(p, [0.9, 1.5])
    assert voltage_curve(p, 1.0) == 0.0  # lambda_i0 = 1 for the unloaded tube


# -- non-ideal energies: V = int E_r dr --------------------------------------------------------


@pytest.mark.parametrize("material", NON_IDEAL, ids=lambda m: m.name)
@pytest.mark.parametrize("V", [0.3, 0.9])
def test_non_ideal_state_satisfies_both_integral_conditions(material, V):
    s = solve_base_state(params(2.0, 1.1, 1.0, V, material))
    hoop, volt, size = twin_integrals(s)
    assert abs(hoop) <= 1e-12 * size
    assert volt == pytest.approx(V * (2.0 - 1.0), rel=1e-12)
    ideal = solve_base_state(params(2.0, 1.1, 1.0, V))
    assert abs(s.lambda_i - ideal.lambda_i) > 1e-4  # the I4 / I6 term matters
    R = np.linspace(1, 2, 5)
    assert not np.allclose(s.electric_field(R), s.displacement(R))


def test_non_ideal_asymptote_and_unbounded_cases():
    # I6 = l1^2 D_r^2 / ... fades as l1 -> 0: same asymptote as neo-Hookean
    thr, kind, _ = voltage_threshold(params(2.0, 1.1, 0.9, 0.0, NON_IDEAL[0]))
    assert kind == "asymptote"
    assert thr == pytest.approx(neo_hookean_asymptote(params(2.0, 1.1, 0.9, 0.0)), rel=1e-12)
    thr, kind, _ = voltage_threshold(params(2.0, 1.1, 0.9, 0.0, NON_IDEAL[1]))
    assert kind == "none" and thr == math.inf  # E_r ~ (1 + 2 I4-term) D_r grows with l2


# -- quadrature ---------------------------------------------------------------------------------


def test_gauss_quadrature_converges_geometrically():
    lam = np.array([1.3])
    exact = tube.UniformWall(gent(97.2), 2.0, 1.1, 0.9, 96).hoop(lam, 0.4)[0][0]
    ns = np.arange(3, 13)
    err = np.array(
        [
            abs(tube.UniformWall(gent(97.2), 2.0, 1.1, 0.9, int(n)).hoop(lam, 0.4)[0][0] - exact)
            for n in ns
        ]
    )
    rate = np.polyfit(ns[:7], np.log(err[:7]), 1)[0]  # ln error ~ -2 n ln(rho)
    assert rate < -1.5
    assert err[-1] < 1e-13 * abs(exact) + 1e-15


def test_profile_quadrature_is_independent_and_agrees():
    s = solve_base_state(params(4.0, 1.2, 0.8, 1.4))
    hoop, volt, size = twin_integrals(s)
    assert abs(hoop) <= 1e-12 * size and s.quadrature_error < 1e-13
    assert volt == pytest.approx(1.4 * 3.0, rel=1e-12)


def test_moduli_are_the_materials_at_the_local_state():
    s = solve_base_state(params(2.0, 1.1, 1.0, 0.5, gent(97.2)))
    R = np.array([[1.0, 1.5], [1.7, 2.0]])
    got = s.moduli(R)
    assert got.shape == (2, 2, 23)
    want = s.tube.material.moduli(*s.elastic_stretches(R), s.displacement(R))
    np.testing.assert_array_equal(got, want)


# -- the neo-Hookean fast path against the generic route ---------------------------------------


@pytest.mark.parametrize("twin", NH_TWINS, ids=lambda m: m.name)
def test_closed_form_route_matches_the_generic_route(twin, rng):
    """16 random (Rbar_o, g, lambda_z, Vbar / Vbar_inf): every output of the base state agrees
    to 1e-12 (measured: 1e-15 - 1e-13)."""
    assert tube.energy_kind(twin) == "ideal"  # not recognised: Gauss quadrature, scan, Chebyshev
    for Ro, g, lz, frac in zip(
        rng.uniform(1.05, 4.0, 16),
        rng.uniform(0.7, 2.0, 16),
        rng.uniform(0.6, 1.6, 16),
        rng.uniform(0.02, 0.97, 16),
    ):
        p = params(Ro, g, lz, frac * neo_hookean_asymptote(params(Ro, g, lz, 0.0)))
        q = Tube.uniform(p.outer_radius, p.length, p.growth, p.stretch, p.voltage, twin)
        fast, slow = solve_base_state(p), solve_base_state(q)
        # two routes indeed
        assert tube.threshold_info(p).nodes == 0 and tube.threshold_info(q).nodes > 0
        for name in ("lambda_i", "lambda_o", "r_i", "r_o", "charge", "voltage_threshold"):
            assert getattr(fast, name) == pytest.approx(getattr(slow, name), rel=1e-12), name
        assert fast.threshold_kind == slow.threshold_kind == "asymptote"
        assert fast.axial_force == pytest.approx(slow.axial_force, rel=1e-12, abs=1e-12)
        assert fast.quadrature_error < 1e-14 and slow.quadrature_error < 1e-13
        R = np.linspace(1.0, Ro, 17)
        want = slow.stresses(R)
        scale = max(np.abs(w).max() for w in want)
        for got, w in zip(fast.stresses(R), want):
            np.testing.assert_allclose(got, w, rtol=0, atol=1e-12 * scale)
        for f in ("pressure", "moduli", "electric_field", "displacement", "radius"):
            w = getattr(slow, f)(R)
            np.testing.assert_allclose(
                getattr(fast, f)(R), w, rtol=0, atol=1e-12 * np.abs(w).max(), err_msg=f
            )
        lam = math.sqrt(g**3 / lz) * np.geomspace(1.001, 300.0, 13)
        np.testing.assert_allclose(voltage_curve(p, lam), voltage_curve(q, lam), rtol=1e-12)
        assert voltage_threshold(p) == (fast.voltage_threshold, "asymptote", math.inf)


def test_closed_form_voltage_rises_strictly_to_the_asymptote():
    """(NH-6) over Rbar_o = 1.005 .. 32: Vbar^2 / Vbar_inf^2 falls strictly in
    y = (lambda_i0 / lambda_i)^2 from 1 (y = 0) to 0 (y = 1), and m = lambda_z M / g falls
    strictly in y on (0, 100]: one lambda_i0, and one lambda_i per Vbar (proof in the docs)."""
    square, traction = (
        np.vectorize(f, otypes=[float]) for f in (neo_hookean.nh_square, neo_hookean.nh_traction)
    )
    y = np.geomspace(1e-4, 1.0, 1500)
    for k in np.geomspace(1e-2, 1e3, 30):  # k = Rbar_o^2 - 1
        f = square(y, k)
        assert np.all(np.diff(f) < 0) and f[0] < 1.0 and f[-1] == 0.0
        assert square(0.0, k) == 1.0
        m = traction(np.geomspace(1e-4, 100.0, 1500), k)
        assert np.all(np.diff(m) < 0) and np.all(m < 0.5 * math.log1p(k))


@pytest.mark.parametrize("frac", [0.2, 0.5, 0.9, 0.999, 1 - 1e-6, 1 - 1e-10])
def test_closed_form_root_is_backward_stable(frac):
    """Vbar(lambda_i) of the test's own closed form (NH-3) returns the requested Vbar."""
    p = params(1.4, 1.3, 0.9, 0.0)
    V = frac * neo_hookean_asymptote(p)
    s = solve_base_state(dataclasses.replace(p, voltage=V))
    assert nh_voltage(p, s.lambda_i) == pytest.approx(V, rel=1e-14)
    log_ratio = 0.5 * math.log1p(1.3**3 / 0.9 * (1.4**2 - 1) / s.r_i**2)  # ln(r_o / r_i)
    assert s.charge * log_ratio == pytest.approx(V * 0.4, rel=1e-14)


@pytest.mark.parametrize(
    "Ro, g, lz", [(2.0, 1.0, 1.0), (1.4, 1.3, 0.9), (4.0, 1.05, 0.8), (1.1, 1.0, 1.0)]
)
def test_one_ulp_below_the_asymptote(Ro, g, lz):
    """A state far out on the branch, or a named error if Vbar / Vbar_inf rounds to 1."""
    p = params(Ro, g, lz, 0.0)
    V = float(np.nextafter(neo_hookean_asymptote(p), 0.0))
    for _ in range(3):
        try:
            s = solve_base_state(dataclasses.replace(p, voltage=V))
        except BaseStateError as err:
            assert "within rounding of the threshold" in str(err)
        else:
            assert 1e3 * math.sqrt(g**3 / lz) < s.lambda_i < math.inf
            assert s.quadrature_error < 1e-15
        V = float(np.nextafter(V, 0.0))


def test_neo_hookean_takes_the_closed_form_route(monkeypatch):
    """No generic stress, field or moduli evaluation for the paper's material."""

    def generic(*args, **kwargs):
        raise AssertionError("generic route taken")

    for name in ("stress", "electric_field", "moduli"):
        monkeypatch.setattr(Material, name, generic)
    p = params(1.4, 1.2345, 0.9876, 0.4)  # a new (g, lambda_z): nothing cached
    s = solve_base_state(p, rtol=1e-10)
    R = np.linspace(1.0, 1.4, 33)
    assert s.moduli(R).shape == (33, 23) and s.pressure(R).shape == (33,)
    assert set(s.profiles(5)) >= {"sigma_rr", "E_r"}
    assert voltage_curve(p, [2.0, 3.0]).shape == (2,) and voltage_threshold(p)[1] == "asymptote"


@pytest.mark.parametrize(
    "material", [gent(20.0), KNOWLES, mooney_rivlin(0.3), *NON_IDEAL], ids=lambda m: m.name
)
def test_mechanical_state_is_the_homogeneous_one_for_every_energy(material):
    """lambda_i0 = sqrt(g^3 / lambda_z): l1 = l2 throughout, so tau_1 = tau_2 (docs Sec. 3), and
    M < 0 below, > 0 above (Baker-Ericksen). The root found here by brentq on the quadrature."""
    g, lz = 1.15, 0.85
    wall = tube.UniformWall(material, 2.0, g, lz, 64)

    def m(lam):
        return float(wall.hoop(np.array([lam]), 0.0)[0][0])

    lam0 = math.sqrt(g**3 / lz)
    assert brentq(m, 0.6 * lam0, 1.7 * lam0, xtol=1e-15, rtol=1e-15) == pytest.approx(
        lam0, rel=1e-13
    )
    lam = lam0 * np.concatenate([np.geomspace(0.6, 0.999, 10), np.geomspace(1.001, 1.7, 10)])
    assert np.array_equal(np.sign([m(x) for x in lam]), np.sign(lam - lam0))
    s = solve_base_state(params(2.0, g, lz, 0.0, material))
    assert s.lambda_i == lam0 and s.charge == 0.0
    srr, stt, _ = s.stresses(np.linspace(1.0, 2.0, 9))
    assert np.abs(srr).max() < 1e-14 and np.abs(stt).max() < 1e-14  # uniaxial: only sigma_zz


def test_docstring_examples():
    assert doctest.testmod(tube, raise_on_error=False).failed == 0


@pytest.mark.slow
def test_gent_has_no_limit_point_over_a_parameter_grid():
    """docs/derivation-base-state.md Sec. 6: 72 cases, always 'locking' at the locking stretch."""
    for jm in (20.0, 97.2, 500.0):
        for Ro in (1.1, 1.5, 2.0, 4.0):
            for lz in (0.8, 1.0, 1.5):
                for g in (1.0, 1.2):
                    thr, kind, lam = voltage_threshold(params(Ro, g, lz, 0.0, gent(jm)))
                    l2, l3 = lam / g, lz / g
                    assert kind == "locking" and thr == math.inf
                    assert l2**2 + l3**2 + 1 / (l2 * l3) ** 2 == pytest.approx(3 + jm, rel=1e-9)


def test_a_gent_tube_has_one_threshold_kind_however_entered():
    """Probe round 7a: 'none' for Tube.uniform(2, gent(5)), 'locking' for the same tube as
    two identical layers (lambda_i 2.618034 both)."""
    from electrogrowth import Layer, Tube, threshold

    one = threshold(Tube.uniform(2.0, material=gent(5.0)), "voltage")
    two = threshold(Tube((Layer(1.5, material=gent(5.0)), Layer(2.0, material=gent(5.0)))))
    assert one.kind == two.kind == "locking" and one.value == two.value == math.inf
    assert one.lambda_i == pytest.approx(two.lambda_i, rel=1e-12)
