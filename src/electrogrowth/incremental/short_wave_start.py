"""The short-wave start of the impedance kernel (impedance.py): where a stiff short wave's
integration may stop carrying the inner face and restart near the outer face from the
dominant subspace of the frozen Stroh system, keeping its orientation.

The dense algebra (the growing projector, the attraction rate, the split of the carried
basis, a family's left-out pairs) is in dominant.py, which knows no table and no mode; here
it is applied to the Stroh matrix frozen at a radius of a table: the plan (where to restart,
from the smallest attraction rate on the outer segment) and the check (is the carried
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
    hold_left_out,
    split_orientation,
)
from .riccati_step import _base_at
from .stroh import stroh_matrix

#: A short wave starts near the outer face from the dominant subspace (dominant.py) only
#: for loose tolerances (the signs of a march): the roots are always integrated through
#: the whole wall. FORGET_MARGIN / rtol bounds the remnant of what was skipped.
FORGET_RTOL, FORGET_MARGIN, FORGET_SAFETY = 1e-9, 10.0, 1.5
#: the carried subspace may be replaced once it is within REMNANT_MAX of the dominant one
#: (then sign det A is that of a matrix within 0.1 of I); it is integrated exactly until
#: then, first over BURN_NATS / rate, then for as long as the remnant says.
REMNANT_MAX, BURN_NATS, MAX_CHECKS = 0.1, 5.0, 3
#: ... and only tried for an integration still PLAN_STEPS steps from the outer face after
#: its first steps (the eigenvalues cost a few steps; a wall crossed in 20 steps gains
#: nothing)
PLAN_STEPS = 30.0


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
    """(R_s, rate): where a short wave's integration of the last segment [R_a, R_b] may
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
    if not R_b - R_a >= 3.0 * FORGET_SAFETY * nats / bound:
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
def forget_check(R, z, J, R_s, m, k, s, keep, table, seg, work):
    """At R, is the carried subspace z~ (chart J) inside the dominant one W+ up to
    REMNANT_MAX? Returns (remnant, sign of det A, z+(R_s)) (dominant.py): the carried
    subspace is X = X+ + X-, X+ = [I; z+] A, and remnant = ||X- A^-1||; inf if the
    split or z+(R_s) cannot be formed."""
    Q = np.empty((8, 8))
    P = np.empty((8, 8))
    Zi = np.empty((8, 8))
    zs = np.empty((4, 4))
    frozen_matrix(R, m, k, s, table, seg, work, Q)
    if not growing_projector(Q, P, Zi):
        return np.inf, 0.0, zs
    hold_left_out(P, keep)
    sign_a, remnant = split_orientation(P, hat_basis(z, J), s)
    if not remnant <= REMNANT_MAX:
        return remnant, sign_a, zs
    frozen_matrix(R_s, m, k, s, table, seg, work, Q)
    if not growing_projector(Q, P, Zi):
        return np.inf, 0.0, zs
    hold_left_out(P, keep)
    if not dominant_impedance(P, zs):
        return np.inf, 0.0, zs
    for i in range(4):  # symmetric up to rounding (W+ is Lagrangian)
        for j in range(i + 1, 4):
            zs[i, j] = zs[j, i] = 0.5 * (zs[i, j] + zs[j, i])
    return remnant, sign_a, zs
