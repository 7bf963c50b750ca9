"""Pattern prescription over two design variables: the target's region in a mode map, the
design with the widest margin there, its sensitivities; or, where the target is never first
in the box, the closest design and what beats it.

The margin is that of one variable (prescribe.py, docs/design.md): at a design u = (x, y),
M(u) = s (v_N(u) - v_T(u)) / |v_T(u)| with T the target mode and N the first non-target
pattern after it. Its maximum over the region is found from a raster of the region (by the
traced boundaries, no solves), refined by Nelder-Mead in the unit
square from the best, each M from single-mode solves of T and its competitors; a scan at the
optimum adds a competitor the set lacked, and the maximisation is repeated. Where the
target is first nowhere, the closest design maximises M < 0 from the map's grid nodes (each
scanned again for the modes ahead of the target), refined the same way. As along one
variable, a crease of a free face is one more competitor (design/onset.py), so a design
where a face creases first has M < 0, and where that holds at every raster point of the
target's region the status is CREASE_FIRST; so is the exact short-wave limit
(design/short_waves.py: a map's "surface" pattern is no mode to solve, so it was left out of
the competitors, and M did not vanish on a boundary with it).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import minimize, minimize_scalar

from ..bifurcation.options import mode_caps
from ..bifurcation.scan import ScanOptions, scan_modes
from ..errors import ElectrogrowthError
from ..incremental.accuracy import check_rtol
from ..outcomes import Kind, json_number
from .map_record import ModeMap, label_json, label_of
from .map_trace import FAILED, Values, valued
from .onset import (
    CREASE_FIRST,
    CreaseRival,
    crease_sensitivity,
    design_verdict,
    gap_to_crease,
    kinked_margin,
    margin_errors,
    margin_sensitivity,
    rivals_at,
)
from .prescribe import (
    AHEAD,
    CREASE,
    FOUND,
    NOT_FIRST,
    NOT_REACHED,
    REFINE_ROUNDS,
    best_member,
    cap_note,
    set_members,
    tie_name,
    unreached_note,
)
from .sensitivity import sensitivities, sensitivity_json
from .short_waves import SURFACE, SurfaceRival, surface_sensitivity
from .targets import Target, check_target

RASTER = 7  # raster points per variable where the margin is first sampled
XATOL = 1e-7  # Nelder-Mead's tolerance on the design, in units of the box's sides


@dataclasses.dataclass(frozen=True)
class MapDesign:
    """Result of :func:`prescribe_map`: ``region`` the traced boundaries with the target on
    one side (polylines), the best (FOUND) or closest (NOT_FIRST) design (x, y), the target
    mode there, its critical ``value``, the ``margin`` M and the ``next_mode`` (what beats
    it, for NOT_FIRST) at ``next_value``; ``to_boundary``: the distance from the design to
    the region's boundary along x and along y (None where no boundary crosses that line);
    the sensitivities as in :class:`~.prescribe.Design`; ``crease_value``,
    ``crease_margin``, ``surface_value``, ``surface_margin``, ``limited_by``, ``verdict``
    as there, and ``region_crease``: how many
    of the raster points in the target's region crease first. ``margin_sides`` and
    ``tied_with``: at a kink of M, as in :class:`~.prescribe.Design`; ``note`` too (a set's
    closest member found at the mode cap)."""

    target: str
    status: str
    keys: tuple[str, str]
    region: tuple
    x: float
    y: float
    mode: tuple[int, int] | None
    value: float
    margin: float
    next_mode: object
    next_value: float
    to_boundary: dict
    sensitivity: dict
    next_sensitivity: dict
    margin_sensitivity: dict
    map: ModeMap
    goal: Target | None = None  # the target as a set of modes (design/targets.py)
    crease_value: float = math.nan
    crease_margin: float = math.nan
    limited_by: str = ""
    verdict: dict = dataclasses.field(default_factory=dict)
    region_crease: dict = dataclasses.field(default_factory=dict)
    crease_sensitivity: dict = dataclasses.field(default_factory=dict)
    margin_sides: dict = dataclasses.field(default_factory=dict)
    tied_with: tuple = ()
    surface_value: float = math.nan
    surface_margin: float = math.nan
    surface_sensitivity: dict = dataclasses.field(default_factory=dict)
    note: str = ""
    margin_error: dict = dataclasses.field(default_factory=dict)

    def as_dict(self) -> dict:
        return {
            "target": self.target,
            "status": self.status,
            "vary": list(self.keys),
            "solve_for": self.map.solve_for,
            "side": self.map.side,
            "region": [b.as_dict() for b in self.region],
            "region_crease": self.region_crease or None,
            "switches": [b.as_dict() for b in self.map.boundaries],
            "triple_points": [t.as_dict() for t in self.map.triple_points],
            "best": {
                "design": [json_number(self.x), json_number(self.y)],
                "mode": None if self.mode is None else list(self.mode),
                "value": json_number(self.value),
                "margin": json_number(self.margin),
                "next_mode": None if self.next_mode is None else label_json(self.next_mode),
                "next_value": json_number(self.next_value),
                "to_boundary": {k: json_number(v) for k, v in self.to_boundary.items()},
                "crease_value": json_number(self.crease_value),
                "crease_margin": json_number(self.crease_margin),
                "surface_value": json_number(self.surface_value),
                "surface_margin": json_number(self.surface_margin),
                "limited_by": self.limited_by or None,
                "tied_with": [tie_name(t) for t in self.tied_with],
                "verdict": self.verdict or None,
                "note": self.note or None,
            },
            "sensitivity": sensitivity_json(self),
        }


def stored_design(record: dict, mmap: ModeMap, target) -> MapDesign:
    """The design written by :meth:`MapDesign.as_dict`, in the map ``mmap`` it was found in
    (:meth:`ModeMap.from_dict`), for ``target`` (as given to :func:`prescribe_map`: a
    predicate cannot be stored). The region is taken again from the map's boundaries with
    a target pattern on one side; the crease's fields are read where the record has them
    (a record written before them has none). A malformed record raises ValueError."""
    goal = check_target(target)
    try:
        best, sens = record["best"], record["sensitivity"]
        num = lambda v: math.nan if v is None else float(v)  # noqa: E731
        table = lambda d: {str(k): num(v) for k, v in d.items()}  # noqa: E731
        mode = None if best["mode"] is None else (int(best["mode"][0]), int(best["mode"][1]))
        nxt = None if best["next_mode"] is None else label_of(best["next_mode"])
        x, y = (num(v) for v in best["design"])
        return MapDesign(
            str(record["target"]), str(record["status"]), mmap.keys,
            tuple(b for b in mmap.boundaries if b.left in goal or b.right in goal),
            x, y, mode, num(best["value"]), num(best["margin"]), nxt, num(best["next_value"]),
            {str(k): None if v is None else float(v) for k, v in best["to_boundary"].items()},
            table(sens["value"]), table(sens["next_value"]), _margins_of(sens), mmap, goal,
            num(best.get("crease_value")), num(best.get("crease_margin")),
            best.get("limited_by") or "", dict(best.get("verdict") or {}),
            dict(record.get("region_crease") or {}), table(sens.get("crease_value", {})),
            _sides_of(sens), tuple(_tie_of(t) for t in best.get("tied_with") or ()),
            num(best.get("surface_value")), num(best.get("surface_margin")),
            table(sens.get("surface_value", {})), str(best.get("note") or ""),
            table(sens.get("margin_error", {})),  # absent in records before 2026-12-08
        )  # fmt: skip
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise ValueError(f"not a stored design: {exc}") from None


def _margins_of(sens: dict) -> dict:
    """A stored ``sensitivity.margin``: null (a kink of M, or not formed) stays None."""
    return {str(k): None if v is None else float(v) for k, v in sens["margin"].items()}


def _sides_of(sens: dict) -> dict:
    """A stored ``sensitivity.margin_sides``: {key: (down, up)} (a record without: {})."""
    num = lambda v: None if v is None else float(v)  # noqa: E731
    rows = (sens.get("margin_sides") or {}).items()
    return {str(k): (num(d["down"]), num(d["up"])) for k, d in rows}


def _tie_of(item):
    """A stored tied competitor: [m, n] as a mode, else its name ("crease", "surface")."""
    return (int(item[0]), int(item[1])) if isinstance(item, list) else str(item)


class _Margins:
    """Critical values of patterns at designs u (unit square), cached; the margin M(u)."""

    def __init__(self, mmap: ModeMap, tube, options):
        self.map, self.tube, self.options = mmap, tube, options
        self.sense = -1.0 if mmap.side == "compression" else 1.0
        self.values = Values(tube, mmap.solve_for, mmap.keys, mmap.box, mmap.side, 1e-12)
        self.creases = CreaseRival(self.at, mmap.solve_for, mmap.side, self.sense)
        self.surfaces = SurfaceRival(
            self.at, mmap.solve_for, mmap.side, self.sense, options.surface
        )

    def xy(self, u):
        return self.values.xy(u)

    def at(self, u):
        return self.values.tube_at(u)

    def caps(self, u) -> tuple[int, int]:
        """The largest m and n the scans of the tube at u search (options.mode_caps)."""
        return mode_caps(self.at(u))

    def value(self, mode, u) -> float:
        """The first critical value of ``mode`` at u (followed from its last value, as on a
        traced boundary); +-inf where it does not come before the threshold."""
        if not (valued(mode) and isinstance(mode, tuple)):
            return self.sense * math.inf
        try:
            v = self.values.value(mode, u)
        except ElectrogrowthError:
            v = None
        return self.sense * math.inf if v is None else v

    def crease(self, u, until: float | None = None) -> float:
        """Where a face creases at u, looked for before ``until`` (design/onset.py)."""
        return self.creases.value(u, until)

    def surface(self, u, until: float | None = None) -> float:
        """The short-wave limit at u where it comes before ``until`` (sense * inf: not)."""
        return self.surfaces.value(u, until)

    def margin(self, mode, others, u) -> tuple[float, object]:
        """(M, the next pattern) at u over the competitors ``others``, the crease and the
        short-wave limit (located only where it can come before the nearest other one)."""
        v = self.value(mode, u)
        if not math.isfinite(v):
            return -math.inf, None
        m, nxt = math.inf, None
        if others:
            nxt = min(others, key=lambda o: self.sense * self.value(o, u))
            m = self.sense * (self.value(nxt, u) - v) / abs(v)
        for rival in (self.crease, self.surface):  # each only where it can come first
            until = v + self.sense * m * abs(v) if math.isfinite(m) else None
            m = min(m, gap_to_crease(v, rival(u, until), self.sense))
        return m, nxt

    def ranked(self, u, top: int | None = None) -> list:
        """The modes a scan at u finds, in the order reached: [((m, n), value), ...] (the
        first ``top``, by default at least 6)."""
        opts = dataclasses.replace(self.options, top=top or max(self.options.top, 6))
        try:
            res = scan_modes(self.at(u), self.map.solve_for, side=self.map.side, options=opts)
        except ElectrogrowthError:
            return []
        c = res.critical
        out = [((c.m, c.n), c.value)] if c.kind == Kind.BIFURCATION else []
        return out + [((r.m, r.n), r.value) for r in res.runners_up if r.family != "torsional"]


def _maximise(margins: _Margins, mode, others, u0, goal):
    """Nelder-Mead on -M in the unit square from u0; a competitor a scan at the optimum
    finds ahead of (or next after) the target is added and the search repeated."""
    u = np.asarray(u0, float)
    for _ in range(REFINE_ROUNDS):

        def neg(w, others=others):
            w = np.clip(w, 0.0, 1.0)
            return -margins.margin(mode, others, w)[0]

        res = minimize(  # bounded: a simplex past the box's side would pay for flat M
            neg, u, method="Nelder-Mead", bounds=[(0.0, 1.0)] * 2,
            options={"xatol": XATOL, "fatol": 1e-13, "initial_simplex": _simplex(u)},
        )  # fmt: skip
        w = np.clip(res.x, 0.0, 1.0)
        if -neg(w) >= -neg(u):
            u = w
        u = _along_ridge(margins, mode, others, u)
        missing = set()
        for m, _ in margins.ranked(u):
            if m not in goal and m not in others:
                missing.add(m)
                if m != mode:
                    break
        if not missing:
            break
        others = tuple(sorted(set(others) | missing))
    return u, others


#: two competitors this close (relative to M) at Nelder-Mead's optimum: a ridge of M
RIDGE = 1e-3
#: the step (unit square) of the tie's gradient by differences
RIDGE_STEP = 1e-4


def _along_ridge(margins: _Margins, mode, others, u):
    """u, or a better design on the tie of the two nearest competitors through it. M =
    min(M_A, M_B) is a ridge along their tie, on which Nelder-Mead stalls: a film's
    (200, 0) stopped 0.024 of the box short of its optimum on the box's edge, M 1.2e-4 low
    (check round 22). M is maximised along the tie (Brent on the arc length, bounded by
    the box), each point put back on it by Newton's method along the tie's gradient."""
    pair = _nearest_two(margins, mode, others, u)
    if pair is None:
        return u
    gap = _gap(margins, pair)
    try:
        grad = np.array([_derivative(gap, u, axis) for axis in (0, 1)])
    except ElectrogrowthError:
        return u
    if not np.all(np.isfinite(grad)) or not grad.any():
        return u
    normal = grad / np.linalg.norm(grad)
    tangent = np.array([-normal[1], normal[0]])
    slope = float(np.linalg.norm(grad))

    def on_tie(t: float):
        p = np.clip(u + t * tangent, 0.0, 1.0)
        for _ in range(4):  # Newton along the normal: the tie is nearly straight here
            d = gap(p)
            if not math.isfinite(d):
                break
            p = np.clip(p - d / slope * normal, 0.0, 1.0)
            if abs(d / slope) < 1e-3 * XATOL:  # on the tie to well within the arc's tolerance
                break
        return p

    def neg(t: float) -> float:
        return -margins.margin(mode, others, on_tie(t))[0]

    lo, hi = _box_span(u, tangent)
    if hi - lo < XATOL:
        return u
    res = minimize_scalar(neg, bounds=(lo, hi), method="bounded", options={"xatol": XATOL})
    best = on_tie(float(res.x))
    return best if -neg(float(res.x)) > margins.margin(mode, others, u)[0] else u


def _nearest_two(margins: _Margins, mode, others, u):
    """The two competitors nearest the target at u where their margins tie to RIDGE."""
    if len(others) < 2:
        return None
    v = margins.value(mode, u)
    if not math.isfinite(v):
        return None
    gaps = sorted(((margins.sense * (margins.value(o, u) - v), o) for o in others),
                  key=lambda g: g[0])  # fmt: skip
    (g_a, a), (g_b, b) = gaps[:2]
    if not (math.isfinite(g_b) and g_a > 0 and g_b - g_a <= RIDGE * g_a):
        return None
    return a, b


def _gap(margins: _Margins, pair):
    a, b = pair
    return lambda p: margins.value(a, p) - margins.value(b, p)


def _derivative(f, u, axis: int) -> float:
    """Central difference of f at u along ``axis`` (one-sided at the box's side)."""
    e = np.zeros(2)
    e[axis] = RIDGE_STEP
    lo, hi = np.clip(u - e, 0.0, 1.0), np.clip(u + e, 0.0, 1.0)
    return (f(hi) - f(lo)) / (hi[axis] - lo[axis])


def _box_span(u, direction) -> tuple[float, float]:
    """The t with u + t direction in the unit square."""
    lo, hi = -math.inf, math.inf
    for k in (0, 1):
        if direction[k] > 0:
            lo, hi = max(lo, -u[k] / direction[k]), min(hi, (1 - u[k]) / direction[k])
        elif direction[k] < 0:
            lo, hi = max(lo, (1 - u[k]) / direction[k]), min(hi, -u[k] / direction[k])
    return lo, hi


def _simplex(u, size: float = 0.05) -> np.ndarray:
    """A starting simplex of side ``size`` at u, inside the unit square."""
    dx = size if u[0] + size <= 1 else -size
    dy = size if u[1] + size <= 1 else -size
    return np.array([u, u + [dx, 0.0], u + [0.0, dy]])


def _distances(mmap: ModeMap, region, x: float, y: float) -> dict:
    """Distance from (x, y) to the region's boundary along x and along y."""
    out = {}
    for axis, name in ((0, mmap.keys[0]), (1, mmap.keys[1])):
        best = None
        for b in region:
            pts = np.array([b.x, b.y]).T
            for p, q in zip(pts[:-1], pts[1:], strict=True):
                other = 1 - axis
                c = (y, x)[axis]  # the fixed coordinate of the line
                if (p[other] - c) * (q[other] - c) > 0 or p[other] == q[other]:
                    continue
                t = (c - p[other]) / (q[other] - p[other])
                hit = p[axis] + t * (q[axis] - p[axis])
                dist = abs(hit - (x, y)[axis])
                best = dist if best is None else min(best, dist)
        out[name] = best
    return out


def prescribe_map(
    tube,
    target,
    mmap: ModeMap,
    *,
    options: ScanOptions = ScanOptions(),
    rtol: float = 1e-12,
    koiter: bool = False,
) -> MapDesign:
    """The design with the widest margin for ``target`` in a mode map (module docstring).

    Parameters
    ----------
    tube : Tube
        The tube the map was made of.
    target : (m, n), list of (m, n), "axisymmetric", "prismatic" or callable
        The pattern aimed at (design/targets.py).
    mmap : ModeMap
        The map (:func:`mode_map`) over the two design variables.
    options : ScanOptions
        The modes the scans at the designs examine (those of the map).
    koiter : bool
        Also the amplitude equation of the chosen design's wrinkle (its branch).

    Returns
    -------
    MapDesign
    """
    check_rtol(rtol)  # refused up front, as in prescribe (not after the margins' work)
    goal = check_target(target)
    margins = _Margins(mmap, tube, options)
    region = tuple(b for b in mmap.boundaries if b.left in goal or b.right in goal)
    us = np.linspace(0, 1, RASTER)
    (x0, x1), (y0, y1) = mmap.box
    raster = mmap.raster(x0 + us * (x1 - x0), y0 + us * (y1 - y0))
    inside = [(np.array([us[i], us[j]]), raster[i, j]) for i, j in np.ndindex(raster.shape)]
    inside = [(u, lab) for u, lab in inside if lab in goal]
    if inside:
        status = FOUND
        found = {lab for b in region for lab in (b.left, b.right)}  # the region's neighbours
        if not found:  # the target is first over the whole box: every other pattern
            found = {lab for row in mmap.labels for lab in row}
        others = tuple(sorted(lab for lab in found if lab not in goal and isinstance(lab, tuple)))
        scored = [(margins.margin(lab, others, u)[0], tuple(u), lab) for u, lab in inside]
        _, u0, mode = max(scored)
        creased = sum(
            margins.sense * (margins.crease(u) - margins.value(lab, u)) < 0 for u, lab in inside
        )
        region_crease = _region_crease(int(creased), len(inside))
        note = ""
    else:
        status = NOT_FIRST
        best = None
        gx = (np.asarray(mmap.xs) - x0) / (x1 - x0)
        gy = (np.asarray(mmap.ys) - y0) / (y1 - y0)
        members = set_members(goal, options)
        for i, j in np.ndindex(len(gx), len(gy)):  # the map's grid nodes, scanned again
            u = np.array([gx[i], gy[j]])
            # a set's first member as along one variable: past the scan's top and window
            found = best_member(u, goal, margins, margins.ranked, members)
            if found is None:
                continue
            ranked, m, v = found
            ahead = tuple(a for a, w in ranked if a not in goal and margins.sense * (w - v) < 0)
            ahead = ahead[:AHEAD]  # the earliest: a scan down to TOP_MAX has hundreds
            if ahead:
                score = margins.margin(m, ahead, u)[0]
                if best is None or score > best[0]:
                    best = (score, tuple(u), m, ahead)
        if best is None:
            return _unreached(goal, mmap, region)
        _, u0, mode, others = best
        note = cap_note(mode, goal, margins.caps(u0))
        region_crease = {}
    u, others = _maximise(margins, mode, others, u0, goal)
    m_u, nxt = margins.margin(mode, others, u)
    v = margins.value(mode, u)
    v_next = margins.value(nxt, u) if nxt is not None else math.nan
    at = margins.at(u)
    sens = sensitivities(at, mode, mmap.solve_for, v, rtol=rtol)
    sens_next, sens_margin = {}, {}
    v_crease = margins.crease(u)
    m_crease = gap_to_crease(v, v_crease, margins.sense)
    limit = margins.surfaces.limit(u)  # the whole march, once: its value is reported
    v_surface = margins.surface(u)
    m_surface = gap_to_crease(v, v_surface, margins.sense)
    by_modes = margins.sense * (v_next - v) / abs(v) if nxt is not None else math.inf
    gaps = {"mode": by_modes, CREASE: m_crease, SURFACE: m_surface}
    limited = min(gaps, key=gaps.__getitem__)  # the first of equal gaps: a mode
    if status == FOUND and m_u < 0:  # a crease before the target everywhere in its region
        status = CREASE_FIRST
    if nxt is not None and math.isfinite(v_next):
        sens_next = sensitivities(at, nxt, mmap.solve_for, v_next, rtol=rtol)
    sens_crease = crease_sensitivity(at, mmap.solve_for, v_crease, tuple(sens))
    sens_surface = surface_sensitivity(at, mmap.solve_for, limit, tuple(sens))
    rivals = {
        "mode": (nxt, v_next, sens_next),
        CREASE: (CREASE, v_crease, sens_crease),
        SURFACE: (SURFACE, v_surface, sens_surface),
    }
    lead = rivals[limited]
    if lead[2]:
        sens_margin = margin_sensitivity(margins.sense, v, sens, lead[1], lead[2])
    sides, tied, errors = {}, (), {}
    if sens_margin:  # M set by a mode, the crease or the limit: a tie is a kink of M
        given = {CREASE: sens_crease, SURFACE: sens_surface}
        near = rivals_at(margins, at, mmap.solve_for, u, v, lead, others, given, rtol)
        errors = margin_errors(at, v, lead[1], sens_margin, rtol)
        sens_margin, sides, tied = kinked_margin(at, margins.sense, v, sens, near, errors)
    x, y = margins.xy(u)
    verdict = design_verdict(
        at,
        mmap.solve_for,
        mmap.side,
        dataclasses.replace(options, top=max(options.top, 6)),
        koiter=koiter,
    )
    return MapDesign(
        goal.name, status, mmap.keys, region, x, y, mode, v, m_u, nxt, v_next,
        _distances(mmap, region, x, y) if status != NOT_FIRST else {},
        sens, sens_next, sens_margin, mmap, goal,
        v_crease if math.isfinite(v_crease) else math.nan, m_crease, limited, verdict,
        region_crease, sens_crease, sides, tied,
        v_surface if math.isfinite(v_surface) else math.nan, m_surface, sens_surface, note,
        errors,
    )  # fmt: skip


def _region_crease(creased: int, points: int) -> dict:
    """How many of the raster points in the target's region crease first."""
    which = "none" if creased == 0 else "all" if creased == points else "part"
    return {"crease_first": which, "crease_first_points": [creased, points], "sampled": "raster"}


def _unreached(goal, mmap, region) -> MapDesign:
    nan = math.nan
    failed = any(lab == FAILED for row in mmap.labels for lab in row)
    return MapDesign(
        goal.name, NOT_REACHED, mmap.keys, region, nan, nan, None, nan, nan, None, nan, {},
        {}, {}, {}, mmap, goal, note=unreached_note(goal, failed),
    )  # fmt: skip
