"""A layered base state continued from a neighbouring one (docs/derivation-layered.md,
"Continuation along a march").

Along a march the tube changes a little from one step to the next, and so does its state.
Instead of walking the loading branches again from the unloaded tube
(:func:`.layered.solve_layered_state`), the unknowns of the neighbour's state (r_i, and
lambda_z under force control) are the start of Newton's method on the same equations the
walk ends with: on the pressure branch at the tube's voltage (the charge c fixed by the
voltage, :class:`.branches.Branch`),

    T(r_i, lambda_z, c) - (P_i - P_o) = 0,     [ N(r_i, lambda_z, c) - N_applied = 0 ],

with a forward-difference Jacobian (all perturbed points in one vectorised evaluation). The
root is accepted only if it is the walk's root, i.e. on the same branch as the neighbour and
before that branch's threshold:

* Newton converged (a step below ``CONVERGED`` within ``MAX_ITER`` iterations);
* continuity: r_i (and lambda_z under force control) moved by at most ``JUMP`` (relative)
  from the neighbour's;
* the load of the last loading stage rises along its branch at the root, as it does on the
  whole walked part of a branch before its threshold: d Vbar / d r_i > 0 on the voltage
  branch (P_i - P_o fixed) when Vbar > 0, else d P_i / d r_i > 0 on the pressure branch at
  V = 0 (for both directions of the pressure); beyond a limit point the continued root has
  the opposite slope, beyond an asymptote or a locking stretch Newton does not converge.
  Under force control the branch is a curve in (r_i, lambda_z) that need not be walked in
  rising r_i (thresholds.chart: a charged film tube under suction, whose r_i first falls as
  the voltage rises): there the direction in which the load rises, at the root, must be
  the one it has at the neighbour's state on its own branch, as it is along the walked part
  (it turns back at a limit point); where the two stages differ (a march from V = 0), the
  slope in r_i as above;
* the independent Chebyshev quadrature of the state agrees with the Gauss rule of the
  neighbour's node count (``quadrature_error`` <= rtol, or its own resolution next to a
  lock, as for every state).

An iterate that is no finite state (past a Gent layer's lock: a neighbour within 1e-3 of its
lock is past it for the next tube) is moved back inside first (:func:`_back_inside`).

Otherwise None is returned and the caller walks from the unloaded tube (the cold solve),
which also raises for a load beyond its threshold. What the local checks cannot see is a
fold pair born strictly between the start of the branch and the root within one step (a
cusp of the branch); the march's step (a few per cent) bounds how far such a pair could be
from the neighbour's state. The thresholds of a continued state (``voltage_threshold``...)
are walked from the unloaded tube when first asked for, as for every state.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from ..model.layers import Tube
from .branches import Branch
from .plies import Wall
from .thresholds import prepare

#: Newton iterations before the warm start gives up
MAX_ITER = 12
#: the largest relative change of r_i (and of lambda_z under force control) from the
#: neighbour's state
JUMP = 0.1
#: the relative Newton step after which the iterate is the root to rounding (the next step,
#: ~ 1e-7 CONVERGED + C CONVERGED^2 for curvature C, is below an ulp)
CONVERGED = 1e-10
#: relative forward-difference step of the Jacobian
_H = 1e-7


@dataclasses.dataclass(frozen=True)
class LazyPrepared:
    """The cold preparation of ``tube`` (voltage 0), made only when a threshold is asked
    for (a continued state has no walked branch of its own)."""

    tube: Tube
    rtol: float

    @functools.cached_property
    def voltage(self):
        return prepare(self.tube, self.rtol).voltage


def continued(tube: Tube, near, rtol: float, guess=None, nodes: int | None = None):
    """(key, wall, prep, r_i, lambda_z, c, rise) of ``tube``'s state continued from the
    solved state ``near`` of a neighbouring tube, or None where that is not the walk's root
    (see the module docstring); ``rise`` is the direction of rising load there
    (:func:`_rise`), which the state keeps for its own continuation. ``guess``: a better
    Newton start (r_i, lambda_z) than the neighbour's own, e.g. extrapolated from two
    neighbours (the checks still compare with ``near``). ``nodes``: the Gauss rule of the
    equations, the neighbour's when None (a finer one where the neighbour's rule does not
    resolve this state: layered.solve_continued)."""
    old = near.tube
    if (
        near._wall is None
        or len(old.layers) != len(tube.layers)
        or old.control != tube.control
        or any(a.material != b.material for a, b in zip(old.layers, tube.layers))
    ):
        return None
    nodes = near._wall.nodes if nodes is None else nodes
    if _same_wall(tube, near._wall.tube) and nodes == near._wall.nodes:
        key, wall, prep = near._wall.tube, near._wall, near._prep  # a voltage march's
    else:
        key = dataclasses.replace(tube, voltage=0.0)
        wall, prep = Wall.build(key, nodes), LazyPrepared(key, rtol)
    branch = Branch(wall, "pressure", vbar=tube.voltage, compiled=True)
    force = tube.control == "force"
    dp = tube.inner_pressure - tube.outer_pressure
    for start in ([] if guess is None else [guess]) + [(near.r_i, near.stretch)]:
        u = np.array(start if force else start[:1], float)
        out = _newton(tube, near, branch, wall, u, dp, force)
        if out is not None:
            return (key, wall, prep, *out)
    return None


def _newton(tube, near, branch, wall, u, dp, force):
    """(r_i, lambda_z, c, rise) by Newton from u, or None (module docstring: the checks)."""
    last = None
    for _ in range(MAX_ITER):
        F, J = _system(branch, u, dp, force)
        if not (np.all(np.isfinite(F)) and np.all(np.isfinite(J))):
            u = _back_inside(branch, u, last, force)
            if u is None:
                return None
            continue
        try:
            step = np.linalg.solve(J, -F)
        except np.linalg.LinAlgError:
            return None
        last, u = u, u + step
        # converged once a step is below CONVERGED: the Jacobian's relative error (~1e-7)
        # and the curvature make the next step smaller than rounding
        if not np.all(abs(step) <= CONVERGED * abs(u)):
            continue
        x, lz = float(u[0]), float(u[1]) if force else tube.stretch
        if abs(x - near.r_i) > JUMP * near.r_i or (
            force and abs(lz - near.stretch) > JUMP * near.stretch
        ):
            return None
        rise = _rise(wall, tube, last, F, J, dp, force)
        if not _rising(rise, tube, force, near):
            return None
        if wall.ideal:  # c = V / Lambda, as Branch.point has it, without the integrals
            thick = tube.outer_radius - 1.0
            c = tube.voltage * thick / float(wall.electric(np.array([x]), np.array([lz]))[1][0])
        else:
            c = float(branch.point([x], [lz])["charge"][0])
        return x, lz, c, rise
    return None


#: halvings of a Newton step that left the finite states, back towards the last iterate
BACK_STEPS = 30


def _back_inside(branch: Branch, u, last, force: bool):
    """An iterate that is not a finite state (past a Gent layer's lock) moved back inside,
    or None: the start, under force control, to the lambda_z that balances the axial force
    at its r_i (Branch.at: a neighbour's state next to a lock is past it for the next tube,
    a Gent core within 1e-3 of its lock grown 2 % more); a later one, its step halved back
    towards the last iterate until the state and its Jacobian's points are finite."""
    if last is None:
        if not force:
            return None
        lz = float(branch.at([u[0]], u[1])["stretch"][0])
        return np.array([u[0], lz]) if math.isfinite(lz) else None
    for _ in range(BACK_STEPS):
        u = last + 0.5 * (u - last)
        F, J = _system(branch, u, 0.0, force)
        if np.all(np.isfinite(F)) and np.all(np.isfinite(J)):
            return u
    return None


def _same_wall(tube: Tube, key: Tube) -> bool:
    """Is ``key`` (a tube at voltage 0) ``tube`` without its voltage? (No new Tube built.)"""
    return (
        tube.layers == key.layers
        and all(
            getattr(tube, f) == getattr(key, f)
            for f in ("length", "stretch", "axial_force", "inner_pressure", "outer_pressure")
        )
        and tube.closed_ends == key.closed_ends
    )


def _system(branch: Branch, u, dp: float, force: bool):
    """Residuals F(u) and their forward-difference Jacobian J, u = (r_i[, lambda_z])."""
    n = len(u)
    pts = np.tile(u, (n + 1, 1))
    h = _H * abs(u)
    pts[np.arange(1, n + 1), np.arange(n)] += h
    lz = pts[:, 1] if force else np.full(n + 1, branch.wall.tube.stretch)
    pt = branch.point(pts[:, 0], lz)
    res = np.stack([pt["dp"] - dp, pt["residual"]])[:n]  # (equations, points)
    return res[:, 0], (res[:, 1:] - res[:, :1]) / h


def _rising(rise, tube: Tube, force: bool, near) -> bool:
    """Does the load of the last loading stage rise along its branch in the direction
    ``rise`` (:func:`_rise` at the root) as on the walked part (the module docstring)?"""
    if rise is None:
        return False
    if (near.tube.voltage == 0) == (tube.voltage == 0):  # the same stage
        # as the neighbour's, not rising r_i: under stretch control too, a branch can run
        # inward (fix23e), and every state continued on it was refused for a cold walk
        # (check round 30 doubt 1: 0.1-1 s a state, against ~5 ms continued)
        there = _near_rise(near, force)
        return there is not None and float(rise @ there) > 0
    return bool(rise[0] > 0)  # walked in rising r_i


def _rise(wall: Wall, tube: Tube, u, F, J, dp: float, force: bool) -> np.ndarray | None:
    """The direction (d r_i / r_i[, d lambda_z / lambda_z]) along the branch at u in which
    the load of the last loading stage rises (None where it is not defined)."""
    vbar = tube.voltage
    if vbar == 0:  # the pressure branch at V = 0 (or the unloaded state): dP_i along it
        if not force:
            return np.array([J[0, 0]])
        t = np.array([J[1, 1], -J[1, 0]])  # the axial balance kept
        t = t * np.sign(J[0] @ t)
    else:  # the voltage branch at fixed P_i - P_o: F(r_i, lambda_z, Vbar) = const along it
        lz = u[1] if force else tube.stretch
        if wall.ideal:
            F_v = _ideal_load_rate(wall, tube, u[0], lz)[: len(u)]
        else:
            hv = _H * vbar
            up = Branch(wall, "pressure", vbar=vbar + hv, compiled=True).point([u[0]], [lz])
            F_v = (np.array([up["dp"][0] - dp, up["residual"][0]])[: len(u)] - F) / hv
        if not force:
            return np.array([-J[0, 0] / F_v[0]])
        # the tangent of the curve in (r_i, lambda_z, Vbar): the null vector of [J | F_v]
        t3 = np.cross(np.append(J[0], F_v[0]), np.append(J[1], F_v[1]))
        t = t3[:2] * np.sign(t3[2])
    t = t / np.abs(u)  # relative: r_i and lambda_z differ in scale
    return t if np.all(np.isfinite(t)) and np.any(t != 0) else None


def _near_rise(near, force: bool = True) -> np.ndarray | None:
    """:func:`_rise` at the neighbour's state on its own branch (kept by a continued one)."""
    if near._rise is not None:
        return near._rise
    old = near.tube
    u = np.array([near.r_i, near.stretch] if force else [near.r_i])
    branch = Branch(near._wall, "pressure", vbar=old.voltage, compiled=True)
    dp = old.inner_pressure - old.outer_pressure
    F, J = _system(branch, u, dp, force)
    return _rise(near._wall, old, u, F, J, dp, force)


def _ideal_load_rate(wall: Wall, tube: Tube, r_i: float, lz: float) -> np.ndarray:
    """d(P_i - P_o, N_applied) / d Vbar at fixed (r_i, lambda_z) for ideal dielectrics, up to a
    positive factor (only its direction is used). On the pressure branch c = Vbar (R_N - 1) /
    Lambda, so d(c^2) / d Vbar = 2 c^2 / Vbar, and P_i - P_o = M - c^2 Q, N = N_m - pi c^2
    Lambda + pi (P_i r_i^2 - P_o r_o^2), the end load dropped from N_applied for closed ends:
    the rate is -(2 c^2 / Vbar) (Q, pi (Lambda + [open ends] r_i^2 Q))."""
    Q, Lam = (float(v[0]) for v in wall.electric(np.array([r_i]), np.array([lz])))
    open_ends = 0.0 if tube.closed_ends else 1.0
    return -np.array([Q, math.pi * (Lam + open_ends * r_i * r_i * Q)])
