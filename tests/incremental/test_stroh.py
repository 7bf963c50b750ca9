"""Tests of the Stroh matrix G of the electro-elastic tube (electrogrowth.incremental.stroh)."""

from __future__ import annotations

import importlib.util
import pathlib

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from electrogrowth.incremental.stroh import (
    SIGN_DELTA,
    SIGN_PHI,
    neo_hookean_stroh_matrix,
    stroh_blocks,
    stroh_matrix,
    stroh_matrix_py,
)
from electrogrowth.model.materials import (
    gent,
    mooney_rivlin,
    neo_hookean,
)
from electrogrowth.model.moduli import MODULI_INDEX, MODULI_NAMES, neo_hookean_moduli

MATERIALS = {
    "neo-hookean": neo_hookean(),
    "gent5": gent(jm=5.0),
    "mooney-rivlin0.3": mooney_rivlin(0.3),
}
MODES = [(0, 0.0), (1, 0.7), (4, 2.5), (12, 0.3), (2.0, 6.0)]
ELECTRIC = [3, 7]  # eta indices of r Delta_r and -Phi
MECHANICAL = [0, 1, 2, 4, 5, 6]
# Paper Appendix B uses eta_7 = +Phi: G_paper = T G T with T = diag(1, ..., 1, -1).
T_PAPER = np.diag([1.0] * 7 + [-1.0])


def G_of(mod, p, m, kr):
    out = np.empty((8, 8))
    stroh_matrix(mod, p, m, kr, out)
    return out


def material_states(material, n, seed):
    """n random base states (l1, l2, l3, d, p) with the moduli and tau_1 = sigma_rr + p."""
    rng = np.random.default_rng(seed)
    l2, l3 = rng.uniform(0.75, 1.35, n), rng.uniform(0.8, 1.3, n)
    l1, d = 1.0 / (l2 * l3), rng.uniform(0.0, 0.8, n)
    p = rng.uniform(-0.5, 2.0, n)
    mods = material.moduli(l1, l2, l3, d)
    tau1 = material.stress(l1, l2, l3, d)[0]
    return [(l1[i], l2[i], l3[i], d[i], p[i], mods[i], tau1[i]) for i in range(n)]


@pytest.fixture(scope="module")
def derivation():
    """The sympy derivation of tools/derive_stroh.py, lambdified: f(*moduli, p, m, kr)."""
    path = pathlib.Path(__file__).resolve().parents[2] / "tools" / "derive_stroh.py"
    spec = importlib.util.spec_from_file_location("derive_stroh", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    G, _ = module.derive()
    args = [module.MOD[n] for n in MODULI_NAMES] + list(sp.symbols("p m kr", real=True))
    return sp.lambdify(args, G, "numpy"), (module.S1, module.S2)


# --- structure --------------------------------------------------------------------------


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("m, kr", MODES)
def test_hamiltonian_structure(name, m, kr):
    seed = 10 * list(MATERIALS).index(name) + int(m)
    for *_, p, mod, _ in material_states(MATERIALS[name], 4, seed=seed):
        G1, G2, G3, G4 = stroh_blocks(mod, p, m, kr)
        scale = np.abs(G3).max()
        np.testing.assert_allclose(G2, G2.T, rtol=0, atol=1e-13 * np.abs(G2).max())
        np.testing.assert_allclose(G3, G3.T, rtol=0, atol=1e-13 * scale)
        np.testing.assert_array_equal(G4, -G1.T)
        # the electric coupling is really there (d > 0), so the check is not vacuous
        assert np.abs(G3[:, 3]).max() > 0


def test_hamiltonian_for_generic_moduli():
    """The structure needs only the major symmetries, not eq. 20-1: random moduli."""
    rng = np.random.default_rng(1)
    for _ in range(20):
        G1, G2, G3, G4 = stroh_blocks(
            rng.uniform(0.2, 3.0, 23), rng.normal(), rng.integers(0, 9), rng.uniform(0, 5)
        )
        np.testing.assert_allclose(G2, G2.T, atol=1e-12)
        np.testing.assert_allclose(G3, G3.T, atol=1e-12 * np.abs(G3).max())
        np.testing.assert_allclose(G4, -G1.T, atol=1e-14)


def test_blocks_and_python_twin_agree_with_kernel():
    rng = np.random.default_rng(2)
    mod = rng.uniform(0.2, 3.0, 23)
    G = G_of(mod, 0.4, 3.0, 1.1)
    ref = np.empty((8, 8))
    stroh_matrix_py(mod, 0.4, 3.0, 1.1, ref)
    np.testing.assert_array_equal(G, ref)
    np.testing.assert_array_equal(
        np.block(
            [
                list(stroh_blocks(mod, 0.4, 3.0, 1.1)[:2]),
                list(stroh_blocks(mod, 0.4, 3.0, 1.1)[2:]),
            ]
        ),
        G,
    )
    # works on a strided row of a 2-D moduli array (as a batched kernel would pass it)
    batch = np.stack([mod, 2 * mod], axis=1)
    np.testing.assert_array_equal(G_of(batch[:, 0], 0.4, 3.0, 1.1), G)


# --- against the derivation -------------------------------------------------------------


def test_matches_sympy_derivation(derivation):
    f, signs = derivation
    assert signs == (SIGN_DELTA, SIGN_PHI)
    rng = np.random.default_rng(3)
    cases = [
        (rng.uniform(0.2, 3.0, 23), rng.normal(), float(rng.integers(0, 9)), rng.uniform(0, 5))
        for _ in range(10)
    ]
    for material in MATERIALS.values():
        cases += [(mod, p, 5.0, 1.3) for *_, p, mod, _ in material_states(material, 3, 4)]
    for mod, p, m, kr in cases:
        ref = np.array(f(*mod, p, m, kr), dtype=float)
        np.testing.assert_allclose(
            G_of(mod, p, m, kr), ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max()
        )


@pytest.mark.parametrize("m, kr", MODES)
def test_neo_hookean_closed_form(m, kr):
    for l1, l2, l3, d, p, mod, _ in material_states(neo_hookean(), 5, seed=5):
        np.testing.assert_allclose(mod, neo_hookean_moduli(l1, l2, l3, d), atol=1e-13)
        G = G_of(mod, p, m, kr)
        np.testing.assert_allclose(
            neo_hookean_stroh_matrix(l1, l2, l3, d, p, m, kr),
            G,
            rtol=1e-13,
            atol=1e-13 * np.abs(G).max(),
        )


def incremental_equation_residuals(fill_g):
    """Residuals of the original PDEs for eta' = G eta / r, G from ``fill_g``.

    ``fill_g(mod, p, m, kr, out)`` is run on sympy symbols for all 23 moduli, p, m and
    kr = k r. Fields u, phidot, D_r, Sigma_ri are built from symbols eta_i with the paper's
    trig factors; d/dr acts by the chain rule d(eta)/dr = G eta / r. D_th, D_z come from
    E = -grad(phidot) and the constitutive E, pdot from S_rr = Sigma_rr. Returns, per
    equation, the coefficients of eta_0..eta_7 (which must vanish identically) and the
    symbols they depend on.
    """
    r, th, z = sp.symbols("r theta z", positive=True)
    m, k, p = sp.symbols("m k p", real=True)
    mod = np.array([sp.Symbol(n, real=True) for n in MODULI_NAMES], dtype=object)
    out = np.empty((8, 8), dtype=object)
    fill_g(mod, p, m, k * r, out)
    exact = lambda e: e.xreplace({f: sp.Rational(f) for f in e.atoms(sp.Float)})  # noqa: E731
    G = sp.Matrix(out).applyfunc(lambda e: exact(sp.sympify(e)))
    eta = sp.Matrix(sp.symbols("eta0:8", real=True))
    deta = G * eta / r

    def d_r(f):
        return sp.diff(f, r) + sum(sp.diff(f, eta[i]) * deta[i] for i in range(8))

    M = lambda name: mod[MODULI_INDEX[name]]  # noqa: E731

    def A(a, i, q, j):  # A_piqj = A_qjpi
        names = [n for n in (f"A{a}{i}{q}{j}", f"A{q}{j}{a}{i}") if n in MODULI_INDEX]
        return M(names[0]) if names else 0

    def Gam(a, i, q):  # Gamma_piq = Gamma_ipq
        names = [n for n in (f"G{a}{i}{q}", f"G{i}{a}{q}") if n in MODULI_INDEX]
        return M(names[0]) if names else 0

    cc, sc = sp.cos(m * th) * sp.cos(k * z), sp.sin(m * th) * sp.cos(k * z)
    cs = sp.cos(m * th) * sp.sin(k * z)
    u = [eta[0] * cc, eta[1] * sc, eta[2] * cs]
    phi = SIGN_PHI * eta[7] * cc
    sig = [eta[4] / r * cc, eta[5] / r * sc, eta[6] / r * cs]
    grad = lambda f: [d_r(f), sp.diff(f, th) / r, sp.diff(f, z)]  # noqa: E731
    gu = [grad(c) for c in u]
    L = sp.Matrix(
        [
            [gu[0][0], gu[0][1] - u[1] / r, gu[0][2]],  # paper eq. 52
            [gu[1][0], gu[1][1] + u[0] / r, gu[1][2]],
            [gu[2][0], gu[2][1], gu[2][2]],
        ]
    )
    E = [-g for g in grad(phi)]
    EL = [
        sum(Gam(q + 1, j + 1, a + 1) * L[j, q] for q in range(3) for j in range(3))
        for a in range(3)
    ]
    D = [SIGN_DELTA * eta[3] / r * cc, (E[1] - EL[1]) / M("K22"), (E[2] - EL[2]) / M("K33")]
    S_nop = sp.Matrix(
        3,
        3,
        lambda a, i: (
            sum(A(a + 1, i + 1, q + 1, j + 1) * L[j, q] for q in range(3) for j in range(3))
            + sum(Gam(a + 1, i + 1, q + 1) * D[q] for q in range(3))
            + p * L[a, i]
        ),
    )
    pdot = S_nop[0, 0] - sig[0]
    S = S_nop - pdot * sp.eye(3)

    def div_S(i):  # dS_pi/dx_p in cylindrical coordinates
        div = d_r(S[0, i]) + sp.diff(S[1, i], th) / r + sp.diff(S[2, i], z)
        return div + [(S[0, 0] - S[1, 1]) / r, (S[1, 0] + S[0, 1]) / r, S[0, 2] / r][i]

    residuals = {
        "incompressibility": L.trace(),
        "Sigma_rth": S[0, 1] - sig[1],
        "Sigma_rz": S[0, 2] - sig[2],
        "E_r": EL[0] + M("K11") * D[0] - E[0],
        "div D": d_r(D[0]) + (sp.diff(D[1], th) + D[0]) / r + sp.diff(D[2], z),
        "div S r": div_S(0),
        "div S th": div_S(1),
        "div S z": div_S(2),
    }
    coeffs = {name: [sp.diff(res, eta[i]) for i in range(8)] for name, res in residuals.items()}
    return coeffs, list(mod) + [p, m, k, r, th, z]


def test_solves_the_incremental_equations():
    """Independent check: eta' = G eta / r satisfies the original PDEs identically."""
    coeffs, _ = incremental_equation_residuals(stroh_matrix_py)
    for name, row in coeffs.items():
        for i, c in enumerate(row):
            c = sp.cancel(sp.together(sp.expand(c)))
            assert c == 0, f"{name}: coefficient of eta{i} is {c}"


@pytest.mark.parametrize("mutation", ["paper-sign", "paper-n-typo", "drop-A2332"])
def test_incremental_equations_detect_a_wrong_matrix(mutation):
    """Negative control of the check above: a G off in one place violates the PDEs."""
    n = sp.Symbol("n", real=True)

    def wrong(mod, p, m, kr, out):
        stroh_matrix_py(mod, p, m, kr, out)
        if mutation == "paper-sign":  # eta_7 = +Phi as in the paper, eta kept
            out[:, 7] *= -1
            out[7, :] *= -1
        elif mutation == "paper-n-typo":  # n for m in G4(2, 1)
            out[5, 4] = n
        else:
            out[5, 2] -= m * kr * mod[MODULI_INDEX["A2332"]]

    coeffs, symbols = incremental_equation_residuals(wrong)
    values = np.random.default_rng(6).permutation(np.arange(2, 80))  # distinct: n != m
    point = {s: sp.Rational(int(v), 7) for s, v in zip(symbols + [n], values)}
    values = [sp.N(c.subs(point)) for row in coeffs.values() for c in row]
    assert max(abs(v) for v in values) > 1e-6


# --- limits and the paper ---------------------------------------------------------------


def elastic_tube_stroh(mod, sigma_rr, p, m, kr):
    """6x6 Stroh matrix of a purely elastic tube, eta = [U, r Sigma_r] (sigma_rr form).

    The classical form (e.g. Destrade et al. 2009; the paper's App. B with Gamma = 0),
    written with sigma_rr, gamma_12 = A1212, beta_12 etc.: uses eq. 20-1 where the
    implementation uses raw moduli, so it checks that step too.
    """
    a = lambda n: mod[MODULI_INDEX[n]]  # noqa: E731
    g12, g13, g21, g31, g32, g23 = (
        a("A1212"),
        a("A1313"),
        a("A2121"),
        a("A3131"),
        a("A3232"),
        a("A2323"),
    )
    b12 = (a("A1111") + a("A2222") - 2 * a("A1122") - 2 * a("A1221")) / 2
    b13 = (a("A1111") + a("A3333") - 2 * a("A1133") - 2 * a("A1331")) / 2
    s = sigma_rr
    k11 = (
        2 * (g12 - s + b12)
        + m**2 * (g21 - (g12 - s) ** 2 / g12)
        + kr**2 * (g31 - (g13 - s) ** 2 / g13)
    )
    k12 = m * (g12 + g21 + 2 * b12 - s**2 / g12)
    k13 = kr * (a("A1111") + a("A2233") - a("A1122") - a("A1133") + p)
    k22 = 2 * m**2 * (g12 - s + b12) + g21 - (g12 - s) ** 2 / g12 + kr**2 * g32
    k23 = m * kr * (a("A1111") + a("A2233") + a("A2332") - a("A1122") - a("A1133") + 2 * p)
    k33 = 2 * kr**2 * (g13 - s + b13) + m**2 * g23
    G1 = np.array([[-1, -m, -kr], [m * (1 - s / g12), 1 - s / g12, 0], [kr * (1 - s / g13), 0, 0]])
    G2 = np.diag([0, 1 / g12, 1 / g13])
    G3 = np.array([[k11, k12, k13], [k12, k22, k23], [k13, k23, k33]])
    return np.block([[G1, G2], [G3, -G1.T]])


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("m, kr", MODES)
def test_no_voltage_decouples_to_elastic_tube(name, m, kr):
    material = MATERIALS[name]
    rng = np.random.default_rng(7)
    for _ in range(3):
        l2, l3, p = rng.uniform(0.75, 1.35), rng.uniform(0.8, 1.3), rng.uniform(-0.5, 2)
        l1 = 1 / (l2 * l3)
        mod = material.moduli(l1, l2, l3, 0.0)  # Vbar = 0: d = 0, Gamma = 0
        G = G_of(mod, p, m, kr)
        assert not G[np.ix_(ELECTRIC, MECHANICAL)].any()
        assert not G[np.ix_(MECHANICAL, ELECTRIC)].any()
        sigma_rr = material.stress(l1, l2, l3, 0.0)[0] - p
        ref = elastic_tube_stroh(mod, sigma_rr, p, m, kr)
        np.testing.assert_allclose(
            G[np.ix_(MECHANICAL, MECHANICAL)], ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max()
        )
        # what is left is Laplace's equation for phidot in the dielectric
        K = mod[[MODULI_INDEX["K11"], MODULI_INDEX["K22"], MODULI_INDEX["K33"]]]
        np.testing.assert_allclose(
            G[np.ix_(ELECTRIC, ELECTRIC)], [[0, m**2 / K[1] + kr**2 / K[2]], [K[0], 0]], rtol=1e-14
        )


def paper_appendix_b(mod, sigma_rr, p, m, kr, n):
    """G exactly as printed in the paper's Appendix B (eta_7 = +Phi, with its n's)."""
    a = lambda name: mod[MODULI_INDEX[name]]  # noqa: E731
    r2, r3 = a("G122") / a("K22"), a("G133") / a("K33")
    g12 = a("A1212") - a("G122") ** 2 / a("K22")
    g21 = a("A2121") - a("G122") ** 2 / a("K22")
    g13 = a("A1313") - a("G133") ** 2 / a("K33")
    g31 = a("A3131") - a("G133") ** 2 / a("K33")
    g23, g32, s = a("A2323"), a("A3232"), sigma_rr
    xi1 = -(r2 * m**2 / g12 + r3 * kr**2 / g13) * s
    xi2 = -(m**2 / a("K22") + r2**2 * m**2 / g12 + kr**2 / a("K33") + r3**2 * kr**2 / g13)
    b12 = (
        a("A1111") + a("A2222") - 2 * a("A1122") - 2 * a("A1221") + 2 * a("G122") ** 2 / a("K22")
    ) / 2
    b13 = (
        a("A1111") + a("A3333") - 2 * a("A1133") - 2 * a("A1331") + 2 * a("G133") ** 2 / a("K33")
    ) / 2
    k11 = (
        2 * (g12 - s + b12)
        + m**2 * (g21 - (g12 - s) ** 2 / g12)
        + kr**2 * (g31 - (g13 - s) ** 2 / g13)
    )
    k12 = m * (g12 + g21 + 2 * b12 - s**2 / g12)
    k13 = kr * (a("A1111") + a("A2233") - a("A1122") - a("A1133") + p)
    k22 = 2 * m**2 * (g12 - s + b12) + g21 - (g12 - s) ** 2 / g12 + kr**2 * g32
    k23 = m * kr * (a("A1111") + a("A2233") + a("A2332") - a("A1122") - a("A1133") + 2 * p)
    k33 = 2 * kr**2 * (g13 - s + b13) + m**2 * g23
    d21, d31 = a("G111") - a("G221"), a("G111") - a("G331")
    G1 = [
        [-1, -m, -kr, 0],
        [m * (1 - s / g12), 1 - s / g12, 0, 0],
        [kr * (1 - s / g13), 0, 0, 0],
        [xi1, -m * s / g12 * r2, 0, 0],
    ]
    G2 = [
        [0, 0, 0, 0],
        [0, 1 / g12, 0, -m / g12 * r2],
        [0, 0, 1 / g13, -kr / g13 * r3],
        [0, m / g12 * r2, kr / g13 * r3, xi2],
    ]
    G3 = [
        [k11, k12, k13, -d21],
        [k12, k22, k23, -m * d21],
        [k13, k23, k33, -kr * d31],
        [d21, m * d21, kr * d31, -a("K11")],
    ]
    G4 = [
        [1, -m * (g12 - s) / g12, -kr * (g13 - s) / g13, xi1],
        [n, -(g12 - s) / g12, 0, -n * s / g12 * r2],
        [kr, 0, 0, 0],
        [0, 0, 0, 0],
    ]
    return np.block([[np.array(G1), np.array(G2)], [np.array(G3), np.array(G4)]])


#: Entries (0-based, 8x8) where the printed Appendix B is wrong: n for m in G4.
PAPER_TYPOS = {(5, 4), (5, 7)}


@pytest.mark.parametrize("name", MATERIALS)
def test_paper_appendix_b(name):
    """App. B = T G T (sign of Phi), except n for m in G4(2,1) and G4(2,4)."""
    for *_, p, mod, tau1 in material_states(MATERIALS[name], 4, seed=8):
        sigma_rr = tau1 - p
        for m, kr in [(3, 0.8), (7, 2.2)]:
            ours = T_PAPER @ G_of(mod, p, m, kr) @ T_PAPER
            scale = np.abs(ours).max()
            printed = paper_appendix_b(mod, sigma_rr, p, m, kr, n=m + 2)
            wrong = {
                tuple(ij)
                for ij in np.argwhere(~np.isclose(printed, ours, rtol=1e-11, atol=1e-11 * scale))
            }
            assert wrong == PAPER_TYPOS
            np.testing.assert_allclose(
                paper_appendix_b(mod, sigma_rr, p, m, kr, n=m),
                ours,
                rtol=1e-11,
                atol=1e-11 * scale,
            )
            # the paper's sign of Phi is exactly what breaks the Hamiltonian structure
            P1, P4 = printed[:4, :4], paper_appendix_b(mod, sigma_rr, p, m, kr, m)[4:, 4:]
            assert not np.allclose(P4, -P1.T)


# --- the impedance ----------------------------------------------------------------------


def integrate_impedance(G_at, r0=1.0, r1=1.25):
    """z(r1) from dz/dr = (-z G1 - z G2 z + G3 + G4 z)/r, z(r0) = 0 (paper eq. Riccati)."""

    def rhs(r, y):
        z = y.reshape(4, 4)
        G = G_at(r)
        G1, G2, G3, G4 = G[:4, :4], G[:4, 4:], G[4:, :4], G[4:, 4:]
        return ((-z @ G1 - z @ G2 @ z + G3 + G4 @ z) / r).ravel()

    sol = solve_ivp(rhs, (r0, r1), np.zeros(16), method="DOP853", rtol=1e-11, atol=1e-12)
    assert sol.success
    return sol.y[:, -1].reshape(4, 4)


@pytest.mark.parametrize("name", MATERIALS)
def test_impedance_stays_symmetric(name):
    ((*_, p, mod, _),) = material_states(MATERIALS[name], 1, seed=9)
    m, k = 3.0, 2.0
    z = integrate_impedance(lambda r: G_of(mod, p, m, k * r))
    assert np.abs(z).max() > 1.0
    assert np.abs(z - z.T).max() < 1e-12 * max(1.0, np.abs(z).max())
    # with the paper's sign of Phi the impedance loses its symmetry
    zp = integrate_impedance(lambda r: T_PAPER @ G_of(mod, p, m, k * r) @ T_PAPER)
    assert np.abs(zp - zp.T).max() > 1e-3
