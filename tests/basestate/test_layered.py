"""Layered tubes (model/layers.py, basestate/layered.py) against closed forms, identities and
today's single-layer solver.

The neo-Hookean closed forms below are written here from docs/derivation-layered.md,
independently of the package: per layer with constant growth (g_r, g_theta, g_z),
r^2 = A + B R^2 (B = g_r g_theta g_z / lambda_z), the traction integral, Q, Lambda and the axial
force integral are elementary. Limit points are located here with scipy (brentq for lambda_z,
minimize_scalar for the maximum), not with the package's scans.
"""

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from electrogrowth.basestate.layered import (
    layered_threshold,
    pressure_response,
    solve_layered_state,
    voltage_response,
)
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.cli.app import main
from electrogrowth.errors import BaseStateError, ConfigError, ParameterError
from electrogrowth.model.layers import Layer, LinearGrowth, Tube
from electrogrowth.model.materials import I1, I5, I6, Material, gent, mooney_rivlin, neo_hookean
from electrogrowth.model.tube_file import load_tube, parse_tube

# -- independent neo-Hookean closed forms (constant growth per layer) -------------------------


def nh_closed(layers, lz, r_i, vbar=0.0):
    """(P_i - P_o, c, N_int, r_o^2) of an ideal neo-Hookean layered tube at (r_i, lambda_z, Vbar);
    layers: (a, b, (g_r, g_theta, g_z), mu, eps). N_int = pi int (2 tau_3 - tau_1 - tau_2) r dr."""
    ra2 = r_i * r_i
    T = Q = Lam = Nm = 0.0
    for a, b, (gr, gt, gz), mu, eps in layers:
        B = gr * gt * gz / lz
        A = ra2 - B * a * a
        rb2 = A + B * b * b
        lnr = 0.5 * math.log(rb2 / ra2)
        T += mu * (
            gr * gz / (gt * lz) * math.log(b / a)
            - gt * gz / (2 * lz * gr) * (2 * lnr + A * (1 / rb2 - 1 / ra2))
        )
        Q += (1 / ra2 - 1 / rb2) / (2 * eps)
        Lam += lnr / eps
        Nm += (
            math.pi
            * mu
            * (
                (lz / gz) ** 2 * (rb2 - ra2)
                - B / gt**2 * (A * math.log(b / a) + B * (b * b - a * a) / 2)
                - gt**2 * gz**2 / (2 * lz**2) * ((b * b - a * a) - A / B * 2 * lnr)
            )
        )
        ra2 = rb2
    c = vbar * (layers[-1][1] - 1.0) / Lam
    return T - c * c * Q, c, Nm - math.pi * c * c * Lam, ra2


def nh_voltage(layers, lz, r_i, dp=0.0):
    """Vbar on the voltage branch at P_i - P_o = dp: c^2 = (T - dp) / Q, V = c Lambda."""
    T, _, _, _ = nh_closed(layers, lz, r_i)
    ra2, Q, Lam = r_i * r_i, 0.0, 0.0
    for a, b, g, _, eps in layers:
        rb2 = ra2 + math.prod(g) * (b * b - a * a) / lz
        Q += (1 / ra2 - 1 / rb2) / (2 * eps)
        Lam += 0.5 * math.log(rb2 / ra2) / eps
        ra2 = rb2
    return math.sqrt((T - dp) / Q) * Lam / (layers[-1][1] - 1.0)


def spec(tube):
    out, a = [], 1.0
    for layer in tube.layers:
        out.append((a, layer.outer_radius, layer.growth, layer.shear_modulus, layer.permittivity))
        a = layer.outer_radius
    return out


BILAYER = Tube(
    (
        Layer(1.15, shear_modulus=8.0, permittivity=2.0, growth=(1.1, 1.3, 1.05)),
        Layer(1.9, growth=(1.0, 1.05, 0.95)),
    ),
    stretch=1.1,
)


# -- 1. one homogeneous, isotropically growing layer is today's tube --------------------------


@pytest.mark.parametrize(
    "material", [neo_hookean(), gent(20), mooney_rivlin(0.3)], ids=["nh", "gent", "mr"]
)
@pytest.mark.parametrize(
    "Ro, g, lz, frac", [(2.0, 1.2, 1.0, 0.6), (1.3, 0.9, 1.1, 0.3), (1.6, 1.4, 0.8, 0.85)]
)
def test_one_layer_is_todays_tube(material, Ro, g, lz, frac):
    p = Tube.uniform(outer_radius=Ro, growth=g, stretch=lz, material=material)
    thr = solve_base_state(p).voltage_threshold
    p = dataclasses.replace(p, voltage=frac * (thr if math.isfinite(thr) else 1.5))
    ref, st = solve_base_state(p), solve_layered_state(p)
    for key in ("lambda_i", "lambda_o", "r_i", "r_o", "charge", "axial_force"):
        assert getattr(st, key) == pytest.approx(getattr(ref, key), rel=1e-12, abs=1e-12), key
    R = np.linspace(1.0, Ro, 17)
    scale = max(1.0, np.abs(ref.stresses(R)).max())
    np.testing.assert_allclose(st.stresses(R), ref.stresses(R), rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(st.pressure(R), ref.pressure(R), rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(st.moduli(R), ref.moduli(R), rtol=0, atol=1e-12 * scale)
    if math.isfinite(thr):
        assert st.voltage_threshold == pytest.approx(thr, rel=1e-12)
        assert st.threshold_kind == ref.threshold_kind
    else:
        assert st.threshold_kind == "locking" and math.isinf(st.voltage_threshold)


# -- 2. identities ------------------------------------------------------------------------------


def _same(s1, s2, tol=1e-12):
    for key in ("lambda_i", "lambda_o", "charge", "axial_force", "stretch", "end_force"):
        assert getattr(s1, key) == pytest.approx(getattr(s2, key), rel=tol, abs=tol), key
    R = np.linspace(1.0, s1.tube.outer_radius, 23)
    scale = max(1.0, np.abs(s1.stresses(R)).max())
    np.testing.assert_allclose(s1.stresses(R), s2.stresses(R), rtol=0, atol=tol * scale)


@pytest.mark.parametrize("split", [1.02, 1.37, 1.88])
@pytest.mark.parametrize("material", [neo_hookean(), mooney_rivlin(0.3)], ids=["nh", "mr"])
def test_identical_layers_split_anywhere_equal_one_layer(split, material):
    inner = Layer(1.1, material, 5.0, growth=(1.1, 1.2, 1.0))
    outer = Layer(1.9, material, 0.7, 1.5)
    whole = Tube((inner, outer), stretch=1.05, voltage=0.25, inner_pressure=0.1)
    piece = dataclasses.replace(inner if split < 1.1 else outer, outer_radius=split)
    layers = (piece, inner, outer) if split < 1.1 else (inner, piece, outer)
    s1, s2 = solve_layered_state(whole), solve_layered_state(Tube(layers, **_loads(whole)))
    _same(s1, s2)
    assert len(s2.interface_radii) == 2
    assert s2.interface_radii[1 if split < 1.1 else 0] == pytest.approx(s1.interface_radii[0])


def _loads(tube):
    return {f.name: getattr(tube, f.name) for f in dataclasses.fields(tube) if f.name != "layers"}


def test_isotropic_growth_as_a_triple_a_function_or_a_scalar():
    base = dict(stretch=0.9, voltage=0.4, inner_pressure=0.05)
    scalar = solve_layered_state(Tube((Layer(1.7, growth=1.25),), **base))
    triple = solve_layered_state(Tube((Layer(1.7, growth=(1.25, 1.25, 1.25)),), **base))
    graded = solve_layered_state(
        Tube((Layer(1.7, growth=LinearGrowth(1.0, 1.7, 1.25, 1.25)),), **base)
    )
    func = solve_layered_state(Tube((Layer(1.7, growth=lambda R: (1.25 + 0 * R,) * 3),), **base))
    for other in (triple, graded, func):
        _same(scalar, other)


@pytest.mark.parametrize("control", ["stretch", "force"])
def test_axial_growth_is_an_axial_prestretch(control):
    """(g_r, g_theta, g_z) at lambda_z, length L == (g_r, g_theta, 1) at lambda_z / g_z, length
    g_z L, pointwise in R: same r(R), elastic stretches, c, stresses, N and current length."""
    gz, lz, L = 1.3, 1.1, 2.0
    layers = [
        Layer(1.2, shear_modulus=4.0, growth=(1.1, 1.2, gz)),
        Layer(1.8, mooney_rivlin(0.4), growth=(1.0, 0.95, gz)),
    ]
    ungrown = [dataclasses.replace(la, growth=la.growth[:2] + (1.0,)) for la in layers]
    loads = dict(voltage=0.3, inner_pressure=0.08)
    if control == "stretch":
        a = Tube(tuple(layers), length=L, stretch=lz, **loads)
        b = Tube(tuple(ungrown), length=gz * L, stretch=lz / gz, **loads)
    else:
        a = Tube(tuple(layers), length=L, axial_force=0.2, closed_ends=True, **loads)
        b = Tube(tuple(ungrown), length=gz * L, axial_force=0.2, closed_ends=True, **loads)
    sa, sb = solve_layered_state(a), solve_layered_state(b)
    assert sa.stretch == pytest.approx(gz * sb.stretch, rel=1e-12)
    assert sa.as_dict()["current_length"] == pytest.approx(sb.as_dict()["current_length"], 1e-12)
    for key in ("lambda_i", "lambda_o", "charge", "axial_force", "end_force"):
        assert getattr(sa, key) == pytest.approx(getattr(sb, key), rel=1e-12, abs=1e-12), key
    R = np.linspace(1.0, 1.8, 19)
    np.testing.assert_allclose(sa.stresses(R), sb.stresses(R), rtol=0, atol=1e-12)
    np.testing.assert_allclose(sa.elastic_stretches(R), sb.elastic_stretches(R), atol=1e-13)
    np.testing.assert_allclose(sa.moduli(R), sb.moduli(R), rtol=0, atol=1e-11)


def test_layer_energy_scaling_is_mu_W_plus_I5_over_2eps():
    """Layer(W + I5/2, mu, eps) == Layer(mu W + I5 / (2 eps)) (the general route), and an I6 term
    scales to I6 / (10 eps): mu_k Omega(F, D / sqrt(mu_k eps_k))."""
    mu, eps = 3.0, 0.5
    loads = dict(stretch=1.05, voltage=0.3, inner_pressure=0.1)
    scaled = Tube((Layer(1.2), Layer(1.6, shear_modulus=mu, permittivity=eps)), **loads)
    explicit = Tube(
        (
            Layer(1.2),
            Layer(
                1.6, Material("explicit", mu * (I1 - 3) / 2 + I5 / (2 * eps), check_units=False)
            ),
        ),
        **loads,
    )
    _same(solve_layered_state(scaled), solve_layered_state(explicit))
    nonideal = Material("nh+I6", (I1 - 3) / 2 + I5 / 2 + I6 / 10, check_units=False)
    scaled = Tube((Layer(1.2), Layer(1.6, nonideal, mu, eps)), **loads)
    explicit = Tube(
        (
            Layer(1.2),
            Layer(
                1.6,
                Material(
                    "e6", mu * (I1 - 3) / 2 + I5 / (2 * eps) + I6 / (10 * eps), check_units=False
                ),
            ),
        ),
        **loads,
    )
    s1, s2 = solve_layered_state(scaled), solve_layered_state(explicit)
    _same(s1, s2)
    R = np.array([1.3, 1.5])
    np.testing.assert_allclose(s1.moduli(R), s2.moduli(R), rtol=1e-12, atol=1e-12)


# -- 3. closed-form inflation (neo-Hookean, fixed lambda_z) -------------------------------------


@pytest.mark.parametrize(
    "tube",
    [
        Tube((Layer(1.5, growth=1.1),), stretch=1.2),
        BILAYER,
        dataclasses.replace(BILAYER, outer_pressure=0.07),
    ],
    ids=["one-layer", "bilayer", "bilayer-Po"],
)
@pytest.mark.parametrize("vbar", [0.0, 0.35])
def test_closed_form_inflation(tube, vbar):
    """P_i(r_i) in closed form at fixed lambda_z, held-back r_i: the solver returns that r_i
    (1e-10), its charge and axial force; the pressure response gives P_i there."""
    layers, lz = spec(tube), tube.stretch
    x0 = solve_layered_state(
        dataclasses.replace(tube, voltage=vbar, inner_pressure=tube.outer_pressure)
    ).r_i
    for r_i in x0 * np.array([1.013, 1.21, 1.77]):
        dp, c, nint, ro2 = nh_closed(layers, lz, r_i, vbar)
        P_i = tube.outer_pressure + dp
        st = solve_layered_state(dataclasses.replace(tube, voltage=vbar, inner_pressure=P_i))
        assert st.r_i == pytest.approx(r_i, rel=1e-10)
        assert st.charge == pytest.approx(c, rel=1e-10, abs=1e-12)
        N = nint + math.pi * (P_i * r_i**2 - tube.outer_pressure * ro2)
        assert st.axial_force == pytest.approx(N, rel=1e-10, abs=1e-10)
        assert st.sigma_rr(1.0) == pytest.approx(-P_i, abs=1e-12)
        assert st.sigma_rr(tube.outer_radius) == pytest.approx(-tube.outer_pressure, abs=1e-12)
    resp = pressure_response(dataclasses.replace(tube, voltage=vbar), x0 * np.array([1.1, 1.4]))
    for r_i, P in zip(resp["r_i"], resp["inner_pressure"]):
        assert P == pytest.approx(tube.outer_pressure + nh_closed(layers, lz, r_i, vbar)[0], 1e-11)


def test_closed_form_voltage_branch_and_asymptotes():
    """Vbar(r_i) at P_i - P_o = 0.1 against the closed form; the pressure asymptote at fixed
    lambda_z is sum mu_k g_r g_z / (g_theta lambda_z) ln(R_k / R_{k-1}) (no maximum)."""
    tube = dataclasses.replace(BILAYER, inner_pressure=0.1)
    resp = voltage_response(tube, points=9)
    assert resp["voltage"][0] == pytest.approx(0.0, abs=1e-7)  # Vbar ~ sqrt at the start
    assert np.all(np.diff(resp["voltage"]) > 0)
    for r_i, v in zip(resp["r_i"][1:], resp["voltage"][1:]):
        assert v == pytest.approx(nh_voltage(spec(tube), tube.stretch, r_i, 0.1), rel=1e-11)
    # Vbar_inf^2 (R_N - 1)^2 = (T_inf - dp) sum_k (G_k - G_{k-1}) / (eps_k lambda_z)
    t_inf = sum(
        mu * gr * gz / (gt * tube.stretch) * math.log(b / a)
        for a, b, (gr, gt, gz), mu, _ in spec(tube)
    )
    dG = sum(math.prod(g) * (b * b - a * a) / 2 / eps for a, b, g, _, eps in spec(tube))
    v_inf = math.sqrt((t_inf - 0.1) * dG / tube.stretch) / (tube.outer_radius - 1.0)
    vthr = layered_threshold(tube)
    assert vthr.kind == "asymptote" and vthr.value == pytest.approx(v_inf, rel=1e-11)
    assert v_inf - voltage_response(tube, [1e3])["voltage"][0] < 1e-9
    thr = layered_threshold(BILAYER, "pressure")
    p_inf = sum(
        mu * gr * gz / (gt * BILAYER.stretch) * math.log(b / a)
        for a, b, (gr, gt, gz), mu, _ in spec(BILAYER)
    )
    assert thr.kind == "asymptote" and thr.value == pytest.approx(p_inf, rel=1e-9)
    far = pressure_response(BILAYER, [10.0, 1e3])["inner_pressure"]
    assert far[0] < far[1] < thr.value and thr.value - far[1] < 1e-9


# -- 4. equilibrium, interfaces, force control ----------------------------------------------------

GENERAL = Tube(
    (
        Layer(1.2, gent(30), 6.0, 1.5, growth=LinearGrowth(1.0, 1.2, (1.0, 1.3, 1.0), 1.05)),
        Layer(1.5, mooney_rivlin(0.3), 1.0, 0.8, growth=(1.0, 1.0, 1.1)),
        Layer(1.9, neo_hookean(), 0.5, 2.0),
    ),
    stretch=1.05,
    voltage=0.3,
    inner_pressure=0.15,
    outer_pressure=0.02,
)


def test_equilibrium_residual_and_interfaces():
    st = solve_layered_state(GENERAL)
    assert st.quadrature_error < 1e-13
    h = 2e-3
    for a, b in zip(GENERAL.radii, GENERAL.radii[1:]):
        R = np.linspace(a + 3 * h, b - 3 * h, 5)
        # five-point derivative in R, d sigma_rr / dr = (d sigma_rr / dR) / (dr / dR)
        st_R = [st.sigma_rr(R + k * h) for k in (-2, -1, 1, 2)]
        r_R = [st.radius(R + k * h) for k in (-2, -1, 1, 2)]
        fd = lambda v: (v[0] - 8 * v[1] + 8 * v[2] - v[3]) / (12 * h)  # noqa: E731
        srr, stt, _ = st.stresses(R)
        np.testing.assert_allclose(fd(st_R) / fd(r_R), (stt - srr) / st.radius(R), atol=1e-8)
    assert st.sigma_rr(1.0) == pytest.approx(-0.15, abs=1e-13)
    assert st.sigma_rr(1.9) == pytest.approx(-0.02, abs=1e-13)
    for k, R in enumerate(GENERAL.radii[1:-1]):
        inner, outer = (GENERAL.layers[k], GENERAL.layers[k + 1])
        s_in, s_out = st.sigma_rr(R, side="inner"), st.sigma_rr(R, side="outer")
        assert s_in == pytest.approx(s_out, abs=1e-14)  # traction continuous
        d_in, d_out = st.displacement(R, side="inner"), st.displacement(R, side="outer")
        assert d_in == pytest.approx(d_out, rel=1e-14)  # D_r continuous
        assert st.radius(R, side="inner") == pytest.approx(st.interface_radii[k], rel=1e-14)
        e_in, e_out = st.electric_field(R, side="inner"), st.electric_field(R, side="outer")
        if k == 1:  # both ideal: E = D / eps jumps by the permittivity ratio
            assert e_in * inner.permittivity == pytest.approx(e_out * outer.permittivity, 1e-13)
        p_in, p_out = st.pressure(R, side="inner"), st.pressure(R, side="outer")
        assert abs(p_in - p_out) > 1e-3  # p jumps with tau_1
    prof = st.profiles(60)
    assert np.all(np.diff(prof["R"]) >= 0) and prof["layer"][-1] == 2


def test_slow_twin_scipy_quad_in_r():
    """A Gent / Mooney-Rivlin / neo-Hookean tube with constant anisotropic growth, re-integrated
    with scipy quad in the current radius r (R(r) in closed form, the layer scaling written
    here): outer traction, voltage and axial force of the solved state."""
    tube = Tube(
        tuple(dataclasses.replace(la, growth=(1.0, 1.15, 1.05)) for la in GENERAL.layers),
        **_loads(GENERAL),
    )
    st = solve_layered_state(tube)
    lz, c = st.stretch, st.charge
    sig, volt, force = -tube.inner_pressure, 0.0, 0.0
    for a, layer, ra, rb in zip(tube.radii, tube.layers, st.radii, st.radii[1:]):
        mu, eps, J = layer.shear_modulus, layer.permittivity, math.prod(layer.growth)
        s = math.sqrt(mu * eps)

        def args(r, a=a, ra=ra, g=layer.growth, J=J, s=s):
            R = math.sqrt(a * a + (r * r - ra * ra) * lz / J)
            l2, l3 = r / (g[1] * R), lz / g[2]
            return 1 / (l2 * l3), l2, l3, c / r / s

        def tau(r, mat=layer.material, mu=mu, args=args):
            return mu * mat.stress(*args(r))

        def field(r, mat=layer.material, mu=mu, s=s, args=args):
            return float(mu / s * mat.electric_field(*args(r)))

        sig += quad(lambda r, t=tau: (t(r)[1] - t(r)[0]) / r, ra, rb, epsabs=1e-15)[0]
        volt += quad(field, ra, rb, epsabs=1e-15)[0]
        n = quad(lambda r, t=tau: (2 * t(r)[2] - t(r)[0] - t(r)[1]) * r, ra, rb)[0]
        force += math.pi * n
    force += math.pi * (tube.inner_pressure * st.r_i**2 - tube.outer_pressure * st.r_o**2)
    assert sig == pytest.approx(-tube.outer_pressure, abs=1e-11)
    assert volt == pytest.approx(tube.physical_voltage, rel=1e-11)
    assert force == pytest.approx(st.axial_force, rel=1e-11, abs=1e-11)


@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("P_o", [0.0, 0.04])
def test_force_control_reproduces_stretch_control(closed, P_o):
    loads = dict(voltage=0.3, inner_pressure=0.12, outer_pressure=P_o, closed_ends=closed)
    sf = solve_layered_state(Tube(GENERAL.layers, axial_force=0.3, **loads))
    assert sf.end_force == pytest.approx(0.3, abs=1e-11)
    ends = math.pi * (0.12 * sf.r_i**2 - P_o * sf.r_o**2)
    assert sf.axial_force == pytest.approx(0.3 + (ends if closed else 0.0), abs=1e-11)
    ss = solve_layered_state(Tube(GENERAL.layers, stretch=sf.stretch, **loads))
    _same(sf, ss, tol=1e-11)
    assert sf.as_dict()["stretch"] == sf.stretch and sf.as_dict()["control"] == "force"
    # the response curve under force control passes through the state, at its stretch
    resp = voltage_response(Tube(GENERAL.layers, axial_force=0.3, **loads), [sf.r_i])
    assert resp["voltage"][0] == pytest.approx(0.3, rel=1e-11)
    assert resp["stretch"][0] == pytest.approx(sf.stretch, rel=1e-11)
    assert resp["axial_force"][0] == pytest.approx(sf.axial_force, rel=1e-11)


# -- 5. thresholds against response curves and independent maxima ------------------------------


def _nh_force_free_stretch(layers, r_i, vbar_of=None, pressure=False):
    """lambda_z with the closed-end (pressure) or free-end (voltage) axial balance, by brentq
    on the closed form; returns (lambda_z, load)."""

    def n(lz):
        if pressure:
            return nh_closed(layers, lz, r_i)[2]  # closed ends, F = 0: N_int = 0
        T, _, _, _ = nh_closed(layers, lz, r_i)
        q_over = T  # c^2 Q = T at P = 0
        ra2, Q, Lam = r_i * r_i, 0.0, 0.0
        for a, b, g, _, eps in layers:
            rb2 = ra2 + math.prod(g) * (b * b - a * a) / lz
            Q += (1 / ra2 - 1 / rb2) / (2 * eps)
            Lam += 0.5 * math.log(rb2 / ra2) / eps
            ra2 = rb2
        return nh_closed(layers, lz, r_i)[2] - math.pi * q_over / Q * Lam

    lz = brentq(n, 0.3, 5.0, xtol=1e-15, rtol=1e-15)
    if pressure:
        return lz, nh_closed(layers, lz, r_i)[0]
    return lz, nh_voltage(layers, lz, r_i)


@pytest.mark.parametrize("control", ["pressure", "voltage"])
def test_limit_points_under_force_control(control):
    """Closed ends, no end force: the inflation pressure has a maximum (neo-Hookean), and the
    voltage of a free tube has one; both located independently (brentq + minimize_scalar on
    the closed forms) and against the package's response curves."""
    layers = (Layer(1.1, shear_modulus=3.0, growth=1.1), Layer(1.3))
    tube = Tube(layers, axial_force=0.0, closed_ends=(control == "pressure"))
    thr = layered_threshold(tube, control)
    assert thr.kind == "limit point"
    sp_ = spec(tube)
    best = minimize_scalar(
        lambda x: -_nh_force_free_stretch(sp_, x, pressure=control == "pressure")[1],
        bounds=(0.8 * thr.lambda_i, 1.25 * thr.lambda_i),
        method="bounded",
        options={"xatol": 1e-11},
    )
    assert thr.value == pytest.approx(-best.fun, rel=1e-11)
    # lambda_i at the maximum: the root of a central-difference slope (accurate to ~1e-10)
    load = lambda x: _nh_force_free_stretch(sp_, x, pressure=control == "pressure")[1]  # noqa: E731
    top = brentq(lambda x: load(x + 1e-5) - load(x - 1e-5), 0.99 * best.x, 1.01 * best.x)
    assert thr.lambda_i == pytest.approx(top, rel=1e-8)
    lz_ref, _ = _nh_force_free_stretch(sp_, thr.lambda_i, pressure=control == "pressure")
    assert thr.stretch == pytest.approx(lz_ref, rel=1e-11)
    respond = pressure_response if control == "pressure" else voltage_response
    key = "inner_pressure" if control == "pressure" else "voltage"
    curve = respond(tube, points=25)[key]
    assert curve.max() <= thr.value * (1 + 1e-14) and curve[-1] == pytest.approx(thr.value, 1e-12)
    at = respond(tube, thr.lambda_i * np.array([0.97, 1.0, 1.03]))[key]
    assert at[1] == pytest.approx(thr.value, rel=1e-13) and at[0] < at[1] > at[2]
    # the maximum is the end of the branch: above it, no state; just below, one is solved
    over = {"pressure": "inner_pressure", "voltage": "voltage"}[control]
    with pytest.raises(BaseStateError, match="threshold"):
        solve_layered_state(dataclasses.replace(tube, **{over: thr.value * 1.001}))
    below = solve_layered_state(dataclasses.replace(tube, **{over: thr.value * 0.999}))
    assert below.r_i < thr.lambda_i


def test_no_pressure_maximum_at_fixed_stretch():
    thr = layered_threshold(
        Tube((Layer(1.1, shear_modulus=3.0, growth=1.1), Layer(1.3))), "pressure"
    )
    assert thr.kind == "asymptote" and math.isinf(thr.lambda_i)


def test_gent_locking_threshold():
    """A Gent inner layer at fixed lambda_z: Vbar rises until its inner face locks (the traction
    integral diverges there, only logarithmically); states just before are solved."""
    tube = Tube((Layer(1.3, gent(10), 2.0), Layer(1.6, growth=(1.0, 1.1, 1.0))), stretch=1.0)
    thr = layered_threshold(tube)
    assert thr.kind == "locking" and math.isinf(thr.value)
    resp = voltage_response(tube, points=15)
    assert np.all(np.diff(resp["voltage"]) > 0) and resp["r_i"][-1] < thr.lambda_i
    target = 0.5 * (resp["voltage"][-2] + resp["voltage"][-1])
    st = solve_layered_state(dataclasses.replace(tube, voltage=target))
    assert resp["r_i"][-2] < st.r_i < resp["r_i"][-1] and st.quadrature_error < 1e-12
    # the lock: the energy of the inner face is not finite beyond thr.lambda_i
    l1, l2, l3 = st.elastic_stretches(1.0)
    assert l1**2 + l2**2 + l3**2 < 13.0


# -- 6. bad input ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "make, words",
    [
        (lambda: Tube((Layer(2.0), Layer(1.5))), ["layers[2].outer_radius", "> 2"]),
        (lambda: Tube((Layer(1.5), Layer(1.5))), ["layers[2].outer_radius", "> 1.5"]),
        (lambda: Layer(0.9), ["outer_radius", "> 1"]),
        (lambda: Layer(1.5, growth=(1.0, 0.0, 1.0)), ["growth g_theta", "0.01 to 100"]),
        (lambda: Layer(1.5, growth=-1.0), ["growth", "0.01 to 100"]),
        (lambda: Layer(1.5, growth=(1.0, 2.0)), ["growth", "g_r, g_theta, g_z"]),
        (lambda: Layer(1.5, shear_modulus=0.0), ["shear_modulus", "1e-08 to 1e+08"]),
        (lambda: Layer(1.5, permittivity=math.inf), ["permittivity"]),
        (lambda: Tube((Layer(1.5, growth=lambda R: (R - 1.2, 1, 1)),)), ["growth function"]),
        (lambda: Tube((Layer(1.5),), stretch=1.0, axial_force=0.0), ["stretch", "axial_force"]),
        (lambda: Tube((Layer(1.5),), voltage=-0.1), ["voltage", "0 <="]),
        (lambda: Tube(()), ["layers", "at least one"]),
        (lambda: Tube((Layer(1.5),), inner_pressure=math.nan), ["inner_pressure"]),
    ],
)
def test_bad_input_is_one_line(make, words):
    with pytest.raises(ParameterError) as err:
        make()
    msg = str(err.value)
    assert "\n" not in msg and all(w in msg for w in words), msg


def test_voltage_beyond_threshold_raises():
    tube = Tube((Layer(1.5),))
    thr = layered_threshold(tube).value
    with pytest.raises(BaseStateError, match="voltage threshold") as err:
        solve_layered_state(dataclasses.replace(tube, voltage=thr))
    assert "\n" not in str(err.value)


def test_as_dict_is_json_and_has_the_keys():
    rec = json.loads(json.dumps(solve_layered_state(dataclasses.replace(GENERAL)).as_dict()))
    for key in (
        "lambda_i",
        "lambda_o",
        "r_i",
        "r_o",
        "interface_radii",
        "voltage_threshold",
        "stretch",
        "charge",
        "axial_force",
        "end_force",
        "layers",
    ):
        assert key in rec
    assert len(rec["interface_radii"]) == 2 and rec["layers"][0]["growth"]["inner"]


def test_energy_expression_layer_and_sympy_energy():
    w = Material("mine", sp.sympify("(I1 - 3)/2 + I5/2"))
    _same(
        solve_layered_state(Tube((Layer(1.4, w),), voltage=0.3)),
        solve_layered_state(Tube((Layer(1.4),), voltage=0.3)),
    )


# -- 7. the tube file and the command line ---------------------------------------------------

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml"


def test_example_tube_file():
    tube = load_tube(EXAMPLE)
    assert tube == Tube(
        (
            Layer(1.1, neo_hookean(), 10.0, 1.0, (1.0, 1.2, 1.0)),
            Layer(2.0, gent(97.2), growth=1.0),
        ),
        length=3.0,
        stretch=1.0,
        voltage=0.3,
        inner_pressure=0.05,
    )


GOOD = """length = 2.0
axial_force = 0.0
closed_ends = true
voltage = 0.2
inner_pressure = 0.05
[[layers]]
outer_radius = 1.2
energy = "(I1 - 3)/2 + (I1 - 3)**2/20 + I5/2"
growth = {inner = [1.0, 1.3, 1.0], outer = 1.0}
[[layers]]
outer_radius = 1.8
material = "mooney-rivlin"
alpha = 0.4
permittivity = 2.0
growth = [1.0, 1.0, 1.1]
"""


def test_tube_file_forms():
    tube = parse_tube(GOOD)
    first, second = tube.layers
    assert tube.control == "force" and tube.closed_ends and tube.length == 2.0
    assert first.growth == LinearGrowth(1.0, 1.2, (1.0, 1.3, 1.0), 1.0)
    assert str(first.material.energy) == str(sp.sympify("(I1 - 3)/2 + (I1 - 3)**2/20 + I5/2"))
    assert second.material.name == "mooney-rivlin(alpha=0.4)" and second.permittivity == 2.0


@pytest.mark.parametrize(
    "edit, line, words",
    [
        (("length = 2.0", "lenght = 2.0"), 1, ["lenght", "unknown key"]),
        (
            ("alpha = 0.4", "jm = 0.4"),
            13,
            ["layers.2.jm", 'parameter of material = "gent"', "which takes alpha"],
        ),
        (("outer_radius = 1.8", "outer_radius = 1.1"), 11, ["layers.2.outer_radius", "> 1.2"]),
        (("[1.0, 1.0, 1.1]", "[1.0, 0.0, 1.1]"), 15, ["layers.2.growth", "0.01 to 100"]),
        (("outer = 1.0}", "outer = -1.0}"), 9, ["layers.1.growth", "0.01 to 100"]),
        (("voltage = 0.2", "voltage = -0.2"), 4, ["voltage", "0 <="]),
        (("axial_force = 0.0", "stretch = 1.0\naxial_force = 0.0"), 2, ["stretch", "both"]),
        (('material = "mooney-rivlin"', 'material = "rubber"'), 12, ["rubber", "choose"]),
        (("alpha = 0.4", "alpha = 2"), 13, ["layers.2.alpha", "alpha = 2"]),
        # probe 8b: jm = 1e-300 was accepted, then blamed on the voltage and growth
        (
            ('material = "mooney-rivlin"\nalpha = 0.4', 'material = "gent"\njm = 1e-300'),
            13,
            ["layers.2.jm", "jm = 1e-300 is out of range; valid range: 0.001 <= jm"],
        ),
        (
            ('energy = "(I1 - 3)/2 + (I1 - 3)**2/20 + I5/2"', 'energy = "I1 + J"'),
            8,
            ["layers.1.energy", "J"],
        ),
        (("inner_pressure = 0.05", "inner_pressure = [1]"), 5, ["inner_pressure", "number"]),
        (("voltage = 0.2", "voltage = 0.2 ="), 4, ["invalid TOML"]),
    ],
)
def test_tube_file_errors_name_key_and_line(edit, line, words):
    text = GOOD.replace(*edit)
    with pytest.raises(ConfigError) as err:
        parse_tube(text, source="t.toml")
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith(f"t.toml:{line}:"), msg
    assert all(w in msg for w in words), msg


def test_tube_file_without_layers():
    with pytest.raises(ConfigError, match="missing \\[\\[layers\\]\\]"):
        parse_tube("voltage = 0.1\n")


def run_cli(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_cli_state_tube_file_and_overrides(capsys, tmp_path):
    status, out, err = run_cli(capsys, "state", "--tube", str(EXAMPLE), "--json")
    assert status == 0 and err == ""
    rec = json.loads(out)
    state = solve_layered_state(load_tube(EXAMPLE))
    for key in ("lambda_i", "lambda_o", "r_i", "r_o", "stretch", "axial_force"):
        assert rec[key] == getattr(state, key)
    assert rec["interface_radii"] == list(state.interface_radii)
    status, out, _ = run_cli(
        capsys,
        "state",
        "--tube",
        str(EXAMPLE),
        "--voltage",
        "0.4",
        "--axial-force",
        "0",
        "--closed-ends",
        "--json",
    )
    tube = dataclasses.replace(
        load_tube(EXAMPLE), voltage=0.4, stretch=None, axial_force=0.0, closed_ends=True
    )
    rec, state = json.loads(out), solve_layered_state(tube)
    assert status == 0 and rec["stretch"] == state.stretch and rec["control"] == "force"
    status, out, _ = run_cli(capsys, "state", "--tube", str(EXAMPLE))
    assert status == 0 and "interface radii" in out and f"{state.r_i:.6g}"[:4] in out
    # without a file: a pressure makes the one-layer tube a layered one
    status, out, _ = run_cli(
        capsys, "state", "--outer-radius", "2", "--inner-pressure", "0.1", "--json"
    )
    ref = solve_layered_state(Tube((Layer(2.0),), inner_pressure=0.1))
    assert status == 0 and json.loads(out)["lambda_i"] == ref.lambda_i


def test_cli_state_tube_errors_are_one_line(capsys, tmp_path):
    path = tmp_path / "t.toml"
    path.write_text(GOOD.replace("voltage = 0.2", "voltage = 3.0"))
    status, out, err = run_cli(capsys, "state", "--tube", str(path))
    assert status == 2 and out == "" and err.count("\n") == 1
    assert f"{path}:4: voltage:" in err and "threshold" in err
    for argv in (["--growth", "2"], ["--jm", "5"]):
        status, out, err = run_cli(capsys, "state", "--tube", str(EXAMPLE), *argv)
        assert status == 2 and out == "" and argv[0] in err and "one-layer" in err
    path.write_text(GOOD.replace("outer_radius = 1.8", "outer_radius = 1.1"))
    status, out, err = run_cli(capsys, "state", "--tube", str(path))
    assert status == 2 and f"{path}:11: layers.2.outer_radius" in err
    status, _, err = run_cli(capsys, "state")
    assert status == 2 and "--outer-radius (or --tube)" in err
    status, out, err = run_cli(
        capsys, "state", "--tube", str(EXAMPLE), "--stretch", "1.1", "--axial-force", "0"
    )
    assert status == 2 and out == "" and "both" in err
