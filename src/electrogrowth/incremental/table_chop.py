"""Chopping and merging the Chebyshev coefficients of a radial table, compiled.

A table (radial_table.py) is built at every step of a march: its 26 functions (the 23
moduli, p, r, w) are interpolated at n Chebyshev points, each function's trailing
coefficients below ``tol`` times its scale (its largest value, at least its unit) are cut
off, and functions whose chopped coefficients are identical (bit for bit: the neo-Hookean
moduli repeat a lot) are stored once. In NumPy that is ~60 small array operations, 50-70 us
a table, a third of a warm critical value's time (BENCHMARKS.md, "one warm mode"); here it
is one loop over the coefficients, ~2 us.

:func:`chop_and_merge` makes exactly the decisions of its slow twin,
``radial_table._chop_numpy`` with ``radial_table._dedupe`` (the same comparisons of the same
floating-point numbers, the same products, no sums), so the tables are identical to the last
bit: tests/incremental/test_table_chop.py compares them on random coefficients and on the
tables of many base states.
"""

from __future__ import annotations

import numba as nb
import numpy as np


@nb.njit(cache=True)
def chop_and_merge(coef, values, tol, unit):
    """Chop and merge the functions of one segment.

    Parameters
    ----------
    coef : (n, F) array
        Chebyshev coefficients (row j: T_j) of F functions, C-contiguous.
    values : (n, F) array
        The functions' values at the nodes.
    tol : float
        A coefficient is negligible when |c| <= tol scale 8.
    unit : (F,) array
        The size of the quantity each function holds: its scale is the larger of its largest
        |value| and its unit (at least 1e-300). A modulus that vanishes at the unstrained
        state (O(I1 - 3) for a Yeoh energy without its square term) carries the rounding of
        the layer's modulus, which is noise of 1e-8 of its own size at a small load: measured
        against itself its tail never falls, against its unit it is zero (issue D1 of probe
        11b). 0 measures a function against itself alone (radial_table._layer_units).

    Returns
    -------
    (tail_ok, rows, fmap)
        tail_ok: the last three coefficients of every function are negligible (else the
        caller doubles n and rows, fmap mean nothing). rows (D, C): the distinct chopped
        functions, in order of first appearance, each zero past its degree (its last
        significant coefficient, at least 1); fmap (F,): function f is row fmap[f].
    """
    n, F = coef.shape
    degree = np.ones(F, np.int64)
    tail_ok = True
    for f in range(F):
        scale = max(1e-300, unit[f])
        for i in range(n):  # np.maximum(np.abs(values).max(axis=0), that), NaN kept
            a = abs(values[i, f])
            if a != a:
                scale = a
                break
            if a > scale:
                scale = a
        limit = tol * scale * 8
        for j in range(n - 1, -1, -1):
            if not abs(coef[j, f]) <= limit:  # significant (NaN is)
                degree[f] = j + 1
                break
        if degree[f] > n - 3:
            tail_ok = tail_ok and n < 3
    bits = coef.view(np.int64)  # bytes equality, as the NumPy twin's tobytes()
    fmap = np.empty(F, np.int64)
    first = np.empty(F, np.int64)
    distinct = 0
    for f in range(F):
        fmap[f] = -1
        for d in range(distinct):
            g = first[d]
            if degree[g] == degree[f]:
                same = True
                for j in range(degree[f]):
                    if bits[j, g] != bits[j, f]:
                        same = False
                        break
                if same:
                    fmap[f] = d
                    break
        if fmap[f] < 0:
            fmap[f] = distinct
            first[distinct] = f
            distinct += 1
    width = 0
    for d in range(distinct):
        width = max(width, degree[first[d]])
    rows = np.empty((distinct, width))
    for d in range(distinct):
        g = first[d]
        for j in range(width):
            rows[d, j] = coef[j, g] * (1.0 if j < degree[g] else 0.0)
    return tail_ok, rows, fmap


@nb.njit(cache=True)
def scale_chop_and_merge(product, values, tol, unit):
    """:func:`chop_and_merge` of the coefficients c = product 2 / n, c[0] halved (n rows),
    product = DCT-II matrix @ values: radial_table._cheb_coefficients' scaling, the same
    floating-point operations, in the compiled pass (``product`` is overwritten with c)."""
    n = product.shape[0]
    scale = 2.0 / n
    for j in range(n):
        for f in range(product.shape[1]):
            product[j, f] = product[j, f] * scale
    for f in range(product.shape[1]):
        product[0, f] = product[0, f] * 0.5
    return chop_and_merge(product, values, tol, unit)
