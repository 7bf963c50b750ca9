"""The modes a scan evaluates in one batch, and their signs on the unloaded tube.

A row of the batch is (m, n, family code) (incremental.targets.Family): the paper's
wrinkles (m, n), n >= 1 of the ranges (axisymmetric at m = 0, the torsion excluded); the
prismatic modes (m, 0), m >= 2, plane-strain wrinkles (ScanOptions.prismatic); the
torsional modes (0, n), u_th = U(r) cos kz (ScanOptions.torsional); and, when asked, a few
probes beyond the ranges (short waves at 2 and 4 times them, capped at M_CAP and N_CAP).
Every target's sign on the stress-free tube is the same for every tube, so it is read
once per grid (:func:`stable_signs`) and shared by every scan, curve and sweep
(docs/derivation.md).
"""

from __future__ import annotations

import functools

import numpy as np

from ..incremental.accuracy import SCAN_STABLE_SIGNS
from ..incremental.targets import Family, ImpedanceTarget
from .march import SIGN_TUBE, unloaded_signs
from .options import M_CAP, N_CAP


def every_mode_ranges(m_range, n_range) -> tuple[tuple[int, int], tuple[int, int]]:
    """The ranges clipped to M_CAP and N_CAP: where a scan's result is read mode by mode
    afterwards (a curve's check that its grid is still stable, certify's choice). A scan's
    ranges reach a thin layer's caps (options.mode_caps, m to 64064 for a lining 1e-3
    thick), which it searched along a few rows, not mode by mode: their rectangle, 64064 x
    30 modes, would take an hour to read at every check."""
    (m0, m1), (n0, n1) = m_range, n_range
    return (m0, min(m1, max(m0, M_CAP))), (n0, min(n1, max(n0, N_CAP)))


def mode_grid(m_range, n_range) -> np.ndarray:
    """All (m, n) pairs, rows, as floats (the paper's ansatz: the wrinkle family)."""
    m, n = np.meshgrid(
        np.arange(m_range[0], m_range[1] + 1), np.arange(n_range[0], n_range[1] + 1), indexing="ij"
    )
    return np.stack([m.ravel(), n.ravel()], axis=1).astype(float)


def family_rows(m_values, n_values, prismatic: bool, torsional: bool) -> np.ndarray:
    """Rows (m, n, family code) of the prismatic modes (m, 0), m >= 2 of ``m_values``, and
    the torsional modes (0, n), n of ``n_values`` (when 0 is among ``m_values``)."""
    rows = []
    if prismatic:
        rows += [(m, 0, Family.PRISMATIC.code) for m in m_values if m >= 2]
    if torsional and 0 in m_values:
        rows += [(0, n, Family.TORSIONAL.code) for n in n_values]
    return np.array(rows, float).reshape(-1, 3)


def scan_grid(
    m_range, n_range, probes: bool, families: tuple[bool, bool] = (False, False)
) -> np.ndarray:
    """Rows (m, n, family code): the (m, n) rectangle of wrinkles, the prismatic and
    torsional rows of the ranges (``families`` = (prismatic, torsional), see
    :func:`family_rows`), plus a few short waves beyond them when ``probes``.

    The critical value need not be monotone in m or n: at Rbar_o = 1.4, Vbar = 0.4 in
    extension it rises from m = 0 to m = 12 and then falls towards an inner-face short
    wave as m grows. Probes at 2 and 4 times the range catch such optima (for the
    prismatic and torsional families too).
    """
    (m0, m1), (n0, n1) = m_range, n_range
    wrinkle = mode_grid(m_range, n_range)
    grid = [
        np.column_stack([wrinkle, np.full(len(wrinkle), Family.WRINKLE.code)]),
        family_rows(range(m0, m1 + 1), range(n0, n1 + 1), *families),
    ]
    if probes:
        ms = sorted({min(2 * m1 + 1, M_CAP), min(4 * m1 + 3, M_CAP)} - set(range(m0, m1 + 1)))
        ns = sorted({min(2 * n1, N_CAP), min(4 * n1, N_CAP)} - set(range(n0, n1 + 1)))
        extra = [(m, n, Family.WRINKLE.code) for m in ms for n in (n0, n0 + 1)]
        extra += [(m, n, Family.WRINKLE.code) for n in ns for m in (m0, m0 + 1)]
        grid += [
            np.array(extra, float).reshape(-1, 3),
            family_rows(ms, ns, *families),
            family_rows([0] if m0 == 0 else [], ns, False, families[1]),
        ]
    return np.vstack(grid)


@functools.lru_cache(maxsize=64)
def stable_signs(m_range, n_range, probes, families) -> np.ndarray:
    """Signs of the kernel targets of :func:`scan_grid` on the unloaded tube, shared by
    every scan, curve and sweep of any tube (one layer or layered, any energy, radius and
    length): the unloaded incremental problem of a stress-free tube is strongly elliptic
    with no non-trivial solution, so no target vanishes along a path of unloaded tubes
    joining two of them and none changes sign (tests/bifurcation/test_scan.py checks it
    across radii, lengths, energies and layered tubes)."""
    modes = scan_grid(m_range, n_range, probes, families)
    targets = ImpedanceTarget(SCAN_STABLE_SIGNS)
    return unloaded_signs(SIGN_TUBE, modes, targets)
