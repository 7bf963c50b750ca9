"""The radial basis of every tube form (polar, meridian, dielectric, wall): the rings'
quadrature points and the maps from the unknowns to a displacement, its R-derivative, a
pressure and a potential there (docs/derivation-koiter.md, "Each ring's values relative to
its inner face").

A displacement is a polynomial on each ring (Lobatto nodes, continuous across the rings).
Its unknowns are not the nodal values x_j but, ring by ring, the value at the ring's inner
node and the differences y_j = x_j - x_inner at its other nodes: on a ring with Lagrange
basis l_0 .. l_{n-1} (sum_j l_j = 1),

    u = x_inner + sum_{j >= 1} y_j l_j,   u' = sum_{j >= 1} y_j l_j',

the constant carrying exactly 1 and derivative exactly 0. The discrete space is the same
(x = T y, T unit lower triangular with entries 0 and 1), so every form, critical value and
mode is the same up to rounding; but a thin stiff film that moves almost rigidly through
its thickness (a fold: nodal values ~1e3 equal to 1e-3, derivative maps ~N^2 / h ~ 1e6)
no longer cancels 1e9 to leave 1e3 in each gradient, and its energy no longer carries
that cancellation's rounding (~1e-5 of a Koiter coefficient's numerator).

A pressure (interior nodes of each ring, its own per ring) and a potential (interior nodes
of the whole wall, zero on the electrodes) keep their nodal values.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import FloatArray
from .plane_forms import _segment_maps


@dataclasses.dataclass(frozen=True)
class _Seg:
    bottom: float
    top: float
    nodes: int


def _per_ring(rings_) -> list:
    """Each ring's Gauss points, weights and nodal maps (value, d/dR, interior pressure)."""
    return [_segment_maps(_Seg(r.inner, r.outer, r.nodes), max(2 * r.nodes, 8)) for r in rings_]


def radial_maps(rings_):
    """The rings' quadrature points R, their weights times R, their layer, and the maps from
    the displacement's unknowns (each ring's inner value and its other nodes' differences
    from it, this module's basis) to its value (V) and its R-derivative (D) at them, and
    from the pressure's (its own interior nodes per ring) to a pressure (P): the radial half
    of every tube form."""
    per = _per_ring(rings_)
    nR = sum(len(p[0]) for p in per)
    n_disp = sum(r.nodes - 1 for r in rings_) + 1
    n_pres = sum(r.nodes - 2 for r in rings_)
    V, D, P = np.zeros((nR, n_disp)), np.zeros((nR, n_disp)), np.zeros((nR, n_pres))
    row, col_d, col_p = 0, 0, 0
    chain = [0]  # the unknowns whose sum is the current ring's inner value
    for r, (Y, _w, Pm, PD, Pi) in zip(rings_, per):
        rows = slice(row, row + len(Y))
        V[rows, chain] = 1.0  # the inner value: a constant on the ring, derivative 0
        V[rows, col_d + 1 : col_d + r.nodes] = Pm[:, 1:]
        D[rows, col_d + 1 : col_d + r.nodes] = PD[:, 1:]
        P[rows, col_p : col_p + r.nodes - 2] = Pi
        row, col_d, col_p = row + len(Y), col_d + r.nodes - 1, col_p + r.nodes - 2
        chain.append(col_d)  # the next ring's inner value adds this one's outer difference
    R = np.concatenate([p[0] for p in per])
    wR = np.concatenate([p[1] for p in per]) * R
    layer = np.concatenate([np.full(len(p[0]), r.layer) for r, p in zip(rings_, per)])
    return R, wR, layer, V, D, P


def potential_maps(rings_) -> tuple[FloatArray, FloatArray]:
    """The maps from a potential's nodal values at the wall's interior nodes (zero on both
    faces, the electrodes) to its value and R-derivative at the quadrature points of
    :func:`radial_maps`."""
    per = _per_ring(rings_)
    n_disp = sum(r.nodes - 1 for r in rings_) + 1
    V = np.zeros((sum(len(p[0]) for p in per), n_disp))
    D = np.zeros_like(V)
    row, col = 0, 0
    for r, (Y, _w, Pm, PD, _Pi) in zip(rings_, per):
        V[row : row + len(Y), col : col + r.nodes] = Pm
        D[row : row + len(Y), col : col + r.nodes] = PD
        row, col = row + len(Y), col + r.nodes - 1
    return V[:, 1:-1], D[:, 1:-1]


def nodal_values(rings_, unknowns: FloatArray) -> FloatArray:
    """A displacement's nodal values (continuous across the rings, from R_i to R_N) from
    its unknowns in :func:`radial_maps`' basis."""
    out = np.array(unknowns, dtype=float)
    at = 0
    for r in rings_:
        out[at + 1 : at + r.nodes] += out[at]
        at += r.nodes - 1
    return out


def face_rows(rings_) -> FloatArray:
    """The rows (2, unknowns) that give a displacement's value on the inner and the outer
    face from its unknowns: the first unknown, and the sum of the inner value and every
    ring's outer difference."""
    n_disp = sum(r.nodes - 1 for r in rings_) + 1
    rows = np.zeros((2, n_disp))
    rows[0, 0] = 1.0
    rows[1, np.cumsum([0] + [r.nodes - 1 for r in rings_])] = 1.0
    return rows
