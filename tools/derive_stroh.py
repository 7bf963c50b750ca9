"""Derive the 8x8 Stroh matrix of the electro-elastic tube with sympy (dev tool).

Run ``PYTHONPATH=src .venv/bin/python tools/derive_stroh.py`` to print the entries of G for
generic moduli (the 23 symbols of ``moduli.MODULI_NAMES``, plus p, m, k, r) and for the
ideal neo-Hookean dielectric. The package does not import this file; the tests load it to
compare ``electrogrowth.incremental.stroh`` with the derivation. The maths is in
docs/derivation-stroh.md.

Route (nothing is transcribed from the paper's Appendix B):

1. incremental fields with the paper's trig factors (eq. incremental-solutions), with
   amplitudes that are functions of r;
2. L = grad u in the cylindrical basis (paper eq. 52), E = -grad(phidot);
3. S_pi = A_piqj L_jq + G_piq D_q + p L_pi - pdot delta_pi and E_p = G_qjp L_jq + K_pq D_q
   (docs/conventions.md), the moduli looked up in the principal basis;
4. the equations: incompressibility (tr L = 0), the definitions of the traction amplitudes
   Sigma_ri = S_ri, the three components of E, div D = 0 and div S = 0 (divergence on the
   first index, paper eq. incremental-constitutive3, with S_ri written through Sigma_ri);
   each is divided by its trig factor, and the quotient is checked to be independent of
   theta and z;
5. a linear solve for the r-derivatives of the Stroh vector and the auxiliary amplitudes
   (D_theta, D_z, pdot), then G = r d(eta')/d(eta).
"""

from __future__ import annotations

import functools
import sys

import sympy as sp

try:
    from electrogrowth.model.moduli import MODULI_NAMES
except ImportError:  # pragma: no cover - run without PYTHONPATH=src
    sys.path.insert(0, "src")
    from electrogrowth.model.moduli import MODULI_NAMES

#: Signs of the electric entries of the Stroh vector: eta = [U_r, U_th, U_z, S1 r Delta_r,
#: r Sigma_rr, r Sigma_rth, r Sigma_rz, S2 Phi]. S1 * S2 = -1 makes G Hamiltonian.
S1, S2 = 1, -1

r, theta, z = sp.symbols("r theta z", positive=True)
m, k, p = sp.symbols("m k p", real=True)
MOD = {name: sp.Symbol(name, real=True) for name in MODULI_NAMES}


def modulus_A(pp: int, i: int, q: int, j: int) -> sp.Expr:
    """A_piqj (indices 1..3) in the principal basis, using A_piqj = A_qjpi."""
    for name in (f"A{pp}{i}{q}{j}", f"A{q}{j}{pp}{i}"):
        if name in MOD:
            return MOD[name]
    return sp.S.Zero


def modulus_G(pp: int, i: int, q: int) -> sp.Expr:
    """Gamma_piq in the principal basis, using Gamma_piq = Gamma_ipq."""
    for name in (f"G{pp}{i}{q}", f"G{i}{pp}{q}"):
        if name in MOD:
            return MOD[name]
    return sp.S.Zero


def modulus_K(pp: int, q: int) -> sp.Expr:
    return MOD.get(f"K{pp}{q}", sp.S.Zero) if pp == q else sp.S.Zero


def incremental_fields():
    """Amplitude functions and the full fields u, phidot, pdot, D (trig factors included)."""
    amp = {n: sp.Function(n)(r) for n in ("Ur", "Ut", "Uz", "Phi", "Dr", "Dt", "Dz", "P")}
    cc = sp.cos(m * theta) * sp.cos(k * z)
    sc = sp.sin(m * theta) * sp.cos(k * z)
    cs = sp.cos(m * theta) * sp.sin(k * z)
    u = [amp["Ur"] * cc, amp["Ut"] * sc, amp["Uz"] * cs]
    D = [amp["Dr"] * cc, amp["Dt"] * sc, amp["Dz"] * cs]
    return amp, u, amp["Phi"] * cc, amp["P"] * cc, D, (cc, sc, cs)


def displacement_gradient(u):
    """L_jq = du_j/dx_q in the cylindrical basis (paper eq. 52); row j, column q."""
    ur, ut, uz = u
    return sp.Matrix(
        [
            [sp.diff(ur, r), (sp.diff(ur, theta) - ut) / r, sp.diff(ur, z)],
            [sp.diff(ut, r), (sp.diff(ut, theta) + ur) / r, sp.diff(ut, z)],
            [sp.diff(uz, r), sp.diff(uz, theta) / r, sp.diff(uz, z)],
        ]
    )


def constitutive(L, D, pdot):
    """S_pi (row p, column i) and the constitutive E_p (updated form, conventions.md)."""
    S = sp.zeros(3, 3)
    E = sp.zeros(3, 1)
    for a in range(3):
        for i in range(3):
            s = sum(
                modulus_A(a + 1, i + 1, q + 1, j + 1) * L[j, q] for q in range(3) for j in range(3)
            )
            s += sum(modulus_G(a + 1, i + 1, q + 1) * D[q] for q in range(3))
            S[a, i] = s + p * L[a, i] - (pdot if a == i else 0)
        E[a] = sum(
            modulus_G(q + 1, j + 1, a + 1) * L[j, q] for q in range(3) for j in range(3)
        ) + sum(modulus_K(a + 1, q + 1) * D[q] for q in range(3))
    return S, E


def divergence_first_index(S):
    """(div S)_i = dS_pi/dx_p, cylindrical (paper eq. incremental-constitutive3)."""
    d = lambda f, i: (sp.diff(f, r), sp.diff(f, theta) / r, sp.diff(f, z))[i]  # noqa: E731
    return [
        d(S[0, 0], 0) + d(S[1, 0], 1) + d(S[2, 0], 2) + (S[0, 0] - S[1, 1]) / r,
        d(S[0, 1], 0) + d(S[1, 1], 1) + d(S[2, 1], 2) + (S[1, 0] + S[0, 1]) / r,
        d(S[0, 2], 0) + d(S[1, 2], 1) + d(S[2, 2], 2) + S[0, 2] / r,
    ]


def strip(expr, factor):
    """expr / factor, checked independent of theta and z (the trig bookkeeping)."""
    q = sp.simplify(sp.expand(expr) / factor)
    if sp.simplify(sp.diff(q, theta)) != 0 or sp.simplify(sp.diff(q, z)) != 0:
        raise AssertionError(f"wrong trig factor {factor} for {expr}")
    return sp.expand(q)


@functools.lru_cache(maxsize=4)
def derive(s1: int = S1, s2: int = S2):
    """Return (G, eta_symbols): the generic 8x8 Stroh matrix with d(eta)/dr = G eta / r.

    G is a sympy Matrix in the symbols ``MOD`` (MODULI_NAMES), p, m and ``kr`` (= k r);
    eta = [U_r, U_th, U_z, s1 r Delta_r, r Sigma_rr, r Sigma_rth, r Sigma_rz, s2 Phi].
    """
    amp, u, phi, pdot, D, (cc, sc, cs) = incremental_fields()
    L = displacement_gradient(u)
    S, E_const = constitutive(L, D, pdot)
    grad_phi = [sp.diff(phi, r), sp.diff(phi, theta) / r, sp.diff(phi, z)]
    div_D = sp.diff(r * D[0], r) / r + sp.diff(D[1], theta) / r + sp.diff(D[2], z)
    sig = {n: sp.Function(n)(r) for n in ("Srr", "Srt", "Srz")}
    # In div S the r-face components S_ri are the traction amplitudes (state variables),
    # tied to the constitutive law by the three definition equations below.
    S_face = S.copy()
    S_face[0, :] = sp.Matrix([[sig["Srr"] * cc, sig["Srt"] * sc, sig["Srz"] * cs]])
    div_S = divergence_first_index(S_face)

    eqs = [
        strip(L.trace(), cc),  # incompressibility
        strip(S[0, 0] - sig["Srr"] * cc, cc),  # traction amplitudes
        strip(S[0, 1] - sig["Srt"] * sc, sc),
        strip(S[0, 2] - sig["Srz"] * cs, cs),
        strip(E_const[0] + grad_phi[0], cc),  # E = -grad phidot
        strip(E_const[1] + grad_phi[1], sc),
        strip(E_const[2] + grad_phi[2], cs),
        strip(div_D, cc),  # Maxwell
        strip(div_S[0], cc),  # equilibrium
        strip(div_S[1], sc),
        strip(div_S[2], cs),
    ]
    # Stroh vector (amplitudes) and its derivative, as plain symbols.
    names = ["Ur", "Ut", "Uz", "s1rDr", "rSrr", "rSrt", "rSrz", "s2Phi"]
    eta = sp.symbols(" ".join(names), real=True)
    deta = sp.symbols(" ".join("d" + n for n in names), real=True)
    Dt, Dz, P = sp.symbols("Dt Dz P", real=True)
    # amplitude function -> expression in eta (S1, S2 signs), derivatives likewise.
    value = {
        amp["Ur"]: eta[0],
        amp["Ut"]: eta[1],
        amp["Uz"]: eta[2],
        amp["Dr"]: s1 * eta[3] / r,
        sig["Srr"]: eta[4] / r,
        sig["Srt"]: eta[5] / r,
        sig["Srz"]: eta[6] / r,
        amp["Phi"]: s2 * eta[7],
        amp["Dt"]: Dt,
        amp["Dz"]: Dz,
        amp["P"]: P,
    }
    slope = {
        amp["Ur"]: deta[0],
        amp["Ut"]: deta[1],
        amp["Uz"]: deta[2],
        amp["Dr"]: s1 * (deta[3] - eta[3] / r) / r,
        sig["Srr"]: (deta[4] - eta[4] / r) / r,
        sig["Srt"]: (deta[5] - eta[5] / r) / r,
        sig["Srz"]: (deta[6] - eta[6] / r) / r,
        amp["Phi"]: s2 * deta[7],
    }
    subs = {sp.Derivative(f, r): v for f, v in slope.items()}
    eqs = [e.subs(subs).subs(value) for e in eqs]
    for e in eqs:
        if e.atoms(sp.Derivative):
            raise AssertionError(f"second derivatives left in {e}")
    sol = sp.solve(eqs, list(deta) + [Dt, Dz, P], dict=True)[0]
    kr = sp.Symbol("kr", real=True)
    rows = [sp.expand(r * sol[d]) for d in deta]
    G = sp.Matrix(
        8, 8, lambda i, j: sp.factor(sp.cancel(sp.diff(rows[i], eta[j]).subs(k, kr / r)))
    )
    if G.free_symbols & {r, k}:
        raise AssertionError("G depends on r or k other than through kr")
    return G, eta


def neo_hookean_substitution(l1, l2, l3, d):
    """Moduli of the ideal neo-Hookean dielectric (moduli.neo_hookean_moduli), symbolic."""
    b1, b2, b3 = l1**2, l2**2, l3**2
    val = dict.fromkeys(MODULI_NAMES, 0)
    val.update(
        A1111=b1 + d**2,
        A1212=b1 + d**2,
        A1313=b1 + d**2,
        A2121=b2,
        A2222=b2,
        A2323=b2,
        A3131=b3,
        A3232=b3,
        A3333=b3,
        G111=2 * d,
        G122=d,
        G133=d,
        K11=1,
        K22=1,
        K33=1,
    )
    return {MOD[n]: v for n, v in val.items()}


def is_hamiltonian(G) -> bool:
    G1, G2, G3, G4 = G[:4, :4], G[:4, 4:], G[4:, :4], G[4:, 4:]
    zero = lambda M: all(sp.simplify(x) == 0 for x in M)  # noqa: E731
    return zero(G2 - G2.T) and zero(G3 - G3.T) and zero(G4 + G1.T)


def main() -> None:
    G, eta = derive()
    print(f"eta = {list(eta)}  (S1 = {S1:+d}, S2 = {S2:+d})")
    for s1, s2 in ((1, 1), (-1, -1), (1, -1), (-1, 1)):
        print(
            f"s1 = {s1:+d}, s2 = {s2:+d}: Hamiltonian (G2 = G2^T, G3 = G3^T, "
            f"G4 = -G1^T) = {is_hamiltonian(derive(s1, s2)[0])}"
        )
    print("\nGeneric moduli, non-zero entries G[i, j] (0-based):")
    for i in range(8):
        for j in range(8):
            if G[i, j] != 0:
                print(f"  G[{i},{j}] = {G[i, j]}")
    l1, l2, l3, d = sp.symbols("l1 l2 l3 d", positive=True)
    Gn = G.subs(neo_hookean_substitution(l1, l2, l3, d)).applyfunc(sp.factor)
    print("\nIdeal neo-Hookean (b_i = l_i^2, d = D_r), non-zero entries:")
    for i in range(8):
        for j in range(8):
            if Gn[i, j] != 0:
                print(f"  G[{i},{j}] = {Gn[i, j]}")


if __name__ == "__main__":
    main()
