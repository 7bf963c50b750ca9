"""The checks of a mode map, each one a pure function of its task (so a pool can run
them): the full scan at a design (the pattern first there) and the certificate of a traced
boundary point (the two critical values agree to CERTIFIED, and no scanned mode comes
earlier). docs/design.md, "Certificates".
"""

from __future__ import annotations

import math

import numpy as np

from ..bifurcation.scan import scan_modes
from ..errors import ElectrogrowthError
from ..outcomes import Kind
from .map_record import Certificate
from .map_trace import FAILED, SURFACE, THRESHOLD, Values, valued

CERTIFIED = 1e-8  # the two (three) critical values of a certified point agree to this


def label_of(res) -> object:
    c = res.critical
    if c.kind == Kind.BIFURCATION:
        return (int(c.m), int(c.n))
    return {Kind.SURFACE: SURFACE, Kind.THRESHOLD: THRESHOLD}.get(c.kind, FAILED)


def scan_label(values: Values, options, u):
    """The pattern a full scan finds first at u, and its value (FAILED, NaN if none)."""
    try:
        res = scan_modes(
            values.tube_at(u), values.solve_for, side=values.side, options=options,
            rtol=values.rtol,
        )  # fmt: skip
    except ElectrogrowthError:
        return FAILED, math.nan
    return label_of(res), res.critical.value


def scan_node(task):
    """One grid node's scan (a pool's task: values, options, u)."""
    return scan_label(*task)


def certificate(task) -> tuple[Certificate, int]:
    """One boundary point checked by full solves and a full scan (a pool's task: values,
    options, the patterns P and Q on either side, u), and the solves it took (on a fresh
    copy of the values: the same here and in a worker)."""
    values, options, p, q, u = task
    values = values.fresh()
    gap = math.nan
    v = None
    if valued(p) and valued(q):
        a, b = values.value(p, u, hinted=False), values.value(q, u, hinted=False)
        if a is not None and b is not None:
            gap, v = abs(a - b), a
    else:
        v = values.value(p if valued(p) else q, u, hinted=False)
    first, w = scan_label(values, options, u)
    ahead = (
        values.sense * (w - v) if v is not None and math.isfinite(w) else math.nan
    )  # < 0: the scan found something earlier
    tol = CERTIFIED * max(1.0, abs(v)) if v is not None else CERTIFIED
    ok = (math.isnan(gap) or gap <= tol) and (first in (p, q) or ahead >= -tol)
    x, y = values.xy(u)
    return Certificate(x, y, gap, first, ahead, bool(ok)), values.solves


def sampled(curve, count: int) -> list[int]:
    """The indices of the ``count`` points of a curve that are certified (ends included)."""
    if not count:
        return []
    return sorted(set(np.linspace(0, len(curve["u"]) - 1, count).round().astype(int)))
