"""What a computation can end in: the kind of a critical point, the status of a point of a
curve or sweep, and the remedy a user can apply to each failure.

Both are string enums: they compare equal to, print and serialise as their plain values
("bifurcation", "ok", ...), which are what JSON, CSV and the sweep store hold.
"""

from __future__ import annotations

import enum

from .errors import ElectrogrowthError


class Kind(enum.StrEnum):
    """What was found where a control parameter first makes the tube unstable."""

    BIFURCATION = "bifurcation"  # wrinkling in a mode (m, n)
    THRESHOLD = "threshold"  # the axisymmetric base state is lost first
    SURFACE = "surface"  # a short-wave (surface) instability: the limit m, k -> infinity
    ELLIPTICITY = "ellipticity"  # strong ellipticity is lost first (no half-space problem)
    NONE = "none"  # no instability in the searched range
    SWITCH = "switch"  # a row of a curve: the critical mode changes, equal values both sides
    END = "end"  # a row of a curve: a branch ends there (a jump, or no wrinkling after it)


class Status(enum.StrEnum):
    """Whether the computation at one point (of a curve or a sweep) succeeded."""

    OK = "ok"
    INACCURATE = "inaccurate"  # computed, but its error estimate exceeds the accuracy asked
    FAILED = "failed"  # an electrogrowth error: no base state, no convergence, ...
    ERROR = "error"  # an unexpected exception: a bug


#: The mode (m, n) recorded where no mode is critical (a threshold, a failure): integer
#: arrays (curve tables, the sweep store) need a value there.
NO_MODE = (-1, -1)

BUG_REMEDY = "this is a bug in electrogrowth: please report it with the input that caused it"


def remedy(exc: BaseException) -> str:
    """The one-line remedy for a failure: the exception's own, or the bug report's."""
    if isinstance(exc, ElectrogrowthError):
        return type(exc).remedy
    return BUG_REMEDY


def status_of(exc: BaseException) -> Status:
    """FAILED for the package's own errors, ERROR for anything else (a bug)."""
    return Status.FAILED if isinstance(exc, ElectrogrowthError) else Status.ERROR
