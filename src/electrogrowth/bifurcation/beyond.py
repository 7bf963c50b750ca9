"""Modes beyond a scan's ranges: is one of them unstable at a given value?

A scan marches every mode of its ranges (m <= 12, n <= 30 by default, widened while the
best sits on an edge or a short-wave probe wins), but a thin stiff film folds at m or n in
the hundreds to thousands (the flat film's wavelength, docs/derivation-film.md), far from
the ranges and their probes. When a low mode of the whole tube comes after the film's
folds but before the probes (Euler buckling (1, 1) of a long tube, the collapse (2, 0)
under an external pressure), nothing in the ranges points beyond them. So the scan asks
here, at the value it is about to report: along each axis, geometric samples (msearch's,
ratio 1.25) from the edge of the range to the cap, on the rows where a film's folds lie

* along m: the wrinkles (m, n_lo) of the smallest n and the prismatic modes (m, 0), every
  m up to EVERY_M = 64 (a skin's folds (35, 0) 2.6e-4 before its rings, unstable between
  the samples m = 29 and 37 only, were missed: probe round 6b), and the wrinkles of every
  n up to the largest n of the scan's first modes (its critical mode and runners-up) + 1:
  a film's first modes lie about a circle (m / R)^2 + (n pi / L)^2 ~ k^2 of its own
  wavenumber, so a row of smaller n has its least m beyond theirs (a film in a thin wall:
  (15, 4) 3.8e-4 before the scanned (11, 5), on neither row above, check round 35d Q3);
* along n: the rings (m_lo, n) of the smallest m (axisymmetric at m = 0) and (m_lo + 1, n),
  and likewise the rows of every m up to their largest m + 1;

where those are many, the rows next to each of those modes and geometric samples between;
their targets at that one state against their signs on the unloaded tube, where every mode is
stable (docs/derivation.md section 3). A row with a sample past its root is searched
(msearch.py), with the rows the search follows anyway. A fold's dip is narrow when its
mode comes just before the value read (the fold (89, 0) 1.8e-9 before a runner-up of its
ring (0, 1), unstable at m = 88, 89 only, between the samples 81 and 101: check round
35d Q7), so the two fold rows are also read densely (relative spacing DENSE = 1 %, every
index where that is below one) inside each stiff layer's fold window: its flat film's
fold number k h ~ (3 mu_s / mu_f)^(1/3) (k = m / R, or n pi / L) times 1 / WINDOW to
WINDOW. One base state and a batch of ~100-1000 loose modes (~0.2 ms each); a band of
unstable modes narrower than those spacings is still not seen (docs/reliability.md).
"""

from __future__ import annotations

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import ElectrogrowthError
from ..incremental.accuracy import SCAN_STABLE_SIGNS
from ..incremental.modes import MODE_MAX
from ..incremental.targets import Family, ImpedanceTarget
from .march import SIGN_TUBE, unloaded_signs
from .msearch import geometric_samples
from .options import EVERY_M, M_CAP, N_CAP, mode_caps

#: rows read besides the fold rows and those next to the scan's first modes, at most
ROWS_MAX = 8
#: a layer's fold window: its flat film's fold number times 1 / WINDOW to WINDOW
WINDOW = 2.5
#: the relative spacing of the samples inside a fold window (every index where it is < 1)
DENSE = 1.01


def read_rows(modes, m_range, n_range, prismatic: bool, axis: str) -> list[tuple[int, int]]:
    """The family rows read beyond the ranges along ``axis`` ((n, code) along m, (m, code)
    along n), the fold rows first (module docstring): along m the wrinkles of the smallest
    n and the prismatic row, then the wrinkles of every n up to the largest n of the
    wrinkles among ``modes`` (the scan's critical mode and runners-up) + 1; along n the rows
    of the smallest m and the next, then every m up to their largest m + 1. Where those
    are more than ROWS_MAX: the rows next to each of ``modes`` and ROWS_MAX - 3 geometric
    samples between."""
    wrinkle = Family.WRINKLE.code
    own = [(v.n if axis == "m" else v.m) for v in modes if v.family == Family.WRINKLE]
    if axis == "m":
        low = max(n_range[0], 1)
        rows = [(low, wrinkle)] + ([(0, Family.PRISMATIC.code)] if prismatic else [])
        first = low + 1
    else:
        low = m_range[0]
        rows = [(low, wrinkle), (low + 1, wrinkle)]
        first = low + 2
    return rows + [(k, wrinkle) for k in _between(first, own)]


def searched_rows(critical, m_range, n_range, prismatic: bool, axis: str) -> set:
    """The family rows a search beyond the ranges follows whatever the read turned
    (scan._searched; certify reads them too): along m the wrinkles of the smallest n, the
    prismatic row and the critical mode's own row, along n the rows of the smallest m
    (axisymmetric rings at m = 0) and the critical mode's own. ``critical`` is the scan's
    critical point, or None where it is no finite mode."""
    code = None if critical is None else Family(critical.family).code
    if axis == "m":
        rows = {(max(n_range[0], 1), Family.WRINKLE.code)}
        if prismatic:
            rows.add((0, Family.PRISMATIC.code))
        if critical is not None and critical.family != Family.TORSIONAL:  # torsion: m = 0
            rows.add((critical.n, code))
        return rows
    rows = {(m_range[0], Family.WRINKLE.code)}
    if critical is not None and critical.family != Family.PRISMATIC:  # prismatic: n = 0
        rows.add((critical.m, code))
    return rows


def _between(lo: int, own: list[int]) -> list[int]:
    """lo up to max(own) + 1, or where that is more than ROWS_MAX, the indices next to each
    of ``own`` (their optima lie nearest the modes found) and geometric samples between."""
    if not own or max(own) + 1 < lo:
        return []
    hi = max(own) + 1
    if hi - lo + 1 <= ROWS_MAX:
        return list(range(lo, hi + 1))
    inner = np.geomspace(lo, hi, ROWS_MAX - 3).round().astype(int).tolist()
    near = [k + d for k in own for d in (-1, 0, 1) if k + d >= lo]
    return sorted({*inner, *near, hi})


def fold_windows(tube, axis: str) -> list[tuple[int, int]]:
    """The index windows (m along m, n along n) about the flat-film folds of each layer
    stiffer than a neighbour (module docstring): k h ~ (3 mu_s / mu_f)^(1/3), k = m / R
    across the tube and n pi / L along it, for a layer of thickness h at mid-radius R,
    within a factor WINDOW either way (the exact flat film, curvature and growth move it
    by less: docs/derivation-film.md). None for a uniform tube, nor where no layer is
    stiffer than a neighbour."""
    if tube.is_uniform:
        return []
    radii, layers = tube.radii, tube.layers
    out = []
    for i, layer in enumerate(layers):
        h, mid = radii[i + 1] - radii[i], 0.5 * (radii[i + 1] + radii[i])
        for j in (i - 1, i + 1):
            if not 0 <= j < len(layers) or layers[j].shear_modulus >= layer.shear_modulus:
                continue
            k = (3.0 * layers[j].shear_modulus / layer.shear_modulus) ** (1.0 / 3.0) / h
            at = k * mid if axis == "m" else k * tube.length / np.pi
            out.append((max(1, int(at / WINDOW)), int(np.ceil(at * WINDOW))))
    return out


def window_samples(windows, edge: int, cap: int) -> list[int]:
    """The indices of ``windows`` in (edge, cap], at relative spacing DENSE (every one
    where that spacing is below one)."""
    out: set[int] = set()
    for lo, hi in windows:
        lo, hi = max(lo, edge + 1), min(hi, cap)
        if lo > hi:
            continue
        k = lo
        out.add(k)
        while k < hi:
            k = min(hi, max(k + 1, int(k * DENSE)))
            out.add(k)
    return sorted(out)


def beyond_rows(
    m_range,
    n_range,
    prismatic: bool,
    axis: str,
    caps: tuple[int, int] = (M_CAP, N_CAP),
    rows=None,
    windows=(),
) -> np.ndarray:
    """Modes (m, n, family code) read beyond the ranges along ``axis`` up to its cap
    (``caps``: the tube's, options.mode_caps): on each of ``rows`` (default :func:`read_rows`
    of no modes: the fold rows) every index to EVERY_M along m, then geometric samples; on the
    fold rows (the first of ``rows``: read_rows) also the indices of the fold ``windows``
    (:func:`window_samples`). Empty when that range already reaches its cap."""
    rows = read_rows((), m_range, n_range, prismatic, axis) if rows is None else rows
    edge, cap = (m_range[1], caps[0]) if axis == "m" else (n_range[1], caps[1])
    if edge >= cap:
        return np.zeros((0, 3))
    if axis == "m":  # every m up to EVERY_M (the scan's own rule: small m are irregular)
        every = list(range(edge + 1, min(EVERY_M, cap) + 1))
        ks = every + geometric_samples(max(edge + 1, EVERY_M + 1), cap)
    else:
        ks = geometric_samples(edge + 1, cap)
    dense = sorted(set(window_samples(windows, edge, cap)) - set(ks))
    modes = [(k, *row) for k in ks for row in rows]
    folds = rows[:2] if axis == "n" or prismatic else rows[:1]
    modes += [(k, *row) for k in dense for row in folds]
    if axis == "n":
        modes = [(m, k, code) for k, m, code in modes]
    else:
        modes = [(k, n, code) for k, n, code in modes]
    return np.array(modes, float).reshape(-1, 3)


#: the signs of modes on the unloaded tube, remembered mode by mode (at most SIGNS_KEPT):
#: they are the same for every tube (scan_grid.stable_signs), and the rows read change
#: with the critical mode from one scan of a sequence to the next
_SIGNS: dict[tuple[float, float, float], float] = {}
SIGNS_KEPT = 200_000


def _stable(modes: np.ndarray) -> np.ndarray:
    """The signs of ``modes`` on the unloaded tube, those not yet known computed together."""
    keys = [tuple(row) for row in modes.tolist()]
    todo = [key for key in dict.fromkeys(keys) if key not in _SIGNS]
    if todo:
        if len(_SIGNS) + len(todo) > SIGNS_KEPT:
            _SIGNS.clear()
        target = ImpedanceTarget(SCAN_STABLE_SIGNS)
        signs = unloaded_signs(SIGN_TUBE, np.array(todo, float), target)
        _SIGNS.update(zip(todo, signs.tolist(), strict=True))
    return np.array([_SIGNS[key] for key in keys], float)


def unstable_beyond(
    params,
    solve_for: str,
    value: float,
    m_range,
    n_range,
    prismatic: bool,
    axes=("m", "n"),
    modes=(),
) -> dict[str, list[tuple[int, int]]]:
    """For each axis of ``axes``: the family rows (:func:`read_rows` of ``modes``, the
    scan's critical mode and runners-up, if any) with a mode beyond the ranges past its
    root at ``value`` (its target's sign there against the unloaded tube's), empty where
    none is, or where the state at ``value`` does not resolve (no evidence either way: the
    result stands)."""
    caps = mode_caps(params)
    rows = {axis: read_rows(modes, m_range, n_range, prismatic, axis) for axis in axes}
    read = {
        axis: beyond_rows(
            m_range, n_range, prismatic, axis, caps, rows[axis], fold_windows(params, axis)
        )
        for axis in axes
    }
    out: dict[str, list[tuple[int, int]]] = {axis: [] for axis in axes}
    turned = _turned(params, solve_for, value, np.vstack([read[axis] for axis in axes]))
    if turned is None:
        return out
    start = 0
    for axis in axes:
        count = read[axis].shape[0]
        past = read[axis][turned[start : start + count]]
        start += count
        fixed = 1 if axis == "m" else 0  # the row's own index: n along m, m along n
        out[axis] = sorted({(int(mode[fixed]), int(mode[2])) for mode in past})
    return out


def _turned(params, solve_for: str, value: float, modes: np.ndarray) -> np.ndarray | None:
    """Which of ``modes`` are past their roots at ``value`` (their targets' signs there
    against the unloaded tube's); None where there are none to read or the state at
    ``value`` does not resolve (no evidence either way)."""
    if not modes.shape[0]:
        return None
    try:
        state = solve_base_state(params.at(solve_for, value))
        now = ImpedanceTarget(SCAN_STABLE_SIGNS)(state, modes)
    except ElectrogrowthError:
        return None
    stable = _stable(modes)
    return np.isfinite(now) & (np.sign(now) != stable)


#: how far past the caps :func:`unstable_past_cap` reads (at most to MODE_MAX): a layer's
#: rows reach its face's limit from below past its folds, so a fold beyond the caps turns
#: every sample from there on at the limit (a lining 1e-3 thick: m ~ 6000 to 13000, check
#: round 34, when the caps were 2000 for every tube)
PAST_CAP = 64


def past_cap_rows(prismatic: bool, caps: tuple[int, int] = (M_CAP, N_CAP)) -> np.ndarray:
    """Rows beyond the caps (``caps``: the tube's, options.mode_caps), geometric samples
    (ratio 1.25) from just past each to PAST_CAP times it (at most MODE_MAX): along m the
    prismatic folds (m, 0) and the wrinkles (m, 1), along n the rings (0, n) and (1, n)."""
    _wrinkle, _prismatic = Family.WRINKLE.code, Family.PRISMATIC.code
    m_cap, n_cap = caps
    ms = geometric_samples(m_cap + 1, min(PAST_CAP * m_cap, MODE_MAX)) if m_cap < MODE_MAX else []
    ns = geometric_samples(n_cap + 1, min(PAST_CAP * n_cap, MODE_MAX)) if n_cap < MODE_MAX else []
    along_m = [(m, 1, _wrinkle) for m in ms] + [(m, 0, _prismatic) for m in ms if prismatic]
    along_n = [(m, n, _wrinkle) for n in ns for m in (0, 1)]
    return np.array(along_m + along_n, float).reshape(-1, 3)


def unstable_past_cap(params, solve_for: str, value: float, prismatic: bool):
    """The first sampled mode (m, n) beyond the caps that is past its root at ``value``,
    else None. The scan resolves modes up to the caps only; where its result is a face's
    short-wave limit, a lining too thin for the caps may fold beyond them first: its
    rows tend to the limit from below (probe 13b's O(1/k) corrections), and a fold
    near m = 13000 came 5.6e-5 before the limit of a lining 1e-3 thick, 1e4 times softer
    than its tube, with status OK (check round 34, when every tube's caps were 2000; its
    caps are now its own, options.mode_caps, and the search finds the fold). One state,
    ~80 modes."""
    modes = past_cap_rows(prismatic, mode_caps(params))
    turned = _turned(params, solve_for, value, modes)
    if turned is None or not turned.any():
        return None
    m, n, _ = modes[int(np.argmax(turned))]
    return int(m), int(n)
