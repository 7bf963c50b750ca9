"""The closed-form neo-Hookean state's fields at many radii in one compiled loop.

A march builds a Chebyshev table of the base state at every step (incremental/
radial_table.py), from r, the 23 moduli and p at 17 radii. For the paper's tube those are
closed forms (docs/derivation-base-state.md), which NumPy evaluates in ~30 small array
operations (30 us, a tenth of a warm critical value); here one loop (~2 us).

:func:`nh_fields` is a transcription of the NumPy route (UniformState._local, ``_tau``,
``_sigma_rr`` and materials.neo_hookean_moduli): the same operations in the same order, each
correctly rounded or the same C library's log1p, so the arrays equal the slow twin's bit for
bit (tests/basestate/test_closed_form_fields.py, on random states).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from ..model.materials import MODULI_INDEX

_B1 = np.array([MODULI_INDEX[n] for n in ("A1111", "A1212", "A1313")])  # b1 + d^2
_B2 = np.array([MODULI_INDEX[n] for n in ("A2121", "A2222", "A2323")])  # b2
_B3 = np.array([MODULI_INDEX[n] for n in ("A3131", "A3232", "A3333")])  # b3
_D = np.array([MODULI_INDEX[n] for n in ("G122", "G133")])  # d; G111 = 2 d
_K = np.array([MODULI_INDEX[n] for n in ("K11", "K22", "K33")])  # 1
_G111 = MODULI_INDEX["G111"]
N_MODULI = len(MODULI_INDEX)


def nh_fields(R, r_i, b, growth, stretch, charge, outer_radius, r_o):
    """(r, moduli (n, 23), p) of the closed-form neo-Hookean state at the radii R.

    r^2 = r_i^2 + b (R^2 - 1) with b = g^3 / lambda_z; l2 = r / (g R), l3 = lambda_z / g,
    l1 = 1 / (l2 l3); d = c / r; the moduli delta_ij (B_pq + D_p D_q), Gamma from I5 / 2,
    K = I; p = tau_1 - sigma_rr with tau_1 = l1^2 + d^2 and sigma_rr by (NH-1),
    (g / 2 lz) [log1p(x) - y]. NumPy's log1p of an array may differ from the C library's
    in the last bit (its vectorised loops), so x is returned and the log1p taken outside.
    """
    r, moduli, tau1, x, y = _nh_parts(R, r_i, b, growth, stretch, charge, outer_radius, r_o)
    return r, moduli, tau1 - 0.5 * growth / stretch * (np.log1p(x) - y)


@nb.njit(cache=True)
def _nh_parts(R, r_i, b, growth, stretch, charge, outer_radius, r_o):
    """r, the moduli, tau_1 and the two terms x, y of (NH-1) of :func:`nh_fields`."""
    n = R.shape[0]
    r = np.empty(n)
    moduli = np.zeros((n, N_MODULI))
    tau1, x, y = np.empty(n), np.empty(n), np.empty(n)
    a, ro2, k = r_i**2 - b, r_o**2, outer_radius**2 - 1.0
    tail = math.log1p(k * a / ro2)  # a scalar: the C library's log1p, as in NumPy's route
    l3 = stretch / growth
    for j in range(n):
        R2m1 = R[j] ** 2 - 1.0
        rj = math.sqrt(r_i**2 + b * R2m1)
        l2 = rj / (growth * R[j])
        l1 = 1.0 / (l2 * l3)
        d = charge / rj
        b1, b2, b3, d2 = l1**2, l2**2, l3**2, d**2
        for i in _B1:
            moduli[j, i] = b1 + d2
        for i in _B2:
            moduli[j, i] = b2
        for i in _B3:
            moduli[j, i] = b3
        for i in _D:
            moduli[j, i] = d
        moduli[j, _G111] = 2 * d
        for i in _K:
            moduli[j, i] = 1.0
        r[j], tau1[j] = rj, b1 + d2
        x[j], y[j] = R2m1 * a / rj**2, tail * ro2 / rj**2 * R2m1 / k
    return r, moduli, tau1, x, y
