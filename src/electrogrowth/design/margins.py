"""The margin of a target mode at a design x: its relative gap to the next mode and to the
crease (design/prescribe.py's module docstring defines M), from critical values of single
modes cached per design.
"""

from __future__ import annotations

import math

from ..bifurcation.critical import critical_value
from ..errors import ElectrogrowthError
from ..outcomes import Kind
from . import onset
from .onset import gap_to_crease


class Margins:
    """Critical values of single modes at designs x, cached, and the margin M(x)."""

    def __init__(self, tube, solve_for, key, side) -> None:
        self.tube, self.solve_for, self.key, self.side = tube, solve_for, key, side
        self.sense = -1.0 if side == "compression" else 1.0
        self.cache: dict = {}
        self.creases: dict = {}

    def crease(self, x: float) -> float:
        """Where a face creases at x (sense * inf: none; design/onset.py)."""
        if x not in self.creases:
            at = self.tube.at(self.key, x)
            self.creases[x] = onset.crease_value(at, self.solve_for, self.side, self.sense)
        return self.creases[x]

    def value(self, mode, x: float) -> float:
        """The first critical value of ``mode`` at x; +-inf (never) if the threshold or no
        bifurcation comes first."""
        if (mode, x) not in self.cache:
            try:
                at = self.tube.at(self.key, x)
                c = critical_value(at, mode[0], mode[1], self.solve_for, side=self.side)
                v = c.value if c.kind == Kind.BIFURCATION else self.sense * math.inf
            except ElectrogrowthError:
                v = self.sense * math.inf
            self.cache[mode, x] = v
        return self.cache[mode, x]

    def margin(self, mode, x: float, v_next: float) -> float:
        v = self.value(mode, x)
        return self.sense * (v_next - v) / abs(v) if math.isfinite(v) else -math.inf

    def best_margin(self, mode, others, x: float) -> tuple[float, tuple | None]:
        """(M, the next mode) at x over the competitors ``others`` and the crease."""
        by_crease = gap_to_crease(self.value(mode, x), self.crease(x), self.sense)
        if not others:
            return by_crease, None
        nxt = min(others, key=lambda o: self.sense * self.value(o, x))
        return min(self.margin(mode, x, self.value(nxt, x)), by_crease), nxt
