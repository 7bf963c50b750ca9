"""The ranges of a tube's numbers and the names of its controls (paper Sec. 3.1).

Non-dimensional units: mu = eps = R_i = 1. The tube itself is :class:`model.layers.Tube`;
the paper's tube is ``Tube.uniform(...)``.
"""

from __future__ import annotations

import math

from ..errors import ParameterError
from .controls import SIDES, check_side  # noqa: F401  (the sides live with the controls)


def _check(name: str, value: float, valid: str, ok) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError(f"{name} = {value!r} is not a number; valid range: {valid}")
    if not math.isfinite(value) or not ok(value):
        raise ParameterError(f"{name} = {value!r} is out of range; valid range: {valid}")


#: The box in which every solver is supported (Rbar_o max, L min and max, g min and max,
#: lambda_z / g min and max); it holds every march (stretch 0.05 g to 8 g, growth 1 to 6).
SUPPORTED = (100.0, 1e-2, 1e3, 1e-2, 1e2, 0.02, 50.0)
SUPPORTED_WHY = (
    "outside it the elastic stretches exceed 50, or the waves a scan resolves are over 1e3"
    " times shorter than the tube's radius or length, beyond the kernel's step budget"
    " (a search would run for hours or lose all digits)"
)


def check_uniform(outer_radius, length, growth, stretch, voltage) -> None:
    """Check the five numbers of the paper's tube (:meth:`model.layers.Tube.uniform`) against
    their physical ranges and the supported box, naming each in the paper's symbols."""
    (ro_max, l_lo, l_hi, g_lo, g_hi, e_lo, e_hi) = SUPPORTED
    _check("outer radius Rbar_o", outer_radius, f"1 < Rbar_o <= {ro_max:g}", lambda v: 1 < v)
    _check("length L", length, f"{l_lo:g} <= L <= {l_hi:g}", lambda v: v > 0)
    _check("growth factor g", growth, f"{g_lo:g} <= g <= {g_hi:g}", lambda v: v > 0)
    _check("axial stretch lambda_z", stretch, "0 < lambda_z < inf", lambda v: v > 0)
    _check("voltage Vbar", voltage, "0 <= Vbar < threshold", lambda v: v >= 0)
    for name, value, lo, hi in (
        ("outer radius Rbar_o", outer_radius, 1.0, ro_max),
        ("length L", length, l_lo, l_hi),
        ("growth factor g", growth, g_lo, g_hi),
        ("elastic axial stretch lambda_z / g", stretch / growth, e_lo, e_hi),
    ):
        if not value <= hi or not lo <= value:
            raise ParameterError(
                f"{name} = {value:.6g} is outside the supported range {lo:g} to {hi:g}:"
                f" {SUPPORTED_WHY}"
            )


#: The control parameters of the paper's tube (Tube.uniform); a layered tube adds pressure
#: and force (model/controls.py).
CONTROLS = ("growth", "stretch", "voltage")
