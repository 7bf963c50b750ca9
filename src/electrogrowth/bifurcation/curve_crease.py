"""The crease along a critical curve: at every row, where a face creases along the same
control (crease.py's criterion) and whether that comes before the row's critical value.

The crease onset depends on the tube at the row's abscissa only, not on the mode, so it is
computed once per distinct x (a switch's two rows share it). It is the march of
:func:`~.crease.crease_onset`: one base state a step, closed-form margins on it; for the
paper's tube about 0.01 s a point against the ~1 s of its mode scan (docs/derivation-crease.md
section 4). A crease "comes first" at a row as in the verdict (verdict.py): it is reached
strictly before the row's critical value along the march (a tie goes to the linear result),
and it is a mechanical crease: a crease by the field criterion is an early bound and is
never ranked first (:func:`~.verdict.advisory`).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import ElectrogrowthError
from .crease import crease_onset
from .verdict import advisory, crease_rival


@dataclasses.dataclass(frozen=True)
class CreaseAlong:
    """Per row of a curve: ``value`` where a face creases (NaN: not reached, or the
    criterion could not be evaluated: ``note``), its ``face``, ``trigger`` ("prismatic",
    "axial", "field"; "" none) and ``error`` (the criterion's accuracy in the control), and
    ``first``: the crease comes before the row's critical value."""

    value: np.ndarray
    face: tuple[str, ...]
    trigger: tuple[str, ...]
    error: np.ndarray
    first: np.ndarray
    note: tuple[str, ...] = ()

    @classmethod
    def empty(cls, rows: int) -> CreaseAlong:
        """Not computed (an interrupted curve's grid points)."""
        nan = np.full(rows, math.nan)
        return cls(nan, ("",) * rows, ("",) * rows, nan.copy(), np.zeros(rows, bool))

    def columns(self) -> dict[str, list]:
        """The table's columns: crease_value, crease_face, crease_trigger, crease_error,
        crease_first (NaN where there is none)."""
        return {
            "crease_value": [float(v) for v in self.value],
            "crease_face": list(self.face),
            "crease_trigger": list(self.trigger),
            "crease_error": [float(v) for v in self.error],
            "crease_first": [bool(f) for f in self.first],
        }


def crease_along(tube, solve_for: str, along: str, side, x, value) -> CreaseAlong:
    """The crease at every row (abscissae ``x``, critical values ``value``) of the curve of
    ``solve_for`` along ``along`` of ``tube`` on ``side``."""
    sense = -1.0 if side == "compression" else 1.0
    onsets = {xi: _onset(tube.at(along, xi), solve_for, side) for xi in map(float, x)}
    rivals = [onsets[float(xi)][0] for xi in x]

    def field(get, empty) -> list:
        return [empty if r is None else get(r) for r in rivals]

    first = [
        r is not None
        and not advisory(r)
        and math.isfinite(v)
        and sense * r.value < sense * v  # strictly before: a tie goes to the linear result
        for r, v in zip(rivals, value)
    ]
    return CreaseAlong(
        np.array(field(lambda r: r.value, math.nan), float),
        tuple(field(lambda r: r.face or "", "")),
        tuple(field(lambda r: r.trigger or "", "")),
        np.array(field(lambda r: r.error_estimate, math.nan), float),
        np.array(first, bool),
        tuple(onsets[float(xi)][1] for xi in x),
    )


def _onset(tube, solve_for: str, side):
    """(the crease as a Rival, None where none is reached; why it is missing where the
    criterion could not be evaluated, else "")."""
    try:
        onset = crease_onset(tube, solve_for, side=side)
    except ElectrogrowthError as exc:  # the curve stands; say why there is no crease
        return None, f"crease criterion not evaluated: {exc}"
    return crease_rival(onset), ""
