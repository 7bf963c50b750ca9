"""Compiled surface-impedance kernel: the Riccati equation through the wall, batched.

For a mode (m, k) the solutions of the Stroh system d eta/dr = G eta / r (paper eq. Stroh)
that satisfy the inner-face conditions S(r_i) = 0 span a 4-dimensional subspace. Written
as S = z U, its conditional impedance z obeys the Riccati equation (paper eq. Riccati)

    dz/dr = (1/r) (G3 + G4 z - z G1 - z G2 z),     z(r_i) = 0,

and the tube bifurcates when det z(r_o) = 0. The impedance has poles inside the wall for
some parameters (the subspace stops being a graph over U), so a naive search reports them
as roots. We therefore integrate the same subspace in whichever of the 16 coordinate
charts of the Lagrangian Grassmannian keeps it bounded: chart J exchanges (U_j, S_j) ->
(S_j, -U_j) for j in J, a symplectic swap under which the Riccati form and the symmetry of
z are preserved. J = {} is the paper's impedance, J = {0,1,2,3} its inverse. The target

    f = sign(det U~) det(z~[J', J']) / sqrt(det(I + z~^T z~)),   J' = complement of J,

equals det(M2) / sqrt(det(M^T M)) for the propagated basis M = [M1; M2] of the subspace:
it is continuous, bounded by 1, independent of the chart and zero exactly at bifurcation.
S is scaled by s = max(1, |(m, k r_o)|) so that z~ is O(1) for every mode.

Integration is in the reference radius R in [1, Rbar_o] (dr/dR = a R / r, a = g^3 /
lambda_z) with Dormand-Prince 8(5,3) (the tableau of dop853.py, one step and its error in
riccati_step.py) and per-member error control; the moduli come from a Chebyshev table
(radial_table.py), which crosses into the compiled code as one record (a RadialTable, or a
TableStack for a batch), so the kernel knows no material.

A short wave's Riccati equation is stiff (its subspace is attracted to the dominant one at
a rate ~ 2 |(m, k r)|), so for loose tolerances (the signs of a march) the kernel may stop
integrating a segment (a layer) once the carried subspace lies in the dominant subspace of the
frozen Stroh system, and restart near the segment's outer end from it, keeping the orientation
(short_wave_start.py, dominant.py, docs/derivation-dominant.md); for tighter ones (the roots) a
restart at radii fixed by the plan that carries the basis' size along, so that det(M2) keeps
its zeros.

Every member of a batch also says which of the four pairs (U_j, S_j) its mode family keeps
(``keep``, a bitmask, ALL_PAIRS = 0b1111 for the paper's ansatz; see charts.py and
incremental/targets.py): the torsional pair at m = 0, the anti-plane pair at k = 0 decouple,
and a family's target is that of its own block, f_J of the kept pairs alone (the factor
1/sqrt(2) of each left-out pair is divided out). With all pairs kept at m = 0 (or k = 0) the
target is exactly the product of the two blocks' targets (docs/derivation-families.md).
"""

from __future__ import annotations

import numba as nb
import numpy as np

from .charts import SWITCH, chart_setup, chart_target, determinant, hat_basis, switch_chart
from .radial_table import RadialTable
from .riccati_step import _EXPONENT, _NS, _base_at, _error, _new_work, _rhs, _step, next_slope
from .short_wave_start import (
    BURN_NATS,
    FORGET_RTOL,
    MAX_CHECKS,
    PLAN_STEPS,
    REMNANT_MAX,
    forget_check,
    forget_plan,
    keep_distance,
    keep_plan,
    keep_restart,
)

#: every pair (U_j, S_j) kept: the paper's ansatz
ALL_PAIRS = 0b1111

#: an accepted step may not end with an entry of z~ above LEAP: such a step went through (or
#: next to) a pole of its chart, where the error estimate, relative to |z~|, accepts anything
#: (entries of 1e279 were accepted when a soft layer follows a stiff one) and the chart and
#: orientation read off it at the next switch are arbitrary (a flipped target).
#: Rejected, the step shrinks until it ends below LEAP and the chart switches cleanly.
LEAP = 16.0 * SWITCH

#: ``forget`` of integrate_one: every wall integrated; the short-wave start that keeps the
#: sign only for rtol >= FORGET_RTOL (the signs of a march) and the one that keeps det(M2)
#: below it; the latter at every rtol (roots refined on det(M2))
WHOLE_WALL, SHORT_WAVE, KEEP_SIZE = 0, 1, 2

#: status codes written by the kernel
OK, MAX_STEPS, STEP_UNDERFLOW, NO_CHART = 0, 1, 2, 3
STATUS_TEXT = {
    OK: "ok",
    MAX_STEPS: "too many steps",
    STEP_UNDERFLOW: "step size underflow",
    NO_CHART: "no bounded impedance chart",
}


@nb.njit(cache=True)
def impedance_scale(m: float, k: float, r_o: float) -> float:
    """The scale s of S used by the kernel: max(1, |(m, k r_o)|)."""
    return max(1.0, np.sqrt(m * m + (k * r_o) ** 2))


@nb.njit(cache=True)
def _start(keep):
    """z~(r_i) of a traction-free face: 0 on the kept pairs (S = 0), 1 on the left-out ones
    (constant: their rows and columns of G are zero); and the factor sqrt(2)^(left out)
    that undoes their 1/sqrt(2) in the target."""
    z = np.zeros((4, 4))
    factor = 1.0
    for j in range(4):
        if not (keep >> j) & 1:
            z[j, j] = 1.0
            factor *= np.sqrt(2.0)
    return z, factor


@nb.njit(cache=True)
def face_impedance(P, m, kr, keep, s):
    """The scaled impedance z_P / s of a follower pressure P on a face (S = z_P U there).

    The incremental traction of a pressure P that follows the face is S^T n = P L^T n
    (tr L = 0; docs/derivation-layered-modes.md), i.e. Sigma_ri = P du_r/dx_i on r = const:

        z_P = -P [[1, m, kr, 0], [m, 1, 0, 0], [kr, 0, 0, 0], [0, 0, 0, 0]],

    symmetric, so the impedance stays in the Lagrangian Grassmannian. Rows and columns of
    left-out pairs are zero.
    """
    zp = np.zeros((4, 4))
    if P == 0.0:
        return zp
    zp[0, 0] = -P
    zp[0, 1] = zp[1, 0] = -P * m
    zp[0, 2] = zp[2, 0] = -P * kr
    zp[1, 1] = -P
    for i in range(4):
        for j in range(4):
            if not ((keep >> i) & 1 and (keep >> j) & 1):
                zp[i, j] = 0.0
            else:
                zp[i, j] /= s
    return zp


@nb.njit(cache=True)
def pressure_target(z, J, orient, zp):
    """The target with the outer-face condition S = z_P U: det(M2 - z_P M1) / sqrt(det(M^T M))
    for the basis M = [M1; M2] = P_J^T [I; z~] of the subspace (zp scaled like z~).

    Equal to :func:`~.charts.chart_target` at zp = 0; bounded (by a power of the norm of
    [[I, 0], [-z_P, I]]) and without poles like it.
    """
    X = hat_basis(z, J)
    B = X[4:] - zp @ X[:4]
    return orient * determinant(B) / np.sqrt(determinant(np.eye(4) + z.T @ z))


@nb.njit(cache=True)
def _radii(table, work):
    """(r_i, r_o): the current radii of the faces."""
    L = table.coef.shape[0]
    r_i = _base_at(table.bounds[0], table, 0, work.vals, work.mod)[1]
    r_o = _base_at(table.bounds[L], table, L - 1, work.vals, work.mod)[1]
    return r_i, r_o


@nb.njit(cache=True)
def integrate_one(m, k, keep, table, rtol, max_steps, forget=SHORT_WAVE):
    """Integrate mode (m, k) through the wall of ``table`` (a RadialTable).

    ``keep`` (bit j set: pair (U_j, S_j) kept; ALL_PAIRS for the paper's ansatz) selects
    the block of a mode family. The impedance starts from the inner face condition (S = 0,
    or the follower pressure's z_P), is carried unchanged across every interface (u, the
    traction, Phi and r Delta_r are continuous, so eta is) and ends with the outer face
    condition. Adaptive steps with the local error of every entry of z~ below
    rtol (1 + |z~|), and a change of chart whenever an entry of z~ exceeds SWITCH (a step
    ending above LEAP is rejected: it jumped a pole of the chart).
    A stiff short wave may restart each segment (layer) near its outer end from the
    dominant subspace once the carried one lies in it (short_wave_start.py; a family's
    left-out pairs stay on their constant line, dominant.hold_left_out): with ``forget``
    SHORT_WAVE (default) keeping only the orientation for rtol >= FORGET_RTOL (the signs
    of a march), and keeping the basis' size too below it; KEEP_SIZE keeps the size at
    every rtol; WHOLE_WALL integrates every wall.
    Returns (f, z~, J, status, steps, log_norm): the target of the kept block, the
    impedance in chart J at R_N, the chart, a status code (OK, MAX_STEPS, STEP_UNDERFLOW,
    NO_CHART; f is NaN unless OK), the steps tried, and log sqrt(det(M^T M)) of the basis
    M carried from the inner face (U~ = I there), which f divides out: f exp(log_norm) is
    det(M2) of that basis, an analytic function of the parameters (NaN where the restart
    kept only the orientation; where it kept the size, det(M2) times a smooth positive
    factor close to 1, with the same zeros to rtol: docs/derivation-dominant.md).
    """
    L = table.coef.shape[0]
    R0, RN = table.bounds[0], table.bounds[L]
    work = _new_work(table)
    r_i, r_o = _radii(table, work)
    s = impedance_scale(m, k, r_o)
    z, factor = _start(keep)
    z += face_impedance(table.face_pressure[0], m, k * r_i, keep, s)
    J, orient, log_det = 0, 1.0, 0.0  # log_det: log|det U~| of the carried basis
    if np.max(np.abs(z)) > SWITCH:
        zn, J, d = switch_chart(z, 0)
        if J < 0:
            return np.nan, z, 0, NO_CHART, 0, np.nan
        z[:, :] = zn
        orient, log_det = np.sign(d), np.log(abs(d))
    chart_setup(J, s, keep, work.perm, work.mult)
    K = np.empty((_NS + 1, 4, 4))
    ztmp = np.empty((4, 4))
    znew = np.empty((4, 4))
    h = (RN - R0) / (4.0 + s)
    steps = 0
    sizes = forget == KEEP_SIZE or (forget == SHORT_WAVE and rtol < FORGET_RTOL)
    signs = forget == SHORT_WAVE and not sizes
    for seg in range(L):  # each layer may restart near its outer end
        R, end = table.bounds[seg], table.bounds[seg + 1]
        R_s, attract, check, checks, plan, first = -1.0, 0.0, np.inf, 0, signs, steps
        settled = np.inf  # past it, X- has decayed as keep_plan's R_c says
        stop_at = np.inf  # where the restart that keeps the size is tried (keep_plan)
        if sizes:
            R_s, stop_at = keep_plan(R, m, k, s, table, seg, rtol, work)
        rate = _rhs(R, z, m, k, table, seg, work, K[0])
        while R < end:
            if plan and steps - first >= 3 and end - R > PLAN_STEPS * h:
                plan = False  # a long integration ahead: is this a stiff short wave?
                R_s, attract = forget_plan(R, m, k, s, table, seg, rtol, work)
                if R_s > 0.0:
                    check = R + BURN_NATS / attract
                    settled = R + keep_distance(rtol, attract)
            if R >= check and checks < MAX_CHECKS:  # forget the inner face? (dominant.py)
                checks += 1
                remnant, sign_a, zs = forget_check(
                    R, z, J, R_s, m, k, s, keep, table, seg, work, R >= settled
                )
                check = R + np.log(max(remnant, 1.0) / (0.1 * REMNANT_MAX)) / attract
                if R < settled and (checks == MAX_CHECKS - 1 or not check <= settled):
                    check = settled  # the last check once settled (next to a root of det A)
                if remnant <= REMNANT_MAX and sign_a != 0.0:
                    R, z, J, orient, check = R_s, zs, 0, orient * sign_a, np.inf
                    log_det = np.nan  # the restarted basis has forgotten the carried one's size
                    if np.max(np.abs(z)) > SWITCH:
                        zn, J, d = switch_chart(z, 0)
                        if J < 0:
                            return np.nan, z, 0, NO_CHART, steps, np.nan
                        z, orient = zn, orient * np.sign(d)
                    chart_setup(J, s, keep, work.perm, work.mult)
                    rate = _rhs(R, z, m, k, table, seg, work, K[0])
                    h = min(h, end - R)
                if not (np.isfinite(check) and check < R_s):
                    check = np.inf
            if R >= stop_at:  # the restart that keeps the size (keep_plan)
                stop_at = np.inf
                sign_a, grow, zs = keep_restart(R, R_s, z, J, m, k, s, keep, table, seg, work)
                if sign_a != 0.0:
                    R, z, J, orient = R_s, zs, 0, orient * sign_a
                    log_det += grow
                    if np.max(np.abs(z)) > SWITCH:
                        zn, J, d = switch_chart(z, 0)
                        if J < 0:
                            return np.nan, z, 0, NO_CHART, steps, np.nan
                        z, orient = zn, orient * np.sign(d)
                        log_det += np.log(abs(d))
                    chart_setup(J, s, keep, work.perm, work.mult)
                    rate = _rhs(R, z, m, k, table, seg, work, K[0])
                    h = min(h, end - R)
            if steps >= max_steps:
                return np.nan, z, J, MAX_STEPS, steps, np.nan
            if h < 1e-14 * (RN - R0):
                return np.nan, z, J, STEP_UNDERFLOW, steps, np.nan
            stop = min(end, stop_at)
            last = R + h >= stop
            if last:
                h = stop - R
            grow = _step(R, h, z, m, k, table, seg, work, K, ztmp, znew, rate)
            err = _error(h, z, znew, K, rtol)
            steps += 1
            if err <= 1.0 and not np.max(np.abs(znew)) <= LEAP:
                err = 1e6  # past a pole of the chart: shrink the step (LEAP)
            if err <= 1.0:
                R = stop if last else R + h
                log_det += grow
                for i in range(4):
                    for j in range(4):
                        z[i, j] = 0.5 * (znew[i, j] + znew[j, i])
                h *= min(10.0, 0.9 * err**_EXPONENT) if err > 0.0 else 10.0
                same = not last  # R is the step's end R + h, where its last stage was
                if np.max(np.abs(z)) > SWITCH:
                    zn, Jn, d = switch_chart(z, J)
                    if Jn < 0:
                        return np.nan, z, J, NO_CHART, steps, np.nan
                    if Jn != J:
                        z[:, :] = zn
                        J = Jn
                        orient *= np.sign(d)
                        log_det += np.log(abs(d))  # U~ of the new chart: W1 U~
                        chart_setup(J, s, keep, work.perm, work.mult)
                        same = False  # the blocks there were in the old chart
                if same:
                    rate = next_slope(z, work, K[0])
                else:
                    rate = _rhs(R, z, m, k, table, seg, work, K[0])
            else:
                h *= max(0.2, 0.9 * err**_EXPONENT)
    log_norm = log_det + 0.5 * np.log(determinant(np.eye(4) + z.T @ z)) - np.log(factor)
    P_o = table.face_pressure[1]
    if P_o == 0.0:
        return factor * chart_target(z, J, orient), z, J, OK, steps, log_norm
    zp = face_impedance(P_o, m, k * r_o, keep, s)
    return factor * pressure_target(z, J, orient, zp), z, J, OK, steps, log_norm


@nb.njit(cache=True)
def integrate_fixed(m, k, keep, table, n_steps):
    """z~(R_N) of mode (m, k), pairs ``keep``, after ``n_steps`` equal steps per segment
    in chart J = {} from a traction-free inner face.

    The steps of :func:`integrate_one` without error control or change of chart (so only
    for modes whose impedance stays bounded there): the global error is O(h^8), h =
    (R_k - R_{k-1}) / n_steps, which the tests fit.
    """
    L = table.coef.shape[0]
    work = _new_work(table)
    s = impedance_scale(m, k, _radii(table, work)[1])
    z = _start(keep)[0]
    chart_setup(0, s, keep, work.perm, work.mult)
    K = np.empty((_NS + 1, 4, 4))
    ztmp = np.empty((4, 4))
    znew = np.empty((4, 4))
    for seg in range(L):
        a, b = table.bounds[seg], table.bounds[seg + 1]
        h = (b - a) / n_steps
        for n in range(n_steps):
            R = a + n * h
            rate = _rhs(R, z, m, k, table, seg, work, K[0])
            _step(R, h, z, m, k, table, seg, work, K, ztmp, znew, rate)
            for i in range(4):
                for j in range(4):
                    z[i, j] = 0.5 * (znew[i, j] + znew[j, i])
    return z


@nb.njit(cache=True)
def _member_table(tables, t):
    """Table t of a TableStack, as the RadialTable it was stacked from."""
    nl = tables.n_segments[t]
    return RadialTable(
        tables.coef[t, :nl],
        tables.n_funcs[t, :nl],
        tables.fmap[t, :nl],
        tables.bounds[t, : nl + 1],
        tables.face_pressure[t],
    )


@nb.njit(cache=True)
def _target_member(b, m, k, keep, table_index, tables, rtol, max_steps, f, status, steps):
    """Member b of a batch: target, status and steps into f[b], status[b], steps[b]."""
    table = _member_table(tables, table_index[b])
    f[b], _, _, status[b], steps[b], _ = integrate_one(m[b], k[b], keep[b], table, rtol, max_steps)


@nb.njit(parallel=True, cache=True)
def target_batch(m, k, keep, table_index, tables, rtol, max_steps):
    """Bifurcation target f for a batch of (mode, base state) pairs, in parallel.

    Member b is mode (m[b], k[b]) of the family block ``keep[b]`` (int64 bitmasks, see
    :func:`integrate_one`) on table ``table_index[b]`` of the TableStack ``tables``.
    Returns (f, status, steps), each of the batch's length.
    """
    n = m.shape[0]
    f, status, steps = np.empty(n), np.empty(n, np.int64), np.empty(n, np.int64)
    for b in nb.prange(n):
        _target_member(b, m, k, keep, table_index, tables, rtol, max_steps, f, status, steps)
    return f, status, steps


@nb.njit(cache=True)
def target_serial(m, k, keep, table_index, tables, rtol, max_steps):
    """:func:`target_batch` on one thread: small batches do not pay the thread launch."""
    n = m.shape[0]
    f, status, steps = np.empty(n), np.empty(n, np.int64), np.empty(n, np.int64)
    for b in range(n):
        _target_member(b, m, k, keep, table_index, tables, rtol, max_steps, f, status, steps)
    return f, status, steps
