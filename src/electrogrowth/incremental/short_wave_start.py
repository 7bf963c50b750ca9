"""The short-wave start of the impedance kernel (impedance.py): where a stiff short wave's
integration may stop carrying the inner face and restart near the outer face from the
dominant subspace of the frozen Stroh system, keeping its orientation.

The dense algebra (the growing projector, the attraction rate, the split of the carried
basis, a family's left-out pairs) is in dominant.py, which knows no table and no mode; here
it is applied to the Stroh matrix frozen at a radius of a table: the plan (where to restart,
from the smallest attraction rate on a segment) and the check (is the carried
subspace in W+ yet, with which sign, and W+'s impedance at the restart radius). Derivation
and checks: docs/derivation-dominant.md.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from .charts import determinant, hat_basis
from .dominant import (
    attraction_rate,
    dominant_impedance,
    growing_projector,
    growth_rate,
    hold_left_out,
    split_orientation,
    split_sizes,
)
from .riccati_step import _base_at
from .stroh import stroh_matrix

#: A short wave starts near a segment's outer end from the dominant subspace (dominant.py)
#: keeping only its orientation for loose tolerances (the signs of a march); below
#: FORGET_RTOL (the roots) it keeps the basis' size too (keep_plan). FORGET_MARGIN / rtol
#: bounds the remnant of what was skipped.
FORGET_RTOL, FORGET_MARGIN, FORGET_SAFETY = 1e-9, 10.0, 1.5
#: the carried subspace may be replaced once it is within REMNANT_MAX of the dominant one
#: (then sign det A is that of a matrix within 0.1 of I); it is integrated exactly until
#: then, first over BURN_NATS / rate, then for as long as the remnant says.
REMNANT_MAX, BURN_NATS, MAX_CHECKS = 0.1, 5.0, 3
#: ... and only tried for an integration still PLAN_STEPS steps from the outer face after
#: its first steps (the eigenvalues cost a few steps; a wall crossed in 20 steps gains
#: nothing)
PLAN_STEPS = 30.0
#: Tighter tolerances (the roots, refined on det(M2)) take the restart that keeps the
#: carried basis' size (keep_plan): at radii fixed by the plan, not by the step sequence,
#: so that det(M2) stays a smooth function of the parameters; the growth of the skipped
#: part by KEEP_NODES-point Gauss-Legendre
KEEP_NODES = 4
_KEEP_X, _KEEP_W = np.polynomial.legendre.leggauss(KEEP_NODES)


@nb.njit(cache=True)
def frozen_matrix(R, m, k, s, table, seg, work, Q):
    """Q = w G~ at R: the Stroh matrix with the moduli frozen there, in hat coordinates
    (chart {}, S scaled by s, all pairs), so that d(eta~)/dR = Q eta~."""
    p, r, w = _base_at(R, table, seg, work.vals, work.mod)
    stroh_matrix(work.mod, p, m, k * r, work.G)
    for a in range(8):
        for b in range(8):
            v = w * work.G[a, b]
            if a < 4 and b >= 4:
                v *= s
            elif a >= 4 and b < 4:
                v /= s
            Q[a, b] = v


@nb.njit(cache=True)
def forget_plan(R_a, m, k, s, table, seg, rtol, work):
    """(R_s, rate): where a short wave's integration of a segment [R_a, R_b] may
    restart from the dominant subspace (dominant.py), and the smallest attraction rate
    seen on [R_a, R_b]; R_s = -1 if that saves nothing (a long wave, a wall attracting
    slowly or not strongly elliptic). Between R_s and R_b any error of the restart decays
    by (FORGET_MARGIN / rtol)^FORGET_SAFETY at the smallest rate."""
    R_b = table.bounds[seg + 1]
    nats = np.log(FORGET_MARGIN / rtol)
    Q = np.empty((8, 8))
    frozen_matrix(R_b, m, k, s, table, seg, work, Q)
    # |det Q| is the product of the 8 |nu|, so 2 |det Q|^(1/8) bounds the rate from above:
    # a wall too thin even for it is refused without the rate (~6 us an evaluation)
    bound = 2.0 * abs(determinant(Q)) ** 0.125
    if not (bound > 0.0 and R_b - R_a >= 3.0 * FORGET_SAFETY * nats / bound):
        return -1.0, 0.0
    rate = attraction_rate(Q)
    if not rate > 0.0 or R_b - R_a < 3.0 * FORGET_SAFETY * nats / rate:
        return -1.0, 0.0
    for R in (R_a, 0.5 * (R_a + R_b)):
        frozen_matrix(R, m, k, s, table, seg, work, Q)
        rate = min(rate, attraction_rate(Q))
    R_s = R_b - FORGET_SAFETY * nats / max(rate, 1e-300)
    if not R_s > R_a + 2.0 * BURN_NATS / max(rate, 1e-300):
        return -1.0, 0.0
    return R_s, rate


@nb.njit(cache=True)
def forget_check(R, z, J, R_s, m, k, s, keep, table, seg, work, settled=False):
    """At R, is the carried subspace z~ (chart J) inside the dominant one W+ up to
    REMNANT_MAX? Returns (remnant, sign of det A, z+(R_s)) (dominant.py): the carried
    subspace is X = X+ + X-, X+ = [I; z+] A, and remnant = ||X- A^-1||; inf if the
    split or z+(R_s) cannot be formed.

    Next to a root of det A (a mode of the inner face) ||X- A^-1|| is unbounded at any
    radius. ``settled``: R is far enough from the segment's start that X- has decayed as
    keep_plan's R_c says; then the remnant relative to the size of A (split_sizes) is
    taken instead, whose sign of det A is wrong only within ~1e-13 of the root (docs:
    "Roots"), immaterial for the loose signs this restart serves."""
    Q = np.empty((8, 8))
    P = np.empty((8, 8))
    Zi = np.empty((8, 8))
    zs = np.empty((4, 4))
    if not _block_projector(R, m, k, s, keep, table, seg, work, Q, P, Zi):
        return np.inf, 0.0, zs
    X = hat_basis(z, J)
    sign_a, remnant = split_orientation(P, X, s)
    if not remnant <= REMNANT_MAX and settled:
        sign_s, _, rho = split_sizes(P, X, s)
        if rho <= REMNANT_MAX and sign_s != 0.0:
            sign_a, remnant = sign_s, rho
    if not remnant <= REMNANT_MAX:
        return remnant, sign_a, zs
    frozen_matrix(R_s, m, k, s, table, seg, work, Q)
    if not (growing_projector(Q, P, Zi) and _graph(P, keep, zs)):
        return np.inf, 0.0, zs
    return remnant, sign_a, zs


@nb.njit(cache=True)
def keep_distance(rtol, rate) -> float:
    """How far from a segment's start X- has decayed by (rtol / FORGET_MARGIN)^FORGET_SAFETY
    at the attraction ``rate`` (after BURN_NATS): where keep_plan splits the basis."""
    return (BURN_NATS + FORGET_SAFETY * np.log(FORGET_MARGIN / rtol)) / rate


@nb.njit(cache=True)
def keep_plan(R_a, m, k, s, table, seg, rtol, work):
    """(R_s, R_c) of the restart that keeps det(M2) (docs/derivation-dominant.md, "Roots"),
    planned from the start R_a of a segment; (-1, inf) if none.

    The basis is carried exactly to R_c = R_a + (BURN_NATS + FORGET_SAFETY
    ln(FORGET_MARGIN / rtol)) / rate, where what it holds outside the dominant subspace
    has decayed far below rtol; there it is split, and the integration restarts at R_s
    (forget_plan's) from W+ with the split's determinant and the growth in between
    (keep_restart). Both radii depend on the parameters only through the rates at three
    fixed radii, so det(M2) stays smooth in them."""
    R_s, rate = forget_plan(R_a, m, k, s, table, seg, rtol, work)
    if R_s < 0.0:
        return -1.0, np.inf
    R_c = R_a + keep_distance(rtol, rate)
    if not R_s > R_c:
        return -1.0, np.inf
    return R_s, R_c


@nb.njit(cache=True)
def keep_restart(R_c, R_s, z, J, m, k, s, keep, table, seg, work):
    """(sign, log_grow, z+(R_s)) to restart at R_s a basis carried exactly to R_c: the
    basis is [I; z+(R)] E(R) A between them, A the U rows of its W+ part at R_c
    (dominant.split_sizes), det E = exp(int tr(Q1 + Q2 z+)) > 0 (Gauss-Legendre on the
    frozen z+); so the restarted basis has the orientation sign det A and the size
    log|det A| + log det E. sign = 0 if a projector or z+ cannot be formed, or if the
    remnant against the frozen W+ is still above REMNANT_MAX (it cannot fall below the
    frozen W+'s own O(1 / |(m, k r)|) error, which multiplies A and moves no zero)."""
    Q = np.empty((8, 8))
    P = np.empty((8, 8))
    Zi = np.empty((8, 8))
    zs = np.empty((4, 4))
    if not _block_projector(R_c, m, k, s, keep, table, seg, work, Q, P, Zi):
        return 0.0, 0.0, zs
    sign, log_a, remnant = split_sizes(P, hat_basis(z, J), s)
    if sign == 0.0 or not remnant <= REMNANT_MAX:  # not attracted as the rate said
        return 0.0, 0.0, zs
    grow = 0.0
    half, mid = 0.5 * (R_s - R_c), 0.5 * (R_s + R_c)
    for q in range(KEEP_NODES):
        frozen_matrix(mid + half * _KEEP_X[q], m, k, s, table, seg, work, Q)
        if not (growing_projector(Q, P, Zi) and _graph(P, keep, zs)):
            return 0.0, 0.0, zs
        grow += half * _KEEP_W[q] * growth_rate(Q, zs, keep)
    frozen_matrix(R_s, m, k, s, table, seg, work, Q)
    if not (growing_projector(Q, P, Zi) and _graph(P, keep, zs)):
        return 0.0, 0.0, zs
    return sign, log_a + grow, zs


@nb.njit(cache=True)
def _block_projector(R, m, k, s, keep, table, seg, work, Q, P, Zi) -> bool:
    """Q <- the Stroh matrix frozen at R, P <- its growing projector with a family's
    left-out pairs held (dominant.hold_left_out); False if P cannot be formed."""
    frozen_matrix(R, m, k, s, table, seg, work, Q)
    if not growing_projector(Q, P, Zi):
        return False
    hold_left_out(P, keep)
    return True


@nb.njit(cache=True)
def _graph(P, keep, zs) -> bool:
    """zs <- z+ of the growing projector P with a family's left-out pairs held, made
    symmetric (W+ is Lagrangian); False if W+ is not a graph over U."""
    hold_left_out(P, keep)
    if not dominant_impedance(P, zs):
        return False
    for i in range(4):
        for j in range(i + 1, 4):
            zs[i, j] = zs[j, i] = 0.5 * (zs[i, j] + zs[j, i])
    return True
