"""The axisymmetric base state of the grown, stretched, charged tube: the voltage curve
Vbar(lambda_i) and its threshold (:mod:`.voltage`, package-internal), the solved state with
its through-wall profiles (:mod:`.tube`), and the same for a layered tube with anisotropic or
graded growth, pressures and axial force, with its thresholds and response curves
(:mod:`.layered`).

May import ``model`` and ``errors``.
"""

from .layered import (
    LayeredState,
    layered_threshold,
    pressure_response,
    solve_layered_state,
    voltage_response,
)
from .tube import BaseState, solve_base_state, voltage_curve, voltage_threshold

__all__ = [
    "BaseState",
    "solve_base_state",
    "voltage_curve",
    "voltage_threshold",
    "LayeredState",
    "layered_threshold",
    "pressure_response",
    "solve_layered_state",
    "voltage_response",
]
