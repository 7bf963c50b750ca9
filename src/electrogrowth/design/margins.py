"""The margin of a target mode at a design x: its relative gap to the next mode and to the
crease (design/prescribe.py's module docstring defines M), from critical values of single
modes cached per design; and, next to a located end of the valid range (a switch to "no
design": the tube is already unstable at the control's start, or has no state, beyond it),
the gap to that end.

Approaching such an end the target's critical value v_T falls to the control's start v_0,
so the relative gap M = s (v_N - v_T) / |v_T| grows without bound for a control that
starts at 0 (voltage, pressure, force): the widest margin would sit on a tube that is
already wrinkled. There the room below the target's onset counts as a competitor:

    M_0(x) = s (v_T - v_0) / (M |v_T|)  =  (v_T - v_0) / (v_N - v_T),

the room from the start to the target relative to the room from the target to the next
competitor (M the gap to the next mode or the crease, whichever is nearer). M_0 = 0 at the
end, as M = 0 at a switch; min(M, M_0) is largest where both rooms balance (for v_0 = 0:
v_N = 2 v_T, M = 1). docs/design.md.
"""

from __future__ import annotations

import math

from ..bifurcation.critical import critical_value
from ..bifurcation.march import control_path
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
        self.starts: dict = {}

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

    def start(self, x: float) -> float:
        """v_0: where the control's march starts on the tube at x (0 for the voltage, 1
        for the growth, the free stretch, the outer pressure, ...)."""
        if x not in self.starts:
            try:
                at = self.tube.at(self.key, x)
                self.starts[x] = control_path(at, self.solve_for, self.side)[0]
            except ElectrogrowthError:  # no start: the end's gap is not counted
                self.starts[x] = math.nan
        return self.starts[x]

    def to_no_design(self, mode, x: float, above: float) -> float:
        """M_0 (module docstring): the room below the target's onset over the room above
        it, ``above`` the relative gap M to the nearer competitor; inf where M is not a
        positive finite gap (the target not first, or nothing after it)."""
        v = self.value(mode, x)
        if not (0 < above < math.inf and math.isfinite(v) and math.isfinite(self.start(x))):
            return math.inf
        return self.sense * (v - self.start(x)) / abs(v) / above

    def best_margin(
        self, mode, others, x: float, edge: bool = False
    ) -> tuple[float, tuple | None]:
        """(M, the next mode) at x over the competitors ``others`` and the crease, and with
        ``edge`` (a region next to a located end of the valid range) that end's gap."""
        m = by_crease = gap_to_crease(self.value(mode, x), self.crease(x), self.sense)
        nxt = None
        if others:
            nxt = min(others, key=lambda o: self.sense * self.value(o, x))
            m = min(self.margin(mode, x, self.value(nxt, x)), by_crease)
        if edge:
            m = min(m, self.to_no_design(mode, x, m))
        return m, nxt
