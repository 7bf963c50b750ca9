"""The 8x8 Stroh matrix G(r) of the incremental electro-elastic tube (paper Sec. 3.3, App. B).

Incremental fields (paper eq. incremental-solutions) with amplitudes depending on r,

    u_r, phidot, pdot, D_r ~ cos(m th) cos(kz),  u_th, D_th ~ sin(m th) cos(kz),
    u_z, D_z ~ cos(m th) sin(kz),  S_rr ~ cos cos, S_rth ~ sin cos, S_rz ~ cos sin,

turn incompressibility, div S = 0 and div D = 0 into d(eta)/dr = G(r) eta / r with

    eta = [U; S],  U = [U_r, U_th, U_z, r Delta_r],
                   S = [r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi].

In the incremental energy W(L, D) + D.grad(phidot) the momentum conjugate to Phi is
r Delta_r (as r Sigma_ri is to U_i); putting Phi in the traction half is the canonical swap
(Phi, r Delta_r) -> (r Delta_r, -Phi), hence the minus sign (``SIGN_DELTA = +1``,
``SIGN_PHI = -1``). With it G is Hamiltonian for all moduli with the major symmetries,

    G = [[G1, G2], [G3, G4]],  G2 = G2^T,  G3 = G3^T,  G4 = -G1^T,

so the impedance z (S = z U) of the Riccati equation dz/dr = (-z G1 - z G2 z + G3 + G4 z)/r
stays symmetric. The paper's Appendix B uses +Phi (not Hamiltonian) and writes n for m in
two entries of G4; docs/derivation-stroh.md derives every entry and lists the differences.

G depends on r only through kr = k r and the moduli. The entries are written with the raw
moduli and p (no use of sigma_rr): with e_1a = Gamma_1aa / K_aa (a = 2, 3),

    gamma_1a = A_1a1a - e_1a Gamma_1aa     (shear modulus at fixed E_a; paper gamma_1a)
    c_1a     = A_1aa1 + p - e_1a Gamma_1aa  (= gamma_1a - sigma_rr for real materials)
    s_1a     = gamma_1a - c_1a = A_1a1a - A_1aa1 - p  (= sigma_rr by paper eq. 20-1)

Decoupled pairs (docs/derivation-families.md): every entry coupling the pair
(U_th, r Sigma_rth) to the others carries a factor m, every entry coupling (U_z, r Sigma_rz)
a factor k r. So at m = 0 the torsion pair decouples from the axisymmetric 6x6 system, and
at k = 0 (n = 0, prismatic) the anti-plane pair from the in-plane 6x6 system; the mode
families of incremental/targets.py are these blocks.
"""

from __future__ import annotations

import numba
import numpy as np
import numpy.typing as npt

from ..model.moduli import MODULI_INDEX

#: A 1-D array of the 23 updated moduli in ``moduli.MODULI_NAMES`` order.
Moduli = npt.NDArray[np.float64]
#: The 8x8 Stroh matrix G, or one of its 4x4 blocks.
StrohMatrix = npt.NDArray[np.float64]

#: Signs of the electric Stroh components: eta[3] = SIGN_DELTA r Delta_r and
#: eta[7] = SIGN_PHI Phi (SIGN_DELTA * SIGN_PHI = -1 makes G Hamiltonian).
SIGN_DELTA = 1
SIGN_PHI = -1

# Positions in the moduli vector (module-level ints are compile-time constants for numba).
A1111 = MODULI_INDEX["A1111"]
A2222 = MODULI_INDEX["A2222"]
A3333 = MODULI_INDEX["A3333"]
A1122 = MODULI_INDEX["A1122"]
A1133 = MODULI_INDEX["A1133"]
A2233 = MODULI_INDEX["A2233"]
A1212 = MODULI_INDEX["A1212"]
A2121 = MODULI_INDEX["A2121"]
A1313 = MODULI_INDEX["A1313"]
A3131 = MODULI_INDEX["A3131"]
A2323 = MODULI_INDEX["A2323"]
A3232 = MODULI_INDEX["A3232"]
A1221 = MODULI_INDEX["A1221"]
A1331 = MODULI_INDEX["A1331"]
A2332 = MODULI_INDEX["A2332"]
G111 = MODULI_INDEX["G111"]
G221 = MODULI_INDEX["G221"]
G331 = MODULI_INDEX["G331"]
G122 = MODULI_INDEX["G122"]
G133 = MODULI_INDEX["G133"]
K11 = MODULI_INDEX["K11"]
K22 = MODULI_INDEX["K22"]
K33 = MODULI_INDEX["K33"]


# IEEE division: where a shear modulus gamma_1a vanishes exactly (strong ellipticity lost;
# a Mooney-Rivlin wall with a negative I2 weight at lambda_z = 0.6666666666666667) the
# Python error model raised ZeroDivisionError for every mode, an internal error; with inf
# entries the integration fails or gives a value near zero, and the callers go on.
@numba.njit(cache=True, error_model="numpy")
def stroh_matrix(mod, p, m, kr, out):
    """Write the Stroh matrix G into ``out`` (paper eq. Stroh, d(eta)/dr = G eta / r).

    Parameters
    ----------
    mod : (23,) float array
        Updated moduli A, Gamma, K at radius r, order ``moduli.MODULI_NAMES``
        (units mu = eps = 1).
    p : float
        Base-state Lagrange multiplier p(r) (units mu).
    m : float
        Circumferential wavenumber.
    kr : float
        Axial wavenumber times radius, k r (dimensionless).
    out : (8, 8) float array
        Overwritten with G, eta = [U_r, U_th, U_z, r Delta_r, r Sigma_rr, r Sigma_rth,
        r Sigma_rz, -Phi].

    Notes
    -----
    Row i is the equation that gives r eta_i': 0 incompressibility; 1, 2 the tractions
    Sigma_rth, Sigma_rz with D_th, D_z eliminated through E_th, E_z; 3 div D = 0; 4, 5, 6
    the r, th, z equilibrium equations; 7 the radial field E_r = -d(phidot)/dr. Scalar
    arithmetic only, so the same code runs compiled and (``stroh_matrix_py``) on sympy
    symbols. Returns nothing; ``out`` is fully overwritten.
    """
    e12 = mod[G122] / mod[K22]
    e13 = mod[G133] / mod[K33]
    gam12 = mod[A1212] - e12 * mod[G122]
    gam13 = mod[A1313] - e13 * mod[G133]
    c12 = mod[A1221] + p - e12 * mod[G122]
    c13 = mod[A1331] + p - e13 * mod[G133]
    t12 = c12 / gam12  # 1 - sigma_rr / gamma_12
    t13 = c13 / gam13
    q12 = e12 * (gam12 - c12) / gam12  # e_12 sigma_rr / gamma_12
    q13 = e13 * (gam13 - c13) / gam13
    # Effective hoop and axial shear stiffnesses left after eliminating U_th', U_z', D.
    h12 = mod[A2121] - e12 * mod[G122] - c12 * c12 / gam12
    h13 = mod[A3131] - e13 * mod[G133] - c13 * c13 / gam13
    b12 = mod[A1111] - 2.0 * mod[A1122] + mod[A2222] + 2.0 * p
    b13 = mod[A1111] - 2.0 * mod[A1133] + mod[A3333] + 2.0 * p
    a13 = mod[A1111] - mod[A1122] - mod[A1133] + mod[A2233]
    g21 = mod[G221] - mod[G111]
    g31 = mod[G331] - mod[G111]
    m2 = m * m
    k2 = kr * kr
    xi = m2 * q12 + k2 * q13
    for i in range(8):
        for j in range(8):
            out[i, j] = 0.0
    # 0: tr L = 0  ->  U_r' = -(U_r + m U_th)/r - k U_z
    out[0, 0] = -1.0
    out[0, 1] = -m
    out[0, 2] = -kr
    # 1: Sigma_rth = A1212 L_21 + (A1221 + p) L_12 + Gamma122 D_th, E_th = m Phi / r
    out[1, 0] = m * t12
    out[1, 1] = t12
    out[1, 5] = 1.0 / gam12
    out[1, 7] = m * e12 / gam12
    # 2: Sigma_rz = A1313 L_31 + (A1331 + p) L_13 + Gamma133 D_z, E_z = k Phi
    out[2, 0] = kr * t13
    out[2, 6] = 1.0 / gam13
    out[2, 7] = kr * e13 / gam13
    # 3: div D = 0  ->  (r Delta_r)' = -(m D_th + k r D_z)
    out[3, 0] = -xi
    out[3, 1] = -m * q12
    out[3, 5] = m * e12 / gam12
    out[3, 6] = kr * e13 / gam13
    out[3, 7] = m2 * (1.0 / mod[K22] + e12 * e12 / gam12) + k2 * (
        1.0 / mod[K33] + e13 * e13 / gam13
    )
    # 4: radial equilibrium, (r Sigma_rr)' = S_thth - m S_thr - k r S_zr (amplitudes;
    #    S_thz, S_zth carry sin(m th) sin(kz), the other S_ij the factor of L_ji)
    out[4, 0] = b12 + m2 * h12 + k2 * h13
    out[4, 1] = m * (b12 + h12)
    out[4, 2] = kr * (a13 + p)
    out[4, 3] = g21
    out[4, 4] = 1.0
    out[4, 5] = -m * t12
    out[4, 6] = -kr * t13
    out[4, 7] = xi
    # 5: hoop equilibrium, (r Sigma_rth)' = m S_thth - S_thr - k r S_zth
    out[5, 0] = m * (b12 + h12)
    out[5, 1] = h12 + m2 * b12 + k2 * mod[A3232]
    out[5, 2] = m * kr * (a13 + mod[A2332] + 2.0 * p)
    out[5, 3] = m * g21
    out[5, 4] = m
    out[5, 5] = -t12
    out[5, 7] = m * q12
    # 6: axial equilibrium, (r Sigma_rz)' = k r S_zz - m S_thz
    out[6, 0] = kr * (a13 + p)
    out[6, 1] = m * kr * (a13 + mod[A2332] + 2.0 * p)
    out[6, 2] = k2 * b13 + m2 * mod[A2323]
    out[6, 3] = kr * g31
    out[6, 4] = kr
    # 7: E_r = -Phi' = Gamma_qj1 L_jq + K11 D_r, eta_7 = -Phi
    out[7, 0] = g21
    out[7, 1] = m * g21
    out[7, 2] = kr * g31
    out[7, 3] = mod[K11]


#: The uncompiled twin of :func:`stroh_matrix` (same code; also accepts sympy objects).
stroh_matrix_py = stroh_matrix.py_func


def stroh_blocks(
    mod: Moduli, p: float, m: float, kr: float
) -> tuple[StrohMatrix, StrohMatrix, StrohMatrix, StrohMatrix]:
    """The 4x4 blocks (G1, G2, G3, G4) of :func:`stroh_matrix`, as new arrays.

    Examples
    --------
    >>> import numpy as np
    >>> from electrogrowth.model.moduli import neo_hookean_moduli
    >>> G1, G2, G3, G4 = stroh_blocks(neo_hookean_moduli(1.0, 1.0, 1.0, 0.5), 1.0, 2, 0.5)
    >>> bool(np.allclose(G4, -G1.T) and np.allclose(G2, G2.T) and np.allclose(G3, G3.T))
    True
    """
    G = np.empty((8, 8))
    stroh_matrix(np.ascontiguousarray(mod, dtype=np.float64), float(p), float(m), float(kr), G)
    return G[:4, :4].copy(), G[:4, 4:].copy(), G[4:, :4].copy(), G[4:, 4:].copy()


def neo_hookean_stroh_matrix(
    l1: float, l2: float, l3: float, d: float, p: float, m: float, kr: float
) -> StrohMatrix:
    """Closed-form G for the ideal neo-Hookean dielectric (paper Sec. 4.2, App. B).

    Moduli of ``moduli.neo_hookean_moduli``: A_1a1a = A1111 = l1^2 + d^2,
    A_2a2a = l2^2, A_3a3a = l3^2, Gamma111 = 2 d, Gamma122 = Gamma133 = d, K = I. Then
    gamma_12 = gamma_13 = l1^2 and s = sigma_rr = l1^2 + d^2 - p. A plain function used to
    test :func:`stroh_matrix`; ``d`` is the current radial displacement D_r.
    """
    b1, b2, b3 = l1 * l1, l2 * l2, l3 * l3
    s = b1 + d * d - p  # sigma_rr
    t = 1.0 - s / b1  # c / gamma = (p - d^2) / l1^2
    w = m * m + kr * kr
    h2 = b2 - d * d - (b1 - s) ** 2 / b1  # h_12
    h3 = b3 - d * d - (b1 - s) ** 2 / b1  # h_13
    b12 = b1 + d * d + b2 + 2.0 * p
    b13 = b1 + d * d + b3 + 2.0 * p
    a = b1 + d * d + p
    ds = d * s / b1
    return np.array(
        [
            [-1.0, -m, -kr, 0.0, 0.0, 0.0, 0.0, 0.0],
            [m * t, t, 0.0, 0.0, 0.0, 1.0 / b1, 0.0, m * d / b1],
            [kr * t, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0 / b1, kr * d / b1],
            [-w * ds, -m * ds, 0.0, 0.0, 0.0, m * d / b1, kr * d / b1, w * (b1 + d * d) / b1],
            [
                b12 + m * m * h2 + kr * kr * h3,
                m * (b12 + h2),
                kr * a,
                -2.0 * d,
                1.0,
                -m * t,
                -kr * t,
                w * ds,
            ],
            [
                m * (b12 + h2),
                h2 + m * m * b12 + kr * kr * b3,
                m * kr * (a + p),
                -2.0 * d * m,
                m,
                -t,
                0.0,
                m * ds,
            ],
            [
                kr * a,
                m * kr * (a + p),
                kr * kr * b13 + m * m * b2,
                -2.0 * d * kr,
                kr,
                0.0,
                0.0,
                0.0,
            ],
            [-2.0 * d, -2.0 * d * m, -2.0 * d * kr, 1.0, 0.0, 0.0, 0.0, 0.0],
        ]
    )
