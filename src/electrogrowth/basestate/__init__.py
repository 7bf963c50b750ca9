"""The axisymmetric base state of any tube: one door (:mod:`.tube`: ``solve_base_state``,
``threshold``), the paper's uniform tube in closed form (:mod:`.uniform`, with the voltage
curve Vbar(lambda_i) and its threshold in :mod:`.voltage`, package-internal), and a layered
tube with anisotropic or graded growth, pressures and axial force, with its thresholds and
response curves (:mod:`.layered`) and its solved state (:mod:`.layered_state`). Both states
follow one protocol, ``_types.State``.

May import ``model`` and ``errors``.
"""

from typing import TYPE_CHECKING

from .. import _lazy
from .tube import solve_base_state, threshold, voltage_curve, voltage_threshold
from .uniform_state import UniformState

#: The former name of :class:`UniformState` (kept for one release).
BaseState = UniformState

# The layered solver's names are imported on first use (PEP 562, _lazy.py): the paper's
# tube does not need it.
_MODULE_OF = _lazy.module_of(
    {
        ".layered": (
            "layered_threshold",
            "pressure_response",
            "solve_layered_state",
            "voltage_response",
        ),
        ".layered_state": ("LayeredState",),
    }
)

if TYPE_CHECKING:  # the names as the type checker reads them
    from .layered import (
        layered_threshold,
        pressure_response,
        solve_layered_state,
        voltage_response,
    )
    from .layered_state import LayeredState


def __getattr__(name: str):
    return _lazy.attribute(__name__, _MODULE_OF, name, globals())


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


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
