"""Axisymmetric base state of a layered tube: anisotropic and graded growth, follower pressures,
prescribed axial stretch or axial force (derivations in docs/derivation-layered.md).

The entry points: :func:`solve_layered_state`, :func:`layered_threshold` and the response
curves :func:`voltage_response`, :func:`pressure_response`. One state of the wall (kinematics,
the equilibrium (*) T = P_i - P_o, the Gauss-Legendre integrals) is in :mod:`.plies`; the
loading branches are in :mod:`.branches`, followed from the unloaded state to their
thresholds in :mod:`.thresholds`. A load beyond its branch's threshold raises BaseStateError.
The solved state, :class:`LayeredState` (re-exported here), is in :mod:`.layered_state`: it is
re-integrated there by an independent Chebyshev quadrature per layer, and solved again with
more nodes when that disagrees (its ``quadrature_error``).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import (
    BaseStateError,
    Beyond,
    BranchNotFollowed,
    ConvergenceError,
    ParameterError,
    StartUnresolved,
)
from ..model.layers import Tube
from .branches import Branch, clean
from .force_box import check_force_when_lost, check_solved_stretch
from .layered_state import LayeredState
from .plies import ORDERS
from .start_probe import UNRESOLVED
from .thresholds import LockedSearch, Threshold, prepare, solve_on, threshold
from .voltage import CLOSING
from .warm import continued

__all__ = [
    "LayeredState",
    "Threshold",
    "layered_threshold",
    "pressure_response",
    "solve_layered_state",
    "voltage_response",
]


# -- entry points -------------------------------------------------------------------------------


def solve_layered_state(tube: Tube, *, rtol: float = 1e-12, near=None, guess=None) -> LayeredState:
    """The axisymmetric base state of a layered tube at its loads.

    Reached from the unloaded state (V = 0, P_i = P_o) by raising the inner pressure to P_i at
    V = 0 (pressure branch), then the voltage to Vbar (voltage branch), each followed in r_i.
    Solves (*) = P_i - P_o and int E_r dr = Vbar (R_N - 1) for (r_i, c), and under force control
    the axial balance for lambda_z.

    ``near``, the solved state of a neighbouring tube (a march's previous step), is the
    start of Newton's method instead (:mod:`.warm`: the same root, checked to be on the same
    branch before its threshold), or ``guess`` = (r_i, lambda_z) when given (extrapolated
    from two neighbours); where that fails, the walk from the unloaded state.

    Raises
    ------
    BaseStateError
        If P_i or Vbar lies beyond the threshold of its branch.

    >>> from electrogrowth.model.layers import Layer, Tube
    >>> state = solve_layered_state(Tube((Layer(2.0),), voltage=0.5))
    >>> round(state.lambda_i, 6), state.threshold_kind
    (1.151387, 'asymptote')
    """
    if near is not None and (state := solve_continued(tube, near, rtol, guess)) is not None:
        return state
    key = dataclasses.replace(tube, voltage=0.0)
    nodes = None
    for _ in range(len(ORDERS)):
        prep = _prepare(key, rtol, nodes)
        if tube.voltage == 0:
            x, lz = prep.loaded
        elif not math.isfinite(tube.voltage * tube.voltage):
            raise BaseStateError(
                f"Vbar = {tube.voltage:.12g} is beyond every state of this tube (Vbar^2"
                " overflows); no axisymmetric state"
            )
        else:  # the branch is walked only up to Vbar unless its threshold is known already
            thr = prep.voltage_to(tube.voltage)
            if thr.kind == "closing":  # as a uniform tube's (uniform.py)
                raise BranchNotFollowed(f"Vbar = {tube.voltage:.12g} for this tube: {CLOSING}")
            if thr.kind == "unresolved":  # the start's probe: as a uniform tube's
                raise StartUnresolved(f"Vbar = {tube.voltage:.12g}: {UNRESOLVED}")
            if thr.kind and not tube.voltage < thr.value:
                raise BaseStateError(
                    f"Vbar = {tube.voltage:.12g} is at or above the voltage threshold"
                    f" Vbar = {thr.value:.12g} ({thr.kind}) of this tube; no axisymmetric state",
                    beyond=Beyond("voltage", tube.voltage, thr.value, tube.outer_radius),
                )
            x, lz = solve_on(prep.branch, thr, tube.voltage * tube.voltage, _voltage_stage(tube))
        # c from the voltage, c = V / Lambda for ideal dielectrics (from (*) it would carry
        # the cancellation of T - (P_i - P_o) near the start, amplified by the square root)
        pt = Branch(prep.wall, "pressure", vbar=tube.voltage).point([x], [lz])
        state = LayeredState._build(tube, prep.wall, prep, x, lz, float(pt["charge"][0]), rtol)
        if _resolved(state, rtol):
            return _in_box(state)
        nodes = _finer(prep.wall.nodes)
        if prep.wall.nodes == ORDERS[-1]:
            break
    raise ConvergenceError(f"layered base state not resolved to rtol = {rtol}")


def solve_continued(tube: Tube, near, rtol: float = 1e-12, guess=None) -> LayeredState | None:
    """The state of ``tube`` continued from ``near`` alone (:mod:`.warm`, its checks and
    the quadrature's), or None where that is not the walk's root: no cold walk after.

    Where the independent quadrature does not confirm the root of the neighbour's Gauss
    rule, the root is continued again with the rule two orders finer, up to the largest, as
    the cold solve refines its own: next to a Gent lock the rule a state needs grows along
    the march (16 to 256 nodes over a few steps), and each refusal cost a walk of the
    loading branches from the unloaded tube, 5-20 s against ~20 ms (check round 35b, P17)."""
    nodes = near._wall.nodes if near._wall is not None else None
    while True:
        warm = continued(tube, near, rtol, guess, nodes)
        if warm is None:
            return None
        _, wall, prep, x, lz, c, rise = warm
        state = LayeredState._build(tube, wall, prep, x, lz, c, rtol, compiled=True)
        if _resolved(state, rtol):
            return _in_box(dataclasses.replace(state, _rise=rise))
        if wall.nodes == ORDERS[-1]:
            return None
        nodes, guess = _finer(wall.nodes), (x, lz)  # the coarser rule's root: a close start


def _prepare(tube: Tube, rtol: float, nodes):
    """thresholds.prepare; an unloaded-state search that met a layer's lock is made again
    with finer Gauss rules up to the largest (a coarse rule's T misplaces the root past
    the lock while the state exists: LockedSearch); under force control, a lost unloaded
    state whose force lies outside the stretch box is refused as the force's
    (basestate/force_box.py)."""
    while True:
        try:
            return prepare(tube, rtol, nodes)
        except LockedSearch as exc:
            if exc.nodes < ORDERS[-1]:
                nodes = _finer(exc.nodes)
                continue
            lost = exc
        except BaseStateError as exc:
            lost = exc
        if tube.control == "force":
            check_force_when_lost(tube, solve_layered_state)
        raise lost


def _resolved(state: LayeredState, rtol: float) -> bool:
    """Does the independent quadrature confirm the state to rtol, or to its own resolution
    where that is coarser? Next to a Gent lock the stresses carry the rounding of
    1 - (I1 - 3) / jm, amplified by its inverse: a core within 1.1e-3 of its lock has
    integrands resolved to ~1e-12 of their size by no Chebyshev degree, and its check's
    residuals (1.2e-12 at 256 nodes, 7e-13 at 384, one root to 1e-16) passed or failed
    rtol = 1e-12 by their noise (fix22a)."""
    noise = min(state.quadrature_noise, NOISE_CAP * rtol)  # beyond it: finer nodes, else none
    return state.quadrature_error <= max(rtol, 1e-14, noise)


#: the check's own noise is accepted up to this many times rtol (a Gent core 1.1e-3 from its
#: lock: 1.2e-12 at rtol 1e-12)
NOISE_CAP = 1e2


def _finer(nodes: int) -> int:
    """The Gauss rule two orders finer than ``nodes`` (the largest at most)."""
    return ORDERS[min(ORDERS.index(nodes) + 2, len(ORDERS) - 1)]


def _in_box(state: LayeredState) -> LayeredState:
    """The state, its solved stretch checked against the box under force control."""
    if state.tube.control == "force":
        check_solved_stretch(state.tube, state.stretch)
    return state


def layered_threshold(tube: Tube, control: str = "voltage", *, rtol: float = 1e-12) -> Threshold:
    """The threshold of the branch of ``control`` ("voltage": Vbar at the tube's pressures;
    "pressure": the inner pressure P_i at the tube's voltage and outer pressure), followed from
    its start (the unloaded state, or P_i = P_o at the tube's voltage), see :class:`Threshold`.
    """
    if control == "voltage":
        return prepare(dataclasses.replace(tube, voltage=0.0), rtol).voltage
    if control != "pressure":
        raise ParameterError(f"control = {control!r} is unknown; choose voltage or pressure")
    branch, start = _pressure_branch(tube, rtol)
    return threshold(branch, *start, "pressure")


def _pressure_branch(tube: Tube, rtol: float):
    start = solve_layered_state(
        dataclasses.replace(tube, inner_pressure=tube.outer_pressure), rtol=rtol
    )
    wall = prepare(
        dataclasses.replace(tube, voltage=0.0, inner_pressure=tube.outer_pressure),
        rtol,
        start._wall.nodes,
    ).wall
    return Branch(wall, "pressure", vbar=tube.voltage), (start.r_i, start.stretch)


def _response(branch, start, thr, lambda_i, points, span):
    if lambda_i is None and thr.walked == "stretch":  # r_i turns along it: sampled in lambda_z
        lz = _samples(start[1], thr.stretch, thr.kind, points, span)
        pt = clean(branch.at_stretch(lz, start[0]))  # each continued from the one before
    else:
        if lambda_i is None:
            lambda_i = _samples(start[0], thr.lambda_i, thr.kind, points, span)
        r_i = np.sort(np.atleast_1d(np.asarray(lambda_i, float)))
        pt = clean(branch.at(r_i, start[1]))
    return {
        "lambda_i": pt["r_i"],
        "lambda_o": pt["r_o"] / branch.wall.tube.outer_radius,
        "r_i": pt["r_i"],
        "r_o": pt["r_o"],
        "voltage": pt["voltage"],
        "inner_pressure": pt["P_i"],
        "stretch": pt["stretch"],
        "charge": pt["charge"],
        "axial_force": pt["axial_force"],
    }


def _samples(first: float, last: float, kind: str, points: int, span: float) -> np.ndarray:
    """``points`` values of the walked coordinate from the branch's start to its threshold's
    (``span`` times the start where that is at infinity, just before a locking one)."""
    end = last if math.isfinite(last) else first * span
    if kind == "locking":
        end = first + 0.999 * (end - first)
    return first * (end / first) ** np.linspace(0.0, 1.0, points)


def voltage_response(
    tube: Tube, lambda_i=None, *, points: int = 41, span: float = 3.0, rtol: float = 1e-12
) -> dict[str, np.ndarray]:
    """The voltage branch at the tube's pressures (tube.voltage ignored), at the inner stretches
    ``lambda_i`` (sorted), or at ``points`` from its start to the threshold's lambda_i (a limit
    point, just before a locking stretch) or to ``span`` times the start (asymptote). A
    branch walked in lambda_z (force control, r_i turning as the load rises:
    thresholds.chart) is sampled in lambda_z from its start to the threshold's, in the
    branch's order.

    Returns arrays: lambda_i (= r_i), lambda_o, r_i, r_o, voltage (Vbar; negative below the
    start for ideal dielectrics), inner_pressure, stretch, charge, axial_force.
    """
    prep = prepare(dataclasses.replace(tube, voltage=0.0), rtol)
    branch = Branch(prep.wall, "voltage", dp=tube.inner_pressure - tube.outer_pressure)
    return _response(branch, prep.loaded, prep.voltage, lambda_i, points, span)


def pressure_response(
    tube: Tube, lambda_i=None, *, points: int = 41, span: float = 3.0, rtol: float = 1e-12
) -> dict[str, np.ndarray]:
    """The pressure branch at the tube's voltage and outer pressure (tube.inner_pressure
    ignored): P_i(lambda_i) from the state with P_i = P_o, as :func:`voltage_response`."""
    branch, start = _pressure_branch(tube, rtol)
    thr = threshold(branch, *start, "pressure") if lambda_i is None else None
    return _response(branch, start, thr, lambda_i, points, span)


def _voltage_stage(tube) -> str:
    """The voltage stage's load in words, with the pressure it is applied at: near a lock a
    tube under pressure was said to have "Vbar = 0.1 ... too close to the locking stretch"
    while the pressure was what moved (probe 13a)."""
    dp = tube.inner_pressure - tube.outer_pressure
    return f"Vbar = {tube.voltage}" + (f" at P_i - P_o = {dp:.12g}" if dp else "")
