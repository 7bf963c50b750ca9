"""The zero curve of a scalar function of two variables, by pseudo-arclength continuation.

A curve d(u) = 0, u = (u_1, u_2) in the unit square (the caller scales its two variables
to [0, 1]), is followed from a point on it along its tangent t: the predictor is
p = u_k + h t, and the corrector solves d = 0 on the line through p orthogonal to t,
p + s t_perp, by Brent's method (events.brent, tolerance :data:`CONTOUR`). That line is the
pseudo-arclength condition t . (u - p) = 0 of the two-unknown system

    d(u) = 0,   t . (u - p) = 0,

solved here without a Jacobian: the one unknown left on the line is bracketed and
converged to 1e-13, so the corrected point is on the curve to the accuracy of d itself. The
first tangent is the caller's (e.g. from the gradient of d: t = (-d_2, d_1) / |grad d|);
after that it is the secant of the last two points. The step h follows a
:class:`~.path.StepPolicy` (:data:`CONTOUR_STEPS`): it doubles up to ``largest`` while the
curve turns by less than :data:`SMOOTH` radians a step, and halves (down to ``smallest``)
when the corrector fails, lands further than half a step from the prediction, or turns
by more than :data:`TURN` (the first step, whose tangent may be a rough guess, may land
:data:`FIRST_OFF` steps off). A function that jumps across the curve (an indicator, +-1) is
followed the same way: Brent's method then locates its jump.

The trace ends at the edge of the square (the exit located on the edge, by Brent's method
along it), where it closes on its start, where the caller's ``stop`` says so (an event,
e.g. a third mode coming first: the caller locates it), or where it is lost (no root near
the prediction at the smallest step). docs/design.md.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from ..errors import ElectrogrowthError
from .events import Tolerance, brent
from .path import StepPolicy

#: the curve's steps, in units of the square's side
CONTOUR_STEPS = StepPolicy(smallest=2e-4, first=0.02, largest=0.08)
#: the corrector's root on its line, in units of the square's side
CONTOUR = Tolerance(1e-13, 1e-15, 200, "absolute")
SMOOTH = 0.05  # a step turning by less than this (radians) lets the next one double
TURN = 0.35  # a step turning by more than this is taken again at half the length
FIRST_OFF = 2.0  # the first corrector may move this many steps off the first tangent
MAX_POINTS = 400

EDGE, CLOSED, STOPPED, LOST = "edge", "closed", "stopped", "lost"


@dataclasses.dataclass(frozen=True)
class Trace:
    """The points of a traced curve in order (unit square), how it ended (``end``: EDGE,
    CLOSED, STOPPED or LOST) and, if STOPPED, the first point past the event (``past``) and
    what ``stop`` returned there (``event``)."""

    points: tuple[tuple[float, float], ...]
    end: str
    past: tuple[float, float] | None = None
    event: object = None


def _inside(u) -> bool:
    return -1e-15 <= u[0] <= 1 + 1e-15 and -1e-15 <= u[1] <= 1 + 1e-15


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / math.hypot(*v)


def _root_on_line(d, p, e, width: float):
    """A root of d on p + s e nearest to s = 0 within |s| <= width (clipped to the square),
    or None."""
    lo, hi = -width, width
    for i in range(2):  # the line clipped to the square
        if abs(e[i]) > 1e-14:
            a, b = sorted(((0.0 - p[i]) / e[i], (1.0 - p[i]) / e[i]))
            lo, hi = max(lo, a), min(hi, b)
    if not lo < hi:
        return None
    f0 = d(p)
    if f0 == 0.0:
        return p
    for frac in (0.125, 0.25, 0.5, 1.0):
        for sgn in (1.0, -1.0):
            s = sgn * frac * width
            if not lo <= s <= hi:
                s = hi if sgn > 0 else lo
            fs = d(p + s * e)
            if fs * f0 < 0:
                a, b = sorted((0.0, s))
                root = brent(lambda t: d(p + t * e), a, b, CONTOUR, ref=0.0)
                return p + root * e
    return None


def _exit(d, x, t, h):
    """Where the curve leaves the square near the ray x + s t (s <= h): the root of d on the
    edge that ray hits, within h of the hit; None if d does not change sign there."""
    s_hit, axis = math.inf, 0
    for i in range(2):
        if abs(t[i]) > 1e-14:
            s = ((1.0 if t[i] > 0 else 0.0) - x[i]) / t[i]
            if s < s_hit:
                s_hit, axis = s, i
    hit = x + s_hit * t
    hit[axis] = round(hit[axis])
    along = np.zeros(2)
    along[1 - axis] = 1.0
    return _root_on_line(d, hit, along, h)


def trace_contour(
    d: Callable[[np.ndarray], float],
    start,
    tangent,
    *,
    policy: StepPolicy = CONTOUR_STEPS,
    stop: Callable[[np.ndarray], object] | None = None,
    max_points: int = MAX_POINTS,
) -> Trace:
    """Follow d(u) = 0 in the unit square from ``start`` (a root) along ``tangent``.

    Parameters
    ----------
    d : callable u -> float
        The scalar condition; may raise ElectrogrowthError where it cannot be evaluated
        (the step is then shortened).
    start, tangent : pairs of floats
        A point of the curve and the direction to go.
    stop : callable u -> object, optional
        Called at each new point; a result other than None ends the trace (STOPPED) with
        that point as ``past``, not among the points.

    Returns
    -------
    Trace
    """
    x = np.asarray(start, float)
    t = _unit(tangent)
    pts = [tuple(x)]
    h = policy.first
    while len(pts) < max_points:
        p = x + h * t
        on_edge = min(x[0], x[1], 1 - x[0], 1 - x[1]) <= 1e-14
        if not _inside(p) and len(pts) == 1 and on_edge:
            return Trace(tuple(pts), EDGE)  # a start on the edge, heading out of the square
        if not _inside(p):
            try:
                q = _exit(d, x, t, h)
            except ElectrogrowthError:
                q = None
            if q is not None and np.linalg.norm(q - x) <= 1.5 * h:
                pts.append(tuple(q))
                return Trace(tuple(pts), EDGE)
            if h <= policy.smallest:
                return Trace(tuple(pts), LOST)
            h = max(h / 2, policy.smallest)
            continue
        first = len(pts) == 1  # the first tangent may be rough (an edge's normal)
        try:
            q = _root_on_line(d, p, np.array([-t[1], t[0]]), (FIRST_OFF if first else 1) * h)
        except ElectrogrowthError:
            q = None
        ok = q is not None and np.linalg.norm(q - p) <= (FIRST_OFF if first else 0.5) * h
        turn = math.acos(np.clip(np.dot(_unit(q - x), t), -1, 1)) if ok else math.inf
        if not ok or (turn > TURN and not first):
            if h <= policy.smallest:
                return Trace(tuple(pts), LOST)
            h = max(h / 2, policy.smallest)
            continue
        if stop is not None:
            event = stop(q)
            if event is not None:
                return Trace(tuple(pts), STOPPED, tuple(q), event)
        t, x = _unit(q - x), q
        pts.append(tuple(x))
        if len(pts) > 3 and np.linalg.norm(x - np.asarray(pts[0])) < h:
            pts.append(pts[0])
            return Trace(tuple(pts), CLOSED)
        if turn < SMOOTH:
            h = min(policy.growth * h, policy.largest)
    return Trace(tuple(pts), LOST)
