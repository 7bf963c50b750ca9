"""The probe that reads which way a voltage branch leaves its uncharged start (docs/
derivation-base-state.md, "The branch that runs inward"; derivation-layered.md).

At the start the wall's residual f = T - (P_i - P_o) of (*) is 0 at q = c^2 = 0; a step h
(relative) along the walked coordinate reads f at q = 0 there, and its sign against that of
dT/dq says on which side a small charge balances the traction. The reading is resolved only
where |f| stands well above the rounding of the magnitudes that cancel in it: the stress
integral's scale int (|tau_1| + |tau_2|) dr / r and |P_i - P_o|, each carrying ~eps of its
size. Next to an inflation asymptote the traction is flat: a neo-Hookean wall [1, 2] at
P_i = ln 2 - d has dT/d ln r_i = 4 d, so at d = 1.6e-10 a step of 1e-6 reads f ~ 6e-16,
two eps of the cancelling 1.39, whose sign is noise (check round 32); so is a uniform wall
whose in-plane shear modulus nearly vanishes (lambda_z -> sqrt 6 for `(1.2 (I1-3) - 0.2
(I2-3))/2 + I5/2`, tests/bifurcation/test_torsion_onset.py). The step therefore grows
tenfold from FIRST_STEP until the reading is resolved, up to REACH, still well inside the
walk's first 8 % step; where it is not resolved even there, StartUnresolved, which the
thresholds turn into kind "unresolved" (value 0: no charged state followed, as "closing";
a charged state asked for raises it, the uncharged one solves).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ..errors import StartUnresolved

#: the first relative step of the probe: where its reading is resolved, the probe is there
FIRST_STEP = 1e-6
#: the farthest the probe steps from the start (relative): an eighth of the walk's first step
#: (1.08), so the reading is still of the branch's first cell
REACH = 1e-2
#: a reading is resolved where |f| >= RESOLVED eps (the magnitudes that cancel in it): the
#: rounding of f measured next to the asymptote is at most 0.74 eps of them (2001 points
#: about the start at d = 1e-6 and 1.6e-10), so its sign and its first three digits hold;
#: and the probed state's own floors lie below it (charge_and_voltage's 1e-13 of the scale,
#: 450 eps; Branch._uncharged's 1e-15), so the state read there is not the start itself
RESOLVED = 1e3

_EPS = float(np.finfo(float).eps)

#: why an "unresolved" threshold is 0 (as CLOSING names a "closing" one)
UNRESOLVED = (
    "which way this tube's voltage branch leaves its uncharged state is not resolved: the"
    f" wall's traction is flat to rounding within {REACH:g} of it (threshold 0, kind"
    " unresolved): no charged state is followed"
)


def rounding(scale, dp) -> np.ndarray:
    """The rounding level of f = T - dp: eps times the magnitudes that cancel in it."""
    return _EPS * (np.abs(scale) + abs(dp))


def probe_step(read: Callable[[float], tuple[float, float]], where: str) -> float:
    """The first step h = FIRST_STEP 10^k (k = 0, 1, ...; h <= REACH) whose reading
    read(h) = (f, rounding level) is resolved: |f| >= RESOLVED times its rounding level, or
    f not finite (the energy ends there: a lock, read by the caller). ``where`` names the
    start in the error.

    Raises
    ------
    StartUnresolved
        If no step within REACH resolves it.
    """
    h, f, level = FIRST_STEP, math.nan, math.nan
    while h <= REACH * (1.0 + 1e-9):
        f, level = read(h)
        if not math.isfinite(f) or abs(f) >= RESOLVED * level:
            return h
        h *= 10.0
    raise StartUnresolved(
        f"which way the voltage branch leaves {where} is not resolved: {REACH:g} (relative)"
        f" from it the uncharged traction residual T - (P_i - P_o) = {f:.3g} is within"
        f" {RESOLVED:g} times its rounding ({level:.3g}) of 0: the wall's traction is flat"
        " there to rounding"
    )
