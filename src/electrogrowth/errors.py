"""Named exceptions of electrogrowth.

Every message is one line that names the offending value and the valid range, so the
command line can print it as is (exit status 2) and a sweep can store it as a status.
A remedy speaks to whoever reads it: its text (``str``, ``.cli``) names command-line flags
("loosen --rtol"), which the command line prints after the message; ``.python`` names
keyword arguments ("pass rtol=1e-10"), which a Python traceback shows under the message
(a note, ``__notes__``). ``str(error)`` is the message alone in both worlds.
"""

from __future__ import annotations

from typing import NamedTuple


class Remedy(str):
    """A one-line remedy in two forms: the text itself is the command line's (``.cli``,
    what the CLI prints and a sweep store keeps), ``.python`` the same advice in terms of
    the Python API (the text itself where the two agree).

    >>> r = Remedy("loosen --rtol", python="pass a larger rtol=")
    >>> r, r.cli, r.python
    ('loosen --rtol', 'loosen --rtol', 'pass a larger rtol=')
    """

    python: str

    def __new__(cls, cli: str = "", *, python: str | None = None) -> Remedy:
        self = super().__new__(cls, cli)
        self.python = cli if python is None else python
        return self

    @property
    def cli(self) -> str:
        return str(self)


def python_remedy(remedy: str) -> str:
    """The Python form of a remedy (a plain string is the same in both worlds)."""
    return remedy.python if isinstance(remedy, Remedy) else remedy


class ElectrogrowthError(Exception):
    """Base class: anything the package raises on purpose. ``remedy`` is the one-line
    advice a user can act on (empty where the message already names the valid range)."""

    remedy: str = Remedy("")

    @property
    def __notes__(self) -> list[str]:
        """What Python prints under the traceback: any notes added, then the remedy in
        Python's terms (the command line prints its own form instead)."""
        notes = self.__dict__.setdefault("_notes", [])
        notes[:] = [n for n in notes if not n.startswith(_NOTE)]
        if self.remedy:
            notes.append(_NOTE + python_remedy(self.remedy))
        return notes

    @__notes__.setter
    def __notes__(self, notes: list[str]) -> None:
        self.__dict__["_notes"] = list(notes)


_NOTE = "remedy: "


class ParameterError(ElectrogrowthError, ValueError):
    """A non-physical or out-of-range input parameter. ``key``: where the value sits in
    what was checked (("layers", "2", "outer_radius"), ("length",); () where not said), so
    a file's reader names its line (model/tube_file.py)."""

    def __init__(self, *args, key: tuple[str, ...] = ()):
        super().__init__(*args)
        self.key = tuple(key)


class UnstableAtStart(ParameterError):
    """The tube is already unstable at the control's start, before any of its load (a mode,
    or a face's short-wave limit): its critical value lies at or before the start. Next to
    a tube that wrinkles in no mode before the control's end (NoBifurcationFound), the
    critical value runs through the control's whole range in between. ``row``: the mode
    (m, n, family code) found unstable there, where a mode was (None: a face)."""

    row: tuple[int, int, int] | None = None


class MaterialError(ElectrogrowthError, ValueError):
    """An unknown material or an energy the package cannot use."""

    remedy = Remedy("use a built-in energy or an expression in I1, I2, I4, I5, I6")


class Beyond(NamedTuple):
    """A load at or beyond its threshold: the tube's key ("voltage", "inner_pressure"), its
    value, the threshold and the tube's Rbar_o (the voltage's scale), in units mu = eps =
    R_i = 1, so the command line can quote both in the units the user gave (kV, kPa)."""

    load: str
    value: float
    threshold: float
    outer_radius: float


class BaseStateError(ElectrogrowthError, RuntimeError):
    """No axisymmetric base state exists (e.g. the voltage is above the threshold).
    ``beyond``: the load and its threshold where that is why (:class:`Beyond`), else None."""

    def __init__(self, *args, beyond: Beyond | None = None):
        super().__init__(*args)
        self.beyond = beyond

    remedy = Remedy(
        "lower the voltage below the threshold (`electrogrowth state` prints it) or"
        " move the growth or stretch back towards 1",
        python="lower the voltage below the threshold (`voltage_threshold` gives it) or"
        " move the growth or stretch back towards 1",
    )


class BranchNotFollowed(BaseStateError):
    """A charged state the package does not follow, though it may exist: the energy's field
    closes the bore and no charge balances the traction inward of the uncharged state
    either (threshold kind "closing"; basestate/voltage.py ``_rises``, ``_runs_inward``,
    thresholds.opens, thresholds.inward). Not a loss of the state: a march whose states end so
    leaves the rest of its path unexamined (bifurcation/state_loss.py ``_fate``)."""

    remedy = Remedy(
        "none within the package: it follows a voltage branch only where the charge opens"
        " the bore; a smaller voltage or other loads may keep the tube on such a branch"
    )


class ConvergenceError(ElectrogrowthError, RuntimeError):
    """A root finder or integrator did not reach the requested accuracy."""

    remedy = Remedy(
        "loosen --rtol (e.g. 1e-10), or certify the point with --method collocation",
        python="pass a looser rtol (e.g. rtol=1e-10), or certify the point with"
        " method='collocation'",
    )


class StartUnresolved(ConvergenceError):
    """Which way a voltage branch leaves its uncharged start is not resolved: within the
    probe's reach (basestate/start_probe.py, 1e-2 of r_i) the wall's traction residual stays
    within the rounding of the stresses that cancel in it (the traction is flat there: next
    to an inflation asymptote, or where the wall's in-plane shear modulus nearly vanishes).
    The threshold is then kind "unresolved"; a charged state may exist: neither a loss nor
    a field that closes the bore (a march reads it as unresolved, bifurcation/state_loss.py)."""

    remedy = Remedy(
        "none from a tolerance: the wall's traction is flat to rounding at this uncharged"
        " state (next to the inner pressure's asymptote, or to a loss of in-plane"
        " ellipticity); loads farther from there are resolved"
    )


#: a collocation value that is not certified: the other method checks it (ConvergenceError's
#: own remedy names collocation, the method that was just used; probe 13a D2)
CHECK_WITH_IMPEDANCE = Remedy(
    "loosen --rtol (e.g. 1e-10), or check the point with --method impedance (the default)",
    python="pass a looser rtol (e.g. rtol=1e-10), or check the point with"
    " method='impedance' (the default)",
)


class CollocationTooLarge(ConvergenceError):
    """Collocation would need more nodes for a mode than its memory budget holds (a short
    wave through a thick wall): the impedance kernel, whose memory does not grow with the
    mode, is the method there."""

    remedy = Remedy(
        "use --method impedance (the default), which resolves such modes; for waves this"
        " short the exact short-wave limit, which every scan computes, is their bound",
        python="use method='impedance' (the default), which resolves such modes; for waves"
        " this short the exact short-wave limit (short_wave_limit) is their bound",
    )


#: what to do where a Gent layer's states next to its lock cannot be resolved (they exist)
NEAR_LOCK = Remedy(
    "the states there are next to a Gent layer's lock, where no wrinkle is computable: ask"
    " for less load, or give the layer a larger jm"
)

#: what to do where a state's stresses overflow a double (an exponential energy far out): the
#: state may exist, but no double-precision solve reaches it, nor would a looser rtol
OVERFLOW = Remedy(
    "the stresses there exceed the range of a double: ask for less load, growth or stretch,"
    " or use an energy that stiffens less steeply"
)


class NoBifurcationFound(ElectrogrowthError, RuntimeError):
    """No bifurcation of the requested kind lies in the searched range."""

    remedy = Remedy(
        "raise --m-max / --n-max, try the other --side, or another control parameter",
        python="widen ScanOptions(m_range=..., n_range=...), try the other side=, or"
        " another control parameter",
    )


class NoBifurcationBeforeLock(NoBifurcationFound):
    """No mode bifurcates up to the last state a march resolves on its way to its control's
    own threshold, a layer's lock whose load grows without bound (Threshold kind "locking"):
    the state is never lost, and the states closer to the lock are not resolved."""

    remedy = Remedy(
        "no mode is computable closer to the lock: give the layer a larger jm to look"
        " further, or scan every mode (leave out --mode)",
        python="no mode is computable closer to the lock: give the layer a larger jm to look"
        " further, or scan every mode (scan_modes)",
    )


class MissingDependencyError(ElectrogrowthError, ImportError):
    """An optional package (an extra such as ``vtk`` or ``sweep``) is not installed."""

    remedy = Remedy("pip install 'electrogrowth[sweep,vtk]'")


class ConfigError(ParameterError):
    """A bad sweep (or tube) file. ``key`` is the dotted path of the offending entry."""

    def __init__(
        self, key: tuple[str, ...], reason: str, *, source: str = "", line: int | None = None
    ):
        where = ":".join(str(p) for p in (source, line) if p not in ("", None))
        name = ".".join(key)
        text = f"{where + ': ' if where else ''}{name + ': ' if name else ''}{reason}"
        super().__init__(text, key=key)
        self.reason, self.source, self.line = reason, source, line


class SweepError(ElectrogrowthError, RuntimeError):
    """The sweep as a whole cannot go on (store in use or of another sweep, lost cluster)."""

    remedy = Remedy(
        "write to another --out store, or wait for the sweep that holds it",
        python="write to another store (compute_sweep(config, out=...)), or wait for the"
        " sweep that holds it",
    )


class UsageError(ElectrogrowthError, ValueError):
    """A bad command line (raised by the parser instead of printing usage and exiting)."""


class FailedPoint(ElectrogrowthError, RuntimeError):
    """A failure kept as data (a point of a sweep or a curve), raised by
    :meth:`~electrogrowth.outcomes.Outcome.unwrap`; ``remedy`` is the point's."""


class InternalError(RuntimeError):
    """A bug kept as data (status ERROR), raised by
    :meth:`~electrogrowth.outcomes.Outcome.unwrap` with the original traceback in its
    message. Not an ElectrogrowthError: it is never the user's mistake."""
