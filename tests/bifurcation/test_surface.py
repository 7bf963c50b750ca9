"""Tests of the short-wave (surface) limit: the half-space problem at a face or interface of
any tube (electrogrowth.incremental.halfspace: traction-free and follower-pressure faces,
bonded interfaces) and its critical values (bifurcation.surface, directions.py).

Derivation and the numbers quoted here: docs/derivation-surface.md, and for pressure and
interfaces docs/derivation-layered-modes.md, section "Short waves at faces with pressure and
at interfaces".
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.bifurcation import directions, surface_march
from electrogrowth.bifurcation.surface import SurfaceLimit, ray_limit, short_wave_limit
from electrogrowth.errors import ParameterError
from electrogrowth.incremental.halfspace import (
    FACES,
    FaceProblem,
    InterfaceProblem,
    face_data,
    schur_target,
    surface_problem,
    surfaces,
    target_from_moduli,
)
from electrogrowth.incremental.impedance import ALL_PAIRS, face_impedance
from electrogrowth.incremental.stroh import stroh_matrix
from electrogrowth.incremental.stroh_limit import (
    decaying_solutions,
    limit_matrix,
    neo_hookean_secular,
)
from electrogrowth.model.layers import Layer, Tube
from electrogrowth.model.materials import gent, mooney_rivlin
from electrogrowth.model.moduli import MODULI_INDEX, neo_hookean_moduli
from tests.tubes import TUBES

try:
    from electrogrowth.bifurcation.critical import critical_value
except ImportError:  # the module may move during a refactoring
    from electrogrowth.bifurcation import critical_value

HALF_PI = 0.5 * math.pi
PSI = np.linspace(0.0, HALF_PI, 9)
J = np.block([[np.zeros((4, 4)), np.eye(4)], [-np.eye(4), np.zeros((4, 4))]])


def biot_stretch() -> float:
    """Biot's critical stretch in uniaxial compression, independently: the root beta of
    beta^3 + beta^2 + 3 beta - 1 = 0 (beta = lambda^(3/2), docs section 6)."""
    beta = brentq(lambda b: b**3 + b**2 + 3 * b - 1, 0.0, 1.0, xtol=1e-17, rtol=1e-15)
    return beta ** (2.0 / 3.0)


def nh_state(l2, l3, d):
    """Neo-Hookean face moduli and p of a traction-free face (sigma_rr = 0)."""
    l1 = 1.0 / (l2 * l3)
    return l1, neo_hookean_moduli(l1, l2, l3, d), l1 * l1 + d * d


def nh_worst(l1, l2, l3, d) -> float:
    """min over psi of the neo-Hookean secular function P (closed form, docs section 5):
    P is a cubic in beta, beta ranges over [l2, l3] / l1; its interior minimum (3 beta^2 +
    2 beta + 3 - delta = 0) exists for delta > 3."""
    delta = d * d / (l1 * l1)
    lo, hi = sorted((l2 / l1, l3 / l1))
    P = lambda b: b**3 + b**2 + (3 - delta) * b - (1 + delta)  # noqa: E731
    cands = [P(lo), P(hi)]
    if 12 * delta - 32 > 0:
        b = (-2 + math.sqrt(12 * delta - 32)) / 6
        if lo < b < hi:
            cands.append(P(b))
    return min(cands)


def nh_tube_critical(params, solve_for, x0, x1, steps=400):
    """Critical value of the neo-Hookean tube from the closed form alone: the first zero
    of min_face min_psi P along x0 -> x1."""

    def h(x):
        st = solve_base_state(params.at(solve_for, x))
        out = []
        for R in (1.0, params.outer_radius):
            l1, l2, l3 = (float(v) for v in st.elastic_stretches(R))
            out.append(nh_worst(l1, l2, l3, float(st.displacement(R))))
        return min(out)

    xs = np.linspace(x0, x1, steps)
    hs = [h(x) for x in xs]
    assert hs[0] > 0
    i = next(i for i in range(steps - 1) if hs[i + 1] <= 0)
    return brentq(h, xs[i], xs[i + 1], xtol=1e-15, rtol=1e-15)


def pressure_impedance(P, psi) -> np.ndarray:
    """The scaled limit Z of the follower-pressure impedance (docs)."""
    c, s = math.cos(psi), math.sin(psi)
    return -P * np.array([[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], [0, 0, 0, 0.0]])


def schur_z(mod, p, psi, face) -> np.ndarray:
    """z = Y X^-1 of the decaying subspace from the ordered real Schur form (independent of
    the projector route of the compiled kernels)."""
    Q, _, _ = decaying_solutions(limit_matrix(mod, p, psi), face)
    return Q[4:] @ np.linalg.inv(Q[:4])


def normalised(z) -> float:
    return 1.0 / math.sqrt(np.linalg.det(np.eye(4) + z.T @ z))


def random_face(rng):
    """Neo-Hookean moduli at random stretches and field, p at random (not a free face)."""
    l2, l3 = rng.uniform(0.7, 1.4, 2)
    d = rng.uniform(-0.6, 0.6)
    l1 = 1.0 / (l2 * l3)
    return neo_hookean_moduli(l1, l2, l3, d), l1 * l1 + d * d + rng.uniform(-0.5, 0.5)


@pytest.fixture(scope="module")
def generic_energies():
    """Gent and Mooney-Rivlin, each with its base state solved once for the module."""
    mats = {"gent": gent(20.0), "mr": mooney_rivlin(0.3)}
    solve_base_state(Tube.uniform(material=mats["gent"]))
    return mats


# --- the limit matrix and the target --------------------------------------------------------


def test_limit_matrix_is_the_scaled_limit_of_the_stroh_matrix():
    """T^-1 G(Lam cos psi, Lam sin psi) T / Lam -> N(psi) like 1/Lam, for arbitrary moduli;
    N is Hamiltonian and homogeneous of degree 0 (its eigenvalues come in +- pairs)."""
    rng = np.random.default_rng(7)
    for _ in range(5):
        mod = rng.uniform(0.3, 2.0, 23)
        p = rng.uniform(-1.0, 2.0)
        for psi in (0.0, 0.4, 1.1, HALF_PI):
            N = limit_matrix(mod, p, psi)
            errs = []
            for lam in (1e3, 1e6):
                G = np.empty((8, 8))
                stroh_matrix(mod, p, lam * math.cos(psi), lam * math.sin(psi), G)
                T = np.array([1, 1, 1, lam, lam, lam, lam, 1.0])
                errs.append(np.abs(G * T[None, :] / T[:, None] / lam - N).max())
            assert errs[1] < 1e-5 * max(1.0, np.abs(N).max())
            assert 5e2 < errs[0] / max(errs[1], 1e-300) < 2e3 or errs[0] < 1e-12
            assert np.abs(J @ N - (J @ N).T).max() < 1e-13
            ev = np.linalg.eigvals(N)
            assert np.abs(ev[:, None] + ev[None, :]).min(axis=1).max() < 1e-7


def test_projector_target_equals_schur_target(generic_energies):
    """The vectorised target (spectral projector) and the ordered-Schur one agree."""
    rng = np.random.default_rng(11)
    for mat in (gent(20.0), mooney_rivlin(0.3)):
        for _ in range(6):
            l2, l3, d = rng.uniform(0.7, 1.5), rng.uniform(0.6, 1.6), rng.uniform(0, 1.2)
            l1 = 1.0 / (l2 * l3)
            mod, p = mat.moduli(l1, l2, l3, d), float(mat.stress(l1, l2, l3, d)[0])
            psi = rng.uniform(0, HALF_PI, 4)
            for face in FACES:
                fast = target_from_moduli(mod, p, psi, face)
                slow = [schur_target(mod, p, x, face) for x in psi]
                assert np.allclose(fast, slow, rtol=0, atol=1e-12)


def test_ellipticity_loss_is_detected():
    """A negative shear modulus: imaginary nu, no decaying split: NaN, not a number."""
    mod = neo_hookean_moduli(1.0, 1.0, 1.0, 0.0)
    problem = FaceProblem.from_moduli(mod, 1.0, "inner")
    assert problem.margin(0.5) > 0.1
    bad = mod.copy()
    bad[MODULI_INDEX["A2323"]] = bad[MODULI_INDEX["A3232"]] = -0.5
    problem = FaceProblem.from_moduli(bad, 1.0, "inner")
    assert problem.margin(0.3) < 1e-9
    assert np.isnan(problem.target(0.3))
    Q, nu, margin = decaying_solutions(limit_matrix(bad, 1.0, 0.3), "outer")
    assert np.isnan(Q).all() and margin < 1e-9

    # the march reports it (kind "ellipticity") instead of a value
    def fake(state):
        g = state.tube.growth
        return directions.Sample(math.nan if g > 1.7 else 2.0 - g, "inner", 0.5)

    kind, value, bracket, _ = surface_march.locate(Tube.uniform(), "growth", None, fake, 1e-12)
    assert kind == "ellipticity" and abs(value - 1.7) < 1e-11 and bracket is None


def test_moduli_past_double_range_raise_not_a_nan():
    """Probe 11a D3: moduli whose products pass 1e308 (c12^2 at ~1e154) made the half-space
    matrix infinite, its target NaN, read as a loss of strong ellipticity, with numpy's
    "overflow encountered in multiply" on stderr. Moduli just below stay a number."""
    from electrogrowth.errors import ConvergenceError

    mod = neo_hookean_moduli(0.8, 1.1, 1.0 / 0.88, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        assert np.isfinite(FaceProblem.from_moduli(1e150 * mod, 1e150, "outer").target(0.3))
        with pytest.raises(ConvergenceError, match="overflows double precision"):
            FaceProblem.from_moduli(1e160 * mod, 1e160, "outer")


def test_an_exponential_energy_compressed_warns_nothing_and_claims_no_ellipticity_loss():
    """Probe 11a D3: Biot's ratio of a Fung-type energy (the crease criterion's text of any
    verdict on it) marched its face until the moduli overflowed: RuntimeWarnings reached
    stderr from the Python API, and the overflow's NaN was reported as the loss of strong
    ellipticity at lambda_z = 0.0921. The march now says the half-space overflows."""
    from electrogrowth import Material
    from electrogrowth.errors import ConvergenceError

    fung = Material("fung-d3", "(I1-3)/2 + I5/2 + 0.1*(exp((I1-3)**2)-1)")  # none cached
    tube = Tube.uniform(2.0, length=1.0, material=fung)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ConvergenceError, match="overflows double precision"):
            ray_limit(tube, 0, 1, "stretch", side="compression")


def test_pressure_impedance_is_the_scaled_limit():
    """T_S^-1 z_P T_U -> Z (S~ = S / Lam, U~_4 = U_4 / Lam) with an O(1/Lam) error."""
    P, psi = 0.7, 0.4
    errs = []
    for lam in (1e3, 1e6):
        m, kr = lam * math.cos(psi), lam * math.sin(psi)
        zp = face_impedance(P, m, kr, ALL_PAIRS, 1.0)
        scaled = np.diag([1 / lam] * 3 + [1.0]) @ zp @ np.diag([1.0] * 3 + [lam])
        errs.append(np.max(np.abs(scaled - pressure_impedance(P, psi))))
    assert errs[1] < 1e-5 and errs[0] / errs[1] > 0.5e3


def test_pressure_face_target_equals_schur_route():
    """sign(det X) det(Y - Z X) / sqrt(det M^T M) (projector, compiled) = det(z - Z) /
    sqrt(det(I + z^T z)) (Schur), both faces, random states and pressures; P = 0 gives the
    traction-free target exactly."""
    rng = np.random.default_rng(7)
    for _ in range(6):
        mod, p = random_face(rng)
        P = rng.uniform(-1.0, 1.0)
        for face in ("inner", "outer"):
            prob = FaceProblem.from_moduli(mod, p, face, pressure=P)
            f = prob.target(PSI)
            ref = [
                np.linalg.det(schur_z(mod, p, x, face) - pressure_impedance(P, x))
                * normalised(schur_z(mod, p, x, face))
                for x in PSI
            ]
            np.testing.assert_allclose(f, ref, rtol=0, atol=1e-12)
            assert np.all(np.abs(f) <= 1 + P * P)
            free = FaceProblem.from_moduli(mod, p, face)
            assert np.array_equal(
                FaceProblem.from_moduli(mod, p, face, pressure=0.0).target(PSI), free.target(PSI)
            )


def test_interface_target_equals_schur_route_and_is_bounded():
    rng = np.random.default_rng(11)
    for _ in range(6):
        (mb, pb), (ma, pa) = random_face(rng), random_face(rng)
        prob = InterfaceProblem.from_moduli(mb, pb, ma, pa)
        f = prob.target(PSI)
        ref = []
        for x in PSI:
            zb, za = schur_z(mb, pb, x, "outer"), schur_z(ma, pa, x, "inner")
            assert np.allclose(zb, zb.T, atol=1e-10) and np.allclose(za, za.T, atol=1e-10)
            ref.append(np.linalg.det(zb - za) * normalised(zb) * normalised(za))
        np.testing.assert_allclose(f, ref, rtol=0, atol=1e-12)
        assert np.all(np.abs(f) <= 1.0)
        np.testing.assert_allclose([prob.target_scalar(x) for x in PSI], f, rtol=0, atol=1e-15)


def test_psi_symmetry_of_pressure_and_interface_problems():
    """f(psi) = f(pi - psi): [0, pi/2] covers every direction with pressure and at
    interfaces too."""
    rng = np.random.default_rng(3)
    mod, p = random_face(rng)
    (mb, pb), (ma, pa) = random_face(rng), random_face(rng)
    for prob in (
        FaceProblem.from_moduli(mod, p, "inner", pressure=0.6),
        FaceProblem.from_moduli(mod, p, "outer", pressure=-0.4),
        InterfaceProblem.from_moduli(mb, pb, ma, pa),
    ):
        np.testing.assert_allclose(prob.target(math.pi - PSI), prob.target(PSI), atol=1e-13)


#: the tubes of the fixture, and a three-layer one with two interfaces (moduli 10, 0.3, 1)
SURFACE_TUBES = {
    **TUBES,
    "three-layer": Tube(
        (Layer(1.1, shear_modulus=10.0), Layer(1.5, shear_modulus=0.3), Layer(2.0))
    ),
}


@pytest.mark.parametrize("tube", SURFACE_TUBES.values(), ids=SURFACE_TUBES)
def test_unloaded_tube_is_stable_at_every_surface(tube):
    """On the reference state f > 0 at every face and interface, whose stable signs are +1:
    at a face the decaying solutions decay into the wall (Re nu < 0 at the inner face, > 0
    at the outer) with a symmetric, negative (inner) / positive (outer) definite impedance;
    at an interface z_b > 0 below and z_a < 0 above."""
    state = solve_base_state(tube.reference())
    n = len(tube.layers)
    assert surfaces(state) == FACES + tuple(f"interface-{k}" for k in range(1, n))
    assert directions.stable_signs(tube) == {s: 1.0 for s in surfaces(state)}
    for face, sign in (("inner", -1.0), ("outer", 1.0)):
        mod, p, _ = face_data(state, face)
        assert np.all(target_from_moduli(mod, p, PSI, face) > 0)
        for x in (*PSI, 0.7):
            Q, nu, _ = decaying_solutions(limit_matrix(mod, p, x), face)
            assert np.all(sign * nu.real > 0)  # Re nu < 0 decays into r > r_i, > 0 into r < r_o
            z = Q[4:] @ np.linalg.inv(Q[:4])
            assert np.allclose(z, z.T, atol=1e-12)
            assert np.all(sign * np.linalg.eigvalsh(0.5 * (z + z.T)) > 0)
    for name in surfaces(state)[2:]:
        R = tube.radii[int(name.split("-")[1])]
        for x in PSI:
            zb = schur_z(
                state.moduli(R, side="inner"), state.pressure(R, side="inner"), x, "outer"
            )
            za = schur_z(
                state.moduli(R, side="outer"), state.pressure(R, side="outer"), x, "inner"
            )
            assert np.all(np.linalg.eigvalsh(zb) > 0) and np.all(np.linalg.eigvalsh(za) < 0)
        assert np.all(surface_problem(state, name).target(PSI) > 0)
    with pytest.raises(ParameterError, match=f"interface-{n}"):
        surface_problem(state, f"interface-{n}")


#: the tubes of the fixture, and Gent and Mooney-Rivlin paper tubes stretched under voltage
SYMMETRY_TUBES = {
    **TUBES,
    "gent": Tube.uniform(material=gent(20.0), stretch=1.3, voltage=0.3),
    "mooney-rivlin": Tube.uniform(material=mooney_rivlin(0.3), stretch=1.3, voltage=0.3),
}


@pytest.mark.parametrize("tube", SYMMETRY_TUBES.values(), ids=SYMMETRY_TUBES)
def test_psi_symmetry_at_every_surface(tube):
    """f(psi) = f(-psi) = f(pi - psi) (k -> -k is z -> -z) at every face (with its pressure)
    and interface: [0, pi/2] covers every direction."""
    psi = np.array([0.13, 0.7, 1.3])
    state = solve_base_state(tube)
    for name in surfaces(state):
        f = surface_problem(state, name).target(psi)
        assert np.all(np.isfinite(f))
        for other in (-psi, math.pi - psi, psi + math.pi):
            assert np.allclose(surface_problem(state, name).target(other), f, atol=1e-13)


# --- neo-Hookean: Biot and the closed-form electro-elastic criterion ----------------------


def test_biot_uniaxial_compression():
    """g = 1, Vbar = 0: homogeneous uniaxial compression; wrinkles along z at Biot's
    lambda_z = 0.443746 (root of the cubic, computed independently)."""
    res = short_wave_limit(Tube.uniform(outer_radius=1.4), "stretch")
    assert isinstance(res, SurfaceLimit) and res.kind == "surface"
    assert abs(res.value - biot_stretch()) < 1e-12
    assert round(res.value, 6) == 0.443746
    assert res.psi == HALF_PI and res.ratio is None
    assert res.error_estimate < 1e-10
    assert res.params.stretch == res.value and res.side == "compression"


def test_neo_hookean_secular_equation_at_synthetic_states():
    """The general solver (23 moduli) vanishes exactly where the scalar electro-elastic
    secular equation does: critical d = l1 sqrt(delta*), delta* = (beta^3 + beta^2 +
    3 beta - 1)/(beta + 1), both faces, several directions; same sign elsewhere."""
    rng = np.random.default_rng(3)
    for l2, l3, psi in [
        (1.2, 0.8, 1.2),
        (1.0, 1.3, 0.4),
        (1.5, 1.1, 0.0),
        (0.9, 0.9, HALF_PI),
        (1.3, 1.6, 0.9),
    ]:
        l1 = 1.0 / (l2 * l3)
        beta = math.sqrt(l2**2 * math.cos(psi) ** 2 + l3**2 * math.sin(psi) ** 2) / l1
        d_crit = l1 * math.sqrt((beta**3 + beta**2 + 3 * beta - 1) / (beta + 1))
        for face in FACES:
            f = lambda d: float(target_from_moduli(*nh_state(l2, l3, d)[1:], psi, face))  # noqa
            root = brentq(f, 0.5 * d_crit, 1.5 * d_crit, xtol=1e-15, rtol=1e-15)
            assert abs(root - d_crit) < 1e-12 * d_crit
        for d in rng.uniform(0, 2.5, 4):
            Pv = neo_hookean_secular(l1, l2, l3, d, psi)
            if abs(Pv) > 1e-6:
                for face in FACES:
                    assert np.sign(
                        target_from_moduli(*nh_state(l2, l3, d)[1:], psi, face)
                    ) == np.sign(Pv)


def test_neo_hookean_worst_direction_is_an_endpoint():
    """Where P'(beta) = 0, P = -2 beta^3 - 4 beta^2 - 2 beta - 4 < 0: P can first vanish
    only at beta(0) or beta(pi/2), so the neo-Hookean worst direction is psi = 0 or pi/2."""
    beta = np.linspace(0.01, 20, 2000)
    delta = 3 * beta**2 + 2 * beta + 3  # P'(beta) = 0
    P = beta**3 + beta**2 + (3 - delta) * beta - (1 + delta)
    assert np.allclose(P, -2 * beta**3 - 4 * beta**2 - 2 * beta - 4) and np.all(P < 0)


@pytest.mark.parametrize(
    "params, solve_for, side, x1, face, psi, closed",
    [
        (
            Tube.uniform(outer_radius=1.4),
            "voltage",
            None,
            1.0,
            "inner",
            HALF_PI,
            0.8478824129396783,
        ),
        (
            Tube.uniform(outer_radius=1.4, voltage=0.4),
            "stretch",
            "extension",
            2.5,
            "outer",
            0.0,
            None,
        ),
        (
            Tube.uniform(outer_radius=2.0, stretch=1.2, voltage=0.2),
            "growth",
            None,
            3.0,
            "inner",
            HALF_PI,
            2.7006482944111054,
        ),
    ],
)
def test_neo_hookean_tube_against_closed_form(params, solve_for, side, x1, face, psi, closed):
    """Tube states with voltage: the general solver's critical value, face and direction
    equal those of the closed-form criterion (independent march + Brent) to 1e-10, as
    tabulated in derivation-surface.md §5; the same tube built of one Layer gives the same
    values to 1e-10."""
    res = short_wave_limit(params, solve_for, side=side)
    x0 = {"voltage": 0.0, "stretch": params.growth, "growth": 1.0}[solve_for]
    exact = nh_tube_critical(params, solve_for, x0, x1)
    assert res.kind == "surface"
    assert abs(res.value - exact) < 1e-10 * max(1.0, exact)
    assert res.face == face and res.psi == psi
    if closed is not None:
        assert abs(res.value - closed) < 1e-10
    tube = Tube(
        (Layer(params.outer_radius, params.material, growth=params.growth),),
        length=params.length,
        stretch=params.stretch,
        voltage=params.voltage,
    )
    lim = short_wave_limit(tube, solve_for, side=side)
    assert lim.kind == "surface" and lim.face == face
    assert abs(lim.value - res.value) < 1e-10
    if closed is not None:
        assert abs(lim.value - closed) < 1e-10


def test_issue_10_extension_example():
    """Issue 10: Rbar_o = 1.4, L = 1, Vbar = 0.4, stretch on the extension side. The scan's
    Richardson estimate is 2.4559 +- 0.0013; the exact limit is at the OUTER face with
    hoop wrinkles (psi = 0, k r / m -> 0)."""
    params = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.4)
    res = short_wave_limit(params, "stretch", side="extension")
    assert res.kind == "surface" and abs(res.value - 2.4559) < 0.0013
    assert res.face == "outer" and res.psi == 0.0 and res.ratio == 0.0
    assert res.error_estimate < 1e-10
    again = short_wave_limit(params, "stretch", side="extension", rtol=1e-10)
    assert abs(again.value - res.value) < 1e-10
    assert abs(res.value - 2.456221128743) < 1e-11


# --- identities ------------------------------------------------------------------------------


def test_growth_is_a_rescaling():
    """(g, lambda_z, Vbar) ~ (1, lambda_z / g, Vbar / g) for the short-wave values."""
    g = 1.3
    a = short_wave_limit(Tube.uniform(growth=g, voltage=0.3), "stretch")
    b = short_wave_limit(Tube.uniform(voltage=0.3 / g), "stretch")
    assert abs(a.value - g * b.value) < 1e-10 and (a.face, a.psi) == (b.face, b.psi)
    g = 1.2
    a = short_wave_limit(Tube.uniform(outer_radius=2.0, growth=g, stretch=1.5), "voltage")
    b = short_wave_limit(Tube.uniform(outer_radius=2.0, stretch=1.5 / g), "voltage")
    assert abs(a.value - g * b.value) < 1e-10 and (a.face, a.psi) == (b.face, b.psi)
    # growth at fixed lambda_z = 1, Vbar = 0 is uniaxial compression lambda_z / g: Biot
    c = short_wave_limit(Tube.uniform(), "growth")
    assert abs(c.value - 1.0 / biot_stretch()) < 1e-10 and c.psi == HALF_PI
    # with voltage: the growth-critical state is critical for the rescaled tube
    c = short_wave_limit(Tube.uniform(stretch=1.1, voltage=0.2), "growth")
    st = solve_base_state(Tube.uniform(stretch=1.1 / c.value, voltage=0.2 / c.value))
    signs = directions.stable_signs(Tube.uniform())
    h = directions.sampler(FACES, signs, directions.Resolution(25, 1e-10, 1e-12))(st)
    assert abs(h.value) < 1e-12 and h.face == c.face


def test_finite_modes_approach_the_limit_like_one_over_j():
    """Modes (j m0, j n0) of the impedance solver tend to the half-space value in the
    direction tan psi = k r / m of the ray, like 1/j (rate fitted), for an oblique ray and
    for m = 0 (psi = pi/2)."""
    params = Tube.uniform(outer_radius=1.4, voltage=0.3)
    lim = ray_limit(params, 3, 1, "growth")
    assert lim.kind == "surface" and 0 < lim.psi < HALF_PI
    js = np.array([8, 16, 32, 64])
    xs = np.array([critical_value(params, 3 * j, j, "growth").value for j in js])
    rate = np.polyfit(np.log(js), np.log(np.abs(xs - lim.value)), 1)[0]
    assert abs(rate + 1.0) < 0.1
    assert abs(xs[-1] - lim.value) > 1e-4  # finite modes are far ...
    assert abs(2 * xs[-1] - xs[-2] - lim.value) < 2e-5  # ... their 1/j extrapolation is not
    # m = 0: wrinkles along z; the short-wave limit of the tube is in that direction too
    params = Tube.uniform(outer_radius=1.4)
    lim = ray_limit(params, 0, 1, "voltage")
    assert lim.psi == HALF_PI and lim.ratio is None
    assert lim.value == pytest.approx(short_wave_limit(params, "voltage").value, abs=1e-13)
    js = np.array([16, 32, 64])
    xs = np.array([critical_value(params, 0, j, "voltage").value for j in js])
    rate = np.polyfit(np.log(js), np.log(np.abs(xs - lim.value)), 1)[0]
    assert abs(rate + 1.0) < 0.15
    assert abs(2 * xs[-1] - xs[-2] - lim.value) < 2e-5


def test_identical_layers_equal_one_layer():
    """Splitting a tube into identical layers changes no short-wave limit (1e-10), and the
    interface between identical layers is never critical (its target stays far from 0)."""
    one = Tube.uniform(outer_radius=1.4, voltage=0.4)
    two = Tube((Layer(1.15), Layer(1.4)), voltage=0.4)
    a = short_wave_limit(one, "stretch", side="extension")
    b = short_wave_limit(two, "stretch", side="extension")
    assert b.kind == "surface" and b.face == a.face == "outer"
    assert abs(a.value - 2.456221128743075) < 1e-10  # the closed form (derivation-surface §5)
    assert abs(b.value - a.value) < 1e-10 and b.psi == a.psi
    # the interface along the whole path up to the critical state
    for x in np.linspace(1.0, b.value, 5):
        state = solve_base_state(two.at("stretch", x))
        v, _ = directions.worst_direction(surface_problem(state, "interface-1"))
        assert v > 0.05
    only = short_wave_limit(two, "stretch", side="extension", faces=("interface-1",))
    assert only.kind in ("none", "threshold")
    # past a film the march goes on toward the asymptote until the interface (a target
    # ~1e-18 there) is no longer resolved: a threshold whose estimate covers the gap left
    assert only.error_estimate > 0 and "asymptote" in only.message


def test_equal_pressure_on_both_faces_changes_nothing():
    """P_i -> P_i + c, P_o -> P_o + c: the deformation is the same, p shifts by c, Sigma by
    c L, and the follower-pressure face condition compensates exactly (docs): the short-wave
    limit and a finite mode's critical value agree to 1e-10."""
    layers = (Layer(1.2, shear_modulus=2.0), Layer(1.6))
    base = Tube(layers, inner_pressure=0.15, outer_pressure=0.05)
    shifted = Tube(layers, inner_pressure=0.55, outer_pressure=0.45)
    a = short_wave_limit(base, "voltage")
    b = short_wave_limit(shifted, "voltage")
    assert a.kind == b.kind == "surface" and a.face == b.face
    assert abs(a.value - b.value) < 1e-10
    ca = critical_value(base, 3, 2, "voltage").value
    cb = critical_value(shifted, 3, 2, "voltage").value
    assert abs(ca - cb) < 1e-10


def test_pressurised_face_limit_is_approached_by_finite_modes():
    """One-layer tube inflated by P_i = 0.15 under voltage: the inner (pressurised) face is
    critical along z (psi = pi/2); the modes (0, j) approach the limit like 1/j (impedance
    kernel; its face condition is z_P, the half-space's is the limit Z). Without the Z term
    the limit would be 0.66751, with Z of the wrong sign 0.66819: both excluded here."""
    tube = Tube((Layer(1.4),), inner_pressure=0.15, voltage=0.3)
    lim = ray_limit(tube, 0, 1, "voltage")
    worst = short_wave_limit(tube, "voltage")
    assert lim.kind == worst.kind == "surface" and lim.face == worst.face == "inner"
    assert worst.psi == HALF_PI and abs(worst.value - lim.value) < 1e-12
    assert abs(lim.value - 0.6625868806198049) < 1e-9
    x = {j: critical_value(tube, 0, j, "voltage").value for j in (16, 32, 64)}
    d = {j: v - lim.value for j, v in x.items()}
    assert all(-1e-3 < d[j] < 0 for j in d)  # from below, shrinking
    assert 1.6 < d[16] / d[32] < 2.2 and 1.7 < d[32] / d[64] < 2.2
    assert abs(2 * x[64] - x[32] - lim.value) < 3e-5  # Richardson in 1/j


# --- other energies -------------------------------------------------------------------------


def test_mooney_rivlin_biot_along_z_but_oblique_wrinkles_first(generic_energies):
    """Mooney-Rivlin in uniaxial compression: along z the in-plane problem is neo-Hookean
    with mu = C1 + C2 lambda_r^2, so the m = 0 ray gives Biot exactly; but an oblique
    direction is reached first (lambda_z = 0.47261 > Biot), confirmed by finite modes."""
    params = Tube.uniform(outer_radius=1.4, material=generic_energies["mr"])
    along_z = ray_limit(params, 0, 1, "stretch")
    assert abs(along_z.value - biot_stretch()) < 1e-9
    worst = short_wave_limit(params, "stretch")
    assert worst.kind == "surface" and 1.1 < worst.psi < 1.3
    assert worst.value == pytest.approx(0.4726130556, abs=1e-9)
    assert worst.error_estimate < 1e-10
    for dpsi in (-0.05, 0.05):  # the worst direction: other directions come later
        other = short_wave_limit(params, "stretch", psi=worst.psi + dpsi)
        assert other.value < worst.value - 1e-4
    fixed = short_wave_limit(params, "stretch", psi=worst.psi)
    assert fixed.value == pytest.approx(worst.value, abs=1e-12)
    ray = ray_limit(params, 5, 1, "stretch")  # tan psi = k r / m close to the worst one
    assert ray.value <= worst.value + 1e-14
    xs = [critical_value(params, 5 * j, j, "stretch").value for j in (32, 64)]
    assert abs(2 * xs[1] - xs[0] - ray.value) < 5e-6
    assert abs(xs[1] - ray.value) > 5e-5


def test_gent_compression_and_voltage(generic_energies):
    """Gent (Jm = 20): uniaxial compression wrinkles along z at 0.42756 (stiffening delays
    Biot's 0.44375), confirmed by the m = 0 modes; with voltage both faces are searched
    and the first one reported."""
    params = Tube.uniform(outer_radius=1.4, material=generic_energies["gent"])
    res = short_wave_limit(params, "stretch")
    assert res.kind == "surface" and res.psi == HALF_PI
    assert res.value == pytest.approx(0.4275605821, abs=1e-9)
    xs = [critical_value(params, 0, j, "stretch").value for j in (32, 64)]
    assert abs(2 * xs[1] - xs[0] - res.value) < 1e-5
    params = dataclasses.replace(params, stretch=1.5)
    both = short_wave_limit(params, "voltage")
    outer = short_wave_limit(params, "voltage", faces=("outer",))
    assert both.face == "inner" and outer.face == "outer"
    assert both.value == pytest.approx(0.6906535844, abs=1e-9)
    assert outer.value == pytest.approx(0.6992191780, abs=1e-9)


def test_both_faces_neo_hookean():
    """Each face alone, and both: the combined value is the first reached."""
    params = Tube.uniform(outer_radius=1.4)
    inner = short_wave_limit(params, "voltage", faces=("inner",))
    outer = short_wave_limit(params, "voltage", faces="outer")
    both = short_wave_limit(params, "voltage")
    assert inner.face == "inner" and outer.face == "outer"
    assert inner.value == pytest.approx(0.8478824129, abs=1e-9)
    assert outer.value == pytest.approx(0.9063041550, abs=1e-9)
    assert both.value == inner.value and both.face == "inner"


def test_threshold_none_and_errors():
    """Base state lost first (kind threshold), nothing in range (none), bad input."""
    res = short_wave_limit(Tube.uniform(outer_radius=1.4), "stretch", side="extension")
    assert res.kind == "none" and math.isnan(res.value) and res.face is None

    # a face that stays stable until the base state is lost (a sampler that never
    # vanishes): kind threshold, where the voltage threshold falls to Vbar = 0.4, i.e.
    # Vbar_inf = sqrt((Rbar_o^2 - 1) ln Rbar_o / 2) / (lambda_z (Rbar_o - 1)) = 0.4
    def stable(state):
        return directions.Sample(1.0, "inner", 0.0)

    params = Tube.uniform(outer_radius=1.4, voltage=0.4)
    kind, value, _, _ = surface_march.locate(params, "stretch", "extension", stable, 1e-12)
    assert kind == "threshold"
    assert abs(value - math.sqrt(0.96 * math.log(1.4) / 2) / (0.4 * 0.4)) < 1e-10
    kind, value, _, _ = surface_march.locate(
        Tube.uniform(outer_radius=2.0), "voltage", None, stable, 1e-12
    )
    assert kind == "threshold" and abs(value - 1.019667) < 1e-6
    with pytest.raises(ParameterError, match="solve_for"):
        short_wave_limit(Tube.uniform(), "force")
    with pytest.raises(ParameterError, match="side"):
        short_wave_limit(Tube.uniform(), "stretch", side="sideways")
    with pytest.raises(ParameterError, match="faces"):
        short_wave_limit(Tube.uniform(), "stretch", faces=("middle",))
    with pytest.raises(ParameterError, match="psi"):
        short_wave_limit(Tube.uniform(), "stretch", psi=2.0)
    with pytest.raises(ParameterError, match="rtol"):
        short_wave_limit(Tube.uniform(), "stretch", rtol=0.0)
    with pytest.raises(ParameterError, match=r"\(0, 0\)"):
        ray_limit(Tube.uniform(), 0, 0, "stretch")
    with pytest.raises(ParameterError, match="already unstable"):
        short_wave_limit(Tube.uniform(outer_radius=1.4, voltage=0.95), "stretch")


# --- interfaces -----------------------------------------------------------------------------


def test_interface_with_a_vanishing_neighbour_is_a_free_face():
    """Uniform axial compression (g = 1, no field) strains every layer alike. The interface
    between a layer and one of vanishing modulus ratio r is the free face of the stiffer
    layer: its limit tends to Biot's stretch linearly in r, whichever side is soft (mirror
    symmetry), and a stiffer neighbour (r = 3) stabilises it (interfacial wrinkling needs
    more compression than surface wrinkling)."""
    biot = biot_stretch()
    x = {}
    for below, above in ((1e-4, 1.0), (1e-3, 1.0), (1.0, 1e-3), (1.0, 3.0)):
        tube = Tube((Layer(1.2, shear_modulus=below), Layer(1.4, shear_modulus=above)))
        lim = short_wave_limit(tube, "stretch", faces=("interface-1",))
        assert lim.kind == "surface" and lim.face == "interface-1" and lim.psi == HALF_PI
        x[below, above] = lim.value
    assert 0 < biot - x[1e-4, 1.0] < 1e-4
    assert abs((biot - x[1e-3, 1.0]) / (biot - x[1e-4, 1.0]) - 10.0) < 0.1
    assert abs(x[1e-3, 1.0] - x[1.0, 1e-3]) < 1e-12
    assert x[1.0, 3.0] < biot - 0.1


def test_interface_is_critical_in_a_growing_embedded_layer():
    """A layer (thickness 0.1, modulus 1) growing between two soft ones (modulus 0.2): the
    faces stay stable and interface-1 wrinkles first, along z. The fixed-direction limit and
    the interface alone give the same value."""
    tube = Tube((Layer(1.3, shear_modulus=0.2), Layer(1.4), Layer(2.0, shear_modulus=0.2)))
    lim = short_wave_limit(tube, "growth[2]")
    assert lim.kind == "surface" and lim.face == "interface-1" and lim.psi == HALF_PI
    assert abs(lim.value - INTERFACE_LIMIT) < 1e-9 and lim.error_estimate < 1e-10
    assert lim.params.layers[1].growth == (lim.value,) * 3
    ray = ray_limit(tube, 0, 1, "growth[2]", faces=("interface-1",))
    assert abs(ray.value - lim.value) < 1e-12


#: short_wave_limit of the embedded-layer tube above (measured, docs)
INTERFACE_LIMIT = 2.1782747522850343


@pytest.mark.slow
def test_finite_modes_approach_the_interface_limit():
    """The embedded-layer tube: modes (0, j) by collocation (one Chebyshev domain per layer)
    close on the interface limit like 1/j once k h >> 1 (docs: j = 32, 64 give +1.661e-3,
    +7.93e-4)."""
    from electrogrowth.incremental.targets import collocation_targets

    tube = Tube((Layer(1.3, shear_modulus=0.2), Layer(1.4), Layer(2.0, shear_modulus=0.2)))

    def root(j, nodes, lo, hi):
        def f(x):
            state = solve_base_state(tube.at("growth[2]", x))
            return float(collocation_targets(state, np.array([[0.0, j]]), nodes=nodes)[0])

        return brentq(f, lo, hi, xtol=1e-12)

    d32 = root(32, 80, 2.176, 2.188) - INTERFACE_LIMIT
    d64 = root(64, 100, 2.176, 2.188) - INTERFACE_LIMIT
    assert 0 < d64 < d32 < 3e-3
    assert 1.7 < d32 / d64 < 2.4
    assert abs(2 * d64 - d32) < 2e-4


@pytest.mark.slow
def test_scan_of_a_layered_tube_ends_in_the_exact_limit():
    """scan_modes on a layered Tube: the optimum runs to short waves, the exact limit (at the
    inner face of two identical layers) is computed through past_surface / short_wave_limit
    and equals the one-layer value (measured: 0.781917528431796 vs 0.7819175284317958;
    ~8 min on a loaded machine)."""
    from electrogrowth.bifurcation.scan import ScanOptions, scan_modes

    tube = Tube((Layer(1.8), Layer(2.5)), length=3.0, stretch=0.8)
    res = scan_modes(tube, "voltage", options=ScanOptions((0, 2), (1, 6)))
    c = res.critical
    assert res.surface_instability and c.kind == "surface" and c.face == "inner"
    one = short_wave_limit(Tube.uniform(2.5, 3.0, stretch=0.8), "voltage")
    assert abs(c.value - one.value) < 1e-10


def test_a_surface_value_is_never_reported_exact():
    """Check round 29, doubt: the neo-Hookean tube's half-space value at two resolutions
    agreed to the bit, and the result claimed exactness (error estimate 0.0). Its estimate
    is now at least the precision its rtol achieves, as every critical value's
    (error_estimate.achieved_floor, 5 rtol |value|), and it covers the distance to the value
    solved 100 times tighter (an independent resolution)."""
    tube = Tube.uniform(outer_radius=1.2, voltage=0.4)
    lim = short_wave_limit(tube, "stretch", side="extension", rtol=1e-12)
    tight = short_wave_limit(tube, "stretch", side="extension", rtol=1e-14)
    assert lim.kind == "surface" and lim.face == "outer"
    assert lim.error_estimate >= 5e-12 * lim.value > 0
    assert abs(lim.value - tight.value) <= lim.error_estimate
