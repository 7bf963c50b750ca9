"""Named exceptions of electrogrowth.

Every message is one line that names the offending value and the valid range, so the
command line can print it as is (exit status 2) and a sweep can store it as a status.
"""


class ElectrogrowthError(Exception):
    """Base class: anything the package raises on purpose. ``remedy`` is the one-line
    advice a user can act on (empty where the message already names the valid range)."""

    remedy = ""


class ParameterError(ElectrogrowthError, ValueError):
    """A non-physical or out-of-range input parameter."""


class MaterialError(ElectrogrowthError, ValueError):
    """An unknown material or an energy the package cannot use."""

    remedy = "use a built-in energy or an expression in I1, I2, I4, I5, I6"


class BaseStateError(ElectrogrowthError, RuntimeError):
    """No axisymmetric base state exists (e.g. the voltage is above the threshold)."""

    remedy = (
        "lower the voltage below the threshold (`electrogrowth state` prints it) or"
        " move the growth or stretch back towards 1"
    )


class ConvergenceError(ElectrogrowthError, RuntimeError):
    """A root finder or integrator did not reach the requested accuracy."""

    remedy = "loosen --rtol (e.g. 1e-10), or certify the point with --method collocation"


class NoBifurcationFound(ElectrogrowthError, RuntimeError):
    """No bifurcation of the requested kind lies in the searched range."""

    remedy = "raise --m-max / --n-max, try the other --side, or another control parameter"


class MissingDependencyError(ElectrogrowthError, ImportError):
    """An optional package (an extra such as ``vtk`` or ``sweep``) is not installed."""

    remedy = "pip install 'electrogrowth[sweep,vtk]'"


class ConfigError(ParameterError):
    """A bad sweep (or tube) file. ``key`` is the dotted path of the offending entry."""

    def __init__(
        self, key: tuple[str, ...], reason: str, *, source: str = "", line: int | None = None
    ):
        self.key, self.reason, self.source, self.line = tuple(key), reason, source, line
        where = ":".join(str(p) for p in (source, line) if p not in ("", None))
        name = ".".join(self.key)
        super().__init__(f"{where + ': ' if where else ''}{name + ': ' if name else ''}{reason}")


class SweepError(ElectrogrowthError, RuntimeError):
    """The sweep as a whole cannot go on (store in use or of another sweep, lost cluster)."""

    remedy = "write to another --out store, or wait for the sweep that holds it"


class UsageError(ElectrogrowthError, ValueError):
    """A bad command line (raised by the parser instead of printing usage and exiting)."""
