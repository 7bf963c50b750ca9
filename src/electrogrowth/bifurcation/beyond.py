"""Modes beyond a scan's ranges: is one of them unstable at a given value?

A scan marches every mode of its ranges (m <= 12, n <= 30 by default, widened while the
best sits on an edge or a short-wave probe wins), but a thin stiff film folds at m or n in
the hundreds to thousands (the flat film's wavelength, docs/derivation-film.md), far from
the ranges and their probes. When a low mode of the whole tube comes after the film's
folds but before the probes (Euler buckling (1, 1) of a long tube, the collapse (2, 0)
under an external pressure), nothing in the ranges points beyond them. So the scan asks
here, at the value it is about to report: along each axis, geometric samples (msearch's,
ratio 1.25) from the edge of the range to the cap, on the rows where a film's folds lie

* along m: the prismatic modes (m, 0) and the wrinkles (m, n_lo) of the smallest n, every
  m up to EVERY_M = 64 (a skin's folds (35, 0) 2.6e-4 before its rings, unstable between
  the samples m = 29 and 37 only, were missed: probe round 6b);
* along n: the rings (m_lo, n) of the smallest m (axisymmetric at m = 0) and (m_lo + 1, n);

their targets at that one state against their signs on the unloaded tube, where every
mode is stable (docs/derivation.md section 3). A sample past its root starts the search
of that axis (msearch.py). One base state and a batch of ~60 loose modes (~30 ms); it
reads a band of unstable folds, which near a film's optimum spans many samples, not a
single mode unstable alone between two samples.
"""

from __future__ import annotations

import functools

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import ElectrogrowthError
from ..incremental.accuracy import SCAN_STABLE_SIGNS
from ..incremental.modes import MODE_MAX
from ..incremental.targets import Family, ImpedanceTarget
from .march import SIGN_TUBE, unloaded_signs
from .msearch import geometric_samples
from .options import EVERY_M, M_CAP, N_CAP, mode_caps


def beyond_rows(
    m_range, n_range, prismatic: bool, axis: str, caps: tuple[int, int] = (M_CAP, N_CAP)
) -> np.ndarray:
    """Rows (m, n, family code) sampled beyond the ranges along ``axis`` up to its cap
    (``caps``: the tube's, options.mode_caps; module docstring); empty when that range
    already reaches its cap."""
    (m_lo, m_hi), (n_lo, n_hi) = m_range, n_range
    m_cap, n_cap = caps
    _wrinkle, _prismatic = Family.WRINKLE.code, Family.PRISMATIC.code
    if axis == "m":
        if m_hi >= m_cap:
            return np.zeros((0, 3))
        rows = [(max(n_lo, 1), _wrinkle)] + ([(0, _prismatic)] if prismatic else [])
        # every m up to EVERY_M (the scan's own rule: small m are irregular), then samples
        every = list(range(m_hi + 1, min(EVERY_M, m_cap) + 1))
        ms = every + geometric_samples(max(m_hi + 1, EVERY_M + 1), m_cap)
        return np.array([(m, n, code) for m in ms for n, code in rows], float)
    if n_hi >= n_cap:
        return np.zeros((0, 3))
    ns = geometric_samples(max(n_hi + 1, 1), n_cap)
    return np.array([(m, n, _wrinkle) for n in ns for m in (m_lo, m_lo + 1)], float)


@functools.lru_cache(maxsize=64)
def _stable(rows: bytes, count: int) -> np.ndarray:
    """The signs of the rows (their float64 bytes, ``count`` of them) on the unloaded tube,
    remembered: they are the same for every tube (scan_grid.stable_signs)."""
    modes = np.frombuffer(rows, dtype=float).reshape(count, 3)
    return unloaded_signs(SIGN_TUBE, modes, ImpedanceTarget(SCAN_STABLE_SIGNS))


def unstable_beyond(
    params, solve_for: str, value: float, m_range, n_range, prismatic: bool, axes=("m", "n")
) -> dict[str, bool]:
    """For each axis of ``axes``: is a sampled mode beyond the ranges past its root at
    ``value`` (its target's sign there against the unloaded tube's)? False where the state
    at ``value`` does not resolve (no evidence either way: the result stands)."""
    caps = mode_caps(params)
    rows = {axis: beyond_rows(m_range, n_range, prismatic, axis, caps) for axis in axes}
    modes = np.vstack([rows[axis] for axis in axes])
    out = dict.fromkeys(axes, False)
    turned = _turned(params, solve_for, value, modes)
    if turned is None:
        return out
    start = 0
    for axis in axes:
        stop = start + rows[axis].shape[0]
        out[axis] = bool(turned[start:stop].any())
        start = stop
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
    stable = _stable(np.ascontiguousarray(modes).tobytes(), modes.shape[0])
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
