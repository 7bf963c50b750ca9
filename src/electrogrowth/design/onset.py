"""What a design is seen to do at onset: the crease of a face as a competitor of the
target's wrinkle in the margin, and the verdict of the chosen design (docs/design.md,
"A crease before the wrinkle").

A crease that comes before the target mode pre-empts it: the face folds sharply before
any smooth wrinkle, and the pattern aimed at is not what is seen. So the margin counts the
crease as one more competitor, M = min(M_modes, M_crease) with

    M_crease(x) = s (v_crease(x) - v_T(x)) / |v_T(x)|,

negative where the crease comes first; the best design never prefers a crease-first
design to one that wrinkles first, and where the crease comes first across the whole
region the result says so (status CREASE_FIRST). As in the verdict (bifurcation/verdict.py)
a crease by the field criterion, an early bound, is not counted.
"""

from __future__ import annotations

import math

import numpy as np

from ..basestate.tube import solve_base_state
from ..bifurcation.crease import MECHANICAL, crease_margin, crease_onset, face_creases
from ..bifurcation.scan import ScanOptions, scan_modes
from ..bifurcation.verdict import advisory, crease_rival, creases
from ..errors import ConvergenceError, ElectrogrowthError
from ..interrupts import reraise_interrupt
from .sensitivity import STEP, _derivative, key_value, margin_error, sensitivities, step_of

CREASE_FIRST = "crease_first"  # first among the wrinkles in its region, but a crease comes first


def crease_value(tube, solve_for: str, side, sense: float, until: float | None = None) -> float:
    """Where a face of ``tube`` creases along the control (a mechanical crease);
    sense * inf where none is reached (before ``until``, if given) or the criterion cannot
    be evaluated."""
    try:
        rival = crease_rival(crease_onset(tube, solve_for, side=side, until=until))
    except ElectrogrowthError:
        return sense * math.inf
    if rival is None or advisory(rival):
        return sense * math.inf
    return rival.value


class CreaseRival:
    """Where a face creases at designs x, cached (:func:`crease_value`): ``tube_at(x)`` the
    tube there. Only a crease before the nearest other rival can set the margin, so it is
    looked for up to ``until`` where one is given; each entry is (v, reach): the crease
    value, or sense * inf and how far the march looked (None: to the control's end)."""

    def __init__(self, tube_at, solve_for: str, side, sense: float):
        self.tube_at, self.solve_for, self.side, self.sense = tube_at, solve_for, side, sense
        self.cache: dict = {}

    def value(self, x, until: float | None = None) -> float:
        """v_C at x where it comes before ``until`` (None or infinite: anywhere); sense *
        inf where it does not. A crease already located past ``until`` is returned as it
        is: it cannot set M there either."""
        until = until if until is not None and math.isfinite(until) else None
        key = tuple(float(c) for c in x) if hasattr(x, "__len__") else x
        if key in self.cache:
            v, reach = self.cache[key]
            if math.isfinite(v) or reach is None:
                return v
            if until is not None and self.sense * (until - reach) <= 0:
                return v  # looked that far already
        v = crease_value(self.tube_at(x), self.solve_for, self.side, self.sense, until)
        self.cache[key] = (v, None if math.isfinite(v) else until)
        return v


def gap_to_crease(v_target: float, v_crease: float, sense: float) -> float:
    """M_crease (module docstring): inf where no crease is reached, -inf where the target
    is never reached."""
    if not math.isfinite(v_target):
        return -math.inf
    if not math.isfinite(v_crease):
        return math.inf
    return sense * (v_crease - v_target) / abs(v_target)


def crease_sensitivities(tube, solve_for: str, value: float, keys, *, step: float = STEP):
    """d(v_C)/dp of the crease value v_C for every key p: by implicit differentiation of
    the onset condition h(v_C, p) = 0, h the drive of the creasing face's trigger minus 1
    on the base state (crease.py), dv_C/dp = -h_p / h_v, both partials by the
    Richardson-extrapolated differences of design/sensitivity.py (base states only, no
    march). Raises ConvergenceError where h_v vanishes."""
    onset = crease_margin_at(tube, solve_for, value)
    face, trigger = onset.face, onset.trigger_of(MECHANICAL)

    def h(t, v: float) -> float:
        state = solve_base_state(t.at(solve_for, v), rtol=1e-12)
        f = next((f for f in face_creases(state) if f.face == face), None)
        if f is None:  # an interface that stops being a candidate (its neighbour stiffened)
            raise ConvergenceError(f"the {face} is no crease candidate at {solve_for} = {v:g}")
        return f.drives[trigger] - 1.0

    h_v = _derivative(lambda v: h(tube, v), value, step_of(tube, solve_for, value, step))
    if not math.isfinite(h_v) or h_v == 0.0:
        raise ConvergenceError(f"the crease drive does not change with {solve_for} at {value:g}")
    out = {}
    for key in keys:
        p = key_value(tube, key)
        f_key = lambda q, key=key: h(tube.at(key, q), value)  # noqa: E731
        h_p = _derivative(f_key, p, step_of(tube, key, p, step))
        out[key] = -h_p / h_v
    return out


def crease_sensitivity(tube, solve_for: str, value: float, keys) -> dict:
    """:func:`crease_sensitivities` where the crease is reached (value finite), else {}
    (also where the onset condition does not determine it: h_v = 0)."""
    if not math.isfinite(value):
        return {}
    try:
        return crease_sensitivities(tube, solve_for, value, keys)
    except ElectrogrowthError:
        return {}


def margin_sensitivity(sense: float, v: float, dv: dict, w: float, dw: dict) -> dict:
    """dM/dp of M = s (w - v) / |v| = s sgn(v) (w / v - 1) from the sensitivities dv of
    the target's value v and dw of the competitor's w (a mode or the crease):
    dM/dp = s sgn(v) (v dw/dp - w dv/dp) / v^2."""
    scale = sense * math.copysign(1.0, v) / v**2
    return {p: scale * (v * dw[p] - w * dv[p]) for p in dv if p in dw}


#: competitors whose margin is within this of the one that sets M are checked for a kink
#: (a gap that a relative step of 1e-4 in p closes needs a slope difference of 10 per unit
#: of log p: none seen; the ties at an optimum are equal to ~1e-9)
TIE_SCREEN = 1e-3


def rivals_at(margins, at, solve_for, x, v, lead, others, given, rtol) -> list:
    """The competitors at x within reach of a tie with ``lead`` (:func:`near_rivals`), each
    with its sensitivities: the modes ``others``, the crease and the short-wave limit.
    ``margins``: a design's margins along its variable or variables (``value(mode, x)``,
    ``crease(x)``, ``surface(x, until)``, ``sense``); ``given``: the sensitivities of the
    crease and of the limit by name ("crease", "surface"), already taken."""

    def sens_of(name, w):
        if name in given:
            return given[name] or None
        try:
            return sensitivities(at, name, solve_for, w, rtol=rtol)
        except ElectrogrowthError:  # a fold of the rival's branch: its kink is not known
            return None

    reach = lead[1] + margins.sense * TIE_SCREEN * abs(v)  # the limit only within the screen
    cands = [(o, margins.value(o, x)) for o in others] + [
        ("crease", margins.crease(x)),
        ("surface", margins.surface(x, reach)),
    ]
    return near_rivals(margins.sense, v, lead, cands, sens_of)


def near_rivals(sense: float, v: float, lead: tuple, candidates, sens_of) -> list:
    """[lead] and every other competitor (name, w) of ``candidates`` whose margin
    s (w - v) / |v| is within TIE_SCREEN of the lead's, as (name, w, dw): ``lead`` (name,
    w, dw) sets M; ``sens_of(name, w)`` gives dw (None where it cannot be formed)."""
    m_lead = sense * (lead[1] - v) / abs(v)
    out = [lead]
    for name, w in candidates:
        near = math.isfinite(w) and sense * (w - v) / abs(v) - m_lead <= TIE_SCREEN
        if name != lead[0] and near:
            out.append((name, w, sens_of(name, w)))
    return out


def margin_errors(tube, v: float, w: float, dv: dict, rtol: float) -> dict:
    """The least error of dM/dp for every key of ``dv`` (sensitivity.margin_error), M
    the gap from the target's v to the competitor's w."""
    return {p: margin_error(tube, p, v, w, rtol) for p in dv}


def kinked_margin(
    tube, sense: float, v: float, dv: dict, rivals, error: dict | None = None
) -> tuple[dict, dict, tuple]:
    """dM/dp of M = min over ``rivals`` [(name, w, dw)] (from :func:`near_rivals`, the one
    that sets M first) of s (w - v) / |v|: (dM/dp by key, {key: (down, up)}, the tied
    rivals).

    At a tie M is the minimum of smooth gaps M_i and has a kink: raising p it follows the
    steepest falling one, dM/dp+ = min_i dM_i/dp, lowering p the steepest rising one,
    dM/dp- = max_i dM_i/dp. The usual optimum is such a tie (probe 8b, D5: +0.061 was
    reported for the length where M falls by 0.045 per unit towards longer tubes). A rival
    counts as tied for p where the kink lies within the sensitivities' own step in p,
    M_i - M_0 <= h |dM_0/dp - dM_i/dp|; then dM/dp is None and ``down``, ``up`` the two
    one-sided derivatives (None both where a tied rival's dw could not be formed). Slopes
    that differ by no more than their ``error`` (:func:`margin_errors`) are one: no kink."""
    lead = rivals[0]
    dm = [None if dw is None else margin_sensitivity(sense, v, dv, w, dw) for _, w, dw in rivals]
    gaps = [sense * (w - v) / abs(v) - sense * (lead[1] - v) / abs(v) for _, w, _ in rivals]
    sens, sides, tied = dict(dm[0]), {}, []
    for p, d0 in dm[0].items():
        h = step_of(tube, p, key_value(tube, p))
        near = []
        for (name, _, _), d, gap in zip(rivals[1:], dm[1:], gaps[1:]):
            if d is None or (p in d and gap <= h * abs(d0 - d[p])):
                near.append(None if d is None else d[p])
                tied += [name] * (name not in tied)
        if None in near:
            sens[p], sides[p] = None, (None, None)
        elif near and max(near + [d0]) - min(near + [d0]) > (error or {}).get(p, 0.0):
            sens[p], sides[p] = None, (max(near + [d0]), min(near + [d0]))
    return sens, sides, tuple(tied)


def crease_margin_at(tube, solve_for: str, value: float):
    """The face nearest its mechanical crease onset at ``solve_for`` = value (a FaceCrease):
    the crease :func:`crease_value` ranks, whose trigger is never the field's."""
    state = solve_base_state(tube.at(solve_for, value), rtol=1e-12)
    return crease_margin(state, MECHANICAL)


def design_verdict(tube, solve_for: str, side, options: ScanOptions, *, koiter: bool) -> dict:
    """The verdict of the chosen design (a scan there, as ``electrogrowth critical``):
    ``kind``, ``value``, ``face``, ``meaning``, the crease (``crease``: value, face,
    trigger, error_estimate, or None), ``wrinkle`` (its mode and value), and with
    ``koiter`` the branch (``branch``, ``koiter``, ``koiter_error``, ``koiter_resonance``;
    ``branch_note``: why not). A scan that fails gives ``kind`` "" and the ``meaning`` of
    the failure."""
    try:
        verdict = scan_modes(tube, solve_for, side=side, options=options).verdict
    except Exception as exc:  # noqa: BLE001 - the design stands; its verdict says why not
        reraise_interrupt(exc)
        return {"kind": "", "meaning": f"no verdict: {type(exc).__name__}: {exc}"}
    note = "not asked (--koiter)"
    if koiter:
        from ..bifurcation.koiter import with_branch  # scipy's dense algebra: only when asked

        verdict, why = with_branch(verdict, tube, solve_for, side)
        note = why or ""
    d = verdict.as_dict()
    keep = ("kind", "value", "face", "meaning", "crease", "wrinkle", "branch", "koiter")
    extra = {k: d[k] for k in ("koiter_error", "koiter_resonance")}
    return {**{k: d[k] for k in keep}, **extra, "branch_note": note}


def observable(verdict: dict) -> str:
    """One line where the chosen design's pattern may not be what is seen: a crease first,
    a subcritical wrinkle; "" otherwise."""
    if verdict.get("kind") == "crease":
        c = verdict["crease"]
        return (
            f"warning: at this design {creases(c['face'], c.get('detail'))} ({c['trigger']}) at"
            f" {c['value']:.4g} before the wrinkle: the target pattern may not be observed"
        )
    if verdict.get("branch") == "subcritical":
        return (
            "warning: the wrinkle is subcritical at this design: the tube jumps to large folds"
            " at onset, so the pattern may not be observed as a small wrinkle"
        )
    return ""


def region_creases(region, curve) -> list[dict]:
    """For each interval of the region: the curve's points in it (its distinct x: a located
    switch is two rows of one x) and how many of them crease first ("none", "part" or "all"
    of them)."""
    out = []
    for iv in region:
        inside = (curve.x >= iv.lo) & (curve.x <= iv.hi)
        xs, at = np.unique(curve.x[inside], return_inverse=True)
        creased = np.zeros(len(xs), bool)
        np.logical_or.at(creased, at, curve.crease.first[inside])
        first, points = int(creased.sum()), len(xs)
        which = "none" if first == 0 else "all" if first == points else "part"
        out.append({"crease_first": which, "crease_first_points": [first, points]})
    return out
