"""A'(c) = dA/dc along a control, by central differences of base states
(docs/derivation-koiter.md, "The control derivative"): the step is relative to the scale
at which the control moves the state, and kept inside the range where the state exists.

The scale is the control's own (model/controls.py KINDS, the march's): 1 for a growth,
the free stretch for the stretch, the voltage's threshold, the wall's sum mu_k ln(R_k /
R_{k-1}) for a pressure and pi sum mu_k (R_k^2 - R_{k-1}^2) for a force; a critical value
beyond it sets it instead. Scaling every modulus by s scales the pressure's, the force's
and (by sqrt(s)) the voltage's step with the control, so the coefficient scales exactly;
an absolute step 2e-3 was past a soft tube's pressure threshold (mu = 0.01: P_cr = -6e-5,
the threshold 1.9e-3).
"""

from __future__ import annotations

import dataclasses
import math

from ..basestate import tube as door
from ..errors import BaseStateError, ConvergenceError
from ..model.controls import KINDS
from ..model.layers import Tube

#: the step over the scale: the Richardson value's error is O(STEP^4) ~ 1e-11
STEP = 2e-3
#: the step over the distance to a threshold: truncation (h / d)^4 ~ 1e-10 of A', and
#: rounding ~1e-9 at most (a voltage 1 % from its asymptote: 2e-3 d gave 5e-9)
NEAR = 1e-2


@dataclasses.dataclass(frozen=True)
class Reach:
    """Where a control moves the base state: ``scale``, the change of the control that
    changes the state by O(1); the state exists for ``lo`` < c < ``hi``."""

    scale: float
    lo: float = -math.inf
    hi: float = math.inf

    def step(self, c: float) -> float:
        """The largest step h: STEP times the scale (or |c| beyond it), or NEAR times the
        distance to an end of the range when that is shorter: near a threshold the state
        changes on that distance (a voltage's asymptote 0.95 % above Vbar_cr: a step of
        2e-3 Vbar_cr left A' wrong by 2e-5)."""
        return min(STEP * max(abs(c), self.scale), NEAR * (c - self.lo), NEAR * (self.hi - c))


def reach(tube: Tube, control: str) -> Reach:
    """The Reach of ``control`` on ``tube``: the scale of its march, the voltage's range
    0 <= Vbar < threshold, the inner pressure's below the inflation threshold; a growth,
    the stretch and a force move the state on (0, inf) or the whole line."""
    kind = tube.check_control(control).kind
    if kind in ("growth", "stretch"):
        return Reach(KINDS[kind].path(tube, True, door)[2], lo=0.0)
    if kind == "force":
        return Reach(KINDS[kind].path(tube, True, door)[2])
    hi = _threshold(tube, kind)
    if kind == "voltage":  # no threshold (a stiffening energy): the critical value's scale
        return Reach(hi if math.isfinite(hi) else 0.0, lo=0.0, hi=hi)
    return Reach(KINDS[kind].path(tube, False, door)[2], hi=hi)


def _threshold(tube: Tube, kind: str) -> float:
    """Where the state of the voltage or the inner pressure is lost (inf if never)."""
    try:
        thr = door.threshold(tube, kind).value
    except (BaseStateError, ConvergenceError):  # a threshold not found is no bound
        return math.inf
    return thr if math.isfinite(thr) else math.inf


def derivative(stiffness, c: float, where: Reach):
    """dA/dc at c: central differences at h and h / 2, Richardson-extrapolated (error
    O(h^4)); the control enters both the state and the growth."""
    d = _differences(stiffness, c, where.step(c), 2)
    return (4 * d[1] - d[0]) / 3


def derivative_and_change(stiffness, c: float, where: Reach):
    """(dA/dc as :func:`derivative` with the steps halved, its change from the unhalved):
    the change bounds the O(h^4) truncation of the finer (1/16 of the coarser's), which
    the discretisation's estimate does not see."""
    d = _differences(stiffness, c, where.step(c), 3)
    coarse, fine = ((4 * d[k + 1] - d[k]) / 3 for k in (0, 1))
    return fine, fine - coarse


#: a step off the halving ladder (h, h / 2, h / 4): its rounding is another sample
SHIFT = 0.7


def derivative_and_noise(stiffness, c: float, where: Reach):
    """(dA/dc as :func:`derivative_and_change`, its change from the unhalved, its change
    from the same extrapolation at steps ``SHIFT`` times as long): A(c) carries the base
    state's rounding (rtol 1e-12), which the differences divide by a step of ~1e-3 of the
    scale; the halving's change is one sample of that noise and can be small by luck (an
    outer film's fold under pressure: 2e-9 at 40 nodes, while steps 0.25 .. 4 h scattered
    A'[phi, phi] by 2e-8), so a second step, off the ladder, samples it again."""
    fine, change = derivative_and_change(stiffness, c, where)
    h = SHIFT * where.step(c)
    d = _differences(stiffness, c, h, 2)
    return fine, change, fine - (4 * d[1] - d[0]) / 3


def _differences(stiffness, c: float, h: float, count: int) -> list:
    """Central differences at h, h / 2, ... (``count`` of them)."""
    steps = [h / 2**k for k in range(count)]
    return [(stiffness(c + s) - stiffness(c - s)) / (2 * s) for s in steps]
