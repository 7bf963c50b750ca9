"""The impedance kernel over the rows of a ``modes`` array on one base state, compiled.

A target evaluation (targets.py, ``impedance_targets``) hands the kernel (impedance.py) the
modes as rows (m, n) or (m, n, family code) and one table. Turning the rows into the
kernel's per-member arrays in NumPy (m, k = n pi / l, the kept Stroh pairs of each row's
family: modes.mode_pairs, ~10 small array operations) cost ~15 us an evaluation, as much as a
table, more than a loose evaluation's kernel spends in some modes; here each row is read
where it is integrated. The arithmetic is NumPy's (k = (n pi) / l, rounded the same way) and
:func:`row_pairs` is modes.mode_pairs row by row (tests/incremental/test_mode_rows.py), so
the targets are those of the per-member kernels (impedance.target_serial) to the last bit.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from .impedance import KEEP_SIZE, _member_table, integrate_one
from .modes import ALL_PAIRS, U_TH, U_Z, Family

_PRISMATIC, _TORSIONAL, _WRINKLE = (Family.PRISMATIC.code, Family.TORSIONAL.code,
                                    Family.WRINKLE.code)  # fmt: skip


@nb.njit(cache=True)
def row_pairs(modes, b) -> int:
    """The Stroh pairs kept by row b of ``modes`` (modes.mode_pairs of that row): its
    family's (third column, or the natural one: prismatic for n = 0, else wrinkle)."""
    if modes.shape[1] > 2:
        code = int(modes[b, 2])
    else:
        code = _PRISMATIC if modes[b, 1] == 0 else _WRINKLE
    if code == _PRISMATIC:
        return ALL_PAIRS & ~U_Z
    if code == _TORSIONAL:
        return U_TH
    return ALL_PAIRS & ~U_TH if modes[b, 0] == 0 else ALL_PAIRS


@nb.njit(cache=True)
def _row_target(modes, b, length, tables, rtol, max_steps, f, status):
    """Row b on table 0 of ``tables``: its target and status into f[b], status[b]."""
    k = modes[b, 1] * math.pi / length  # NumPy's modes[:, 1] * math.pi / length
    f[b], _, _, status[b], _, _ = integrate_one(
        modes[b, 0], k, row_pairs(modes, b), _member_table(tables, 0), rtol, max_steps
    )


@nb.njit(cache=True)
def rows_serial(modes, length, tables, rtol, max_steps):
    """(f, status) of every row of ``modes`` (m, n[, code]) on the one state of the
    TableStack ``tables``, current length ``length`` (k = n pi / length), one thread."""
    n = modes.shape[0]
    f, status = np.empty(n), np.empty(n, np.int64)
    for b in range(n):
        _row_target(modes, b, length, tables, rtol, max_steps, f, status)
    return f, status


@nb.njit(parallel=True, cache=True)
def rows_parallel(modes, length, tables, rtol, max_steps):
    """:func:`rows_serial` in parallel over the rows (a scan's batch)."""
    n = modes.shape[0]
    f, status = np.empty(n), np.empty(n, np.int64)
    for b in nb.prange(n):
        _row_target(modes, b, length, tables, rtol, max_steps, f, status)
    return f, status


@nb.njit(cache=True)
def rows_determinant(modes, length, tables, rtol, max_steps):
    """(f, log_norm, status) of every row of ``modes`` on the one state of ``tables``, a
    short wave restarted only in the way that keeps the basis' size (impedance.KEEP_SIZE),
    row by row as :func:`rows_serial`:
    f exp(log_norm) is det(M2) (times a smooth positive factor where restarted), what a
    root is refined on."""
    n = modes.shape[0]
    f, log_norm, status = np.empty(n), np.empty(n), np.empty(n, np.int64)
    table = _member_table(tables, 0)
    for b in range(n):
        k = modes[b, 1] * math.pi / length
        f[b], _, _, status[b], _, log_norm[b] = integrate_one(
            modes[b, 0], k, row_pairs(modes, b), table, rtol, max_steps, KEEP_SIZE
        )
    return f, log_norm, status
