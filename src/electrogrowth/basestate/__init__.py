"""The axisymmetric base state of any tube: one door (:mod:`.tube`: ``solve_base_state``,
``threshold``), the paper's uniform tube in closed form (:mod:`.uniform`, with the voltage
curve Vbar(lambda_i) and its threshold in :mod:`.voltage`, package-internal), and a layered
tube with anisotropic or graded growth, pressures and axial force, with its thresholds and
response curves (:mod:`.layered`). Both states follow one protocol, ``_types.State``.

May import ``model`` and ``errors``.
"""

from .layered import (
    LayeredState,
    layered_threshold,
    pressure_response,
    solve_layered_state,
    voltage_response,
)
from .tube import solve_base_state, threshold, voltage_curve, voltage_threshold
from .uniform import UniformState

#: The former name of :class:`UniformState` (kept for one release).
BaseState = UniformState

__all__ = [
    "BaseState",
    "UniformState",
    "solve_base_state",
    "threshold",
    "voltage_curve",
    "voltage_threshold",
    "LayeredState",
    "layered_threshold",
    "pressure_response",
    "solve_layered_state",
    "voltage_response",
]
