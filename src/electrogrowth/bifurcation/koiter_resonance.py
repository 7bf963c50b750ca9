"""Where the amplitude equation of a tube's mode breaks down: a second harmonic of the mode
bifurcating next to its onset (docs/derivation-koiter.md, "Resonance").

The second-order correction psi of a mode (m, n) lives on the harmonics of phi's products:
(2m, 2n), (2m, 0) and (0, 2n) (and the axisymmetric (0, 0), the base state's own
stiffness). psi solves A(c_c) psi = -C[phi, phi, .] / 2 on those harmonics, so where one of
them is itself critical at c_c, A is singular there and c_2 has a pole: c_2 ~ 1 / (c_c - c_h),
c_h the control at which the harmonic bifurcates. The expansion c = c_c + c_2 eps^2 then
holds only while |c - c_c| << |c_h - c_c|: two modes interact (a uniform tube's (1, 1) of
L = 8 in compression: c_2 = 12.5 times its slender-tube value, (2, 2) 0.075 % away).

The harmonics' impedance targets are read on a grid across a window of WINDOW of |c_c|
(of the control's scale where c_c is next to zero) about c_c; a sign change is a
harmonic's root, located by Brent's method.

The mode itself can end the expansion too: where its neutral curve folds, the mode is
unstable only in a window past onset and restabilises at c_r. Its eigenvalue
sigma(c) ~ A' (c - c_c) + sigma'' (c - c_c)^2 / 2 then has c_r - c_c = -2 A' / sigma'', and c_2,
which divides by A', grows like 1 / (c_r - c_c): a pole of the same kind (a Gent tube J_m
1.32, (0, 1) in compression: c_2 = -1.59 against -0.27 neo-Hookean, c_r 5.8 % past onset;
probe round 12a). The mode's own target is read on the same grid continued to OWN_WINDOW
past onset; its first sign change strictly past onset is c_r.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..basestate.tube import solve_base_state
from ..brent import brentq
from ..errors import BaseStateError, ConvergenceError, ParameterError
from ..incremental.targets import ImpedanceTarget
from ..model.layers import Tube
from .march import control_path

#: the window about the onset searched for a harmonic's root, relative to |c_c| (or to the
#: control's scale where c_c is within NEAR_ZERO of it of zero: a pressure or force next
#: to zero), and its grid's points. Not the scale alone: a film's collapse pressure is
#: 1/12 of its scale, and 5 % of the scale flagged harmonics 70 % away from onset
#: (probe round 10a)
WINDOW = 0.05
NEAR_ZERO = 1e-3
POINTS = 21
#: how far past onset (relative, as WINDOW) the mode's own restabilisation is looked for,
#: on the same grid spacing: the expansion's range is a fact worth a note this far out
OWN_WINDOW = 0.1
#: the harmonics' targets: a root needs a few digits only (a distance, not a value)
TARGET = ImpedanceTarget(rtol=1e-10)


@dataclasses.dataclass(frozen=True)
class Resonance:
    """A second harmonic (m, n) of the mode that bifurcates at ``value`` of the control,
    ``gap`` = |value - c_c| / size from the onset c_c (size: :func:`window_size`);
    ``before``: the march from the control's start reaches it first (the mode is then not
    the tube's first)."""

    m: int
    n: int
    value: float
    gap: float
    before: bool
    #: the mode itself, restabilising at ``value`` past onset (not a harmonic)
    own: bool = False

    def words(self, control: str) -> str:
        """The note a user reads: which harmonic, where, and what it means."""
        if self.own:
            return (
                f"the mode restabilises at {control} = {self.value:.6g},"
                f" {100 * self.gap:.2g} % past onset (its neutral curve folds): the one-mode"
                " expansion holds only while the control stays much closer to onset than that"
            )
        first = ", before the mode's onset" if self.before else ""
        # the root to 6 digits: Brent's at 1e-9 of the size, a note's precision
        return (
            f"its second harmonic ({self.m}, {self.n}) bifurcates at {control} ="
            f" {self.value:.6g}{first}, {100 * self.gap:.2g} % from onset: the one-mode"
            " expansion holds only while the control stays much closer to onset than that"
            " (mode interaction)"
        )


def harmonics(m: int, n: int) -> list[tuple[int, int]]:
    """The modes of psi other than (0, 0): (2m, 0) for a prismatic mode, (0, 2n) for an
    axisymmetric one, all three for a wrinkle."""
    if n == 0:
        return [(2 * m, 0)]
    if m == 0:
        return [(0, 2 * n)]
    return [(2 * m, 2 * n), (2 * m, 0), (0, 2 * n)]


def nearest_resonance(
    tube: Tube, mode: tuple[int, int], control: str, side: str | None, onset: float
) -> Resonance | None:
    """The root nearest ``onset`` of a harmonic within WINDOW, or of the mode itself past
    onset within OWN_WINDOW (its restabilisation), or None."""
    start, end, scale = control_path(tube, control, side)
    size = window_size(onset, scale)
    sense = 1.0 if end >= start else -1.0
    lo, hi = sorted((start, end))
    # WINDOW's grid of POINTS about onset, continued past onset to OWN_WINDOW
    step = 2.0 * WINDOW / (POINTS - 1)
    ts = step * np.arange(-round(WINDOW / step), round(OWN_WINDOW / step) + 1)
    xs = np.unique(np.clip(onset + sense * size * ts, lo, hi))
    own = (int(mode[0]), int(mode[1]))
    found = [*harmonics(*mode), own]
    rows = np.array(found, dtype=float)
    values = np.array([_targets(tube, control, x, rows) for x in xs])  # (points, modes)
    best = None
    for j, (hm, hn) in enumerate(found):
        mine = j == len(found) - 1
        for a, b, fa, fb in zip(xs, xs[1:], values[:, j], values[1:, j]):
            if not (np.isfinite(fa) and np.isfinite(fb)) or fa * fb > 0:
                continue
            if mine and min(sense * (a - onset), sense * (b - onset)) <= 0:
                continue  # the onset itself, or before it
            if not mine and min(abs(a - onset), abs(b - onset)) > WINDOW * size:
                continue  # a harmonic's root past WINDOW: the grid's continuation is the mode's
            root = _root(tube, control, rows[j : j + 1], a, b, size)
            if root is None:
                continue
            gap = abs(root - onset) / size
            if gap > (OWN_WINDOW if mine else WINDOW) or (best is not None and gap >= best.gap):
                continue
            best = Resonance(hm, hn, root, gap, sense * (root - onset) < 0, own=mine)
    return best


def window_size(onset: float, scale: float) -> float:
    """What the window and the gap are relative to: |c_c|, or the control's scale where
    c_c is next to zero (within NEAR_ZERO of the scale)."""
    return abs(onset) if abs(onset) > NEAR_ZERO * scale else scale


def _targets(tube: Tube, control: str, x: float, rows: np.ndarray) -> np.ndarray:
    """The harmonics' targets at control x; NaN where the state or the kernel fails."""
    try:
        return TARGET(solve_base_state(tube.at(control, x)), rows)
    except (BaseStateError, ConvergenceError, ParameterError):
        return np.full(rows.shape[0], math.nan)


def _root(
    tube: Tube, control: str, row: np.ndarray, a: float, b: float, size: float
) -> float | None:
    """The harmonic's root in [a, b] (its target changes sign there), or None where the
    target is not computable inside (a note is not worth an error)."""
    try:
        return brentq(lambda x: float(_targets(tube, control, x, row)[0]), a, b, xtol=1e-9 * size)
    except (ValueError, RuntimeError):  # a NaN met inside, or no convergence
        return None
