"""Named exceptions of electrogrowth.

Every message is one line that names the offending value and the valid range, so the
command line can print it as is (exit status 2) and a sweep can store it as a status.
"""


class ElectrogrowthError(Exception):
    """Base class: anything the package raises on purpose."""


class ParameterError(ElectrogrowthError, ValueError):
    """A non-physical or out-of-range input parameter."""


class MaterialError(ElectrogrowthError, ValueError):
    """An unknown material or an energy the package cannot use."""


class BaseStateError(ElectrogrowthError, RuntimeError):
    """No axisymmetric base state exists (e.g. the voltage is above the threshold)."""


class ConvergenceError(ElectrogrowthError, RuntimeError):
    """A root finder or integrator did not reach the requested accuracy."""


class NoBifurcationFound(ElectrogrowthError, RuntimeError):
    """No bifurcation of the requested kind lies in the searched range."""


class MissingDependencyError(ElectrogrowthError, ImportError):
    """An optional package (an extra such as ``vtk`` or ``sweep``) is not installed."""
