"""The best circumferential wavenumber m beyond the every-m scan: a coarse-to-fine search.

A thin stiff film on a soft wall folds at a finite m of tens to hundreds (a flat film's
wavelength 2 pi R / m ~ 2 pi h (mu_f / 3 mu_s)^(1/3), docs/derivation-film.md), far beyond
the range worth scanning mode by mode. There the critical value of a family row (a
prismatic (m, 0), or a wrinkle (m, n) at fixed n) is a smooth function of m with one
minimum (the film's bending cost falls and the substrate's rises with m), so it is found by

1. geometric sampling: m_j = m_edge * RATIO^j up to ``m_cap`` (one march over the batch:
   the first sample to bifurcate is the best, and the minimum lies between its two
   neighbours);
2. refining: ``SPLIT`` evenly spaced integers inside the bracket, marched as one batch,
   the bracket narrowed to the neighbours of the best, until it holds at most ``SPLIT + 2``
   integers, which are marched all together.

Every march shares its base states among the batch (march.first_bifurcations), and the
roots that decide are finished at the scan's own rtol, so neighbouring m (whose critical
values differ by ~ (g - 1) / m^2 near the minimum) are ordered correctly. Small m, where
modes are irregular (the value jumps between neighbours and families), stay with the
every-m scan of scan.py.
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np

from ..errors import NoBifurcationFound
from ..incremental.accuracy import SCAN_SIGNS, SCAN_STABLE_SIGNS
from ..incremental.targets import Family, ImpedanceTarget
from .march import SIGN_TUBE, ModeValue, first_bifurcations, unloaded_signs

RATIO = 1.25  # geometric sampling: m_cap / m_edge = 2000 / 64 takes 16 samples
SPLIT = 8  # interior samples of a refining march


@dataclasses.dataclass(frozen=True)
class SearchResult:
    """The best mode of the search and the modes marched on the way (sorted by value)."""

    best: ModeValue
    found: tuple[ModeValue, ...]
    at_cap: bool  # the best m is m_cap: the minimum may lie beyond


def geometric_samples(m_edge: int, m_cap: int) -> list[int]:
    """m_edge, m_edge RATIO, m_edge RATIO^2, ... rounded, distinct, ending with m_cap."""
    out, x = [m_edge], float(m_edge)
    while out[-1] < m_cap:
        x *= RATIO
        m = min(max(int(round(x)), out[-1] + 1), m_cap)
        out.append(m)
    return out


def refine_samples(lo: int, hi: int) -> list[int]:
    """Integers strictly between lo and hi: all when there are at most SPLIT + 2 of them,
    else SPLIT evenly spaced ones."""
    inside = hi - lo - 1
    if inside <= SPLIT + 2:
        return list(range(lo + 1, hi))
    return sorted({int(round(x)) for x in np.linspace(lo, hi, SPLIT + 2)[1:-1]})


def search_m(
    params, solve_for: str, side, rows, m_edge: int, m_cap: int, rtol: float
) -> SearchResult:
    """The best m in [m_edge, m_cap] of the family rows ``rows`` ((n, family code) pairs),
    by geometric sampling and refinement (module docstring); NoBifurcationFound if none of
    the samples bifurcates before the end of the march."""
    march = functools.partial(_first, params, solve_for, side, rows, rtol)
    samples = geometric_samples(m_edge, m_cap)
    seen = list(march(samples))
    best = seen[0]
    row = [(best.n, _code(best))]
    lo, hi = _neighbours(samples, best.m)
    while hi - lo > 1:  # (at the cap too: the minimum may lie just below it)
        inner = refine_samples(lo, hi)
        complete = len(inner) == hi - lo - 1  # every integer of the bracket is marched
        try:
            got = list(march(inner, row))
        except NoBifurcationFound:  # none of them before the end of the march: best stands
            break
        seen += got
        if _earlier(got[0], best, side):
            best = got[0]
        lo, hi = _neighbours([lo, *inner, best.m, hi], best.m)
        if complete:
            break
    key = {(v.m, v.n, v.family): v for v in seen}
    ordered = sorted(key.values(), key=lambda v: _sense(side) * v.value)
    return SearchResult(best, tuple(ordered), best.m == m_cap)


def _first(params, solve_for, side, rows, rtol, ms, only=None) -> list[ModeValue]:
    """The first modes to bifurcate among m in ``ms`` of the rows (``only`` rows instead,
    if given), finished at ``rtol``; NoBifurcationFound if none does."""
    modes = np.array([(m, n, code) for m in ms for n, code in (only or rows)], float)
    loose = ImpedanceTarget(SCAN_SIGNS)
    fine = ImpedanceTarget(rtol)
    stable = ImpedanceTarget(SCAN_STABLE_SIGNS)
    res = first_bifurcations(
        params,
        solve_for,
        side,
        modes,
        loose,
        top=3,
        brent_targets=fine,
        stable_signs=_stable(modes, stable),
    )
    if not res.found:
        raise NoBifurcationFound(f"no mode with m in {ms[0]}..{ms[-1]} bifurcates")
    return res.found


def _stable(modes, targets):
    return unloaded_signs(SIGN_TUBE, modes, targets)


def _code(v: ModeValue) -> int:
    return Family(v.family).code


def _neighbours(ms, m) -> tuple[int, int]:
    """The samples either side of m in the sorted ``ms`` (m itself at an end)."""
    ms = sorted(set(ms))
    i = ms.index(m)
    return ms[max(i - 1, 0)], ms[min(i + 1, len(ms) - 1)]


def _sense(side) -> float:
    return -1.0 if side == "compression" else 1.0


def _earlier(a: ModeValue, b: ModeValue, side) -> bool:
    """Is a reached before b along the march?"""
    return _sense(side) * a.value < _sense(side) * b.value
