"""The accuracy policy: how the one tolerance a user gives becomes every tolerance inside.

A user asks for one relative tolerance ``rtol`` (default 1e-12). Each stage needs its own
accuracy, derived here and nowhere else:

=====================  =================================  =========================================
name                   value                              why
=====================  =================================  =========================================
``fine``               rtol                               the kernel's local tolerance at the root
``coarse``             100 rtol                           a second resolution: the error estimate
                                                          (collocation: 3/4 of the fine nodes,
                                                          targets.coarser)
``march_signs``        max(rtol, 1e-8)                    one mode's march only needs signs
``table``              min(1e-9, max(1e-15, 1e-4 rtol))   Chebyshev tables a little finer than the
                                                          integration, never below round-off
``collocation_nodes``  40 (rtol >= 1e-11), 56 (>= 1e-13),  the spectral method's resolution
                       else 72                            (more where a mode needs them)
``STABLE_SIGN``        1e-10                              sign of one mode on the unloaded tube
``SCAN_SIGNS``         1e-5                               signs of every mode along a scan's march
                                                          (no sign error seen at 1e-4); tightened
                                                          for a tube whose targets it does not
                                                          resolve (march.calibrated)
``SCAN_STABLE_SIGNS``  1e-9                               signs of every mode on the unloaded tube
``runners_up``         max(rtol, 1e-9)                    the roots of a scan's march; the critical
                                                          mode and the runners-up are re-solved at
                                                          ``fine`` (bifurcation/runners.py)
``CERTIFIED``          1e4                                a critical value is certified when its
                                                          error estimate is at most
                                                          CERTIFIED rtol |value|
                                                          (:func:`certified`)
``CERTIFY_RTOL``       1e-8                               the two methods of ``certify`` agree
                                                          this well (relative)
=====================  =================================  =========================================
"""

from __future__ import annotations

import dataclasses

from ..errors import ParameterError

STABLE_SIGN = 1e-10
SCAN_SIGNS = 1e-5
SCAN_STABLE_SIGNS = 1e-9
#: a value is certified when its error estimate is at most CERTIFIED rtol |value|
#: (:func:`certified`, bifurcation/critical.py)
CERTIFIED = 1e4
#: a load below this fraction of its control's natural scale (model.controls.natural_scale)
#: is as good as none: its error is measured against that, not against itself
ZERO_LOAD = 1e-6
#: the two methods must agree this well for a certified value (bifurcation/certify.py)
CERTIFY_RTOL = 1e-8


@dataclasses.dataclass(frozen=True)
class Accuracy:
    """Every tolerance of a computation, derived from the user's ``rtol`` (table above)."""

    rtol: float = 1e-12

    @property
    def fine(self) -> float:
        return self.rtol

    @property
    def coarse(self) -> float:
        return 100.0 * self.rtol

    @property
    def march_signs(self) -> float:
        return max(self.rtol, 1e-8)

    @property
    def table(self) -> float:
        return min(1e-9, max(1e-15, 1e-4 * self.rtol))

    @property
    def collocation_nodes(self) -> int:
        # rtol / 100, the critical value's refinement, must refine collocation too
        return 40 if self.rtol >= 1e-11 else 56 if self.rtol >= 1e-13 else 72

    @property
    def runners_up(self) -> float:
        return max(self.rtol, SCAN_STABLE_SIGNS)


def certified(estimate: float, value: float, rtol: float, natural: float) -> bool:
    """Is a critical value known to CERTIFIED ``rtol`` of itself by its error ``estimate``?

    Relative to the value, which is what ``rtol`` asks: the rule was relative to max(1,
    |value|), so a film's critical pressure of 2.9e-6 was "certified" at rtol 1e-12 with an
    estimate of 1.2e-7 of itself. A value within ZERO_LOAD of its control's ``natural``
    scale (a force crossing zero along a curve) is measured against that floor instead:
    no solve gives a vanishing value to a fraction of itself."""
    return estimate <= CERTIFIED * rtol * max(abs(value), ZERO_LOAD * natural)


RTOL_RANGE = (1e-14, 1e-4)


def check_rtol(rtol: float, name: str = "rtol") -> float:
    """Return ``rtol`` if it lies in RTOL_RANGE, else raise ParameterError naming it."""
    if not RTOL_RANGE[0] <= rtol <= RTOL_RANGE[1]:
        raise ParameterError(
            f"{name} = {rtol!r} is out of range; valid range: "
            f"{RTOL_RANGE[0]:g} to {RTOL_RANGE[1]:g}"
        )
    return rtol
