"""Pattern prescription along one design variable: where a target pattern comes first, the
design with the widest margin against the next pattern, and its sensitivities.

The margin at a design x (a value of the design variable) is the relative gap between the
critical value v_T(x) of the target mode T and that of the next mode N, the first mode
outside the target set reached after T:

    M(x) = s (v_N(x) - v_T(x)) / |v_T(x)|,

s = +1 where the control grows from its stable start (growth, voltage, stretch in extension,
inflating pressure) and -1 where it falls (stretch in compression, axial force): M > 0
exactly where T comes first, and M is the fraction by which the control can overshoot v_T
before N could also wrinkle. A crease of a free face is one more competitor (design/onset.py:
M is also at most the relative gap to the crease), so a design where a face creases before
T has M < 0; so is the exact short-wave limit (design/short_waves.py: where the target's
region borders an interval in which the limit comes first, M vanishes at that switch as at
any other). The best design maximises M over the target's region; where a crease comes
first across the whole region it is the one nearest to wrinkling first (CREASE_FIRST).
Where no x in [lo, hi] makes the target first, the closest design maximises M < 0 (the
smallest relative gap) and N is the mode that beats T there. In a span of the region that
ends at a located end of the valid range (next to a failed scan: the tube is already
unstable at the control's start beyond it), v_T falls to the start there and M alone grows
without bound, so the room below the target counts too (design/margins.py: M_0 = (v_T -
v_0) / (v_N - v_T), and at a cliff, where v_T does not fall to v_0, the relative distance
to the end M_end; ``limited_by`` NO_DESIGN). At a tie of competitors (a kink of M) the
margin's sensitivity is one-sided (design/onset.py :func:`kinked_margin`), and the kink
itself is located as the two competitors' tie (:func:`_at_kink`). docs/design.md.
"""

from __future__ import annotations

import dataclasses
import math

from ..bifurcation.msearch import geometric_samples, neighbours, refine_samples
from ..bifurcation.scan import TOP_MAX, ScanOptions, scan_modes
from ..bifurcation.scan_grid import scan_grid
from ..continuation.events import SWITCH, brent, widening_windows
from ..errors import ElectrogrowthError, Remedy
from ..incremental.accuracy import check_rtol
from ..outcomes import Kind, Status, json_number
from . import onset
from .margins import Margins
from .onset import CREASE_FIRST, gap_to_crease
from .sensitivity import sensitivities, sensitivity_json
from .sequence import Interval, ModeSequence, check_vary, mode_sequence, no_design_ends
from .short_waves import SURFACE, surface_sensitivity
from .targets import Target, check_target

FOUND = "found"  # the target comes first in its region; the best design has M > 0
NOT_FIRST = "not_first"  # never first in [lo, hi]: the closest design (M < 0)
NOT_REACHED = "not_reached"  # no target mode among the modes scanned anywhere
REFINE_ROUNDS = 3  # a competitor missed by the refinement is added, at most this often
XTOL = 1e-9  # relative accuracy of the best design
AHEAD = 6  # competitors ahead of the closest design's target mode that are kept
MEMBERS_MAX = 256  # a set's members solved directly when none is among a scan's first ones
NO_DESIGN = "no design"  # limited_by: the gap to a located end of the valid range
RANGE_END = "range end"  # limited_by: no competitor before the end of the control's range
CREASE = "crease"  # the crease as a competitor (a tie at a kink of M)
#: windows, widening 4-fold from XTOL max(1, |x|), in which the kink next to the bounded
#: Brent's maximiser is looked for: up to 1024 times its tolerance (it left the kink within
#: 0.5 of it in probe 9b); a smooth maximum costs 4 solves per window
KINK_WINDOWS = 6
#: the end's gap sets M where it is within this (relative) of M: at the balance Brent
#: leaves them ~1e-6 apart (probe 8b, D4), a relative step of the sensitivities (1e-4)
BALANCE = 1e-4


@dataclasses.dataclass(frozen=True)
class Design:
    """Result of :func:`design` (module docstring for the margin M).

    ``note``: why the result may not be final (a set's closest member found at the mode cap,
    :func:`_past_window`), or for NOT_REACHED what to try (:func:`unreached_note`), else
    empty.

    ``status`` FOUND: ``x`` is the design with the widest margin in the ``region`` (the
    intervals where the target is first), ``mode`` is critical there at ``value`` and
    ``next_mode`` comes next at ``next_value``; ``to_boundary`` is the distance from x to
    the nearest end of the region (its intervals joined where they touch) that is a located
    switch or a located end of the valid range, next to a failed scan (None if both ends are
    the ends of the range). NOT_FIRST: no region; x is the
    closest design, M < 0, and
    ``next_mode`` beats the target there (where the target only ties with it at one x, an
    interval of no width, x is that point and M ~ 0). CREASE_FIRST: the target is first among the
    wrinkles in its region, but a free face creases before it at every design there; x is
    the design nearest to wrinkling first (M < 0, ``limited_by`` "crease").
    ``crease_value`` is where a face creases at x (NaN: none; ``crease_sensitivity`` its
    d/dp), ``crease_margin`` the relative gap to it (``margin_sensitivity`` is that of the
    gap that sets M; empty for "no design"), ``surface_value`` and ``surface_margin`` the
    exact short-wave limit at x and the gap to it (NaN: the scans leave it out, or none is
    met; ``surface_sensitivity`` its d/dp), ``limited_by`` which competitor sets M
    ("mode", "crease", "surface", "no design": the room below the target, next to a
    located end of the valid range, or "range end": no competitor comes before the end of
    the control's range, and M is the room up to it, a lower bound, design/margins.py),
    ``verdict`` the verdict of a scan at x (design/onset.py :func:`design_verdict`) and
    ``region_crease`` how many of the curve's points in each interval of the region
    crease first. NOT_REACHED: no target mode was found among the
    scanned modes (x and the values are NaN). ``sensitivity``: d(value)/dp of the target
    mode's critical value for every parameter p of the tube at x; ``margin_sensitivity``:
    dM/dp from the two modes' sensitivities; ``next_sensitivity``: those of the next mode.
    Where another competitor ties with the one that sets M (the usual case at the widest
    margin: a kink of M, design/onset.py :func:`kinked_margin`), ``tied_with`` names it,
    ``margin_sensitivity`` is None for each p at whose kink M is not differentiable and
    ``margin_sides`` holds (down, up) there: dM/dp lowering p and raising it.
    ``margin_error``: the least error of each dM/dp (sensitivity.margin_error): slopes
    within it of each other are no kink, a slope within it of 0 is printed as 0.
    """

    target: str
    status: str
    key: str
    solve_for: str
    region: tuple[Interval, ...]
    x: float
    mode: tuple[int, int] | None
    value: float
    margin: float
    next_mode: tuple[int, int] | None
    next_value: float
    to_boundary: float | None
    sensitivity: dict
    next_sensitivity: dict
    margin_sensitivity: dict
    sequence: ModeSequence
    crease_value: float = math.nan
    crease_margin: float = math.nan
    limited_by: str = ""
    verdict: dict = dataclasses.field(default_factory=dict)
    region_crease: tuple = ()
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
            "vary": self.key,
            "solve_for": self.solve_for,
            "side": self.sequence.side,
            "region": [
                iv.as_dict() | crease for iv, crease in zip(self.region, self._crease_rows())
            ],
            "switches": [s.as_dict() for s in self.sequence.switches],
            "sequence": [iv.as_dict() for iv in self.sequence.intervals],
            "best": {
                "design": json_number(self.x),
                "mode": None if self.mode is None else list(self.mode),
                "value": json_number(self.value),
                "margin": json_number(self.margin),
                "next_mode": None if self.next_mode is None else list(self.next_mode),
                "next_value": json_number(self.next_value),
                "to_boundary": json_number(self.to_boundary),
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

    def _crease_rows(self) -> list[dict]:
        return list(self.region_crease) or [{} for _ in self.region]


def _ranked(res) -> list[tuple[tuple[int, int], float]]:
    """The modes of a scan in the order they are reached: [((m, n), value), ...]."""
    out = []
    c = res.critical
    if c.kind == Kind.BIFURCATION:
        out.append(((c.m, c.n), c.value))
    out += [((r.m, r.n), r.value) for r in res.runners_up if r.family != "torsional"]
    return out


def prescribe(
    tube,
    solve_for: str,
    target,
    vary: tuple[str, float, float],
    *,
    side: str | None = None,
    options: ScanOptions = ScanOptions(),
    points: int = 9,
    rtol: float = 1e-12,
    sequence: ModeSequence | None = None,
    koiter: bool = False,
) -> Design:
    """The design x in [lo, hi] with the widest margin M for the target pattern.

    Parameters
    ----------
    tube, solve_for, vary, side, options, points
        As in :func:`mode_sequence` (``sequence``: its result, if already computed).
    target : (m, n), list of (m, n), "axisymmetric" (m = 0), "prismatic" (n = 0) or callable
        The pattern aimed at: a set of modes (a callable (m, n) -> bool).
    rtol : float
        Accuracy of the target evaluations behind the sensitivities.
    koiter : bool
        Also the amplitude equation of the chosen design's wrinkle (its branch, where
        bifurcation/koiter.py covers it; several seconds).

    Returns
    -------
    Design
        The region, the best (or closest) design, its margin
        M = s (v_next - v_target) / |v_target|, at most the gap to a crease (module
        docstring), the verdict at the design, and the sensitivities
        dv/dp = -f_p / f_v of the target's critical value (design/sensitivity.py).
    """
    check_rtol(rtol)  # before the sequence: a bad rtol is refused, not found after minutes
    goal = check_target(target)
    key, lo, hi = (
        check_vary(vary) if sequence is None else (sequence.key, sequence.lo, sequence.hi)
    )
    if sequence is None:
        sequence = mode_sequence(tube, solve_for, vary, side=side, options=options, points=points)
    side = sequence.side
    margins = Margins(tube, sequence.solve_for, key, side, width=hi - lo, surface=options.surface)
    scan_opts = dataclasses.replace(options, top=max(options.top, 6))

    def scan(x, top=None):  # the modes in the order reached; none where the scan fails
        opts = scan_opts if top is None else dataclasses.replace(scan_opts, top=top)
        try:
            res = scan_modes(tube.at(key, x), sequence.solve_for, side=side, options=opts)
        except ElectrogrowthError:
            return []
        return _ranked(res)

    hits = [iv for iv in sequence.intervals if iv.kind == Kind.BIFURCATION and iv.mode in goal]
    # an interval of no width is a tie at one x (a range that starts at the target's switch):
    # the target is first nowhere, it was "found" with M = 4e-16 and to_boundary 0 (probe 9b)
    region = tuple(iv for iv in hits if not no_width(iv, sequence))
    grid = sorted(set(float(x) for x in sequence.curve.x))
    edges = no_design_ends(sequence)
    if region:
        status, best = FOUND, _best_in_region(region, grid, goal, margins, scan, edges)
    else:
        status, best = (
            NOT_FIRST,
            _tied_only([iv for iv in hits if no_width(iv, sequence)], goal, margins, scan),
        )
        if best is None:
            best = _closest(grid, goal, margins, scan, set_members(goal, options))
    if best is None:
        failed = any(iv.kind == Status.FAILED for iv in sequence.intervals)
        return _unreached(goal, key, sequence, region, unreached_note(goal, failed))
    x, mode, others = best
    note = cap_note(mode, goal, margins.caps(x)) if status == NOT_FIRST else ""
    span = _span(region, x)
    edge = _touches(span, edges)
    m_x, nxt = margins.best_margin(mode, others, x, edge)
    v = margins.value(mode, x)
    v_next = margins.value(nxt, x) if nxt is not None else math.nan
    at = tube.at(key, x)
    sens = sensitivities(at, mode, sequence.solve_for, v, rtol=rtol)
    sens_next, sens_margin = {}, {}
    v_crease = margins.crease(x)
    m_crease = gap_to_crease(v, v_crease, margins.sense)
    limit = margins.surfaces.limit(x)  # the whole march, once: its value is reported
    v_surface = margins.surface(x)
    m_surface = gap_to_crease(v, v_surface, margins.sense)
    by_modes = margins.margin(mode, x, v_next) if nxt is not None else math.inf
    m_end = margins.to_range_end(mode, x)
    gaps = {"mode": by_modes, CREASE: m_crease, SURFACE: m_surface, RANGE_END: m_end}
    limited = min(gaps, key=gaps.__getitem__)  # the first of equal gaps: a mode
    gap_end = margins.to_no_design(mode, others, x, gaps[limited], edge)
    if edge and gap_end <= m_x + BALANCE * abs(m_x):
        limited = NO_DESIGN  # the room below the target, to the end of the valid range
    if status == FOUND and m_x < 0:  # a crease before the target everywhere in its region
        status = CREASE_FIRST
    if nxt is not None and math.isfinite(v_next):
        sens_next = sensitivities(at, nxt, sequence.solve_for, v_next, rtol=rtol)
    sens_crease = onset.crease_sensitivity(at, sequence.solve_for, v_crease, tuple(sens))
    sens_surface = surface_sensitivity(at, sequence.solve_for, limit, tuple(sens))
    rivals = {
        "mode": (nxt, v_next, sens_next),
        CREASE: (CREASE, v_crease, sens_crease),
        SURFACE: (SURFACE, v_surface, sens_surface),
    }
    # NO_DESIGN: M_0 moves with v_0, M_end with the end; RANGE_END with the path's end:
    # not derived here
    if limited in rivals and rivals[limited][2]:
        lead = rivals[limited]
        sens_margin = onset.margin_sensitivity(margins.sense, v, sens, lead[1], lead[2])
    sides: dict[str, tuple[float, float]] = {}
    tied: tuple = ()
    errors: dict = {}
    if sens_margin:  # M set by a mode, the crease or the limit: a tie is a kink of M
        given = {CREASE: sens_crease, SURFACE: sens_surface}
        near = onset.rivals_at(margins, at, sequence.solve_for, x, v, lead, others, given, rtol)
        errors = onset.margin_errors(at, v, lead[1], sens_margin, rtol)
        sens_margin, sides, tied = onset.kinked_margin(at, margins.sense, v, sens, near, errors)
    ends = (
        []
        if span is None
        else [abs(x - span.lo)] * (not span.lo_edge) + [abs(span.hi - x)] * (not span.hi_edge)
    )
    return Design(
        goal.name,
        status,
        key,
        sequence.solve_for,
        region,
        x,
        mode,
        v,
        m_x,
        nxt,
        v_next,
        min(ends) if ends else None,
        sens,
        sens_next,
        sens_margin,
        sequence,
        v_crease if math.isfinite(v_crease) else math.nan,
        m_crease,
        limited,
        onset.design_verdict(at, sequence.solve_for, side, scan_opts, koiter=koiter),
        tuple(onset.region_creases(region, sequence.curve)),
        sens_crease,
        sides,
        tied,
        v_surface if math.isfinite(v_surface) else math.nan,
        m_surface,
        sens_surface,
        note,
        errors,
    )


def tie_name(rival) -> object:
    """A tied competitor for JSON: a mode as [m, n], the crease as "crease"."""
    return list(rival) if isinstance(rival, tuple) else rival


def _touches(span: Interval | None, ends) -> tuple:
    """The located ends of the valid range at which the joined interval ``span`` ends
    (empty: none)."""
    return () if span is None else tuple(e for e in (span.lo, span.hi) if e in ends)


def _span(region, x: float) -> Interval | None:
    """The region's intervals joined where they touch (a set's modes side by side), the one
    holding x."""
    spans: list[Interval] = []
    for iv in region:
        if spans and spans[-1].hi == iv.lo:
            last = spans.pop()
            iv = dataclasses.replace(iv, lo=last.lo, lo_edge=last.lo_edge)
        spans.append(iv)
    return next((sp for sp in spans if sp.contains(x)), None)


def _unreached(goal: Target, key, sequence, region, note: str) -> Design:
    nan = math.nan
    return Design(
        goal.name, NOT_REACHED, key, sequence.solve_for, region, nan, None, nan, nan, None,
        nan, None, {}, {}, {}, sequence, note=note,
    )  # fmt: skip


def unreached_note(goal: Target, failed: bool) -> Remedy:
    """What to try when no target mode was found (NOT_REACHED). A listed mode is solved
    directly at every scanned design, whatever the scans' window: widening it cannot help
    (it was advised for a (2, 0) well inside it, whose window lay between two failed grid
    points, probe 14d D1), a finer grid can; a set's members are those the window holds."""
    where = "between the grid's points" + (" and in its failed intervals" if failed else "")
    if goal.modes:
        return Remedy(
            f"no target mode bifurcates at the scanned designs (each solved directly): it may"
            f" come first {where}; raise --points, or move the --vary range",
            python=f"no target mode bifurcates at the scanned designs (each solved directly):"
            f" it may come first {where}; raise points=, or move the vary range",
        )
    return Remedy(
        "no member of the set among the scanned modes: widen --m-max / --n-max, or raise --points",
        python="no member of the set among the scanned modes: widen ScanOptions(m_range=...,"
        " n_range=...), or raise points=",
    )


def _best_in_region(region, grid, goal: Target, margins: Margins, scan, edges=frozenset()):
    """(x, target mode, competitors) of the widest margin over the region's intervals (in
    a span that ends at a located end of the valid range, ``edges``, M counts its gap)."""
    best = None
    for iv in region:
        edge = _touches(_span(region, 0.5 * (iv.lo + iv.hi)), edges)
        inside = [x for x in grid if iv.lo < x < iv.hi] + [0.5 * (iv.lo + iv.hi)]
        if iv.lo_edge:
            inside.append(iv.lo)
        if iv.hi_edge:
            inside.append(iv.hi)
        inside = sorted(set(inside))
        found = set()
        for x in inside:
            comps = _competitors(iv.mode, scan(x), goal)
            if not comps and not goal.modes:  # a set's first modes are all its own: further
                comps = _competitors(iv.mode, scan(x, TOP_MAX), goal)
            found |= set(comps)
        others = tuple(sorted(found))
        if not others:
            continue
        scores = [margins.best_margin(iv.mode, others, x, edge)[0] for x in inside]
        i = max(range(len(inside)), key=scores.__getitem__)
        a = inside[i - 1] if i > 0 else iv.lo
        b = inside[i + 1] if i + 1 < len(inside) else iv.hi
        x, others = _refine(iv.mode, others, a, b, inside[i], goal, margins, scan, edge)
        score = margins.best_margin(iv.mode, others, x, edge)[0]
        if best is None or score > best[0]:
            best = (score, x, iv.mode, others)
    return None if best is None else best[1:]


def no_width(iv, sequence) -> bool:
    """Is ``iv`` no wider than the x_error of the switches that bound it (a tie at one x)?
    A range that starts at a switch located again to 1e-13 of x may start 1.7e-15 before
    it: (35, 0) was "found" on that sliver."""
    errors = [
        s.x_error for s in sequence.switches if s.x in (iv.lo, iv.hi) and math.isfinite(s.x_error)
    ]
    return iv.hi - iv.lo <= max(errors, default=0.0)


def _tied_only(ties, goal: Target, margins: Margins, scan):
    """(x, target mode, competitors) at the point of ``ties`` (intervals of no width, where
    a target mode only ties with another) with the largest M: the closest design, M ~ 0
    (the rounding of the two values); None without such points."""
    best = None
    for iv in ties:
        others = tuple(_competitors(iv.mode, scan(iv.lo), goal))
        if others:
            m = margins.best_margin(iv.mode, others, iv.lo)[0]
            if best is None or m > best[0]:
                best = (m, iv.lo, iv.mode, others)
    return None if best is None else best[1:]


def _closest(grid, goal: Target, margins: Margins, scan, members):
    """(x, target mode, competitors ahead of it) where the best target mode comes closest
    to first: M < 0 maximised. A set none of
    whose modes is among a scan's first TOP_MAX (a film's 64 x 31 folds and wrinkles before
    its first ring) is ranked by solving its scanned ``members`` directly
    (:func:`set_members`); a set's best member found is followed past the modes looked at
    (:func:`_past_window`)."""
    scored = []
    for x in grid:
        found = best_member(x, goal, margins, scan, members)
        if found is None:
            continue
        ranked, mode, v = found
        # the earliest competitors decide M < 0 (the first of them alone, the rest for _refine)
        ahead = tuple(m for m, w in ranked if m not in goal and margins.sense * (w - v) < 0)
        ahead = ahead[:AHEAD]
        if ahead:
            scored.append((margins.best_margin(mode, ahead, x)[0], x, mode, ahead))
    if not scored:
        return None
    j = max(range(len(scored)), key=lambda k: scored[k][0])
    _, x0, mode, ahead = scored[j]
    a = b = x0
    others = set(ahead)
    if j > 0 and scored[j - 1][2] == mode:
        a, others = scored[j - 1][1], others | set(scored[j - 1][3])
    if j + 1 < len(scored) and scored[j + 1][2] == mode:
        b, others = scored[j + 1][1], others | set(scored[j + 1][3])
    x, others = _refine(mode, tuple(sorted(others)), a, b, x0, goal, margins, scan)
    return x, mode, others


def best_member(x, goal: Target, margins, scan, members):
    """(the modes ranked at x, the target's first mode there, its value), or
    None where no target mode is found: as :func:`_closest` takes it (its docstring), for
    prescribe_map.py's closest design too. ``margins``: ``value``/``sense`` as
    :class:`Margins`; ``scan(x, top=None)``: the modes in the order reached."""
    ranked = scan(x)
    for mode in goal.modes:  # listed modes beyond the scan's top: solved directly
        if all(r[0] != mode for r in ranked) and math.isfinite(margins.value(mode, x)):
            ranked.append((mode, margins.value(mode, x)))
    hits = [(mode, v) for mode, v in ranked if mode in goal and math.isfinite(v)]
    if not hits and not goal.modes:  # a set's modes all come later: ranked further
        ranked = scan(x, TOP_MAX)
        hits = [(mode, v) for mode, v in ranked if mode in goal and math.isfinite(v)]
        if not hits:  # ... past the first TOP_MAX: its members solved directly
            solved = [(mode, margins.value(mode, x)) for mode in members]
            hits = [(mode, v) for mode, v in solved if math.isfinite(v)]
    if not hits:
        return None
    mode, v = min(hits, key=lambda h: margins.sense * h[1])
    if not goal.modes:  # a set, not a list: its members go on past the scanned window
        mode, v = _past_window(mode, v, x, goal, margins)
    return ranked, mode, v


def cap_note(mode, goal: Target, caps: tuple[int, int]) -> str:
    """``note`` where a set's closest member found sits at a mode cap of its design's tube
    (``caps``, bifurcation.options.mode_caps; whether the scan or :func:`_past_window`
    reached it there), else empty."""
    at = [cap for k, cap in zip(mode, caps, strict=True) if k >= cap]
    if goal.modes or not at:
        return ""
    return (
        f"the closest member found, {mode}, is at the mode cap {at[0]}: a member of the"
        " set beyond it may come closer"
    )


def _past_window(mode, v: float, x: float, goal: Target, margins: Margins):
    """(member, value): the member of the set ``goal`` nearest to first along
    n, then m, from ``mode`` (at ``v``), the best one among the modes looked at at x.

    A scan's window (ScanOptions' ranges, widened only for its own critical mode) or the
    set's scanned members hold the set's first modes only: a film's best ring (0, 182) lies
    far past a window of n <= 4, whose edge (0, 8) was reported as the closest member with
    M = -0.370 against -0.0185 (probe 13c). Where the next member along an axis comes
    earlier, the members go on by single-mode solves, in msearch.py's geometric steps, until
    their values turn away (or the mode cap), and the bracket is refined as there."""
    for axis in (1, 0):
        mode, v = _along_axis(mode, v, x, axis, goal, margins)
    return mode, v


def _along_axis(mode, v: float, x: float, axis: int, goal: Target, margins: Margins):
    """:func:`_past_window` along one axis (1: n, 0: m); never = sense * inf (not a member,
    or it does not bifurcate)."""

    def member(k):
        return (k, mode[1]) if axis == 0 else (mode[0], k)

    def value(k):
        trial = member(k)
        return margins.value(trial, x) if trial in goal else margins.sense * math.inf

    def later(a, b):  # is member a reached after member b (or with it)?
        return margins.sense * seen[a] >= margins.sense * seen[b]

    k0, cap = mode[axis], margins.caps(x)[axis]  # as far as the scans of the tube at x go
    if k0 >= cap or margins.sense * value(k0 + 1) >= margins.sense * v:
        return mode, v  # they turn away at once: no edge to go past
    seen = {k0: v, k0 + 1: value(k0 + 1)}  # (cached)
    best = k0 + 1
    for k in geometric_samples(max(k0, 1), cap):  # from 1: 0 x RATIO stays 0
        if k <= best:
            continue
        seen[k] = value(k)
        if later(k, best):
            break
        best = k
    lo, hi = neighbours(list(seen), best)
    while hi - lo > 1:  # the bracket refined as msearch.py's is
        inner = refine_samples(lo, hi)
        seen.update({k: value(k) for k in inner if k not in seen})
        best = min([lo, *inner, hi], key=lambda k: margins.sense * seen[k])
        complete = len(inner) == hi - lo - 1
        lo, hi = neighbours([lo, *inner, hi], best)
        if complete:
            break
    return member(best), seen[best]


def set_members(goal: Target, options: ScanOptions) -> tuple:
    """The modes of a set ``goal`` (not a list) among those a scan with ``options`` covers,
    or none when they are more than MEMBERS_MAX (solved one by one at each design)."""
    if goal.modes:
        return ()
    families = (options.prismatic, options.torsional)
    rows = scan_grid(options.m_range, options.n_range, False, families)
    found = tuple(dict.fromkeys((int(m), int(n)) for m, n, _ in rows if (m, n) in goal))
    return found if len(found) <= MEMBERS_MAX else ()


def _competitors(mode, ranked, goal: Target) -> list:
    """The modes of a scan that decide M for ``mode``: every non-target mode ahead of it
    and the first one after it."""
    out, passed = [], False
    for m, _ in ranked:
        passed = passed or m == mode
        if m not in goal:
            out.append(m)
            if passed:
                break
    return out


def _refine(mode, others, a, b, x0, goal: Target, margins: Margins, scan, edge=()):
    """Maximise M over [a, b] by bounded Brent from the grid's best x0; a competitor that a
    scan at the optimum finds but ``others`` lacks is added and the maximisation repeated
    (``edge``: M counts the gap to a located end of the valid range)."""
    from scipy.optimize import minimize_scalar

    x = x0
    for _ in range(REFINE_ROUNDS):
        if b > a:
            res = minimize_scalar(
                lambda t, others=others: -margins.best_margin(mode, others, t, edge)[0],
                bounds=(a, b),
                method="bounded",
                options={"xatol": XTOL * max(1.0, abs(x0))},
            )
            better = -res.fun >= margins.best_margin(mode, others, x0, edge)[0]
            x = float(res.x) if better else x0
        missing = [m for m in _competitors(mode, scan(x), goal) if m not in others]
        if not missing:
            break
        others = tuple(sorted(set(others) | set(missing)))
    return _at_kink(mode, others, a, b, x, margins, edge), others


def _at_kink(mode, others, a, b, x, margins: Margins, edge=()):
    """The kink of M next to the maximiser x of the bounded Brent (``_refine``), located as
    the tie of its two competitors: Brent (SWITCH, as a mode switch) on s (w_1 - w_2), w_1
    the competitor (a mode, the crease or the short-wave limit) that sets M at x, w_2 the
    next. The bounded
    maximisation alone left the usual optimum, such a kink, 5e-8 (relative) off and M 3e-6
    low (probe 9b). x itself where M is smooth there, no such tie lies within [a, b], or
    the room below the target (``edge``) sets M."""
    if not b > a:
        return x
    w = {c: _rival_value(margins, c, x) for c in (*others, CREASE)}
    # the limit where it is among the first two (the march only as far as the second)
    w[SURFACE] = margins.surface(x, sorted(w.values(), key=lambda u: margins.sense * u)[1])
    first, second = sorted(w, key=lambda c: margins.sense * w[c])[:2]
    near = abs(w[second] - w[first]) <= onset.TIE_SCREEN * abs(margins.value(mode, x))
    m_x = margins.best_margin(mode, others, x, edge)[0]
    if not (near and math.isfinite(w[second]) and m_x == margins.margin(mode, x, w[first])):
        return x

    def d(t):
        return margins.sense * (_rival_value(margins, first, t) - _rival_value(margins, second, t))

    tie = _bracketed_root(d, x, a, b)
    if tie is None or not margins.best_margin(mode, others, tie, edge)[0] >= m_x:
        return x
    return tie


def _bracketed_root(d, x: float, a: float, b: float) -> float | None:
    """The root of d next to x in [a, b] (d(x) <= 0 there), by windows widening from the
    bounded Brent's own tolerance; None if d keeps its sign."""
    if d(x) == 0:
        return x
    step = XTOL * max(1.0, abs(x))
    for lo, hi, _ in widening_windows(x, step, KINK_WINDOWS, bounds=(a, b)):
        for p, q in ((lo, x), (x, hi)):
            if q > p and (d(p) > 0) != (d(q) > 0):
                return brent(d, p, q, SWITCH)
    return None


def _rival_value(margins: Margins, rival, x: float) -> float:
    """The critical value of a competitor at x: a mode's, where a face creases, or the
    short-wave limit."""
    if rival == SURFACE:
        return margins.surface(x)
    return margins.crease(x) if rival == CREASE else margins.value(rival, x)
