"""The best wavenumber m (or n) beyond the mode-by-mode scan: a coarse-to-fine search.

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

Each family row is searched on its own, and the earliest of their bests wins: rows have
their own minima. A film inside a thin wall (check round 35d, Q3) has its wrinkle row
(m, 5) lowest at m = 11, inside the scan, and its fold row (m, 0) at m = 66, in a dip
narrower than the samples' spacing; one march over all rows took the wrinkle row's first
sample (13, 5) for the best, refined next to it and never looked at the fold, which comes
1.4e-3 earlier.

Every march shares its base states among the batch (march.first_bifurcations), and the
roots that decide are finished at the scan's own rtol, so neighbouring m (whose critical
values differ by ~ (g - 1) / m^2 near the minimum) are ordered correctly. Small m, where
modes are irregular (the value jumps between neighbours and families), stay with the
every-m scan of scan.py.

The same search runs along n (:func:`search_n`, rows of fixed m): a long tube lined with a
film that grows isotropically folds into rings (0, n) of the flat film's wavelength, n ~
hundreds, beyond the n range's doublings. The integers next to the best are all marched
(``top - 1`` either side, at most NEIGHBOURS), so the runners-up of a searched optimum are
its true neighbours; along n, on the rows of m within ``top - 1`` of the best's too (a ring
(0, n)'s next modes are (1, n), (0, n +- 1), (2, n), ...).
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
NEIGHBOURS = 8  # integers either side of the best marched for the runners-up (at most)


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
    params, solve_for: str, side, rows, edge: int, cap: int, rtol: float, top: int = 1
) -> SearchResult:
    """The best m in [edge, cap] of the family rows ``rows`` ((n, family code) pairs),
    by geometric sampling and refinement (module docstring), with the ``top - 1`` integers
    either side of it marched too; NoBifurcationFound if none of the samples bifurcates
    before the end of the march."""
    return _search(params, solve_for, side, rows, (edge, cap), rtol, top, "m")


def search_n(
    params,
    solve_for: str,
    side,
    rows,
    edge: int,
    cap: int,
    rtol: float,
    top: int = 1,
    m_span: tuple[int, int] | None = None,
) -> SearchResult:
    """:func:`search_m` along n: the best n in [edge, cap] of the rows ``rows`` ((m, family
    code) pairs); its runners-up are looked for on the wrinkle rows of m within ``top - 1``
    of the best's too, inside ``m_span`` (if given)."""
    return _search(params, solve_for, side, rows, (edge, cap), rtol, top, "n", m_span)


def _search(params, solve_for, side, rows, span, rtol, top, axis, m_span=None) -> SearchResult:
    march = functools.partial(_first, params, solve_for, side, rows, rtol, axis=axis)
    seen, missed = [], None
    for row in sorted(rows):  # each row has its own minimum (module docstring)
        try:
            seen += _row_search(march, row, span, side, axis)
        except NoBifurcationFound as exc:  # none of this row's samples: the others may
            missed = exc
    if not seen:
        raise missed
    best = min(seen, key=lambda v: _sense(side) * v.value)
    near = rows if m_span is None else _near_rows(rows, best, m_span, top)
    seen += _neighbourhood(march, near, seen, best, span, top, axis)
    key = {(v.m, v.n, v.family): v for v in seen}
    ordered = sorted(key.values(), key=lambda v: _sense(side) * v.value)
    # The neighbourhood marches every row, not only the refined best's: a mode of another
    # row found there may come first ((17, 0) before the refined (16, 1), probe 8b D2), and
    # the best is the earliest of all the search found.
    best = ordered[0]
    return SearchResult(best, tuple(ordered), _index(best, axis) == span[1])


def _row_search(march, row, span, side, axis) -> list[ModeValue]:
    """The modes one family row's geometric sampling and refinement marched, its best
    first among them (NoBifurcationFound where none of its samples bifurcates)."""
    edge, cap = span
    samples = geometric_samples(edge, cap)
    seen = list(march(samples, [row]))
    best = seen[0]
    lo, hi = neighbours(samples, _index(best, axis))
    while hi - lo > 1:  # (at the cap too: the minimum may lie just below it)
        inner = refine_samples(lo, hi)
        complete = len(inner) == hi - lo - 1  # every integer of the bracket is marched
        try:
            got = list(march(inner, [row]))
        except NoBifurcationFound:  # none of them before the end of the march: best stands
            break
        seen += got
        if _earlier(got[0], best, side):
            best = got[0]
        lo, hi = neighbours([lo, *inner, _index(best, axis), hi], _index(best, axis))
        if complete:
            break
    return seen


def _neighbourhood(march, rows, seen, best, span, top, axis) -> list[ModeValue]:
    """The integers within top - 1 of the best that the refinement skipped (a bracket's
    samples are spaced, and it followed the best's row alone), marched on every row so
    that the runners-up are the next modes (a film's (115, 1) comes before (117, 0) of the
    best's row, probe round 6b)."""
    at, wide = _index(best, axis), min(top - 1, NEIGHBOURS)
    done = {(_index(v, axis), _fixed(v, axis), _code(v)) for v in seen}
    near = range(max(span[0], at - wide), min(span[1], at + wide) + 1)
    todo = [k for k in near if any((k, *row) not in done for row in rows)]
    if not todo:
        return []
    try:
        return list(march(todo, sorted(rows), top=top))
    except NoBifurcationFound:
        return []


def _near_rows(rows, best: ModeValue, m_span: tuple[int, int], top: int) -> set:
    """``rows`` and the wrinkle rows (m, n >= 1) of m within top - 1 of the best's, inside
    ``m_span``: a ring (0, 587) of a film has (1, 587), (2, 587), (1, 586) and (3, 587)
    before its own row's (0, 585) (probe round 8a), as the m search's neighbourhood has the
    other n rows (round 6b)."""
    wide = min(top - 1, NEIGHBOURS)
    lo, hi = max(m_span[0], best.m - wide), min(m_span[1], best.m + wide)
    return set(rows) | {(m, Family.WRINKLE.code) for m in range(lo, hi + 1)}


def _first(params, solve_for, side, rows, rtol, ks, only=None, *, axis="m", top=3):
    """The first ``top`` modes to bifurcate among index k in ``ks`` (m or n, ``axis``) of the
    rows (``only`` rows instead, if given), finished at ``rtol``; NoBifurcationFound if none
    does."""
    pairs = only or rows
    if axis == "m":
        modes = [(k, n, code) for k in ks for n, code in pairs]
    else:
        modes = [(m, k, code) for k in ks for m, code in pairs]
    modes = np.array([mode for mode in modes if _is_mode(*mode)], float).reshape(-1, 3)
    if not len(modes):
        raise NoBifurcationFound(f"no mode with {axis} in {ks[0]}..{ks[-1]} on these rows")
    loose = ImpedanceTarget(SCAN_SIGNS)
    fine = ImpedanceTarget(rtol)
    stable = ImpedanceTarget(SCAN_STABLE_SIGNS)
    res = first_bifurcations(
        params,
        solve_for,
        side,
        modes,
        loose,
        top=top,
        brent_targets=fine,
        stable_signs=_stable(modes, stable),
    )
    if not res.found:
        raise NoBifurcationFound(f"no mode with {axis} in {ks[0]}..{ks[-1]} bifurcates")
    return res.found


def _is_mode(m, n, code) -> bool:
    """Is (m, n) of family ``code`` a mode? A search from an edge m = 1 (or 0) on the
    prismatic row would otherwise march (1, 0), a rigid translation of the cross-section, or
    (0, 0), the base state's own limit point: the march then reads the unloaded tube as
    already unstable (probe 8b, D11)."""
    return m >= 2 if code == Family.PRISMATIC.code else n >= 1  # as incremental.check_mode


def _stable(modes, targets):
    return unloaded_signs(SIGN_TUBE, modes, targets)


def _code(v: ModeValue) -> int:
    return Family(v.family).code


def _index(v: ModeValue, axis: str) -> int:
    """The searched wavenumber of v: m or n."""
    return v.m if axis == "m" else v.n


def _fixed(v: ModeValue, axis: str) -> int:
    """The wavenumber of v's row, fixed in the search: n or m."""
    return v.n if axis == "m" else v.m


def neighbours(ms, m) -> tuple[int, int]:
    """The samples either side of m in the sorted ``ms`` (m itself at an end)."""
    ms = sorted(set(ms))
    i = ms.index(m)
    return ms[max(i - 1, 0)], ms[min(i + 1, len(ms) - 1)]


def _sense(side) -> float:
    return -1.0 if side == "compression" else 1.0


def _earlier(a: ModeValue, b: ModeValue, side) -> bool:
    """Is a reached before b along the march?"""
    return _sense(side) * a.value < _sense(side) * b.value
