"""The dense linear algebra of a collocation evaluation: the matrix equilibrated (its
target's sigma_min / sigma_max without the scaling of a thin stiff layer) and BLAS on one
thread (OpenBLAS's threads spin against other processes on a busy machine)."""

from __future__ import annotations

import contextlib
import functools

import numpy as np


def equilibrated(M: np.ndarray, sweeps: int = 3) -> np.ndarray:
    """D_r M D_c with positive diagonal D_r, D_c that bring every row's and column's largest
    entry near 1 (alternating square-root scalings, ``sweeps`` times).

    det keeps its sign and M is singular exactly where it was, so the target keeps its
    roots; but sigma_min / sigma_max no longer carries the scaling of a thin, stiff layer,
    whose rows (lengths in units of its own half-thickness, stresses of its modulus) are
    1e5-1e6 times another layer's: a film 0.002 thick and 89 times as stiff made the ratio
    1e-17 to 1e-21, rounding, and its sign flip with the node count; equilibrated, 1e-12
    and a root within 1e-6 of the impedance method's (tests/bifurcation/
    test_collocation_thin_film.py)."""
    return equilibration(M, sweeps)[0]


def equilibration(M: np.ndarray, sweeps: int = 3) -> tuple[np.ndarray, np.ndarray]:
    """(D_r M D_c, diag D_c): :func:`equilibrated` with its column scaling, the same
    arithmetic. A null vector y of D_r M D_c is D_c^{-1} x for x one of M's, so x = D_c y;
    the null vector must be taken there, not from M itself: a thin stiff film's rows,
    1e4-1e6 times another layer's, leave M no separated smallest singular value (its last
    three sigma / sigma_max 3.5e-16, 2.2e-16, 2.2e-19 for an inner film's fold at 80 nodes;
    equilibrated 2.5e-6, 2.0e-8, 3.4e-18), and its last singular vector is rounding."""
    A = np.abs(M)
    M = M.copy()
    cols = np.ones(M.shape[1])
    for _ in range(sweeps):
        r = 1.0 / np.sqrt(np.maximum(A.max(axis=1), 1e-300))
        A *= r[:, None]
        M *= r[:, None]
        c = 1.0 / np.sqrt(np.maximum(A.max(axis=0), 1e-300))
        A *= c[None, :]
        M *= c[None, :]
        cols *= c
    return M, cols


@contextlib.contextmanager
def one_blas_thread():
    """Run the dense algebra of one evaluation with BLAS on one thread; yields scipy.linalg.

    Its matrices (a few hundred rows) gain little from BLAS threads on an idle machine,
    and lose 15-50x on a busy one, where OpenBLAS's threads spin against other processes
    (measured at load ~3.5 on 2 cores: 0.23-0.83 s per evaluation at 24-56 nodes against
    13-17 ms on one thread; docs/collocation.md). scipy.linalg and threadpoolctl are
    imported here: the peer method alone needs them, not every process."""
    import scipy.linalg

    with _blas_controller().limit(limits=1, user_api="blas"):
        yield scipy.linalg


@functools.cache
def _blas_controller():
    """The BLAS libraries of this process, found once (after scipy.linalg has loaded its
    own OpenBLAS, besides NumPy's)."""
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()
