"""Chebyshev collocation of the incremental problem: analytic limits, convergence, identities.

The base states come from a small independent fixture (ideal dielectric, traction-free faces,
Gauss-Legendre integrals), so these tests do not depend on ``electrogrowth.basestate.tube`` or the
Stroh/Riccati engine except the two slow ones that cross-check them. Exact reference: the
Bessel-function solution of the homogeneously compressed neo-Hookean tube (V = 0, g = 1).
"""

import ast
import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
import scipy.optimize
from scipy.special import ivp, kvp

from electrogrowth.errors import NoBifurcationFound, ParameterError
from electrogrowth.incremental import collocation as col
from electrogrowth.incremental.nodal_law import full_moduli
from electrogrowth.model.layers import Tube
from electrogrowth.model.materials import (
    I1,
    I2,
    I4,
    I5,
    I6,
    Material,
    gent,
    mooney_rivlin,
    neo_hookean,
)
from electrogrowth.model.moduli import MODULI_INDEX

HALF_SPACE = 0.443745615894947  # lambda_z with lambda_z^{3/2} = root of x^3 + x^2 + 3x - 1

# -- an independent base state (ideal dielectric) ------------------------------------------

_GX, _GW = np.polynomial.legendre.leggauss(48)


@dataclasses.dataclass(frozen=True)
class FixtureState:
    """Traction-free base state: sigma_rr = int_{r_i}^r (tau_2 - tau_1) ds / s, p = tau_1 -
    sigma_rr, D_r = c / r, c = V / ln(r_o / r_i) (E = D for an ideal dielectric)."""

    tube: Tube
    r_i: float
    r_o: float
    charge: float

    @property
    def current_length(self) -> float:
        return self.tube.stretch * self.tube.length

    face_pressures = (0.0, 0.0)

    @property
    def stretch(self) -> float:
        return self.tube.stretch

    @property
    def radii(self) -> tuple[float, float]:
        return (self.r_i, self.r_o)

    def reference_radius(self, r, *, layer: int = 0):
        t = self.tube
        return np.sqrt(1 + t.stretch * (np.asarray(r) ** 2 - self.r_i**2) / t.growth**3)

    def radius(self, R, *, side="outer"):
        p = self.tube
        return np.sqrt(self.r_i**2 + p.growth**3 * (np.asarray(R, float) ** 2 - 1) / p.stretch)

    def _stretches(self, r):
        p = self.tube
        R = np.sqrt(1 + p.stretch * (r**2 - self.r_i**2) / p.growth**3)
        l2, l3 = r / R / p.growth, p.stretch / p.growth
        return 1 / (l2 * l3), l2, l3, self.charge / r

    def sigma_rr(self, r):
        r = np.asarray(r, float)
        s = self.r_i + (r[..., None] - self.r_i) * (_GX + 1) / 2
        tau = self.tube.material.stress(*self._stretches(s))
        return (r - self.r_i) / 2 * np.sum(_GW * (tau[1] - tau[0]) / s, axis=-1)

    def moduli(self, R, *, side="outer"):
        return self.tube.material.moduli(*self._stretches(self.radius(R)))

    def pressure(self, R, *, side="outer"):
        r = self.radius(R)
        return self.tube.material.stress(*self._stretches(r))[0] - self.sigma_rr(r)


def fixture_state(params: Tube) -> FixtureState:
    g, lz, V = params.growth, params.stretch, params.physical_voltage

    def state(ri):
        ro = math.sqrt(ri**2 + g**3 * (params.outer_radius**2 - 1) / lz)
        return FixtureState(params, ri, ro, V / math.log(ro / ri))

    hom = math.sqrt(g**3 / lz)  # V = 0: homogeneous, lambda^2 lambda_z = g^3
    ri = scipy.optimize.brentq(
        lambda x: float(state(x).sigma_rr(state(x).r_o)),
        0.3 * hom,
        4 * hom,
        xtol=1e-15,
        rtol=1e-15,
    )
    return state(ri)


def tube(**kw) -> Tube:
    return Tube.uniform(**{"outer_radius": 1.5, "length": 3.0, **kw})


def critical(params, m, n, solve_for, bracket, nodes=24):
    return col.critical_collocation(
        params, m, n, solve_for, bracket, nodes=nodes, xtol=1e-15, base_state=fixture_state
    )


# -- exact solution: homogeneously compressed neo-Hookean tube, V = 0, g = 1 ---------------


def bessel_determinant(lz, m, n, Ro, L):
    """det of the traction matrix of the exact incremental solution.

    Pre-stretch lambda_r = lambda_th = lambda = lambda_z^{-1/2}, p = lambda^2, so
    S_ri = lambda^2 (L_ir + L_ri) - pdot delta_ri. Solutions of lambda^2 lap_perp u +
    lambda_z^2 u_zz = grad pdot, div u = 0 with pdot = (lambda^2 - lambda_z^2) k^2 phi1:
    u = grad phi1 (phi1 = Z_m(kr)), curl(psi e_z), curl curl(chi e_z) (psi, chi = Z_m(skr)),
    s = lambda_z / lambda, Z = I_m, K_m.
    """
    lam2 = 1 / lz
    k = n * np.pi / (lz * L)
    s = lz / math.sqrt(lam2) * k
    cols = []
    for fam, a in ((1, k), (2, s), (3, s)):
        for bessel in (ivp, kvp):
            rows = []
            for r in (math.sqrt(lam2), Ro * math.sqrt(lam2)):
                Z = [a**d * bessel(m, a * r, d) for d in range(3)]
                dZr = Z[1] / r - Z[0] / r**2  # d(Z/r)/dr
                if fam == 1:
                    U, dU = (Z[1], -m / r * Z[0], -k * Z[0]), (Z[2], -m * dZr, -k * Z[1])
                    P = (lam2 - lz**2) * k**2 * Z[0]
                elif fam == 2:
                    U, dU, P = (m / r * Z[0], -Z[1], 0.0), (m * dZr, -Z[2], 0.0), 0.0
                else:
                    U = (k * Z[1], -m * k / r * Z[0], -(s**2) * Z[0])
                    dU, P = (k * Z[2], -m * k * dZr, -(s**2) * Z[1]), 0.0
                rows += [
                    2 * lam2 * dU[0] - P,
                    lam2 * (dU[1] - (m * U[0] + U[1]) / r),
                    lam2 * (dU[2] - k * U[0]),
                ]
            cols.append(rows)
    A = np.array(cols).T
    if m == 0:  # torsion (psi, S_rth) decouples
        A = A[np.ix_([0, 2, 3, 5], [0, 1, 4, 5])]
    return np.linalg.det(A / abs(A).max(axis=0))


# -- building blocks ------------------------------------------------------------------------


def test_chebyshev_blocks_are_exact_on_polynomials():
    x, D = col.chebyshev_lobatto(13)
    assert np.allclose(D @ x**12, 12 * x**11, atol=1e-11)
    P = col.interior_interpolation(13)  # degree-10 pressure space
    assert np.allclose(P @ x[1:-1] ** 10, x**10, atol=1e-13)


@pytest.mark.parametrize(
    "material", [neo_hookean(), mooney_rivlin(0.6), gent(5.0)], ids=lambda mat: mat.name
)
def test_full_moduli_obey_the_stress_relation(material):
    """A_piqj - A_ipqj = tau_pq delta_ij - tau_iq delta_pj (docs/conventions.md)."""
    l2, l3, d = 1.3, 0.8, 0.6
    tau = np.diag(material.stress(1 / (l2 * l3), l2, l3, d))
    A = full_moduli(material.moduli(1 / (l2 * l3), l2, l3, d)[None, :])[0][..., 0]
    eye = np.eye(3)
    rhs = np.einsum("pq,ij->piqj", tau, eye) - np.einsum("iq,pj->piqj", tau, eye)
    assert np.allclose(A - A.transpose(1, 0, 2, 3), rhs, atol=1e-12)


def test_full_moduli_fill_every_symmetric_slot():
    A, G, K = (t[..., 0] for t in full_moduli(np.arange(1.0, 24.0)[None, :]))
    assert np.array_equal(A, A.transpose(2, 3, 0, 1)) and np.array_equal(G, G.transpose(1, 0, 2))
    assert (np.count_nonzero(A), np.count_nonzero(G), np.count_nonzero(K)) == (21, 7, 3)
    assert A[1, 0, 0, 1] == A[0, 1, 1, 0] == 1 + MODULI_INDEX["A1221"]
    assert G[1, 0, 1] == G[0, 1, 1] == 1 + MODULI_INDEX["G122"]


def test_matrix_is_square_and_exactly_real():
    state = fixture_state(tube(growth=1.1, stretch=0.9, voltage=0.5))
    Mc = col._complex_matrix(state, 3, 2, 24)
    assert Mc.shape == (5 * 24 - 2, 5 * 24 - 2)
    assert abs(Mc.imag).max() <= 1e-14 * abs(Mc.real).max()


def test_fluxes_match_the_paper_component_formulas(rng):
    """The generic contraction against paper eqs. incremental-constitutive1-2 written out,
    for a non-ideal Mooney-Rivlin-type energy under voltage (all 23 moduli non-zero), with
    random real amplitudes."""
    energy = (
        0.4 * (I1 - 3) + 0.1 * (I2 - 3) + 0.3 * I4 + 0.25 * I5 + 0.1 * I6 + 0.05 * (I1 - 3) * I5
    )
    params = tube(
        growth=1.1,
        stretch=0.9,
        voltage=0.5,
        material=Material("nonideal", energy, check_units=False),
    )
    state, m, n, nn = fixture_state(params), 3, 2, 12
    grid = col._grid(state, n, nn)
    v = rng.standard_normal(5 * nn - 2)
    L, S, Dq = (np.einsum("...c,c->...", X, v) for X in col._fluxes(state, grid, m))
    cols = col._layout(nn)
    Ur, Ut, Uz, Phi = (v[cols[f]] for f in ("U_r", "U_th", "U_z", "Phi"))
    P = col.interior_interpolation(nn) @ v[cols["P"]]
    D, r, k = grid.Dx, grid.rh, grid.kh
    R = np.sqrt(1 + params.stretch * ((r * grid.h) ** 2 - state.r_i**2) / params.growth**3)
    M = dict(zip(MODULI_INDEX, np.moveaxis(state.moduli(R), -1, 0)))
    assert all(np.all(abs(x) > 1e-3) for x in M.values())
    p = state.pressure(R)
    # real cos/sin amplitudes; the complex ones carry cc -> 1, sc, cs -> -i, ss -> -1
    L11, L22, L33 = D @ Ur, (Ur + m * Ut) / r, k * Uz  # cc
    L12, L21, L32, L23 = -(m * Ur + Ut) / r, D @ Ut, -m * Uz / r, -k * Ut  # sc, sc, ss, ss
    L13, L31 = -k * Ur, D @ Uz  # cs
    E1, E2, E3 = -(D @ Phi), m * Phi / r, k * Phi  # cc, sc, cs
    D1 = (E1 - M["G111"] * L11 - M["G221"] * L22 - M["G331"] * L33) / M["K11"]
    D2 = (E2 - M["G122"] * (L12 + L21)) / M["K22"]
    D3 = (E3 - M["G133"] * (L13 + L31)) / M["K33"]
    Srr = (M["A1111"] + p) * L11 + M["A1122"] * L22 + M["A1133"] * L33 + M["G111"] * D1 - P
    Stt = M["A1122"] * L11 + (M["A2222"] + p) * L22 + M["A2233"] * L33 + M["G221"] * D1 - P
    Szz = M["A1133"] * L11 + M["A2233"] * L22 + (M["A3333"] + p) * L33 + M["G331"] * D1 - P
    Srt = M["A1212"] * L21 + (M["A1221"] + p) * L12 + M["G122"] * D2
    Str = M["A2121"] * L12 + (M["A1221"] + p) * L21 + M["G122"] * D2
    Srz = M["A1313"] * L31 + (M["A1331"] + p) * L13 + M["G133"] * D3
    Szr = M["A3131"] * L13 + (M["A1331"] + p) * L31 + M["G133"] * D3
    Stz = M["A2323"] * L32 + (M["A2332"] + p) * L23
    Szt = M["A3232"] * L23 + (M["A2332"] + p) * L32
    cc, sc, ss = 1, -1j, -1
    expect = {
        (0, 0): Srr * cc,
        (1, 1): Stt * cc,
        (2, 2): Szz * cc,
        (0, 1): Srt * sc,
        (1, 0): Str * sc,
        (0, 2): Srz * sc,
        (2, 0): Szr * sc,
        (1, 2): Stz * ss,
        (2, 1): Szt * ss,
    }
    for (a, b), want in expect.items():
        assert np.allclose(S[a, b], want, rtol=1e-12, atol=1e-12 * abs(Srr).max()), (a, b)
    for got, want in zip(Dq, (D1 * cc, D2 * sc, D3 * sc)):
        assert np.allclose(got, want, rtol=1e-12, atol=1e-12 * abs(D1).max())
    assert np.allclose(L[0, 1], L12 * sc) and np.allclose(L[1, 2], L23 * ss)


@pytest.mark.parametrize("bessel", [ivp, kvp], ids=["I_m", "K_m"])
def test_maxwell_rows_annihilate_the_exact_potential(bessel):
    """At V = 0 (K = I, Gamma = 0) div D = 0 is Laplace's equation; Phi = Z_m(k r) solves it."""
    state, m, n, nn = fixture_state(tube()), 3, 2, 30
    grid = col._grid(state, n, nn)
    v = np.zeros(5 * nn - 2)
    v[col._layout(nn)["Phi"]] = bessel(m, grid.kh * grid.rh, 0)
    rows = col.collocation_matrix(state, m, n, nodes=nn)[3 * nn + 1 : 4 * nn - 1]  # Maxwell
    assert abs(rows @ v).max() < 1e-10 * abs(v).max() * abs(rows).max()


def test_module_is_independent_of_the_stroh_engine():
    tree = ast.parse(Path(col.__file__).read_text())
    names = {a.name for node in ast.walk(tree) if isinstance(node, ast.Import) for a in node.names}
    names |= {node.module or "" for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    local = {n.lstrip(".").split(".")[-1] for n in names}
    assert not local & {"stroh", "impedance", "impedance_reference", "bifurcation"}, names


# -- stability of the unloaded tube, no spurious pressure mode -------------------------------


@pytest.mark.parametrize("Ro, L", [(1.4, 1.0), (2.0, 5.0), (1.1, 10.0)])
def test_unloaded_tube_is_stable_for_every_mode(Ro, L):
    state = fixture_state(tube(outer_radius=Ro, length=L))
    f = [
        col.collocation_target(state, m, n, nodes=nodes)
        for m in (0, 1, 2, 4, 7)
        for n in (1, 2, 4, 8, 16)
        for nodes in (8, 21)
    ]
    assert min(f) > 0


def test_no_spurious_pressure_mode():
    """sigma_min of the unloaded matrix stays O(1) as nodes grow (P_N - P_{N-2}). With P on
    every node and tr L = 0 imposed at the faces it fell like nodes^-2 (8e-4 -> 2e-5)."""
    state = fixture_state(tube(outer_radius=2.0, voltage=0.5))
    smin = [
        np.linalg.svd(col.collocation_matrix(state, 2, 1, nodes=N), compute_uv=False)[-1]
        for N in (10, 20, 40, 60)
    ]
    assert min(smin) > 0.02
    assert smin[0] / smin[-1] < 3


# -- exactness: the Bessel solution of the homogeneous tube ---------------------------------


@pytest.mark.parametrize(
    "m, n, guess", [(0, 1, 0.686344), (1, 1, 0.793122), (2, 1, 0.802480), (3, 2, 0.617205)]
)
def test_matches_exact_bessel_solution(m, n, guess):
    bracket = (guess - 0.005, guess + 0.005)
    exact = scipy.optimize.brentq(bessel_determinant, *bracket, args=(m, n, 1.5, 3.0), xtol=1e-15)
    assert critical(tube(), m, n, "stretch", bracket) == pytest.approx(exact, abs=1e-10)


# -- spectral convergence -------------------------------------------------------------------


def test_spectral_convergence_with_voltage_and_growth():
    """Critical growth of mode (2, 1) at Vbar = 0.6 (inhomogeneous state): successive
    differences drop geometrically, ~ 10^-0.6 per added node, to the 1e-12 rounding floor."""
    params = tube(voltage=0.6)
    g = {N: critical(params, 2, 1, "growth", (1.15, 1.175), nodes=N) for N in (8, 10, 12, 16, 24)}
    d = np.abs(np.diff(list(g.values())))
    assert d[0] > 1e-5 and d[1] < 1e-6 and d[2] < 3e-8 and d[3] < 1e-11
    assert g[24] == pytest.approx(1.15661253300, abs=1e-11)
    rate = np.polyfit([10, 12, 16], np.log10(d[:3]), 1)[0]
    assert rate < -0.5  # digits gained per node


# -- known limits ---------------------------------------------------------------------------


def test_biot_half_space_cubic():
    roots = np.roots([1, 1, 3, -1])
    x = roots[abs(roots.imag) < 1e-12].real[0]
    assert x == pytest.approx(0.295598, abs=1e-6)
    assert x ** (2 / 3) == pytest.approx(HALF_SPACE, abs=1e-14)


@pytest.mark.parametrize(
    "n1, nodes, err1, tol",
    [(5, 40, 1.29e-3, 1e-4), pytest.param(10, 60, 6.85e-4, 3e-5, marks=pytest.mark.slow)],
)
def test_thick_tube_short_wave_limit_is_the_surface_instability(n1, nodes, err1, tol):
    """Rbar_o = 2, V = 0, g = 1: the state is homogeneous uniaxial compression, lambda_r =
    lambda_th = lambda_z^{-1/2}, so lambda_z / lambda_r = lambda_z^{3/2} must reach 0.295598.
    The first mode (largest lambda_z) sits on the convex outer face and approaches from above
    like 1/n (n1 and 2 n1); its inner-face twin lies below 0.443746."""
    params = tube(outer_radius=2.0, length=1.0)
    lz = {
        n: critical(params, 0, n, "stretch", (HALF_SPACE + 1e-6, 0.447), nodes=nodes)
        for n in (n1, 2 * n1)
    }
    err = [lz[n] - HALF_SPACE for n in lz]
    assert err[0] == pytest.approx(err1, rel=0.01)
    assert 1.8 < err[0] / err[1] < 2.2
    assert 2 * lz[2 * n1] - lz[n1] == pytest.approx(HALF_SPACE, abs=tol)
    state = fixture_state(dataclasses.replace(params, stretch=lz[2 * n1]))
    mode = col.mode_shape_collocation(state, 0, 2 * n1, nodes=nodes)
    assert abs(mode["U_r"][-1]) > 1e4 * abs(mode["U_r"][0])  # outer face >> inner face
    inner = critical(params, 0, 2 * n1, "stretch", (0.44, HALF_SPACE - 1e-6), nodes=nodes)
    assert -2 * err[1] > inner - HALF_SPACE > -3 * err[1]


def test_euler_buckling_of_a_slender_tube():
    """1 - lambda_z -> pi^2 (Rbar_o^2 + 1) / (4 ell^2): Euler load EI pi^2/ell^2 over EA,
    I/A = (r_o^2 + r_i^2)/4 for an annulus; relative error O(ell^-2)."""
    Ro, errors = 1.5, []
    for L in (20.0, 40.0, 80.0):
        guess = math.pi**2 * (Ro**2 + 1) / (4 * L**2)
        lz = critical(
            tube(outer_radius=Ro, length=L),
            1,
            1,
            "stretch",
            (1 - 2 * guess, 1 - 0.5 * guess),
            nodes=16,
        )
        euler = math.pi**2 * (Ro**2 + 1) / (4 * (lz * L) ** 2)
        errors.append(abs((1 - lz) / euler - 1))
    assert errors[-1] < 5e-3
    assert all(3.5 < a / b < 4.5 for a, b in zip(errors, errors[1:]))
    mode = col.mode_shape_collocation(
        fixture_state(tube(outer_radius=Ro, length=80.0, stretch=lz)), 1, 1, nodes=16
    )
    # rigid-section bending u = w(z) e_x: U_th = -U_r, uniform through the wall
    assert np.allclose(mode["U_th"], -mode["U_r"], atol=0.01)
    assert np.allclose(abs(mode["U_r"]), 1, atol=0.01)


# -- isotropic growth is a rescaling --------------------------------------------------------


def test_growth_is_a_rescaling_of_the_target():
    """(g, lambda_z, Vbar) and (1, lambda_z / g, Vbar / g): same tube scaled by g; the
    matrix, built in units of the wall half-thickness, is identical."""
    g, lz, V = 1.3, 0.95, 0.7
    grown = fixture_state(tube(outer_radius=1.6, length=4.0, growth=g, stretch=lz, voltage=V))
    plain = fixture_state(tube(outer_radius=1.6, length=4.0, stretch=lz / g, voltage=V / g))
    for m, n in [(0, 1), (1, 1), (2, 3), (4, 2)]:
        a, b = (col.collocation_target(s, m, n, nodes=24) for s in (grown, plain))
        assert a == pytest.approx(b, rel=1e-8)


def test_growth_is_a_rescaling_of_the_critical_value():
    g_cr = critical(tube(), 2, 1, "growth", (1.2, 1.3))
    lz_cr = critical(tube(), 2, 1, "stretch", (1 / 1.3, 1 / 1.2))
    assert g_cr == pytest.approx(1 / lz_cr, abs=1e-11)


# -- the base-state contract of electrogrowth.basestate.tube ----------------------------------


@pytest.mark.slow
def test_agrees_with_the_tube_base_state():
    params = tube(outer_radius=1.6, length=4.0, growth=1.1, voltage=0.5)
    v = col.critical_collocation(params, 2, 1, "growth", (1.0, 1.3), nodes=24)
    assert v == pytest.approx(critical(params, 2, 1, "growth", (1.0, 1.3), nodes=24), abs=1e-11)


@pytest.mark.slow
@pytest.mark.parametrize("m, n, bracket", [(2, 1, (1.15, 1.175)), (0, 1, (1.4, 1.425))])
def test_certifies_the_impedance_engine(m, n, bracket):
    """The Stroh/Riccati engine and the collocation agree on a grown, charged tube."""
    bifurcation = pytest.importorskip("electrogrowth.bifurcation.critical")
    params = tube(voltage=0.6)
    riccati = bifurcation.critical_value(params, m, n, "growth", bracket=bracket).value
    assert critical(params, m, n, "growth", bracket) == pytest.approx(riccati, abs=2e-11)


# -- failures -------------------------------------------------------------------------------


def test_failures_are_named():
    with pytest.raises(NoBifurcationFound, match="widen or move the bracket"):
        critical(tube(), 2, 1, "stretch", (0.95, 1.0))
    with pytest.raises(ParameterError, match="solve_for"):
        critical(tube(), 2, 1, "force", (0.9, 1.0))
    with pytest.raises(ParameterError, match="nodes"):
        col.collocation_target(fixture_state(tube()), 2, 1, nodes=4)


# -- a softening energy: tr L at the faces (probe 13a D2) -----------------------------------

#: A1111 + p = 2 W1 + 4 W11 + p = 0 unloaded (W11 = -1/2): it passes through 0 near the
#: faces at small growth
SOFTENING = "0.5*(I1-3) + I5/2 - 0.25*(I1-3)**2"


@pytest.mark.parametrize("nodes", [24, 40])
def test_softening_energy_has_no_spurious_face_mode(nodes):
    """Probe 13a D2: the target of this energy (Rbar_o 1.5, L 1, Vbar 0.2, mode (2, 1))
    changed sign at g = 1.04883 for every mode and node count, while the kernel and the
    shooting twin stay positive up to their root 1.37439: tr L at a face node is free in
    the collocation (tr L = 0 only at interior nodes) and its only coefficient, A1111 + p
    in S_rr, passed through 0 there, a singular matrix the continuous problem does not have.
    The moduli are now shifted by c delta delta (absorbed by the pressure) to keep it
    positive: the target keeps its stable sign up to the genuine root."""
    from electrogrowth.basestate.tube import solve_base_state

    params = Tube.uniform(1.5, 1.0, voltage=0.2, material=Material("soft", SOFTENING))
    f = [
        col.collocation_target(solve_base_state(params.at("growth", g)), 2, 1, nodes=nodes)
        for g in (1.0, 1.04, 1.0486, 1.0488, 1.04883, 1.0489, 1.06, 1.3, 1.37, 1.38)
    ]
    assert min(f[:-1]) > 0 > f[-1], f


def test_the_face_shift_leaves_a_neo_hookean_tube_bit_identical():
    """The shift acts only where A1111 + p < A1212: for the neo-Hookean tube (A1111 + p ~ 2
    A1212 here) the matrix is the one assembled from the moduli as they are."""
    from electrogrowth.incremental import nodal_law

    state = fixture_state(tube(growth=1.1, stretch=0.9, voltage=0.5))
    A, _, _ = full_moduli(state.moduli(np.linspace(1.0, 1.5, 7)))
    shifted = A.copy()
    nodal_law._shift_out_of_the_face_mode(shifted, state.pressure(np.linspace(1.0, 1.5, 7)))
    assert np.array_equal(shifted, A)
