"""The boundaries of a mode map, traced: the two-pattern conditions, their curves from the
coarse map's sign changes, and the triple points where three patterns are critical.

A pattern (a *label*) is a mode (m, n), "surface" (the exact short-wave limit) or
"threshold" (no wrinkle before the axisymmetric state is lost). Its value at a design
u = (x, y) is the first critical value of one fixed mode (``critical_value``), the
short-wave limit (``short_wave_limit``), or none where it does not come before the
threshold. The boundary between P and Q is the curve

    d_PQ(x, y) = s (v_P(x, y) - v_Q(x, y)) = 0,

s = -1 for a control that falls from its stable start, +1 otherwise, so d_PQ < 0 where P
comes first. Against "threshold" the condition is the indicator d = -1 where P bifurcates
before the threshold and +1 where it does not, whose jump is the boundary. Each curve is
followed by continuation.contour (pseudo-arclength, Brent's corrector to 1e-13 of the
box's side) from a root on an edge of the coarse grid whose ends have P and Q first. At
each new point the patterns first at the nearby grid nodes are compared: where a third,
C, comes first the curve has passed a triple point, located by Newton's method on
(d_PQ, d_PC) = 0; where d_PQ jumps instead of vanishing (a pattern's first root appears or
vanishes) the curve ends there ("jump"). A pattern more than 5% behind is compared again
only after three points or a move of 0.05 of the box's side, whichever comes first (a
lead of 5% cannot close sooner where the critical values change by O(1) across the box).

A triple point is accepted only if nothing comes earlier there: no compared pattern, and
nothing a full scan finds (``check``; a mode no task had seen is added to the compared
ones). Where something does, the curve met it first, before the point Newton found: the
last step passed two events in one (triple points closer than a step), so the trace is
taken again from the last point before the event with steps of a quarter of that one,
until the triple point holds or the step is the smallest (then the curve ends "lost"); a
jump is located the same way, to the smallest step. Where a curve ends, but for a closed
one (it leaves the box, ends at a jump or is lost), a full scan checks it too: a pattern
first there that was not compared means the curve crossed its region unseen, so the curve
is taken again from its start with it compared, to the triple point where it meets that
region. A closed curve ends at its start, scanned before it was traced. docs/design.md.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..bifurcation.critical import critical_value
from ..bifurcation.surface import short_wave_limit
from ..continuation.contour import (
    CLOSED,
    CONTOUR,
    CONTOUR_STEPS,
    LOST,
    STOPPED,
    trace_contour,
)
from ..continuation.events import brent
from ..errors import ElectrogrowthError, NoBifurcationFound
from ..outcomes import Kind

SURFACE, THRESHOLD, FAILED = "surface", "threshold", "failed"
AGREE = 1e-9  # |v_P - v_Q| / max(1, |v|) on a traced point; more is a jump of d
NEWTON_TOL = 1e-13  # the triple point's conditions, relative to max(1, |v|)
NEWTON_STEP = 1e-6  # the finite-difference step of its Jacobian (unit square)
BIG = 1e3  # d where a pattern does not come before the threshold (sign only)
HINT = 0.02  # the bracket of a followed critical value: +- this times max(1, |v|)
NEAR = 1.5  # candidates: the patterns of grid nodes within this many cells
TRIPLE, JUMP = "triple", "jump"
FAR = 0.05  # a pattern this far behind (relative) is compared again only ...
RECHECK = 3  # ... after this many points of a curve, or ...
FAR_MOVE = 0.05  # ... after a move of this much of the box's side, whichever is first
REFINE = 0.25  # a step that passed a triple point too far is taken again this much shorter


def valued(label) -> bool:
    return label not in (THRESHOLD, FAILED)


class Values:
    """The patterns' values over the design square, cached: ``tube_at(u)`` is the tube at
    unit coordinates u, ``value(label, u)`` the pattern's critical value there (None where
    it does not come before the threshold)."""

    def __init__(self, tube, solve_for, keys, box, side, rtol):
        self.tube, self.solve_for, self.keys, self.box = tube, solve_for, keys, box
        self.side, self.rtol = side, rtol
        self.sense = -1.0 if side == "compression" else 1.0
        self.cache: dict = {}
        self.hint: dict = {}
        self.solves = 0

    def fresh(self) -> Values:
        """A copy knowing what this one has solved (for a map: the grid's values), with no
        brackets carried over and no solves counted: a task's start, the same in this
        process and in a worker that unpickled it."""
        copy = Values(self.tube, self.solve_for, self.keys, self.box, self.side, self.rtol)
        copy.cache = dict(self.cache)
        return copy

    def xy(self, u) -> tuple[float, float]:
        (x0, x1), (y0, y1) = self.box
        return x0 + float(u[0]) * (x1 - x0), y0 + float(u[1]) * (y1 - y0)

    def tube_at(self, u):
        x, y = self.xy(u)
        return self.tube.at(self.keys[0], x).at(self.keys[1], y)

    def value(self, label, u, *, hinted: bool = True) -> float | None:
        key = (label, float(u[0]), float(u[1]), hinted)
        if key not in self.cache:
            self.cache[key] = self._solve(label, u, hinted)
        return self.cache[key]

    def _solve(self, label, u, hinted):
        at = self.tube_at(u)
        self.solves += 1
        if label == SURFACE:
            lim = short_wave_limit(at, self.solve_for, side=self.side, rtol=self.rtol)
            return lim.value if lim.kind == Kind.SURFACE else None
        c = None
        v0 = self.hint.get(label) if hinted else None
        if v0 is not None:
            w = HINT * max(1.0, abs(v0))
            try:
                c = critical_value(
                    at, *label, self.solve_for, side=self.side, rtol=self.rtol,
                    bracket=(v0 - w, v0 + w),
                )  # fmt: skip
            except ElectrogrowthError:
                c = None
        if c is None:
            try:
                c = critical_value(at, *label, self.solve_for, side=self.side, rtol=self.rtol)
            except NoBifurcationFound:
                return None  # no root in the control's whole range: it does not come
        if c.kind != Kind.BIFURCATION:
            return None
        self.hint[label] = c.value
        return c.value

    def condition(self, p, q):
        """d_PQ(u) (module docstring): < 0 where P comes first."""
        s = self.sense
        if valued(p) and valued(q):

            def d(u):
                a, b = self.value(p, u), self.value(q, u)
                if a is None or b is None:
                    return 0.0 if a is b else (BIG if a is None else -BIG)
                return s * (a - b)

            return d
        mode, sign = (p, 1.0) if valued(p) else (q, -1.0)

        def indicator(u):
            return sign * (-1.0 if self.value(mode, u) is not None else 1.0)

        return indicator

    def agree(self, p, q, u) -> bool:
        """Are P and Q equally critical at u (not a jump of d)?"""
        if not (valued(p) and valued(q)):
            return True
        a, b = self.value(p, u), self.value(q, u)
        return a is not None and b is not None and abs(a - b) <= AGREE * max(1.0, abs(a))

    def first(self, labels, u):
        """The label of ``labels`` (valued) that comes first at u, and its value."""
        best = (None, None)
        for lab in labels:
            if not valued(lab):
                continue
            v = self.value(lab, u)
            if v is not None and (best[1] is None or self.sense * (v - best[1]) < 0):
                best = (lab, v)
        return best


def gradient(d, u, h: float = NEWTON_STEP) -> np.ndarray:
    """Central differences of d at u (unit square), one-sided at its edges."""
    g = np.zeros(2)
    for i in range(2):
        e = np.zeros(2)
        e[i] = h
        a = u - e if u[i] - h >= 0 else u
        b = u + e if u[i] + h <= 1 else u
        g[i] = (d(b) - d(a)) / float(np.linalg.norm(b - a))
    return g


def triple_point(values: Values, p, q, c, u0):
    """Newton's method on (d_PQ, d_PC)(u) = 0 from u0; (u, value) or None."""
    f1, f2 = values.condition(p, q), values.condition(p, c)
    u = np.asarray(u0, float)
    for _ in range(30):
        f = np.array([f1(u), f2(u)])
        v = values.value(p, u)
        if v is None:
            return None
        if np.max(np.abs(f)) <= NEWTON_TOL * max(1.0, abs(v)):
            return u, v
        jac = np.array([gradient(f1, u), gradient(f2, u)])
        try:
            step = np.linalg.solve(jac, -f)
        except np.linalg.LinAlgError:
            return None
        if np.linalg.norm(step) > 0.2:
            step *= 0.2 / np.linalg.norm(step)
        u = np.clip(u + step, 0.0, 1.0)
    return None


def edge_root(values: Values, p, q, a, b):
    """The root of d_PQ on the segment from node a (P first) to node b (Q first), or None
    if d_PQ does not change sign there."""
    d = values.condition(p, q)
    a, b = np.asarray(a, float), np.asarray(b, float)

    def along(t):
        return d(a + t * (b - a))

    try:
        if not along(0.0) < 0 < along(1.0):
            return None
        t = brent(along, 0.0, 1.0, CONTOUR, ref=0.0)
    except ElectrogrowthError:
        return None
    return a + t * (b - a)


def follow(values: Values, p, q, start, tangent, candidates, policy=CONTOUR_STEPS, check=None):
    """Trace d_PQ = 0 from ``start`` along ``tangent``: (points, end, triple) with end EDGE,
    CLOSED, TRIPLE, JUMP or LOST and triple (labels, u, value) where it met a third pattern.

    ``candidates(u)`` are the patterns compared at each point; ``check(u, v)``, if given,
    names a pattern a full scan finds earlier than v at u (else None): asked at a triple
    point and where the curve ends but for a closed one (it leaves the box, ends at a jump,
    which is first located to the smallest step as an event is, or is lost); a pattern
    found at an end that was not compared before is compared from then on, and the curve is
    taken again from ``start``. A closed curve ends at its start, already scanned (the seed
    edge's root, or a triple point)."""
    d = values.condition(p, q)
    seen: dict = {}  # pattern -> (its relative lead over P and Q, the point it was checked)
    count = [0]

    def stop(u):
        if not values.agree(p, q, u):
            return JUMP
        count[0] += 1
        v = values.value(p, u) if valued(p) else values.value(q, u)
        for c in candidates(u):
            if c in (p, q) or not valued(c) or v is None:
                continue
            lead, when, where = seen.get(c, (0.0, 0, u))
            near = np.linalg.norm(np.asarray(u) - where) < FAR_MOVE
            if lead > FAR and count[0] - when < RECHECK and near:
                continue  # far behind a few points ago and close by: checked again later
            w = values.value(c, u)
            lead = math.inf if w is None else values.sense * (w - v) / max(1.0, abs(v))
            seen[c] = (lead, count[0], np.asarray(u, float))
            if lead < -AGREE:
                return c
        return None

    pts = [np.asarray(start, float)]
    t = np.asarray(tangent, float)
    first_policy, retaken = policy, set()
    while True:
        tr = trace_contour(d, pts[-1], t, stop=stop, policy=policy)
        pts = pts[:-1] + [np.array(x) for x in tr.points]
        end = tr.end  # EDGE, CLOSED or LOST, or STOPPED at an event (below)
        if tr.end == STOPPED:
            last, past = pts[-1], np.asarray(tr.past)
            if tr.event != JUMP:
                found = _event(values, p, q, tr.event, last, past, candidates, check)
                if found is not None:
                    u, v = found
                    return pts + [u], TRIPLE, ((p, q, tr.event), u, v)
            step = float(np.linalg.norm(past - last))
            if step > 2 * policy.smallest:
                # an event not located, or a jump: again from the last point, shorter, so
                # the curve ends within the smallest step of where it passed it
                short = max(REFINE * step, policy.smallest)
                policy = dataclasses.replace(policy, first=short, largest=short)
                t = past - last
                continue
            end = JUMP if tr.event == JUMP else LOST
        if end != CLOSED and check is not None:
            c = _end_check(values, p, q, pts[-1], check)
            if c is not None and c not in retaken:
                # the curve ends where c comes first: it met c's region on the way, unseen
                # as c was not compared; taken again from its start with c compared
                retaken.add(c)
                pts, t = [np.asarray(start, float)], np.asarray(tangent, float)
                policy = first_policy
                seen.clear()
                count[0] = 0
                continue
        return pts, end, None


def _end_check(values: Values, p, q, u, check):
    """A pattern a full scan finds earlier than P and Q where the curve ends (leaves the
    box, at a jump, lost)."""
    v = values.value(p, u) if valued(p) else values.value(q, u)
    return None if v is None else check(u, v)


def _event(values: Values, p, q, c, last, past, candidates, check):
    """The triple point of P, Q and C between the last point and the one past the event,
    (u, value), or None if Newton's method fails, lands off that step, or something comes
    earlier there (the step passed another event first)."""
    dc = values.condition(p, c)
    g0, g1 = dc(last), dc(past)
    t = g0 / (g0 - g1) if g0 != g1 and math.isfinite(g0 - g1) else 0.5
    found = triple_point(values, p, q, c, last + min(max(t, 0.0), 1.0) * (past - last))
    if found is None:
        return None
    u, v = found
    if np.linalg.norm(u - last) > 1.5 * np.linalg.norm(past - last):
        return None  # a triple point elsewhere on the curves, not this step's event
    tol = AGREE * max(1.0, abs(v))
    for e in candidates(u):
        if e not in (p, q, c) and valued(e):
            w = values.value(e, u)
            if w is not None and values.sense * (w - v) < -tol:
                return None
    if check is not None and check(u, v) is not None:
        return None
    return found
