"""The error estimate of a critical value (bifurcation/critical.py): the distance from the
value to the root of the same mode's target at a second resolution, and at least the floor
the target's rounding puts under any root (measured at the value: collocation's dense
determinant with the fine target, the kernel's with the second resolution's).
"""

from __future__ import annotations

import math

from ..continuation.events import Remembered, brent, widening_windows


def second_resolution(g_coarse, value: float, path: tuple[float, float]) -> float:
    """|root of the 100x looser target - value|: the error estimate of the value.

    First by the secant (:func:`secant_estimate`, 2-3 evaluations), which stands only on a
    sign change it has seen; otherwise the root is searched in widening windows around the
    value, clipped to the march's ``path`` (start, end): the probes stay in the control's
    domain (a window of +-4.2 put a growth at -0.16), and a root before the start is not
    this one. Without a root in the widest window the estimate is that window's half-width
    (the looser root is at least that far): an uncertified value, not a failure. Where the
    looser target is not positive at the path's start, its root is the start (as a march
    reports it, continuation.events.first_roots), known to :func:`start_floor`.

    The secant's distance is at least the second resolution's rounding noise over its slope
    (:func:`rounding_floor`, two more evaluations): a long tube's Euler mode (L = 200, a
    critical force -3.6e-3) has a target of ~1e-15 over the window, rounding noise of 5e-16
    and a slope of 7e-6, so its roots are known to ~7e-11 while a single secant sampled that
    noise once (2e-12 to 5e-11 at four rtol)."""
    g_coarse = Remembered(g_coarse)  # Brent evaluates a window's ends again
    fast = secant_estimate(g_coarse, value, path)
    if fast is not None:
        return max(fast, rounding_floor(g_coarse, value, path, NOISE_OFFSETS))
    bounds = (min(path), max(path))
    windows = list(widening_windows(value, SECANT_STEP * max(1.0, abs(value)), 12, bounds=bounds))
    for lo, hi, _ in windows:
        if lo < hi and g_coarse(lo) * g_coarse(hi) < 0:
            return abs(brent(g_coarse, lo, hi) - value)
    if g_coarse(path[0]) <= 0:  # its root is the start, as a march reports it (not NaN)
        return max(abs(value - path[0]), start_floor(g_coarse, path))
    return windows[-1][2]  # the widest window's half-width


#: a value solved at ``rtol`` is not known better than ACHIEVED rtol |value|, whatever its
#: second resolution says: the kernel's rtol is a local tolerance, and the error it leaves in
#: a value accumulates over the steps (probe 9a D3: 1.2 rtol |value| at rtol 1e-12 with two
#: resolutions 2e-16 apart). Not more: the floor decides the estimate of many values (the
#: paper's tube, growth, (0, 1): 1.4e-12 -> 6.3e-12 for an error of 1.6e-14), and an
#: overstated estimate costs printed digits. A film's (135, 3) at rtol 1e-10 is 10 rtol
#: |value| off, twice this floor (its second resolution covers it at 1e-11 and 1e-12):
#: docs/derivation.md section 6
ACHIEVED = 5.0


def achieved_floor(value: float, rtol: float) -> float:
    """The least error estimate of a value solved at ``rtol``: ACHIEVED rtol |value|. Two
    resolutions 100x apart can share their error: a film's (67, 0) at rtol 1e-12 and at
    1e-10 landed 2e-16 apart, both 1.2e-12 from the value at 1e-14 (probe 9a, D3). Relative
    to |value|, not max(1, |value|): the kernel's tolerance is relative, and a critical force
    of 6e-5 known to 2e-14 is not to be reported as known to 1e-11 (the CLI prints the digits
    the estimate supports). A small value whose error is larger still, an absolute one, is
    the second resolution's to show. docs/derivation.md section 6."""
    return ACHIEVED * rtol * abs(value)


def start_floor(g, path: tuple[float, float]) -> float:
    """How far from the path's start a root of g reported at the start (g not positive
    there: continuation.events.first_roots) may lie: |g(start)| over g's slope along the
    first SECANT_STEP max(1, |start|) of the path, its Newton step from the start (0 where
    the slope is not read). A film at its fold at P_i = 0 has a target of 4e-15 there on
    a slope of 0.24: its root is known within 2e-14 of the start, not exactly (probe 12b,
    D3)."""
    start, end = path
    h = math.copysign(min(SECANT_STEP * max(1.0, abs(start)), abs(end - start)), end - start)
    g0, g1 = g(start), g(start + h)
    slope = (g1 - g0) / h
    if not (math.isfinite(slope) and slope != 0.0 and math.isfinite(g0)):
        return 0.0
    return abs(g0 / slope)


#: the secant's step back towards the path's start, and the first window's half-width,
#: relative to max(1, |value|)
SECANT_STEP = 1e-6


def secant_estimate(g, value: float, path: tuple[float, float]) -> float | None:
    """The distance from ``value`` to the root of g (positive at the path's start) by the
    secant through g at the value and a step SECANT_STEP max(1, |value|) = h back towards
    the start, or None where the secant is not backed by a sign change within h.

    The root x_c of g is |value - x_c| = d ~ 1e-11 from the value (the two targets are 100x
    apart in accuracy), where g is a straight line to O(d h g''/g'): the secant's distance
    equals the root's to ~1e-4 relative, the digits an error estimate has (Brent located
    x_c to 2e-15 |value|). It is returned only when g changes sign between the value and the
    step back (the root is then interpolated) or between the value and twice the
    extrapolated distance beyond it, at least the rounding floor's 1e-12 max(1, |value|)
    (one more evaluation, or none): a root of g lies there, as near as the secant says.
    Farther than STRAIGHT h from the value, one more evaluation at the secant's root checks
    that g is a straight line over h: a stiff film's target turns from one plateau to the
    other within 1e-8 of the root, where the secant would put the root at h / 2.
    docs/derivation.md section 6."""
    lo, hi = min(path), max(path)
    sense = 1.0 if path[1] >= path[0] else -1.0
    h = SECANT_STEP * max(1.0, abs(value))
    back = value - sense * h
    if not lo <= back <= hi:
        return None
    g0 = g(value)
    if g0 == 0.0:
        return 0.0
    g1 = g(back)
    if not (math.isfinite(g0) and math.isfinite(g1)) or g1 <= 0.0 or g1 == g0:
        return None
    d = h * g0 / (g1 - g0)  # the secant's root lies at value + sense d
    if g0 >= 0.0:  # the root is beyond the value: it must be bracketed there
        # not nearer than the rounding floor's read (the same point: no evaluation more),
        # where a root d ~ 1e-15 away is within the target's noise and 2 d may not bracket it
        beyond = value + sense * max(2.0 * d, NOISE_OFFSETS[-1] * max(1.0, abs(value)))
        if not (0.0 < d <= h and lo <= beyond <= hi) or g(beyond) >= 0.0:
            return None
    if abs(d) > STRAIGHT * h and abs(g(value + sense * d)) > STRAIGHT * max(abs(g0), g1):
        return None  # not a straight line over h: a steep step (a stiff film's target)
    return abs(d)


#: The secant is taken on trust while the root lies within STRAIGHT h of the value (then g
#: changes across h by ~1/STRAIGHT times its value there: a straight line, or the distance
#: is overstated, never understated); farther, g at the secant's root must be below
#: STRAIGHT times its values at the ends, else Brent's windows decide.
STRAIGHT = 1e-3


def collocation_floor(g, value: float, path: tuple[float, float]) -> float:
    """How far collocation's own root may be from ``value``: the larger of its secant's
    distance (:func:`secant_estimate`: two resolutions share the determinant's rounding,
    flat over ~1e-10 about the root) and its rounding noise (:func:`rounding_floor`) at
    ROUNDING_OFFSETS. A film 0.005 thick and 4425 times stiffer (mode (16, 0)) has
    departures of 1e-16 on a slope of 6e-10 at 56 nodes: 2e-7, where its roots scatter by
    2e-8 with the node count and the base state's last digits, and the two resolutions had
    agreed to 2e-10 (docs/derivation.md section 6)."""
    secant = secant_estimate(g, value, path) or 0.0
    return max(secant, rounding_floor(g, value, path, ROUNDING_OFFSETS))


def rounding_floor(g, value: float, path: tuple[float, float], offsets) -> float:
    """The distance within which a root of g is not known for its rounding: the largest
    departure of g at ``offsets`` max(1, |value|) about the value (where the true g is a
    straight line to ~1e-18) from the line through g at the value with the slope of the
    secant back SECANT_STEP max(1, |value|) towards the path's start, over that slope. For a
    well-conditioned target the floor is ~1e-15; 0 where the line is not available."""
    lo, hi = min(path), max(path)
    scale = max(1.0, abs(value))
    h = SECANT_STEP * scale
    sense = 1.0 if path[1] >= path[0] else -1.0
    back = value - sense * h
    if not lo <= back <= hi:
        return 0.0
    g0, g1 = g(value), g(back)
    slope = (g0 - g1) / (sense * h)
    if not (math.isfinite(slope) and slope != 0.0):
        return 0.0
    departure = 0.0
    for t in offsets:
        x = value + t * scale
        if lo <= x <= hi:
            departure = max(departure, abs(g(x) - g0 - slope * (x - value)))
    return departure / abs(slope) if math.isfinite(departure) else 0.0


#: offsets (relative to max(1, |value|)) at which collocation's rounding noise is read
ROUNDING_OFFSETS = (-2e-12, -1e-12, 1e-12, 2e-12)
#: ... and the second resolution's (two reads: they are paid by every critical value)
NOISE_OFFSETS = (-1e-12, 1e-12)
