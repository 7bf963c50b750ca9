"""Chebyshev tables of the base state through the wall, the input of the compiled kernels.

The Stroh matrix at a radius needs the 23 updated moduli and the Lagrange multiplier p
there. They depend on the mode only through (m, k r), so one table per base state serves
every mode. Each of the 24 functions of the reference radius R in [1, Rbar_o] is analytic,
so a Chebyshev interpolant converges geometrically: we interpolate on Chebyshev points,
chop the coefficients below ``tol`` relative to the largest function value, and store
identical functions (the neo-Hookean moduli repeat a lot) once. This keeps any material,
however its moduli were obtained, out of the compiled code: the kernel only runs Clenshaw
sums.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import ConvergenceError
from ..model.materials import MODULI_NAMES

N_FUNCS = len(MODULI_NAMES) + 1  # 23 moduli, then p


@dataclasses.dataclass(frozen=True)
class RadialTable:
    """Chebyshev coefficients of the moduli and p over R in [1, Rbar_o].

    Attributes
    ----------
    coef : (F, C) array
        Coefficients of the F distinct functions (Chebyshev T_0..T_{C-1} in x, where
        x = (2 R - 1 - Rbar_o) / (Rbar_o - 1)).
    degree : (F,) int array
        Number of significant coefficients of each distinct function.
    fmap : (24,) int array
        Function f of MODULI_NAMES + ("p",) is row fmap[f] of ``coef``.
    geom : (4,) array
        (Rbar_o, r_i^2, a, F) with r(R)^2 = r_i^2 + a (R^2 - 1), a = g^3 / lambda_z, and
        F the number of distinct functions (as a float, to keep one array).
    """

    coef: np.ndarray
    degree: np.ndarray
    fmap: np.ndarray
    geom: np.ndarray


def _cheb_coefficients(values: np.ndarray) -> np.ndarray:
    """Coefficients from values at the Chebyshev points of the first kind (DCT-II)."""
    n = values.shape[0]
    k = np.arange(n)
    theta = np.pi * (k + 0.5) / n
    basis = np.cos(np.outer(k, theta))  # (coef index, node index)
    c = basis @ values * (2.0 / n)
    c[0] *= 0.5
    return c


def build_table(state, *, tol: float = 1e-15, max_nodes: int = 129) -> RadialTable:
    """Tabulate ``state.moduli`` and ``state.pressure`` (a tube.BaseState).

    The number of nodes doubles from 17 until the trailing coefficients of every function
    fall below ``tol`` times its scale.

    Raises
    ------
    ConvergenceError
        If ``max_nodes`` Chebyshev points do not resolve the base state.
    """
    ro = state.params.outer_radius
    n = 17
    while True:
        k = np.arange(n)
        x = np.cos(np.pi * (k + 0.5) / n)
        R = 0.5 * (1 + ro) + 0.5 * (ro - 1) * x
        vals = np.concatenate([state.moduli(R), state.pressure(R)[:, None]], axis=1)
        coef = _cheb_coefficients(vals).T  # (24, n)
        scale = np.maximum(np.abs(vals).max(axis=0), 1e-300)
        small = np.abs(coef) <= tol * scale[:, None] * 8
        tail_ok = small[:, -3:].all()
        if tail_ok or n >= max_nodes:
            break
        n = 2 * n - 1
    if not tail_ok:
        raise ConvergenceError(
            f"base state not resolved by {max_nodes} Chebyshev points (Rbar_o = {ro});"
            " the wall is too thick or strained for the table")
    # significant coefficients: n minus the trailing run of small ones (at least 1)
    degree = np.maximum(n - np.argmax(~small[:, ::-1], axis=1) * (~small).any(axis=1), 1)
    degree[~(~small).any(axis=1)] = 1
    return _dedupe(coef, degree, state)


def _dedupe(coef, degree, state) -> RadialTable:
    seen: dict[bytes, int] = {}
    fmap = np.empty(N_FUNCS, dtype=np.int64)
    for f in range(N_FUNCS):
        fmap[f] = seen.setdefault(coef[f, :degree[f]].tobytes(), len(seen))
    first = np.unique(fmap, return_index=True)[1]  # first function of each distinct row
    degs = degree[first]
    table = coef[first, :degs.max()] * (np.arange(degs.max()) < degs[:, None])
    g, lz = state.params.growth, state.params.stretch
    geom = np.array([state.params.outer_radius, state.r_i**2, g**3 / lz, float(len(first))])
    return RadialTable(table, np.array(degs, dtype=np.int64), fmap, geom)


def stack_tables(tables: list[RadialTable]):
    """Pad a list of tables into the arrays the batch kernel takes.

    Returns (coef (T, F, C), degree (T, F), fmap (T, 24), geom (T, 4)).
    """
    F = max(t.coef.shape[0] for t in tables)
    C = max(t.coef.shape[1] for t in tables)
    coef = np.zeros((len(tables), F, C))
    degree = np.zeros((len(tables), F), dtype=np.int64)
    for i, t in enumerate(tables):
        coef[i, :t.coef.shape[0], :t.coef.shape[1]] = t.coef
        degree[i, :t.degree.size] = t.degree
    fmap = np.stack([t.fmap for t in tables])
    geom = np.stack([t.geom for t in tables])
    return coef, degree, fmap, geom
