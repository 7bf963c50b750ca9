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
        out["runners_up"] = [dataclasses.asdict(r) for r in self.runners_up]
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
