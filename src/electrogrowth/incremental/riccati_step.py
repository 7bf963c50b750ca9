"""One step of the impedance kernel (impedance.py), compiled: the Riccati equation of the
scaled impedance z~ in its current chart, with the base state read off the Chebyshev table,
and a Dormand-Prince 8(5,3) step (the tableau of dop853.py) with DOP853's error norm.

    dz~/dR = w (G~3 - z~ G~1 - (z~ G~1)^T - z~ G~2 z~),   w = (dr/dR) / r,

using G~4 = -G~1^T (G Hamiltonian); the chart's permutation and signs (charts.py) are held
in the scratch record :class:`_Work`, allocated once per integration.

The base state is most of a stage's cost (the table's Clenshaw recurrences, the Stroh
matrix, its blocks in the chart), and it does not depend on z~: a step computes it at its
eleven stage radii first, together (:func:`_stage_blocks`), and keeps the last one, R + h,
which serves the error stage K_12 and the next step's first slope too (:func:`next_slope`),
so an accepted step costs eleven base states instead of thirteen. The arithmetic is that of
one radius at a time, to the bit (tests/incremental/test_riccati_step.py); with the helpers
inlined, the stage sums skipping the tableau's zeros and the eleven recurrences written
out as scalars, a step takes ~2.5 us instead of ~3.7 us.
"""

from __future__ import annotations

from typing import NamedTuple

import numba as nb
import numpy as np

from .dop853 import E3, E5, N_STAGES, ORDER, A, B, C
from .stroh import stroh_matrix

_NS = N_STAGES


_A = np.ascontiguousarray(A)


_B = np.ascontiguousarray(B)


_C = np.ascontiguousarray(C)


_E3 = np.ascontiguousarray(E3)


_E5 = np.ascontiguousarray(E5)


def _nonzero_columns(a):
    """Row s of ``a``'s nonzero columns, in order, padded with -1: a stage's sum skips
    the tableau's zeros (16 of DOP853's 66 A_sq and 4 of its 12 B_s), and in the same
    order of terms it is the same sum to the bit (adding 0 K is exact for finite K)."""
    a = np.atleast_2d(a)
    out = np.full(a.shape, -1, np.int64)
    for s, row in enumerate(a):
        nz = np.flatnonzero(row)
        out[s, : nz.size] = nz
    return out


_AQ = _nonzero_columns(_A)
_BQ = _nonzero_columns(_B)[0]


_EXPONENT = -1.0 / ORDER  # step-size exponent of the error estimate


class _Work(NamedTuple):
    """Scratch arrays of one integration, allocated once: a step allocates nothing."""

    vals: np.ndarray  # (2 F,) the two Clenshaw recurrences of the F table functions
    mod: np.ndarray  # (23,) the moduli at the current radius
    G: np.ndarray  # (8, 8) the Stroh matrix
    Gt: np.ndarray  # (8, 8) its blocks in the current chart, scaled
    P: np.ndarray  # (4, 8) z~ [G~1 G~2]
    perm: np.ndarray  # (8,) the current chart ...
    mult: np.ndarray  # (8, 8) ... and its signs times the scaling of S
    x2: np.ndarray  # (11,) the Clenshaw argument 2 x at the stage radii 1..11 of a step
    stage_vals: np.ndarray  # (F, 11) the table's functions there, ...
    stage_Gt: np.ndarray  # (12, 8, 8) ... the blocks G~ ...
    stage_w: np.ndarray  # (12,) ... and w
    stage_rate: np.ndarray  # (12,) d log det U~ / dR at the stages of a step


@nb.njit(cache=True)
def _new_work(table):
    F = table.coef.shape[1]
    return _Work(
        np.empty(2 * F),
        np.empty(23),
        np.empty((8, 8)),
        np.empty((8, 8)),
        np.empty((4, 8)),
        np.empty(8, np.int64),
        np.empty((8, 8)),
        np.empty(_NS - 1),
        np.empty((F, _NS - 1)),
        np.empty((_NS, 8, 8)),
        np.empty(_NS),
        np.empty(_NS),
    )


@nb.njit(cache=True)
def _base_at(R, table, seg, vals, mod):
    """Fill mod[23] at R in segment ``seg``; return (p, r, w = (dr/dR)/r).

    One Clenshaw recurrence for all distinct functions of the segment at once (the
    coefficient rows are zero-padded), so the inner loop runs across functions and
    vectorises.
    """
    coef, fmap = table.coef[seg], table.fmap[seg]
    a, b = table.bounds[seg], table.bounds[seg + 1]
    x2 = 2.0 * (2.0 * R - a - b) / (b - a)
    nf, width = table.n_funcs[seg], coef.shape[1]
    b1 = vals  # reuse scratch: vals[:nf] = b1, vals[nf:2nf] = b2
    for f in range(2 * nf):
        b1[f] = 0.0
    for j in range(width - 1, 0, -1):
        for f in range(nf):
            t = x2 * b1[f] - b1[nf + f] + coef[f, j]
            b1[nf + f] = b1[f]
            b1[f] = t
    for f in range(nf):
        b1[f] = 0.5 * x2 * b1[f] - b1[nf + f] + coef[f, 0]
    for f in range(23):
        mod[f] = vals[fmap[f]]
    return vals[fmap[23]], vals[fmap[24]], vals[fmap[25]]


@nb.njit(cache=True, inline="always")
def _rhs(R, z, m, k, table, seg, work, out):
    """dz~/dR = w (G3 - z G1 - (z G1)^T - z G2 z), using G4 = -G1^T (G Hamiltonian);
    returns d log|det U~| / dR there (:func:`_riccati`)."""
    p, r, w = _base_at(R, table, seg, work.vals, work.mod)
    _blocks(work.mod, p, m, k * r, work, work.Gt)
    return _riccati(z, work.Gt, w, work.P, out)


@nb.njit(cache=True, inline="always")
def _blocks(mod, p, m, kr, work, Gt):
    """Gt <- the blocks G~1, G~2 (rows 0-3) and G~3 (rows 4-7, cols 0-3) of the Stroh
    matrix in the current chart, scaled (work.perm, work.mult)."""
    G, perm, mult = work.G, work.perm, work.mult
    stroh_matrix(mod, p, m, kr, G)
    # most steps are in the chart J = {} (perm the identity), where the same products need
    # no gather (~10 %); loops of fixed length, which the compiler unrolls (a third faster
    # than one loop with a row-dependent length)
    if perm[0] == 0 and perm[1] == 1 and perm[2] == 2 and perm[3] == 3:
        for a in range(4):
            for b in range(8):
                Gt[a, b] = G[a, b] * mult[a, b]
        for a in range(4, 8):
            for b in range(4):
                Gt[a, b] = G[a, b] * mult[a, b]
    else:
        for a in range(4):
            for b in range(8):
                Gt[a, b] = G[perm[a], perm[b]] * mult[a, b]
        for a in range(4, 8):
            for b in range(4):
                Gt[a, b] = G[perm[a], perm[b]] * mult[a, b]


@nb.njit(cache=True, inline="always")
def _riccati(z, Gt, w, P, out):
    """out <- w (G~3 - z G~1 - (z G~1)^T - z G~2 z) from the blocks ``Gt`` (P scratch).

    Returns w tr(G~1 + G~2 z~), the rate of log|det U~| of the carried basis [U~; z~ U~]
    (dU~/dR = w (G~1 + G~2 z~) U~): its integral through the wall is the size of the
    solutions that the Riccati form divides out (impedance.integrate_one's log_norm)."""
    for i in range(4):
        for j in range(4):
            a1 = 0.0
            a2 = 0.0
            for q in range(4):
                a1 += z[i, q] * Gt[q, j]
                a2 += z[i, q] * Gt[q, 4 + j]
            P[i, j] = a1
            P[i, 4 + j] = a2
    for i in range(4):
        for j in range(i, 4):
            acc = Gt[4 + i, j] - P[i, j] - P[j, i]
            for q in range(4):
                acc -= P[i, 4 + q] * z[q, j]
            out[i, j] = w * acc
            out[j, i] = w * acc
    rate = 0.0
    for i in range(4):
        rate += Gt[i, i] + P[i, 4 + i]
    return w * rate


@nb.njit(cache=True)
def _stage_blocks(R, h, m, k, table, seg, work):
    """The blocks G~ and w at the stage radii R + C_s h, s = 1..11, into work.stage_Gt,
    work.stage_w (C_11 = 1: the last is R + h, K_12's radius too).

    The radii of a step are known before its stages are, so the table's Clenshaw
    recurrences run for all eleven at once (:func:`_clenshaw_eleven`): the same arithmetic
    radius by radius as :func:`_base_at`, the same bits.
    """
    coef, fmap = table.coef[seg], table.fmap[seg]
    a, b = table.bounds[seg], table.bounds[seg + 1]
    x2, v = work.x2, work.stage_vals  # v[f, s - 1]: function f at stage radius s
    for st in range(1, _NS):
        x2[st - 1] = 2.0 * (2.0 * (R + _C[st] * h) - a - b) / (b - a)
    for f in range(table.n_funcs[seg]):
        _clenshaw_eleven(coef[f], x2, v[f])
    mod = work.mod
    for st in range(1, _NS):
        for f in range(23):
            mod[f] = v[fmap[f], st - 1]
        p, r, w = v[fmap[23], st - 1], v[fmap[24], st - 1], v[fmap[25], st - 1]
        _blocks(mod, p, m, k * r, work, work.stage_Gt[st])
        work.stage_w[st] = w


@nb.njit(cache=True, inline="always")
def _clenshaw_eleven(c, x, out):
    """out[s] = sum_j c_j T_j(x[s] / 2), s = 0..10, by :func:`_base_at`'s recurrence.

    Eleven independent recurrences written out as scalars, so that they stay in registers
    and the processor overlaps them: one recurrence is a chain of dependent multiply-adds,
    and a loop over arrays of them is not vectorised (the arrays might alias), which made
    the table 40 % of a step. Written out, 1.7-1.9x faster at degrees 8-14.
    """
    x0, x1, x2, x3 = x[0], x[1], x[2], x[3]
    x4, x5, x6, x7 = x[4], x[5], x[6], x[7]
    x8, x9, x10 = x[8], x[9], x[10]
    u0 = u1 = u2 = u3 = u4 = u5 = u6 = u7 = u8 = u9 = u10 = 0.0
    w0 = w1 = w2 = w3 = w4 = w5 = w6 = w7 = w8 = w9 = w10 = 0.0
    for j in range(c.size - 1, 0, -1):
        cj = c[j]
        u0, w0 = x0 * u0 - w0 + cj, u0
        u1, w1 = x1 * u1 - w1 + cj, u1
        u2, w2 = x2 * u2 - w2 + cj, u2
        u3, w3 = x3 * u3 - w3 + cj, u3
        u4, w4 = x4 * u4 - w4 + cj, u4
        u5, w5 = x5 * u5 - w5 + cj, u5
        u6, w6 = x6 * u6 - w6 + cj, u6
        u7, w7 = x7 * u7 - w7 + cj, u7
        u8, w8 = x8 * u8 - w8 + cj, u8
        u9, w9 = x9 * u9 - w9 + cj, u9
        u10, w10 = x10 * u10 - w10 + cj, u10
    c0 = c[0]
    out[0] = 0.5 * x0 * u0 - w0 + c0
    out[1] = 0.5 * x1 * u1 - w1 + c0
    out[2] = 0.5 * x2 * u2 - w2 + c0
    out[3] = 0.5 * x3 * u3 - w3 + c0
    out[4] = 0.5 * x4 * u4 - w4 + c0
    out[5] = 0.5 * x5 * u5 - w5 + c0
    out[6] = 0.5 * x6 * u6 - w6 + c0
    out[7] = 0.5 * x7 * u7 - w7 + c0
    out[8] = 0.5 * x8 * u8 - w8 + c0
    out[9] = 0.5 * x9 * u9 - w9 + c0
    out[10] = 0.5 * x10 * u10 - w10 + c0


@nb.njit(cache=True)
def _step(R, h, z, m, k, table, seg, work, K, ztmp, znew, rate0):
    """One DOP853 step of size h from (R, z), given K[0] = dz~/dR there and ``rate0``, the
    rate of log|det U~| there (:func:`_riccati`).

    Writes the 8th-order solution at R + h into ``znew`` and the stages into K[1..12],
    K[12] = dz~/dR at (R + h, znew) being the last one of the error estimate. The base
    state at R + h stays in work.stage_Gt[11] (see :func:`next_slope`). Returns the
    step's increment of log|det U~|, by the same 8th-order weights (the rate depends on
    z~ alone, so this is DOP853 on the system augmented by log|det U~|; its error is not
    controlled: it only scales the target, never moves its zeros).
    """
    rate = work.stage_rate
    rate[0] = rate0
    _stage_blocks(R, h, m, k, table, seg, work)
    for st in range(1, _NS):
        for i in range(4):
            for j in range(4):
                acc = 0.0
                for t in range(st):
                    q = _AQ[st, t]
                    if q < 0:
                        break
                    acc += _A[st, q] * K[q, i, j]
                ztmp[i, j] = z[i, j] + h * acc
        rate[st] = _riccati(ztmp, work.stage_Gt[st], work.stage_w[st], work.P, K[st])
    for i in range(4):
        for j in range(4):
            acc = 0.0
            for t in range(_NS):
                q = _BQ[t]
                if q < 0:
                    break
                acc += _B[q] * K[q, i, j]
            znew[i, j] = z[i, j] + h * acc
    _riccati(znew, work.stage_Gt[_NS - 1], work.stage_w[_NS - 1], work.P, K[_NS])
    grow = 0.0
    for t in range(_NS):
        q = _BQ[t]
        if q < 0:
            break
        grow += _B[q] * rate[q]
    return h * grow


@nb.njit(cache=True)
def next_slope(z, work, out):
    """out <- dz~/dR at the end R + h of the step just taken, from the base state its last
    stage left (the same bits as :func:`_rhs` there, if the chart has not changed since);
    returns the rate of log|det U~| there."""
    return _riccati(z, work.stage_Gt[_NS - 1], work.stage_w[_NS - 1], work.P, out)


@nb.njit(cache=True)
def _error(h, z, znew, K, rtol):
    """DOP853's error norm of a step (<= 1: accept), entry ij in units of
    rtol (1 + max(|z_ij|, |znew_ij|))."""
    e5 = 0.0
    e3 = 0.0
    for i in range(4):
        for j in range(4):
            a5 = 0.0
            a3 = 0.0
            for q in range(_NS + 1):
                a5 += _E5[q] * K[q, i, j]
                a3 += _E3[q] * K[q, i, j]
            sc = rtol * (1.0 + max(abs(z[i, j]), abs(znew[i, j])))
            e5 += (a5 / sc) ** 2
            e3 += (a3 / sc) ** 2
    err = 0.0
    if e5 > 0.0 or e3 > 0.0:
        err = h * e5 / np.sqrt((e5 + 0.01 * e3) * 16.0)
    if not (np.isfinite(err) and np.all(np.isfinite(znew))):
        err = 1e6  # overflow or NaN in a stage: retry with a smaller step
    return err
