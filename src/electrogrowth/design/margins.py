"""The margin of a target mode at a design x: its relative gap to the next mode, to the
crease and to the exact short-wave limit (design/prescribe.py's module docstring defines M;
design/short_waves.py), from critical values of single modes cached per design; and, next
to a located end of the valid range (a switch to "no design": the tube is already unstable
at the control's start, or has no state, beyond it), the gap to that end.

Approaching such an end the target's critical value v_T falls to the control's start v_0,
so the relative gap M = s (v_N - v_T) / |v_T| grows without bound for a control that
starts at 0 (voltage, pressure, force): the widest margin would sit on a tube that is
already wrinkled. There the room below the target's onset counts as a competitor:

    M_0(x) = s (v_T - v_0) / (M |v_T|)  =  (v_T - v_0) / (v_N - v_T),

the room from the start to the target relative to the room from the target to the next
competitor (M the gap to the next mode, the crease or the short-wave limit, whichever is
nearest). M_0 = 0 at the end, as M = 0 at a switch; min(M, M_0) is largest where both
rooms balance (for v_0 = 0: v_N = 2 v_T, M = 1).

That rule assumes v_T falls to v_0 at the end. At a cliff it does not: the target's onset
stays away from the start up to the end and beyond it the tube is unstable at v_0 at once
(an ungrown tube of Rbar_o = 1.4 under a voltage: g_cr of (0, 1) is 1.104 up to the
critical voltage of the ungrown tube, 0.7234620, then 1). M_0 stays ~5 there and never
limited the design, which sat 2e-8 (relative) from the cliff (probe 8b, D4). So next to a
cliff the room below is measured by the design variable itself:

    M_end(x) = |x - x_e| / |x_e|   (|x_e| = 0: the width of [lo, hi]),

the fraction by which the design variable can move towards the end x_e before the tube is
unstable with no control (for a load varied, its own margin to its critical value at the
control's start); the margin is then min(M, M_0, M_end). An end is a cliff where M_0 at the
end itself is not ~0: a smooth end, located to 1e-13 (SWITCH), leaves M_0 = 3e-5 there (the
grown tube of tests/design/test_boundary_after_failed_point.py: v_T = 6e-6), a cliff a
finite room (5.07 in probe 8b's case).

The other end of a valid range, where no mode bifurcates before the end of the control's
range v_e beyond it (its cap, e.g. g = 6): there v_T rises to v_e, and a competitor that
the march does not meet before v_e has no value (+-inf), so M was infinite next to it
(probe 14d: the (2, 0) window of a pressurised tube, M = inf at P_i = -0.0005, where (3,
0) lies past g = 6). All that is known is that the competitors come after v_e, so the room
up to it is one more gap:

    M_e(x) = s (v_e - v_T) / |v_T|,

a lower bound of the true M, which vanishes at that end as M does at a switch; where a
competitor is met before v_e its own gap is the smaller. docs/design.md.
"""

from __future__ import annotations

import math

from ..bifurcation.critical import critical_value
from ..bifurcation.march import control_path
from ..bifurcation.options import mode_caps
from ..errors import ElectrogrowthError
from ..outcomes import Kind
from . import onset
from .onset import gap_to_crease
from .short_waves import SurfaceRival

#: M_0 at a located end above which the end is a cliff (module docstring): a smooth end
#: leaves 3e-5, a cliff such as probe 8b's D4 leaves 5
CLIFF = 1e-2


class Margins:
    """Critical values of single modes at designs x, cached, and the margin M(x)
    (``width``: that of the design range [lo, hi], the scale of M_end at an end x_e = 0;
    ``surface``: count the short-wave limit, as the scans do with ScanOptions.surface)."""

    def __init__(self, tube, solve_for, key, side, width: float = 1.0, surface=True) -> None:
        self.tube, self.solve_for, self.key, self.side = tube, solve_for, key, side
        self.width = width
        self.cliffs: dict = {}
        self.sense = -1.0 if side == "compression" else 1.0
        self.cache: dict = {}
        self.starts: dict = {}
        self.ends: dict = {}
        at = lambda x: tube.at(key, x)  # noqa: E731
        self.surfaces = SurfaceRival(at, solve_for, side, self.sense, surface)
        self.creases = onset.CreaseRival(at, solve_for, side, self.sense)

    def surface(self, x: float, until: float | None = None) -> float:
        """The short-wave limit at x where it comes before ``until`` (sense * inf: not;
        design/short_waves.py)."""
        return self.surfaces.value(x, until)

    def crease(self, x: float, until: float | None = None) -> float:
        """Where a face creases at x, looked for before ``until`` (design/onset.py)."""
        return self.creases.value(x, until)

    def caps(self, x: float) -> tuple[int, int]:
        """The largest m and n the scans of the tube at x search (options.mode_caps)."""
        return mode_caps(self.tube.at(self.key, x))

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

    def range_end(self, x: float) -> float:
        """v_e: where the control's march ends on the tube at x (its cap, e.g. g = 6; or
        the threshold where the path ends there)."""
        if x not in self.ends:
            try:
                at = self.tube.at(self.key, x)
                self.ends[x] = control_path(at, self.solve_for, self.side)[1]
            except ElectrogrowthError:  # no path: no end to count
                self.ends[x] = self.sense * math.inf
        return self.ends[x]

    def to_range_end(self, mode, x: float) -> float:
        """M_e (module docstring): the room from the target's onset to the end of the
        control's range (-inf where the target has no onset, as the other gaps)."""
        return gap_to_crease(self.value(mode, x), self.range_end(x), self.sense)

    def room_below(self, mode, x: float, above: float) -> float:
        """M_0 (module docstring): the room below the target's onset over the room above
        it, ``above`` the relative gap M to the nearer competitor; inf where M is not a
        positive finite gap (the target not first, or nothing after it)."""
        v = self.value(mode, x)
        if not (0 < above < math.inf and math.isfinite(v) and math.isfinite(self.start(x))):
            return math.inf
        return self.sense * (v - self.start(x)) / abs(v) / above

    def to_no_design(self, mode, others, x: float, above: float, ends=()) -> float:
        """The gap to the located ends ``ends`` of the valid range: M_0, and M_end for an
        end that is a cliff (module docstring)."""
        gap = self.room_below(mode, x, above)
        for end in ends:
            if self.cliff(mode, others, end):
                gap = min(gap, abs(x - end) / (abs(end) or self.width))
        return gap

    def cliff(self, mode, others, end: float) -> bool:
        """Does the target's onset keep room below at the end itself (M_0 >= CLIFF there),
        so that beyond it the tube is unstable at the control's start at once? Not where M_0
        is not defined there (inf: no competitor above, or the target not first)."""
        if (mode, others, end) not in self.cliffs:
            above = self.best_margin(mode, others, end)[0]
            self.cliffs[mode, others, end] = CLIFF <= self.room_below(mode, end, above) < math.inf
        return self.cliffs[mode, others, end]

    def best_margin(self, mode, others, x: float, ends=()) -> tuple[float, tuple | None]:
        """(M, the next mode) at x over the competitors ``others``, the crease and the
        short-wave limit, and with ``ends`` (the located ends of the valid range that the
        region's span reaches) the gap to them."""
        v = self.value(mode, x)
        m, nxt = (math.inf if math.isfinite(v) else -math.inf), None
        if others:
            nxt = min(others, key=lambda o: self.sense * self.value(o, x))
            m = self.margin(mode, x, self.value(nxt, x))
        if math.isfinite(v):  # the crease and the limit only where they can come first
            for rival in (self.crease, self.surface):
                until = v + self.sense * m * abs(v) if math.isfinite(m) else None
                m = min(m, gap_to_crease(v, rival(x, until), self.sense))
        m = min(m, self.to_range_end(mode, x))
        if ends:
            m = min(m, self.to_no_design(mode, others, x, m, ends))
        return m, nxt
