"""Where a tube turns unstable at its control's start as a design variable x moves: the
root in x of one mode's target on the state at the control's start.

A mode sequence ends its valid range where the scans start to fail "already unstable in
mode (m, n) at the start" (bifurcation/curve_switches.py, ``edge``). The bisection on "the
scan succeeds" reads the scans' start check, whose signs come from loose targets (a fine
one only where the loose sign is doubtful): next to the root it ends where the loose
target's error ends, not at the root. For an ungrown tube's (2, 1) at the end of its valid
range in Vbar, 1.66e-11 above the mode's own critical voltage, with the bracket, 6.4e-14,
as the estimate (check round 20, D2).

Here the end is the root of s f(x), f the mode's kernel target at FINE on the state at
the control's start of the tube at x, s its stable sign (the sign on that tube unloaded):
Brent's method on the bisection's bracket, widened (doubling, at most WIDEN relative)
where the loose reading put the root outside it. Its error: the distance to the root at
COARSE (the second resolution, as for a critical value), at least Brent's tolerance.
"""

from __future__ import annotations

import math

from ..basestate.tube import solve_base_state
from ..continuation.events import SWITCH, brent
from ..errors import ElectrogrowthError
from ..incremental.modes import row_family, with_family
from ..incremental.targets import ImpedanceTarget
from .critical import stable_sign
from .march import control_path

#: the target's tolerances: the root and its second resolution
FINE, COARSE = 1e-13, 1e-11
#: the bracket is widened up to this, relative to max(1, |x|): the loose start check's
#: signs err by ~1e-11 near the root (check round 20, D2)
WIDEN = 1e-7


def start_root(params, along, solve_for, side, row, good: float, bad: float):
    """(x, x_error): where mode ``row`` (m, n, family code), stable at the control's start
    at ``along`` = good and unstable at bad, turns unstable there; None where its fine
    target shows no such sign change within WIDEN of [good, bad] or does not solve."""
    m, n, _ = row
    family = row_family(row)
    mode = with_family(m, n, family)

    def signed(x: float, rtol: float) -> float:
        tube = params.at(along, x)
        start = control_path(tube, solve_for, side)[0]
        state = solve_base_state(tube.at(solve_for, start))
        sign = stable_sign(m, n, tube, family=family.value)
        return sign * float(ImpedanceTarget(rtol)(state, mode)[0])

    try:
        bracket = _bracket(lambda x: signed(x, FINE), good, bad)
        if bracket is None:
            return None
        x = brent(lambda y: signed(y, FINE), *bracket, SWITCH)
        try:
            second = brent(lambda y: signed(y, COARSE), *bracket, SWITCH)
        except ElectrogrowthError:  # no sign change at COARSE: the bracket bounds it
            second = bracket[0] if abs(bracket[0] - x) > abs(bracket[1] - x) else bracket[1]
    except ElectrogrowthError:
        return None
    return x, max(abs(second - x), SWITCH.at(x))


def _bracket(f, good: float, bad: float):
    """[a, b] with f(a) > 0 >= f(b) (a on good's side), from [good, bad] widened outwards
    by doubling the step, or None."""
    sense = math.copysign(1.0, bad - good)
    width = abs(bad - good) or SWITCH.at(good)
    limit = WIDEN * max(1.0, abs(good))
    a, b = good, bad
    step = width
    while f(a) <= 0:
        a = good - sense * step
        if step > limit:
            return None
        step *= 2.0
    step = width
    while f(b) > 0:
        b = bad + sense * step
        if step > limit:
            return None
        step *= 2.0
    return a, b
