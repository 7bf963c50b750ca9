"""The record of a mode scan (bifurcation/scan.py computes it): the critical point, the
runners-up, the ranges scanned and the short-wave limit where it was computed; its verdict
(what comes first of it and a crease), its JSON record, labelled arrays and notebook table.
"""

from __future__ import annotations

import dataclasses
import functools

from ..labelled import scan_dataset
from ..summary import scan_html
from .critical import CriticalPoint
from .march import ModeValue
from .options import M_CAP, N_CAP
from .verdict import Verdict, verdict_of
from .verdict import record as verdict_record


@dataclasses.dataclass(frozen=True)
class ScanResult:
    """Result of :func:`~electrogrowth.scan_modes`: the critical point and the next modes after it.

    ``critical`` is the first linear instability (a wrinkle, the short-wave limit or the
    threshold); ``verdict`` (computed when first read) what comes first of it and a crease
    of a free face (bifurcation/crease.py), with the runner-up of each kind. ``as_dict``
    (the JSON of ``electrogrowth critical``) gives the verdict's kind and value at the top.
    Each runner-up is solved at the scan's rtol, with its ``error_estimate``
    (bifurcation/runners.py).
    """

    critical: CriticalPoint
    runners_up: tuple[ModeValue, ...]
    m_range: tuple[int, int]
    n_range: tuple[int, int]
    surface_instability: bool = False  # the critical point is the short-wave limit
    short_wave_limit: float | None = None  # the exact limit m, k -> inf, where computed
    short_wave_error: float | None = None
    #: the largest m and n its searches reached: the tube's (scan.scan_caps), past which a
    #: mode at them may hide a shorter wave that comes first
    caps: tuple[int, int] = (M_CAP, N_CAP)

    @functools.cached_property
    def verdict(self) -> Verdict:
        """What comes first: the linear result, a crease or the threshold (verdict.py)."""
        c, runners = self.critical, self.runners_up
        finite = runners[0] if self.surface_instability and runners else None
        swl = self.short_wave_limit
        short = None if swl is None or self.surface_instability else (swl, self.short_wave_error)
        return verdict_of(c, finite=finite, short_wave=short)

    def as_dict(self) -> dict:
        out = self.critical.as_dict()
        out["runners_up"] = [runner_record(r, self.caps) for r in self.runners_up]
        out["m_range"], out["n_range"] = list(self.m_range), list(self.n_range)
        out["surface_instability"] = self.surface_instability
        out["short_wave_limit"] = self.short_wave_limit
        out["short_wave_error"] = self.short_wave_error
        return verdict_record(out, self.verdict, self.critical)

    def to_xarray(self):
        """The critical point and the runners-up as an ``xarray.Dataset`` on dimension rank
        (0 = critical), units and descriptions in attributes (labelled.py; needs xarray)."""
        return scan_dataset(self)

    def _repr_html_(self) -> str:
        return scan_html(self)


def runner_record(r: ModeValue, caps: tuple[int, int] = (M_CAP, N_CAP)) -> dict:
    """A runner-up's JSON record: its fields and ``note``, which says where it sits at the
    largest m or n its scan reached (``caps``; None elsewhere). A scan does not look beyond
    its caps, so shorter waves may come before such a runner-up: a long film's rings (0, 2000) and
    (0, 1999) were listed next with no word while their optimum lies near n = 2056 (probe
    12b); the critical mode at a cap says so in its status (scan._capped)."""
    out = dataclasses.asdict(r)
    over = [f"{k} = {cap}" for k, v, cap in zip("mn", (r.m, r.n), caps, strict=True) if v >= cap]
    out["note"] = (
        f"at the largest {' and '.join(over)} its scan searched: a mode beyond it may come first"
        if over
        else None
    )
    return out
