"""Newton's method on a tube's full discrete equations along the bifurcated branch, the
control unknown: the second route to the Koiter coefficient shared by the tests of the
tube's amplitude equation in other controls and under pressures."""

from __future__ import annotations

import numpy as np

from electrogrowth.bifurcation.koiter_film import _nearest_zero
from electrogrowth.incremental.ring_basis import nodal_values


def peak_row(rings_, radial, start: int, size: int):
    """The row that gives, from the full unknowns (``size`` of them), u_r of harmonic 1
    (its unknowns from ``start``) at the node where the mode's u_r (``radial``, its
    unknowns) is largest: the value Newton prescribes. The unknowns are each ring's inner
    value and differences (ring_basis.py), so a nodal value is a sum of them."""
    T = nodal_values(rings_, np.eye(len(radial)))
    row = np.zeros(size)
    row[start : start + len(radial)] = T[int(np.argmax(np.abs(T @ radial)))]
    return row


def mode_in_full(first, stiffness, one, size: int):
    """(mode, row): the critical mode of the one-harmonic forms ``first`` (the null vector
    of ``stiffness``, scaled to a unit peak |u_r|) placed in harmonic 1 of each field of the
    full unknowns (``one``: harmonic -> slice, ``size`` of them), and the row giving its
    largest nodal u_r (:func:`peak_row`, the value Newton prescribes)."""
    phi = _nearest_zero(stiffness)[1]
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    mode = np.zeros(size)
    for f, sl in zip(range(3), first.slices):
        mode[one[(f, 1)]] = phi[sl]
    return mode, peak_row(first.rings, phi[first.slices[0]], one[(0, 1)].start, size)


def branch_curvature(c_c, mode_vector, row, residual, jacobian, eps_values):
    """(c(eps) - c_c) / eps^2 for each eps: Newton on residual(c, w) = 0 with ``row`` @ w
    (u_r of harmonic 1 where the mode, ``mode_vector`` in the full unknowns, is largest:
    :func:`peak_row`) prescribed to eps times the mode's value, from w = eps mode,
    c = c_c."""
    out = []
    for eps in eps_values:
        w, c, size = eps * mode_vector, c_c, len(mode_vector)
        for _ in range(30):
            h = 1e-3 * max(1.0, abs(c))
            J = np.zeros((size + 1, size + 1))
            J[:size, :size] = jacobian(c, w)
            J[:size, size] = (residual(c + h, w) - residual(c - h, w)) / (2 * h)
            J[size, :size] = row
            rhs = np.concatenate([residual(c, w), [row @ (w - eps * mode_vector)]])
            step = np.linalg.solve(J, rhs)
            w, c = w - step[:size], c - step[size]
            if abs(step[size]) < 1e-14:
                break
        out.append((c - c_c) / eps**2)
    return out


def onset_floor(stiffness, c_c: float, samples: int = 11) -> float:
    """The rounding floor of the onset c_c: the largest departure, in c, of the
    eigenvalue of A(c) nearest zero from its tangent at ``samples`` points 2e-13 |c_c|
    apart around c_c (the tangent's slope from +-1e-6 |c_c|). Newton's c(eps) carries a
    floor of the same size, so D(eps) = (c - c_c) / eps^2 carries ~2 floor / eps^2."""
    h = 1e-6 * max(1.0, abs(c_c))
    slope = (_nearest_zero(stiffness(c_c + h))[0] - _nearest_zero(stiffness(c_c - h))[0]) / (2 * h)
    steps = 2e-13 * max(1.0, abs(c_c)) * np.arange(-(samples // 2), samples // 2 + 1)
    departures = [_nearest_zero(stiffness(c_c + d))[0] - slope * d for d in steps]
    return float(np.max(np.abs(departures)) / abs(slope))


def richardson_floor(floor: float, eps: float) -> float:
    """What a rounding floor ``floor`` in each c (and in c_c) can do to :func:`richardson`
    of D at eps, 2 eps, 4 eps: (64 D_0 - 20 D_1 + D_2) / 45, each D_i off by up to
    2 floor / eps_i^2, sums to (64 + 5 + 1/16) / 45 * 2 floor / eps^2 <= 3.1 floor / eps^2."""
    return 3.1 * floor / eps**2


def richardson(D):
    """The eps -> 0 limit of D(eps) = c_2 + c_4 eps^2 + c_6 eps^4 at eps, 2 eps, 4 eps (or
    of c_2 + c_4 eps^2 from two values)."""
    R1 = [(4 * D[i] - D[i + 1]) / 3 for i in range(len(D) - 1)]
    return R1[0] if len(R1) == 1 else (16 * R1[0] - R1[1]) / 15
