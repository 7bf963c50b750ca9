"""The closed-form neo-Hookean state's fields at many radii in one compiled loop.

A march builds a Chebyshev table of the base state at every step (incremental/
radial_table.py), from r, the 23 moduli and p at 17 radii. For the paper's tube those are
closed forms (docs/derivation-base-state.md), which NumPy evaluates in ~30 small array
operations (30 us, a tenth of a warm critical value); here one loop (~2 us).

:func:`nh_fields` is a transcription of the NumPy route (UniformState._local, ``_tau``,
``_sigma_rr`` and moduli.neo_hookean_moduli): the same operations in the same order, each
correctly rounded or the same C library's log1p, so the arrays equal the slow twin's bit for
bit (tests/basestate/test_closed_form_fields.py, on random states). :func:`nh_table_block`
writes the table's whole block (the moduli, p, r and w = (dr/dR) / r) in the same pass: the
table's column stacking and w were another ~10 small array operations per step.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from ..errors import ParameterError
from ..model.moduli import MODULI_INDEX

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
    a, ro2, k, tail, l3 = _nh_constants(r_i, b, growth, stretch, outer_radius, r_o)
    for j in range(n):
        r[j], tau1[j], x[j], y[j] = _nh_point(
            R[j], r_i, b, growth, l3, charge, a, ro2, k, tail, moduli[j]
        )
    return r, moduli, tau1, x, y


def nh_table_block(R, r_i, b, growth, stretch, charge, outer_radius, r_o, J):
    """The (n, 26) block [23 moduli, p, r, w] of the closed-form state at the radii R, the
    rows of a radial table (incremental/radial_table.py), w = J R / (lambda_z r^2); the same
    bits as :func:`nh_fields` stacked with w in NumPy, in one compiled pass (the log1p of
    (NH-1) in NumPy, as there). ParameterError if a radius leaves the wall."""
    xy = np.empty((2, R.shape[0]))
    block = _nh_block(R, r_i, b, growth, stretch, charge, outer_radius, r_o, J, xy)
    if block.shape[0] != R.shape[0]:
        raise ParameterError(f"R outside the wall [1, {outer_radius:g}]")
    _finish_p(block, np.log1p(xy[0]), xy[1], 0.5 * growth / stretch)
    return block


@nb.njit(cache=True)
def _nh_block(R, r_i, b, growth, stretch, charge, outer_radius, r_o, J, xy):
    """The block of :func:`nh_table_block` with tau_1 in the column of p, and x, y of (NH-1)
    into the rows of ``xy``; no rows at all if a radius leaves the wall
    (UniformState._inside's bounds)."""
    n = R.shape[0]
    for j in range(n):
        if R[j] < 1.0 - 1e-12 or R[j] > outer_radius * (1.0 + 1e-12):
            return np.zeros((0, N_MODULI + 3))
    block = np.zeros((n, N_MODULI + 3))
    a, ro2, k, tail, l3 = _nh_constants(r_i, b, growth, stretch, outer_radius, r_o)
    for j in range(n):
        rj, block[j, N_MODULI], xy[0, j], xy[1, j] = _nh_point(
            R[j], r_i, b, growth, l3, charge, a, ro2, k, tail, block[j]
        )
        block[j, N_MODULI + 1] = rj
        block[j, N_MODULI + 2] = J * R[j] / (stretch * rj * rj)  # NumPy's order of operations
    return block


@nb.njit(cache=True)
def _finish_p(block, log1p_x, y, c):
    """p = tau_1 - c (log1p(x) - y) into the column of tau_1 (c = g / (2 lambda_z), as
    NumPy's scalar-times-array order computes it)."""
    for j in range(block.shape[0]):
        block[j, N_MODULI] = block[j, N_MODULI] - c * (log1p_x[j] - y[j])


@nb.njit(cache=True)
def _nh_constants(r_i, b, growth, stretch, outer_radius, r_o):
    """(A = r_i^2 - b, r_o^2, Rbar_o^2 - 1, log1p(kappa_o), lambda_z / g) of a state."""
    a, ro2, k = r_i**2 - b, r_o**2, outer_radius**2 - 1.0
    tail = math.log1p(k * a / ro2)  # a scalar: the C library's log1p, as in NumPy's route
    return a, ro2, k, tail, stretch / growth


@nb.njit(cache=True)
def _nh_point(Rj, r_i, b, growth, l3, charge, a, ro2, k, tail, row):
    """The 23 moduli at R = Rj into row[:23]; returns (r, tau_1, x, y) there."""
    R2m1 = Rj**2 - 1.0
    rj = math.sqrt(r_i**2 + b * R2m1)
    l2 = rj / (growth * Rj)
    l1 = 1.0 / (l2 * l3)
    d = charge / rj
    b1, b2, b3, d2 = l1**2, l2**2, l3**2, d**2
    for i in _B1:
        row[i] = b1 + d2
    for i in _B2:
        row[i] = b2
    for i in _B3:
        row[i] = b3
    for i in _D:
        row[i] = d
    row[_G111] = 2 * d
    for i in _K:
        row[i] = 1.0
    return rj, b1 + d2, R2m1 * a / rj**2, tail * ro2 / rj**2 * R2m1 / k
