"""Chebyshev tables of the base state through the wall, the input of the compiled kernels.

The Stroh matrix at a radius needs the 23 updated moduli and the Lagrange multiplier p
there. They depend on the mode only through (m, k r), so one table per base state serves
every mode. Each of the 24 functions of the reference radius R in [1, Rbar_o] is analytic,
so a Chebyshev interpolant converges geometrically: we interpolate on Chebyshev points,
chop the coefficients below ``tol`` relative to the largest function value, and store
identical functions (the neo-Hookean moduli repeat a lot) once. This keeps any material,
however its moduli were obtained, out of the compiled code: the kernel only runs Clenshaw
sums, and with the map R -> r of the wall,

    r(R)^2 = r_i^2 + a (R^2 - 1),   a = g^3 / lambda_z   (incompressibility),

it needs nothing else. A table is one record (:class:`RadialTable`), and the tables of a
batch of base states are one padded record (:class:`TableStack`); both are named tuples of
arrays and numbers, which the compiled kernel takes as they are.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..errors import ConvergenceError
from ..model.materials import MODULI_NAMES

N_FUNCS = len(MODULI_NAMES) + 1  # 23 moduli, then p


class RadialTable(NamedTuple):
    """Chebyshev coefficients of the moduli and p of one base state over R in [1, Rbar_o].

    Attributes
    ----------
    coef : (F, C) array
        Coefficients of the F distinct functions (Chebyshev T_0..T_{C-1} in x, where
        x = (2 R - 1 - Rbar_o) / (Rbar_o - 1)), zero past each function's last significant
        one.
    fmap : (24,) int array
        Function f of MODULI_NAMES + ("p",) is row fmap[f] of ``coef``.
    outer_radius : float
        Rbar_o, the outer radius of the reference configuration (inner radius 1).
    inner_radius_sq : float
        r_i^2, the squared current inner radius.
    area_ratio : float
        a = g^3 / lambda_z, so that r(R)^2 = r_i^2 + a (R^2 - 1).
    """

    coef: np.ndarray
    fmap: np.ndarray
    outer_radius: float
    inner_radius_sq: float
    area_ratio: float


class TableStack(NamedTuple):
    """The tables of T base states padded to one shape: the batch kernel's input.

    The fields of :class:`RadialTable` with a leading axis T, and ``n_funcs`` (T,) int:
    table t is ``coef[t, :n_funcs[t]]`` (rows and columns past it are zero).
    """

    coef: np.ndarray
    n_funcs: np.ndarray
    fmap: np.ndarray
    outer_radius: np.ndarray
    inner_radius_sq: np.ndarray
    area_ratio: np.ndarray


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
            " the wall is too thick or strained for the table"
        )
    # significant coefficients: n minus the trailing run of small ones (at least 1)
    degree = np.maximum(n - np.argmax(~small[:, ::-1], axis=1) * (~small).any(axis=1), 1)
    degree[~(~small).any(axis=1)] = 1
    return _dedupe(coef, degree, state)


def _dedupe(coef, degree, state) -> RadialTable:
    """One row per distinct chopped function, zero past its ``degree`` coefficients."""
    seen: dict[bytes, int] = {}
    fmap = np.empty(N_FUNCS, dtype=np.int64)
    for f in range(N_FUNCS):
        fmap[f] = seen.setdefault(coef[f, : degree[f]].tobytes(), len(seen))
    first = np.unique(fmap, return_index=True)[1]  # first function of each distinct row
    degs = degree[first]
    table = coef[first, : degs.max()] * (np.arange(degs.max()) < degs[:, None])
    g, lz = state.params.growth, state.params.stretch
    return RadialTable(
        table, fmap, float(state.params.outer_radius), float(state.r_i**2), float(g**3 / lz)
    )


def stack_tables(tables: list[RadialTable]) -> TableStack:
    """Pad a list of tables into the one record the batch kernel takes."""
    F = max(t.coef.shape[0] for t in tables)
    C = max(t.coef.shape[1] for t in tables)
    coef = np.zeros((len(tables), F, C))
    for i, t in enumerate(tables):
        coef[i, : t.coef.shape[0], : t.coef.shape[1]] = t.coef
    return TableStack(
        coef=coef,
        n_funcs=np.array([t.coef.shape[0] for t in tables], dtype=np.int64),
        fmap=np.stack([t.fmap for t in tables]),
        outer_radius=np.array([t.outer_radius for t in tables], dtype=float),
        inner_radius_sq=np.array([t.inner_radius_sq for t in tables], dtype=float),
        area_ratio=np.array([t.area_ratio for t in tables], dtype=float),
    )
