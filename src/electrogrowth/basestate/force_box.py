"""The supported box of the elastic axial stretch (model/params.SUPPORTED) for a tube under
force control, whose lambda_z is solved, not given: a prescribed lambda_z is refused outside
0.02 g_z to 50 g_z when the tube is built (model/tube_checks.check_supported); a force that
leads there is refused here, naming the force (probe 10b D2: F = 1000 on Rbar_o = 1.5 asks
for lambda_z = 254.6; its refusal blamed a voltage never given, and F = 250, lambda_z =
63.7, was accepted without a word).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import BaseStateError, ConvergenceError, ParameterError
from ..model.params import SUPPORTED, SUPPORTED_WHY

#: a stretch at the box's edge, moved inside it by this (relative): lambda_z / g_z rounded
#: back is then inside the box the tube's own check applies
_INSIDE = 1e-12


def check_solved_stretch(tube, stretch: float) -> None:
    """Refuse the axial force of ``tube`` (force control) if its solved ``stretch`` puts a
    layer's elastic axial stretch lambda_z / g_z outside the box (graded layers unchecked,
    as for a prescribed stretch)."""
    outside = _outside(tube, stretch)
    if outside is not None:
        k, elastic = outside
        lo, hi = SUPPORTED[5:7]
        raise ParameterError(
            f"axial force F = {tube.axial_force:.6g} gives layers[{k}] an elastic axial"
            f" stretch lambda_z / g_z = {elastic:.6g}, outside the supported range"
            f" {lo:g} to {hi:g}: {SUPPORTED_WHY}"
        )


def _outside(tube, stretch: float):
    """(k, lambda_z / g_z) of the first constant-growth layer whose elastic axial stretch
    at ``stretch`` is outside the box, or None."""
    lo, hi = SUPPORTED[5:7]
    for k, layer in enumerate(tube.layers, 1):
        if not layer.graded and not lo <= stretch / layer.growth[2] <= hi:
            return k, stretch / layer.growth[2]
    return None


def load_in_box(tube, thr) -> float | None:
    """Where the loading branch of a force-controlled ``tube`` (its walked Threshold) leaves
    the box: the control's value (Vbar, or P_i) at the last walked state whose elastic axial
    stretches are all inside it, where a later one (or the threshold's own) is outside;
    None where the branch stays inside up to its threshold, or lambda_z is prescribed. A
    voltage march of a charged three-layer tube pulled by a compressive force ran to its
    limit point at lambda_z = 76.4 and reported it, status ok, while every state past
    Vbar = 23895 (an elastic axial stretch above 50) is refused (check round 17, D1): its
    march ends here, at the last walked state before it (22801.7)."""
    if tube.control != "force" or not thr.grid:
        return None
    _, stretches, loads = thr.grid
    out = [j for j, lz in enumerate(stretches) if _outside(tube, lz) is not None]
    if not out and _outside(tube, thr.stretch) is None:
        return None
    last = (out[0] if out else len(loads)) - 1
    if last < 0:  # the branch's start itself: the tube is refused where it is built
        return None
    load = float(loads[last])
    return math.sqrt(max(load, 0.0)) if thr.control == "voltage" else load


def check_force_when_lost(tube, solve) -> None:
    """When no unloaded state of ``tube`` (force control) was found: refuse its axial force
    if it lies outside the forces that hold the unloaded state (V = 0, P_i = P_o) at the
    edges of the stretch box; otherwise return (the caller's own error stands). ``solve``:
    the layered solver (layered.solve_layered_state, which calls this module)."""
    edges = _stretch_edges(tube)
    if edges is None:
        return
    f_lo, f_hi = (_unloaded_force(tube, s, solve) for s in edges)
    F = tube.axial_force
    if not _rises_between(tube, edges, (f_lo, f_hi), solve):
        return  # the edges' forces bound nothing: a saturating energy's are ~0 at both
    if (f_hi is None or not F > f_hi) and (f_lo is None or not F < f_lo):
        return
    lo, hi = SUPPORTED[5:7]
    span = " to ".join("?" if f is None else f"{f:.6g}" for f in (f_lo, f_hi))
    raise ParameterError(
        f"axial force F = {F:.6g} is outside the supported range {span} of this tube (the"
        f" forces at which its elastic axial stretch lambda_z / g_z is {lo:g} and {hi:g}"
        f" when unloaded, V = 0 and P_i = P_o): {SUPPORTED_WHY}"
    )


#: unloaded forces read between the box's edges before they are taken as its range
INTERIOR = 5


def _rises_between(tube, edges, ends, solve) -> bool:
    """Do the unloaded forces rise from one edge of the stretch box to the other, through
    INTERIOR stretches between (geometric)? Only then are the edges' forces the range of
    forces that hold an unloaded state. A saturating energy (0.572 tanh((I1 - 3) / 1.144)
    + I5/2) gives ~0 at both edges: a valid F = -0.16 was refused with "the supported
    range 0 to 0" where the pressures were past their threshold (check round 27)."""
    if None in ends:
        return True  # one edge unknown: the other alone bounds F, as before
    inside = [_unloaded_force(tube, s, solve) for s in np.geomspace(*edges, INTERIOR + 2)[1:-1]]
    forces = [ends[0], *inside, ends[1]]
    return None not in forces and bool(np.all(np.diff(forces) > 0))


def _stretch_edges(tube):
    """The lambda_z at the box's edges for every constant-growth layer (None if all are
    graded or the layers' boxes do not overlap)."""
    gz = [layer.growth[2] for layer in tube.layers if not layer.graded]
    if not gz:
        return None
    lo, hi = SUPPORTED[5:7]
    s_lo, s_hi = max(lo * g for g in gz), min(hi * g for g in gz)
    if not s_lo < s_hi:
        return None
    return s_lo * (1 + _INSIDE), s_hi * (1 - _INSIDE)


def _unloaded_force(tube, stretch: float, solve):
    """The axial force (as ``tube.axial_force`` counts it) of the unloaded state at the
    prescribed ``stretch`` by ``solve``, or None where that state is not found."""
    fixed = dataclasses.replace(
        tube, stretch=stretch, axial_force=None, voltage=0.0, inner_pressure=tube.outer_pressure
    )
    try:
        state = solve(fixed)
    except (BaseStateError, ConvergenceError, ParameterError):
        return None
    return state.end_force if tube.closed_ends else state.axial_force
