"""Chebyshev tables of the base state through the wall, the input of the compiled kernels.

The Stroh matrix at a radius needs the 23 updated moduli and the Lagrange multiplier p
there, and the integration in the reference radius R needs the current radius r(R) and
w(R) = (dr/dR) / r. They depend on the mode only through (m, k r), so one table per base
state serves every mode. The wall is a stack of **segments**, one per layer (one for the
homogeneous tube of the paper), R in [R_{k-1}, R_k]: the moduli, p and dr/dR jump at an
interface (each layer has its own energy, modulus and growth), but inside a layer each of
the 26 functions is analytic, so a Chebyshev interpolant per segment converges
geometrically. We interpolate on Chebyshev points, chop the coefficients below ``tol``
relative to each function's scale (its largest value, at least the size of the quantity it
holds in its layer: :func:`_layer_units`), and store identical functions (the neo-Hookean
moduli repeat a lot) once per segment. This keeps any material, any growth (anisotropic,
graded) and any layering out of the compiled code: the kernel only runs Clenshaw sums. With
r dr = (J / lambda_z) R dR (J = det F_g; docs/derivation-layered.md (K)),

    w(R) = J(R) R / (lambda_z r(R)^2).

The moduli, p and the face pressures are tabulated in units of a reference modulus mu_ref and
permittivity eps_ref of the tube's own (:func:`table_units`: 1 whenever the layers' values
straddle 1, else the nearest of them): A and p over mu_ref, Gamma over sqrt(mu_ref / eps_ref),
K times eps_ref. That is a positive diagonal rescaling of the Stroh vector (S by mu_ref, the
electric pair by sqrt(mu_ref eps_ref)), which keeps the sign of the kernel's target and its
zeros, and makes a one-layer tube of modulus mu_k the same table as one of modulus 1: its
error control (relative to 1 + |z~|) would otherwise be absolute for a soft tube and read
mixed scales for a stiff one.

A table is one record (:class:`RadialTable`, with the follower pressures on the two faces,
which enter the face conditions), and the tables of a batch of base states are one padded
record (:class:`TableStack`); both are named tuples of arrays, which the compiled kernel
takes as they are.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from ..errors import OVERFLOW, ConvergenceError
from ..model.moduli import MODULI_NAMES
from .table_chop import scale_chop_and_merge

N_MODULI = len(MODULI_NAMES)
#: rows of ``fmap`` after the 23 moduli: p, r and w = (dr/dR) / r
P_FUNC, R_FUNC, W_FUNC = N_MODULI, N_MODULI + 1, N_MODULI + 2
N_FUNCS = N_MODULI + 3


class RadialTable(NamedTuple):
    """Chebyshev coefficients of the moduli, p, r and w of one base state, per segment.

    Attributes
    ----------
    coef : (L, F, C) array
        Segment s (layer s + 1) has the coefficients of its distinct functions in rows
        0 .. n_funcs[s] - 1 (Chebyshev T_0..T_{C-1} in x = (2 R - a - b) / (b - a) on
        [a, b] = [bounds[s], bounds[s + 1]]), zero past each function's last significant
        one and in the padding rows.
    n_funcs : (L,) int array
        Distinct functions of each segment.
    fmap : (L, 26) int array
        Function f of MODULI_NAMES + (p, r, w) is row fmap[s, f] of ``coef[s]``.
    bounds : (L + 1,) array
        The reference radii of the faces and interfaces, 1 = R_0 < R_1 < ... < R_L.
    face_pressure : (2,) array
        Follower pressures (P_i, P_o) on the inner and outer face (units mu_ref).
    """

    coef: np.ndarray
    n_funcs: np.ndarray
    fmap: np.ndarray
    bounds: np.ndarray
    face_pressure: np.ndarray


class TableStack(NamedTuple):
    """The tables of T base states padded to one shape: the batch kernel's input.

    The fields of :class:`RadialTable` with a leading axis T, and ``n_segments`` (T,) int:
    table t has segments 0 .. n_segments[t] - 1 (the rest is zero padding).
    """

    coef: np.ndarray
    n_funcs: np.ndarray
    fmap: np.ndarray
    bounds: np.ndarray
    face_pressure: np.ndarray
    n_segments: np.ndarray


@functools.lru_cache(maxsize=16)
def _chebyshev_points(n: int) -> tuple[np.ndarray, np.ndarray]:
    """(x, basis): the n Chebyshev points of the first kind, cos(pi (k + 1/2) / n), and the
    DCT-II matrix cos(j theta_k) (coefficient index j, node index k), read-only."""
    k = np.arange(n)
    theta = np.pi * (k + 0.5) / n
    x, basis = np.cos(np.pi * (k + 0.5) / n), np.cos(np.outer(k, theta))
    x.setflags(write=False)
    basis.setflags(write=False)
    return x, basis


@functools.lru_cache(maxsize=64)
def _nodes(a: float, b: float, n: int) -> np.ndarray:
    """The n Chebyshev points of the first kind mapped onto R in [a, b], read-only: a march
    tabulates the same wall at every step."""
    R = 0.5 * (a + b) + 0.5 * (b - a) * _chebyshev_points(n)[0]
    R.setflags(write=False)
    return R


def _cheb_coefficients(values: np.ndarray) -> np.ndarray:
    """Coefficients from values at the Chebyshev points of the first kind (DCT-II)."""
    n = values.shape[0]
    c = _chebyshev_points(n)[1] @ values * (2.0 / n)
    c[0] *= 0.5
    return c


def table_units(state) -> tuple[float, float]:
    """(mu_ref, eps_ref) of the table of ``state``: 1 where the layers' shear moduli
    (permittivities) straddle 1, else the one nearest to 1 (one layer: its own)."""
    return layer_units(state.tube.layers)


def layer_units(layers) -> tuple[float, float]:
    """:func:`table_units` of a tube with these ``layers`` (a piecewise linear function of
    the moduli, bent where the smallest or largest crosses 1: the kernel's det(M2) carries
    a power of them, design/sensitivity.py differentiates across no bend)."""
    mu = [layer.shear_modulus for layer in layers]
    eps = [layer.permittivity for layer in layers]
    # clip(1, lo, hi) in plain floats: a table is built at every step of a march
    return float(min(max(1.0, min(mu)), max(mu))), float(min(max(1.0, min(eps)), max(eps)))


@functools.lru_cache(maxsize=64)
def _column_units(mu: float, eps: float) -> np.ndarray:
    """The divisor of each of the 26 columns (moduli by family, p, r, w) for the table
    units (mu, eps): see the module docstring."""
    family = {"A": mu, "G": math.sqrt(mu / eps), "K": 1.0 / eps}
    units = np.array([family[name[0]] for name in MODULI_NAMES] + [mu, 1.0, 1.0])
    units.setflags(write=False)  # shared by every table of these units
    return units


@functools.lru_cache(maxsize=64)
def _layer_units(mu_k: float, eps_k: float, mu: float, eps: float) -> np.ndarray:
    """The size of each of the 26 columns in a layer of modulus mu_k and permittivity eps_k,
    in the table units (mu, eps): mu_k for the A moduli and p, 1 / eps_k for K. A column's
    Chebyshev tail is measured against the larger of its largest value and this: a modulus
    that vanishes at the unstrained state (O(I1 - 3) for a Yeoh energy without its square
    term) holds the rounding of mu_k, never smaller, so at a small load its tail is noise of
    1e-8 of itself and 1e-16 of mu_k (table_chop.chop_and_merge). 0 (each column its own
    scale) for G, which is odd in D (its rounding is relative to itself), and for r and w,
    positive everywhere."""
    family = {"A": mu_k / mu, "G": 0.0, "K": eps / eps_k}
    units = np.array([family[name[0]] for name in MODULI_NAMES] + [mu_k / mu, 0.0, 0.0])
    units.setflags(write=False)  # shared by every table of these units
    return units


#: the column sizes of a layer tabulated in its own units (a uniform tube's table)
_UNIT_LAYER = _layer_units(1.0, 1.0, 1.0, 1.0)


def _segments(state, mu: float, eps: float):
    """[(a, b, values, unit)] per segment: values(R) is the (n, 26) array of the 23 moduli,
    p, r and w at the reference radii R (strictly inside [a, b]), in the table's units
    (mu, eps) (:func:`table_units`), and unit (26,) the size of each (:func:`_layer_units`)."""
    tube = state.tube
    radii = tube.radii
    units = _column_units(mu, eps)
    unit = mu == 1.0 and eps == 1.0  # the reference modulus and permittivity: no division

    layered = hasattr(state, "layer_fields")  # a LayeredState: one layer's fields at once
    uniform = hasattr(state, "table_block")  # a UniformState: the whole block, one call

    def values(R, k, layer):
        # J = det F_g: a constant layer's product once (the same floating-point product)
        J = np.prod(layer.growth_at(R), axis=0) if layer.graded else math.prod(layer.growth)
        if uniform:  # compiled for the closed form (basestate/closed_form_fields.py)
            out = state.table_block(R, J)
        else:
            if layered:  # r, the moduli and p from one evaluation of the layer's fields
                f = state.layer_fields(R, k, moduli=True)
                r, moduli, p = f["r"], f["moduli"], f["tau1"] - f["sigma_rr"]
            else:
                r, moduli, p = state.radius(R), state.moduli(R), state.pressure(R)
            w = J * R / (state.stretch * r * r)
            out = np.column_stack([moduli, p, r, w])
        return out if unit else out / units

    return [
        (
            a,
            b,
            lambda R, k=k, layer=layer: values(R, k, layer),
            _layer_units(layer.shear_modulus, layer.permittivity, mu, eps),
        )
        for k, (a, b, layer) in enumerate(zip(radii, radii[1:], tube.layers))
    ]


def _segment_table(a, b, values, unit, tol, max_nodes):
    """(chopped distinct coefficient rows, fmap) of one segment whose columns have the sizes
    ``unit`` (the chopping and merging compiled: table_chop.py)."""
    n, tails = 17, []
    while True:
        vals = values(_nodes(a, b, n))
        if not np.isfinite(vals).all():  # no number of points resolves an overflow
            err = ConvergenceError(
                f"the base state's moduli overflow a double on R in [{a:g}, {b:g}]"
            )
            err.remedy = OVERFLOW  # neither a looser rtol nor collocation reaches them
            raise err
        tail_ok, rows, fmap = _chop(vals, tol, unit)
        if tail_ok or n >= max_nodes:
            break
        if n >= 129:  # the noise floor is looked for only where it can be reached
            tails.append(_tail(vals, unit))
        n = 2 * n - 1
    if not tail_ok and len(tails) >= 1:  # rounding noise, not want of points?
        last = _tail(vals, unit)
        tail_ok = bool(np.all((last <= 8 * tol) | ((last >= 0.1 * tails[-1]) & (last <= 1e-9))))
    if not tail_ok:
        raise ConvergenceError(
            f"base state not resolved by {max_nodes} Chebyshev points on R in"
            f" [{a:g}, {b:g}]; the wall is too thick or strained for the table"
        )
    return rows, fmap


def _tail(vals, unit) -> np.ndarray:
    """The largest of the last three Chebyshev coefficients of each function, relative to
    its scale (its largest value, at least its ``unit``). Where it no longer falls as the
    points double (and is small), it is the rounding of the values, not a want of points: a
    Gent layer next to its lock amplifies the rounding of I1 by 1 / (1 - (I1 - 3) / jm); the
    kernel does not see it."""
    with np.errstate(over="ignore", invalid="ignore"):  # values next to the double range
        coef = (_chebyshev_points(vals.shape[0])[1] @ vals) * (2.0 / vals.shape[0])
    return abs(coef[-3:]).max(0) / np.maximum(np.maximum(abs(vals).max(0), 1e-300), unit)


def _chop(vals, tol, unit):
    """(tail_ok, rows, fmap) of the functions with values ``vals`` at the Chebyshev points
    and sizes ``unit``:
    the DCT's product in NumPy, its scaling (:func:`_cheb_coefficients`), the chopping and
    the merging compiled (table_chop.py; its twin: :func:`_chop_numpy` of the coefficients)."""
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is an unresolved tail
        coef = _chebyshev_points(vals.shape[0])[1] @ vals
    return scale_chop_and_merge(coef, vals, tol, unit)


def _chop_numpy(coef, vals, tol, unit):
    """The slow twin of table_chop.chop_and_merge, in NumPy: (tail_ok, rows, fmap)."""
    coef = coef.T  # (26, n)
    n = coef.shape[1]
    scale = np.maximum(np.abs(vals).max(axis=0), np.maximum(1e-300, unit))
    small = np.abs(coef) <= tol * scale[:, None] * 8
    tail_ok = bool(small[:, -3:].all())
    # significant coefficients: n minus the trailing run of small ones (at least 1)
    degree = np.maximum(n - np.argmax(~small[:, ::-1], axis=1) * (~small).any(axis=1), 1)
    degree[~(~small).any(axis=1)] = 1
    return (tail_ok, *_dedupe(coef, degree))


def _dedupe(coef, degree):
    """One row per distinct chopped function, zero past its ``degree`` coefficients."""
    seen: dict[bytes, int] = {}
    fmap = np.empty(N_FUNCS, dtype=np.int64)
    for f in range(N_FUNCS):
        fmap[f] = seen.setdefault(coef[f, : degree[f]].tobytes(), len(seen))
    first = np.unique(fmap, return_index=True)[1]  # first function of each distinct row
    degs = degree[first]
    return coef[first, : degs.max()] * (np.arange(degs.max()) < degs[:, None]), fmap


def build_table(state, *, tol: float = 1e-15, max_nodes: int = 1025) -> RadialTable:
    """Tabulate a base state (a UniformState or a LayeredState), segment by
    segment.

    The number of nodes of a segment doubles from 17 until the trailing coefficients of
    every function fall below ``tol`` times its scale.

    Raises
    ------
    ConvergenceError
        If ``max_nodes`` Chebyshev points do not resolve a segment.
    """
    if hasattr(state, "table_block"):  # the paper's tube: one segment, unit moduli
        return _uniform_table(state, tol, max_nodes)
    mu, eps = table_units(state)
    segments = _segments(state, mu, eps)
    parts = [_segment_table(a, b, f, unit, tol, max_nodes) for a, b, f, unit in segments]
    bounds = [segments[0][0]] + [b for _, b, _, _ in segments]
    return RadialTable(
        _padded([c for c, _ in parts]),
        np.array([c.shape[0] for c, _ in parts], dtype=np.int64),
        np.array([fm for _, fm in parts], dtype=np.int64),
        np.array(bounds, dtype=float),
        np.array(state.face_pressures, dtype=float) / mu,
    )


def _uniform_table(state, tol: float, max_nodes: int) -> RadialTable:
    """:func:`build_table` of a UniformState (one layer of unit modulus and permittivity,
    unloaded faces): the same table, without the general path's bookkeeping (a march builds
    one at every evaluation)."""
    tube = state.tube
    J = math.prod(tube.layers[0].growth)  # as _segments' values: the same product
    b = tube.outer_radius
    rows, fmap = _segment_table(
        1.0, b, lambda R: state.table_block(R, J), _UNIT_LAYER, tol, max_nodes
    )
    return RadialTable(
        np.ascontiguousarray(rows)[None],
        np.array([rows.shape[0]], dtype=np.int64),
        fmap[None],
        np.array([1.0, b]),
        np.zeros(2),  # unloaded faces; writeable, as every table's (a read-only array is
    )  # another type to the kernel, which would compile again)


def _padded(rows: list[np.ndarray]) -> np.ndarray:
    """The (L, F, C) array of the segments' (F_s, C_s) coefficient rows, zero-padded."""
    if len(rows) == 1:  # one layer (a march's every step): its rows, C-contiguous as the
        return np.ascontiguousarray(rows[0], dtype=float)[None]  # padded copy would be
    F = max(c.shape[0] for c in rows)
    C = max(c.shape[1] for c in rows)
    coef = np.zeros((len(rows), F, C))
    for s, c in enumerate(rows):
        coef[s, : c.shape[0], : c.shape[1]] = c
    return coef


def stack_tables(tables: list[RadialTable]) -> TableStack:
    """Pad a list of tables into the one record the batch kernel takes."""
    if len(tables) == 1:  # one state (a march's step): its arrays as they are, no padding
        t = tables[0]
        return TableStack(
            coef=t.coef[None],
            n_funcs=t.n_funcs[None],
            fmap=t.fmap[None],
            bounds=t.bounds[None],
            face_pressure=t.face_pressure[None],
            n_segments=np.array([t.coef.shape[0]], dtype=np.int64),
        )
    L = max(t.coef.shape[0] for t in tables)
    F = max(t.coef.shape[1] for t in tables)
    C = max(t.coef.shape[2] for t in tables)
    T = len(tables)
    coef = np.zeros((T, L, F, C))
    n_funcs = np.zeros((T, L), dtype=np.int64)
    fmap = np.zeros((T, L, N_FUNCS), dtype=np.int64)
    bounds = np.zeros((T, L + 1))
    for i, t in enumerate(tables):
        nl, nf, nc = t.coef.shape
        coef[i, :nl, :nf, :nc] = t.coef
        n_funcs[i, :nl] = t.n_funcs
        fmap[i, :nl] = t.fmap
        bounds[i, : nl + 1] = t.bounds
    return TableStack(
        coef=coef,
        n_funcs=n_funcs,
        fmap=fmap,
        bounds=bounds,
        face_pressure=np.stack([t.face_pressure for t in tables]),
        n_segments=np.array([t.coef.shape[0] for t in tables], dtype=np.int64),
    )
