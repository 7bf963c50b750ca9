"""electrogrowth: growth, voltage and wrinkling of soft electro-elastic tubes.

The public surface, one name per stage of the computation (units mu = eps = R_i = 1)::

    tube   = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.4)    # model
    state  = solve_base_state(tube)                                        # basestate
    crit   = critical_value(tube, 0, 1, "growth")                          # bifurcation
    scan   = scan_modes(tube, "growth", options=ScanOptions(m_range=(0, 8)))
    curve  = critical_curve(tube, "growth", "stretch", [0.9, 1.0, 1.1])
    shape  = mode_shape(crit)                                              # shapes

Plots live in :mod:`electrogrowth.figures`, sweeps in :mod:`electrogrowth.sweep`, the
command line in :mod:`electrogrowth.cli`; docs/architecture.md maps every module.
"""

from . import _lazy

__version__ = "0.1.0"

# Where each public name lives. The names are imported on first use (PEP 562), so that
# `import electrogrowth` (and with it `electrogrowth --help` and `--version`) does not pay
# for numba, sympy and scipy until a computation needs them.
_EXPORTS = {
    ".basestate.layered": ("layered_threshold", "pressure_response", "voltage_response"),
    ".basestate.layered_state": ("LayeredState",),
    ".basestate.tube": ("solve_base_state", "threshold", "voltage_curve", "voltage_threshold"),
    ".basestate.uniform_state": ("UniformState",),
    ".basestate": ("BaseState",),
    ".bifurcation.certify": ("Certificate", "certify"),
    ".bifurcation.critical": ("CriticalPoint", "critical_value"),
    ".bifurcation.crease": ("CreaseOnset", "crease_onset"),
    ".bifurcation.verdict": ("Verdict",),
    ".bifurcation.koiter": ("FilmOnHalfSpace", "KoiterResult", "koiter_coefficient"),
    ".bifurcation.curves": ("Curve", "critical_curve"),
    ".bifurcation.problem": ("Problem",),
    ".bifurcation.scan": ("ScanOptions", "scan_modes"),
    ".bifurcation.scan_record": ("ScanResult",),
    ".design.prescribe": ("Design", "prescribe"),
    ".design.mode_map": ("mode_map",),
    ".design.map_record": ("ModeMap",),
    ".design.prescribe_map": ("MapDesign", "prescribe_map"),
    ".design.sequence": ("ModeSequence", "mode_sequence"),
    ".errors": (
        "BaseStateError",
        "ConfigError",
        "ConvergenceError",
        "ElectrogrowthError",
        "FailedPoint",
        "InternalError",
        "MaterialError",
        "MissingDependencyError",
        "NoBifurcationFound",
        "ParameterError",
        "Remedy",
        "SweepError",
        "UsageError",
    ),
    ".incremental.accuracy": ("Accuracy",),
    ".incremental.targets": ("Family", "Method"),
    ".model.layers": ("Layer", "LinearGrowth", "Tube", "TubeParameters"),
    ".model.materials": (
        "I1",
        "I2",
        "I4",
        "I5",
        "I6",
        "Material",
        "gent",
        "material_by_name",
        "mooney_rivlin",
        "neo_hookean",
    ),
    ".model.tube_file": ("load_tube",),
    ".model.units": ("Scales", "tube_from_quantities"),
    ".outcomes": ("Kind", "Outcome", "Status"),
    ".shapes.mode_shape": ("ModeShape", "mode_shape"),
    ".sweep.file": ("load_config",),
    ".sweep.run": ("compute_sweep",),
}
_MODULE_OF = _lazy.module_of(_EXPORTS)


def __getattr__(name: str):
    """Import a public name from its module on first use (then it is a plain attribute)."""
    return _lazy.attribute(__name__, _MODULE_OF, name, globals())


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


__all__ = [
    # model
    "TubeParameters",
    "Layer",
    "LinearGrowth",
    "Tube",
    "load_tube",
    "Scales",
    "tube_from_quantities",
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
    "UniformState",
    "threshold",
    "solve_base_state",
    "voltage_curve",
    "voltage_threshold",
    # bifurcation
    "Problem",
    "CriticalPoint",
    "critical_value",
    "ScanOptions",
    "ScanResult",
    "scan_modes",
    "Certificate",
    "certify",
    "CreaseOnset",
    "crease_onset",
    "Verdict",
    "koiter_coefficient",
    "KoiterResult",
    "FilmOnHalfSpace",
    # design
    "ModeSequence",
    "mode_sequence",
    "Design",
    "prescribe",
    "ModeMap",
    "mode_map",
    "MapDesign",
    "prescribe_map",
    "Curve",
    "critical_curve",
    "Method",
    "Family",
    "Accuracy",
    "Kind",
    "Status",
    "Outcome",
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
    "FailedPoint",
    "InternalError",
    "Remedy",
]
