"""electrogrowth: growth, voltage and wrinkling of soft electro-elastic tubes.

The public surface, one name per stage of the computation (units mu = eps = R_i = 1)::

    tube   = TubeParameters(outer_radius=1.4, length=1.0, voltage=0.4)    # model
    state  = solve_base_state(tube)                                        # basestate
    crit   = critical_value(tube, 0, 1, "growth")                          # bifurcation
    scan   = scan_modes(tube, "growth", options=ScanOptions(m_range=(0, 8)))
    curve  = critical_curve(tube, "growth", "stretch", [0.9, 1.0, 1.1])
    shape  = mode_shape(crit)                                              # shapes

Plots live in :mod:`electrogrowth.figures`, sweeps in :mod:`electrogrowth.sweep`, the
command line in :mod:`electrogrowth.cli`; docs/architecture.md maps every module.
"""

__version__ = "0.1.0"

from .basestate.layered import (
    LayeredState,
    layered_threshold,
    pressure_response,
    voltage_response,
)
from .basestate.tube import BaseState, solve_base_state, voltage_curve, voltage_threshold
from .bifurcation.critical import CriticalPoint, critical_value
from .bifurcation.curves import Curve, critical_curve
from .bifurcation.scan import ScanOptions, ScanResult, scan_modes
from .errors import (
    BaseStateError,
    ConfigError,
    ConvergenceError,
    ElectrogrowthError,
    MaterialError,
    MissingDependencyError,
    NoBifurcationFound,
    ParameterError,
    SweepError,
    UsageError,
)
from .incremental.accuracy import Accuracy
from .incremental.targets import Family, Method
from .model.layers import Layer, LinearGrowth, Tube
from .model.materials import (
    I1,
    I2,
    I4,
    I5,
    I6,
    Material,
    gent,
    material_by_name,
    mooney_rivlin,
    neo_hookean,
)
from .model.params import TubeParameters
from .model.tube_file import load_tube
from .outcomes import Kind, Status
from .shapes.mode_shape import ModeShape, mode_shape
from .sweep.file import load_config
from .sweep.run import compute_sweep

__all__ = [
    # model
    "TubeParameters",
    "Layer",
    "LinearGrowth",
    "Tube",
    "load_tube",
    "LayeredState",
    "layered_threshold",
    "pressure_response",
    "voltage_response",
    "Material",
    "gent",
    "material_by_name",
    "mooney_rivlin",
    "neo_hookean",
    "I1",
    "I2",
    "I4",
    "I5",
    "I6",
    # base state
    "BaseState",
    "solve_base_state",
    "voltage_curve",
    "voltage_threshold",
    # bifurcation
    "CriticalPoint",
    "critical_value",
    "ScanOptions",
    "ScanResult",
    "scan_modes",
    "Curve",
    "critical_curve",
    "Method",
    "Family",
    "Accuracy",
    "Kind",
    "Status",
    # shapes and sweeps
    "ModeShape",
    "mode_shape",
    "compute_sweep",
    "load_config",
    # errors
    "ElectrogrowthError",
    "ParameterError",
    "MaterialError",
    "BaseStateError",
    "ConvergenceError",
    "NoBifurcationFound",
    "MissingDependencyError",
    "ConfigError",
    "SweepError",
    "UsageError",
]
