"""What a computation can end in: the kind of a critical point, the status of a result, the
remedy a user can apply to each failure, and :class:`Outcome`, the one shape every result
record shares.

Kind and Status are string enums: they compare equal to, print and serialise as their
plain values ("bifurcation", "ok", ...), which are what JSON, CSV and the sweep store hold.

The four result records (``CriticalPoint``, ``SurfaceLimit``, a curve's ``CurvePoint``
and a sweep's ``PointResult``) are Outcomes: each has ``kind``, ``status``, ``value``,
``error_estimate``, ``message`` and ``remedy`` with one meaning, ``outcome_dict()`` (the
same six keys, plain values) and ``unwrap()``, the switch from "failures are data" (a
sweep, a curve) to "failures raise" (a Python caller who wants the value or an
exception). A failure is FAILED when it is one of the package's own errors (the user can
act on its message and remedy) and ERROR otherwise: a bug, kept with its traceback and
never blamed on the input.
"""

from __future__ import annotations

import enum
import math
import traceback as _traceback
from typing import TYPE_CHECKING

from .errors import ElectrogrowthError, FailedPoint, InternalError, Remedy


class Kind(enum.StrEnum):
    """What was found where a control parameter first makes the tube unstable."""

    BIFURCATION = "bifurcation"  # wrinkling in a mode (m, n)
    THRESHOLD = "threshold"  # the axisymmetric base state is lost first
    SURFACE = "surface"  # a short-wave (surface) instability: the limit m, k -> infinity
    CREASE = "crease"  # a free face reaches the crease onset (bifurcation/crease.py) first
    ELLIPTICITY = "ellipticity"  # strong ellipticity is lost first (no half-space problem)
    NONE = "none"  # no instability in the searched range (or nothing computed: a failure)
    SWITCH = "switch"  # a row of a curve: the critical mode changes, equal values both sides
    END = "end"  # a row of a curve: a branch ends there (a jump, or no wrinkling after it)


class Status(enum.StrEnum):
    """Whether the computation of one result (a point of a curve or a sweep) succeeded."""

    OK = "ok"
    INACCURATE = "inaccurate"  # computed, but its error estimate exceeds the accuracy asked
    FAILED = "failed"  # an electrogrowth error: no base state, no convergence, ...
    ERROR = "error"  # an unexpected exception: a bug


#: The mode (m, n) recorded where no mode is critical (a threshold, a failure): integer
#: arrays (curve tables, the sweep store) need a value there.
NO_MODE = (-1, -1)

BUG_REMEDY = Remedy(
    "this is a bug in electrogrowth: please report it with the input that caused it"
)


def json_number(v: float | None) -> float | None:
    """A number for JSON, which has neither NaN nor infinities: those (and None) as None."""
    return float(v) if v is not None and math.isfinite(v) else None


def remedy(exc: BaseException) -> str:
    """The one-line remedy for a failure (a :class:`~electrogrowth.errors.Remedy`, both
    forms): the exception's own, or the bug report's."""
    if isinstance(exc, ElectrogrowthError):
        return exc.remedy
    return BUG_REMEDY


def status_of(exc: BaseException) -> Status:
    """FAILED for the package's own errors, ERROR for anything else (a bug)."""
    return Status.FAILED if isinstance(exc, ElectrogrowthError) else Status.ERROR


def traceback_of(exc: BaseException) -> str:
    """The traceback of a bug, kept with the record that holds it ("" for the package's
    own errors: their message and remedy say all a user needs)."""
    if status_of(exc) is Status.FAILED:
        return ""
    return "".join(_traceback.format_exception(exc))


class Outcome:
    """The shape every result record shares (a base of the frozen result dataclasses;
    each declares the fields in the order its callers construct it).

    The shared fields (each record declares them, in its own order):

    kind : Kind
        What was found (bifurcation, threshold, surface, ellipticity, none); "" where
        nothing was computed (FAILED, ERROR).
    status : Status
        OK; INACCURATE (a value whose error estimate exceeds the accuracy asked); FAILED
        (one of the package's errors, see ``message`` and ``remedy``); ERROR (a bug: the
        record's ``traceback`` holds where).
    value : float
        The critical value (NaN where nothing was computed).
    error_estimate : float
        Its estimated absolute error (NaN where not estimated).
    message : str
        Why a result failed or is inaccurate ("" when OK).
    remedy : str
        What to try (a :class:`~electrogrowth.errors.Remedy`: the text names CLI flags,
        ``.python`` the keyword arguments; "" when OK).
    """

    if TYPE_CHECKING:  # the shared fields, declared by each record (a dataclass) in its order
        kind: str
        status: Status
        value: float
        error_estimate: float
        message: str
        remedy: str
    #: where a bug happened (records that catch exceptions keep it as a field)
    traceback: str = ""
    #: the keys of :meth:`outcome_dict`, in order
    OUTCOME_KEYS = ("kind", "status", "value", "error_estimate", "message", "remedy")

    @property
    def ok(self) -> bool:
        """Computed (OK or INACCURATE): ``value`` and ``kind`` mean what they say."""
        return self.status in (Status.OK, Status.INACCURATE)

    def unwrap(self):
        """The record itself if it was computed; else raise: FailedPoint (an
        ElectrogrowthError, with the record's message and remedy) for FAILED,
        InternalError (with the original traceback) for ERROR."""
        if self.status == Status.FAILED:
            exc = FailedPoint(self.message)
            exc.remedy = self.remedy
            raise exc
        if self.status == Status.ERROR:
            raise InternalError(f"{self.message}\n{self.traceback}".rstrip())
        return self

    def outcome_dict(self) -> dict:
        """The six shared fields as JSON-ready plain values (NaN -> None, the remedy in
        Python's terms)."""
        out = {}
        for key in self.OUTCOME_KEYS:
            v = getattr(self, key)
            if key == "remedy":
                v = v.python if isinstance(v, Remedy) else str(v)
            elif isinstance(v, float):
                v = json_number(v)
            elif isinstance(v, str):
                v = str(v)
            out[key] = v
        return out
