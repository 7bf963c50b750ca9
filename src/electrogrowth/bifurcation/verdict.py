"""One verdict per result: what comes first along the control, and what comes next.

The linear analysis (critical.py, scan.py) finds the first wrinkle (kind BIFURCATION), the
short-wave surface limit (SURFACE) or the loss of the axisymmetric state (THRESHOLD); the
crease criterion (crease.py) finds where a face creases (CREASE: a free
face, or an interface bonded to a much softer layer). A :class:`Verdict`
puts them on one footing: ``kind`` and ``value`` of the first reached, the runner-up of
every other kind that was found (``wrinkle``, ``surface``, ``crease``, ``threshold``: a
:class:`Rival` or None), and ``meaning``, one line for a user.

``branch`` ("supercritical" / "subcritical"), ``koiter`` (the coefficient of the
amplitude equation) and ``koiter_error`` (its error estimate) are a slot for the weakly
nonlinear expansion of the wrinkle: None until it is computed.
"""

from __future__ import annotations

import dataclasses
import math

from ..digits import apart
from ..errors import ElectrogrowthError
from ..model.controls import parse_control
from ..outcomes import Kind, Status, json_number
from .crease import crease_onset
from .march import control_path
from .state_loss import own_threshold

#: the kinds a verdict compares, and the record key of each one's runner-up
RIVALS = {
    Kind.BIFURCATION: "wrinkle",
    Kind.SURFACE: "surface",
    Kind.CREASE: "crease",
    Kind.THRESHOLD: "threshold",
}


@dataclasses.dataclass(frozen=True)
class Rival:
    """One kind of instability at its value: a wrinkle (``m``, ``n``, ``family``; ``detail``
    ONE_MODE where it is the one mode asked for, not a scan's first), a surface or crease
    (``face``; a crease's ``trigger``: prismatic, axial or field; at an interface ``detail``
    says which, and which layer folds) or the threshold (``detail``: what is lost)."""

    kind: str
    value: float
    error_estimate: float | None = None
    m: int | None = None
    n: int | None = None
    family: str | None = None
    face: str | None = None
    trigger: str | None = None
    detail: str | None = None

    def as_dict(self) -> dict:
        out = dataclasses.asdict(self)
        out["kind"] = str(self.kind)
        out["value"], out["error_estimate"] = (
            json_number(self.value),
            json_number(self.error_estimate),
        )
        return out


@dataclasses.dataclass(frozen=True)
class Verdict:
    """What comes first (``kind``, ``value``, ``face``), the runner-up of each other kind,
    the one-line ``meaning``, and the slot ``branch``/``koiter`` (None: not computed)."""

    kind: str
    value: float
    face: str | None
    meaning: str
    wrinkle: Rival | None = None
    surface: Rival | None = None
    crease: Rival | None = None
    threshold: Rival | None = None
    criterion: str | None = None
    side: str | None = None  # "compression": the march decreases the control
    branch: str | None = None  # "supercritical" | "subcritical"; None: not computed
    koiter: float | None = None  # the Koiter coefficient; None: not computed
    koiter_error: float | None = None  # its change from a coarser resolution
    #: a second harmonic next to onset (koiter_resonance.Resonance as a dict), or None
    koiter_resonance: dict | None = None
    #: the field criterion's crease where a mechanical crease is reached too (``crease``):
    #: an early bound, a note in ``meaning``, never ranked (:func:`advisory`)
    field_crease: Rival | None = None

    @property
    def first(self) -> Rival | None:
        """The rival that comes first (None when nothing was found)."""
        key = RIVALS.get(Kind(self.kind))
        return None if key is None else getattr(self, key)

    @property
    def runners_up(self) -> tuple[Rival, ...]:
        """The other kinds found, in the order they are reached."""
        return tuple(r for r in self._ordered() if r is not self.first)

    def _ordered(self):
        found = [getattr(self, key) for key in RIVALS.values()]
        sense = -1.0 if self.side == "compression" else 1.0
        return sorted((r for r in found if r is not None), key=lambda r: sense * r.value)

    def as_dict(self) -> dict:
        return {
            "kind": str(self.kind),
            "value": json_number(self.value),
            "face": self.face,
            "meaning": self.meaning,
            **{key: _rival_dict(getattr(self, key)) for key in RIVALS.values()},
            "field_crease": _rival_dict(self.field_crease),
            "crease_criterion": self.criterion,
            "branch": self.branch,
            "koiter": self.koiter,
            "koiter_error": self.koiter_error,
            "koiter_resonance": self.koiter_resonance,
        }


def _rival_dict(r: Rival | None):
    return None if r is None else r.as_dict()


def judge(
    side: str | None,
    *,
    wrinkle: Rival | None = None,
    surface: Rival | None = None,
    crease: Rival | None = None,
    threshold: Rival | None = None,
    criterion: str | None = None,
    name: str = "the control",
    field_crease: Rival | None = None,
    start: float | None = None,
) -> Verdict:
    """The verdict of the rivals found: the first reached along the march (decreasing on
    the compression side, else increasing) comes first; a tie goes to the linear result.
    ``field_crease``, the field criterion's crease beside a mechanical ``crease``, is a
    note (:func:`advisory`). ``start``: the control's value where the march starts, which
    no value of ``meaning`` may read as (:func:`meaning`).

    >>> w = Rival(Kind.BIFURCATION, 0.511, m=0, n=1, family="wrinkle")
    >>> c = Rival(Kind.CREASE, 0.558, 0.005, face="outer", trigger="axial")
    >>> v = judge("compression", wrinkle=w, crease=c, name="lambda_z")
    >>> str(v.kind), v.value, [str(r.kind) for r in v.runners_up]
    ('crease', 0.558, ['bifurcation'])
    """
    sense = -1.0 if side == "compression" else 1.0
    found = (wrinkle, surface, threshold, crease, field_crease)
    rivals = [r for r in found if r is not None]
    rivals = [r for r in rivals if math.isfinite(r.value)]
    ranked = [r for r in rivals if not advisory(r)]
    if not ranked:
        note = "no instability found in the searched range"
        if rivals:
            note += f"; {_what(rivals[0])} at {name} = {_shown(rivals[0], start)}"
        return Verdict(
            Kind.NONE, math.nan, None, note, crease=crease, side=side, field_crease=field_crease
        )
    first = min(ranked, key=lambda r: sense * r.value)  # the first listed wins a tie
    return Verdict(
        first.kind,
        first.value,
        first.face,
        meaning(first, [r for r in rivals if r is not first], sense, name, start),
        wrinkle,
        surface,
        crease,
        threshold,
        criterion,
        side,
        field_crease=field_crease,
    )


#: a wrinkle's ``detail`` where it is the one mode asked for (``critical_value``): no other
#: mode was looked at, so it is not "the tube wrinkles" (probe round 12a: `critical --mode
#: 12 0` said so of a tube whose (11, 0) comes first)
ONE_MODE = "the mode asked for"


def advisory(r: Rival) -> bool:
    """A crease by the field criterion informs but never comes first: its value is that of
    a bonded film that can neither thin nor stretch (derivation-crease.md), and the tube's
    face does both under the voltage; a prestretched film creases at a markedly higher
    field (Wang, Tahir, Zhang & Zhao, Soft Matter 7, 6583 (2011)), so it is an early bound."""
    return r.kind == Kind.CREASE and r.trigger == "field"


def _mode(r: Rival) -> str:
    return f"mode (m, n) = ({r.m}, {r.n})"


def _shown(r: Rival, *others: float | None) -> str:
    """``r``'s value with the digits its error estimate supports, and enough to tell it
    from ``others``: 4 digits printed a film's onset 1.00027786548 (estimate 5e-12) as
    "1", the unloaded start, and a surface limit and the next mode 6.5e-5 apart both as
    "0.7961" (probe 12b, D2)."""
    return apart(r.value, r.error_estimate, *others)


def meaning(
    first: Rival, others: list[Rival], sense: float, name: str, start: float | None = None
) -> str:
    """One line for a user: what they will see first and what it pre-empts, each value with
    the digits its estimate supports and never printed as the control's ``start`` or as
    the other event's value (:func:`_shown`)."""
    notes = "".join(
        f"; note: {_what(r)} at {name} = {_shown(r, start, first.value)}"
        for r in others
        if advisory(r)
    )
    others = [r for r in others if not advisory(r)]
    nxt = min(others, key=lambda r: sense * r.value) if others else None
    after = ""
    if nxt is not None:
        after = f"; next: {_what(nxt)} at {name} = {_shown(nxt, start, first.value)}"
    at = _shown(first, start, None if nxt is None else nxt.value)
    close = ""
    if first.kind == Kind.CREASE and first.error_estimate is not None:
        if math.isinf(first.error_estimate):  # crease.energy_shift: no Biot ratio
            close = " (a neo-Hookean criterion this energy may never reach: it may not crease)"
        elif nxt is not None and abs(nxt.value - first.value) <= first.error_estimate:
            close = " (within the crease criterion's accuracy of it: too close to call)"
    # with one mode asked for no other wrinkle was looked at: "before any smooth wrinkle"
    # was said of a crease at 0.558 while (1, 1) wrinkles at 0.901 (probe 13c, D1)
    one = any(r.kind == Kind.BIFURCATION and r.detail == ONE_MODE for r in others)
    scan_says = " (a scan says whether another mode comes first)"
    if first.kind == Kind.CREASE:
        head = (
            f"{creases(first.face, first.detail)} (sharp folds, {_trigger(first.trigger)})"
            f" at {name} = {at} before "
            + (f"the mode asked for wrinkles{scan_says}" if one else "any smooth wrinkle")
        )
    elif first.kind == Kind.BIFURCATION and first.detail == ONE_MODE:
        head = (
            f"{_mode(first)} wrinkles smoothly at {name} = {at} (the mode asked for: a scan"
            " says whether another mode comes first)"
        )
    elif first.kind == Kind.BIFURCATION:
        head = f"the tube wrinkles smoothly in {_mode(first)} at {name} = {at}"
    elif first.kind == Kind.SURFACE:
        head = f"short-wave surface wrinkles at the {first.face} face at {name} = {at}"
    else:
        head = (
            f"the axisymmetric state is lost ({first.detail or 'threshold'}) at {name} ="
            f" {at} before "
            + (f"any crease or the mode asked for{scan_says}" if one else "any wrinkle or crease")
        )
    return head + after + close + notes


def _what(r: Rival) -> str:
    if advisory(r):
        return (
            f"the {r.face} face's field reaches the electro-creasing field of a bonded,"
            " unstretched film (an early bound for a crease)"
        )
    if r.kind == Kind.CREASE:
        return f"a crease at {crease_where(r.face, r.detail)}"
    if r.kind == Kind.BIFURCATION:  # u_theta alone is a twist, not a wrinkle (check 21, D3)
        what = "torsional" if r.family == "torsional" else "wrinkle"
        return f"the {what} {_mode(r)}"
    if r.kind == Kind.SURFACE:
        return f"short-wave wrinkles at the {r.face} face"
    return "the loss of the axisymmetric state"


def crease_where(face: str | None, detail: str | None = None) -> str:
    """Where a crease forms, in words: "the inner face", "the outer face", or at an
    interface its ``detail`` ("interface 1|2 (R = 1.5), layer 1 folds")."""
    if face is not None and face.startswith("interface") and detail:
        return detail
    return f"the {face} face"


def creases(face: str | None, detail: str | None = None) -> str:
    """ "the inner face creases" or "the tube creases at interface 1|2 (...)"."""
    where = crease_where(face, detail)
    return f"{where} creases" if where.startswith("the ") else f"the tube creases at {where}"


def _trigger(trigger: str | None) -> str:
    return {
        "prismatic": "fold lines along the axis, by hoop compression",
        "axial": "rings, by axial compression",
        "field": "by the electric field",
    }.get(trigger or "", "")


def crease_rival(onset) -> Rival | None:
    """A :class:`~.crease.CreaseOnset` as a rival (None where no crease was reached): the
    mechanical crease where the field criterion is met first and a mechanical one is
    reached too (``onset.ranked``; the field's is :func:`field_rival`), else the onset."""
    if onset is not None and onset.ranked.kind == Kind.CREASE:
        onset = onset.ranked
    return _onset_rival(onset)


def field_rival(onset) -> Rival | None:
    """The field criterion's crease where :func:`crease_rival` is the mechanical one (an
    early bound beside it), else None (the field's, if any, is crease_rival itself)."""
    if onset is None or onset.ranked is onset or onset.ranked.kind != Kind.CREASE:
        return None
    return _onset_rival(onset)


def _onset_rival(onset) -> Rival | None:
    if onset is None or onset.kind != Kind.CREASE:
        return None
    at_interface = onset.face is not None and onset.face.startswith("interface")
    return Rival(
        Kind.CREASE,
        onset.value,
        onset.error_estimate,
        face=onset.face,
        trigger=onset.trigger,
        detail=onset.label if at_interface else None,  # a free face names itself
    )


def record(base: dict, verdict: Verdict, critical=None, *, first_on_top: bool = True) -> dict:
    """A result's JSON record with the verdict: ``verdict``, ``verdict_value`` and
    ``verdict_face`` (what comes first), the runner-up of each kind (``wrinkle``,
    ``surface``, ``crease``, ``threshold``), ``meaning``, ``crease_criterion``, ``branch``
    and ``koiter``. With ``first_on_top`` (a scan) ``kind``, ``value``, ``face`` and
    ``error_estimate`` are also those of what comes first (m, n and family null unless a
    wrinkle does; the tube's fields at a crease's value: ``critical`` is the linear
    result); without it (one mode asked for) they stay the mode's."""
    out = dict(base)
    v = verdict.as_dict()
    out.update({key: value for key, value in v.items() if key not in ("kind", "value", "face")})
    out["verdict"], out["verdict_value"], out["verdict_face"] = v["kind"], v["value"], v["face"]
    first = verdict.first
    if not first_on_top or first is None:
        return out
    if critical is not None and verdict.kind == Kind.CREASE:
        out.update(critical.params.at(critical.solve_for, verdict.value).as_dict())
    out["kind"], out["face"] = v["kind"], v["face"]
    if first.kind in (Kind.CREASE, Kind.THRESHOLD):
        out["value"] = first.value
        out["error_estimate"] = json_number(first.error_estimate)
        out["m"] = out["n"] = out["family"] = None
        out["psi"] = None
        if first.kind == Kind.CREASE:
            out["method"] = "crease criterion"
        if unestablished(first):
            out["status"] = str(Status.INACCURATE)
    return out


def unestablished(r: Rival | None) -> bool:
    """A crease whose criteria say nothing for its energy (no finite error estimate:
    crease.energy_shift is inf, a solid that never wrinkles at its surface): a value of
    unknown accuracy, never status ok where it comes first (probe round 13c: a Gent J_m = 3
    tube's crease came first with status ok and no estimate)."""
    if r is None or r.kind != Kind.CREASE:
        return False
    return r.error_estimate is None or not math.isfinite(r.error_estimate)


#: how a control is named in a verdict's meaning
_NAMES = {"growth": "g", "stretch": "lambda_z", "voltage": "Vbar", "pressure": "P_i", "force": "F"}


def control_symbol(solve_for: str) -> str:
    """g, lambda_z, Vbar, P_i or F (a layer's growth as its control string)."""
    kind = parse_control(solve_for).kind
    return solve_for if kind == "growth" and solve_for != "growth" else _NAMES[kind]


def threshold_rival(critical, onset) -> Rival | None:
    """Where the axisymmetric state is lost: the linear result's threshold, else the
    voltage or inflation threshold of the tube (where that is the control), else the one
    the crease march met (None: not reached)."""
    kind = parse_control(critical.solve_for).kind
    if critical.kind == Kind.THRESHOLD:
        why = f"; {critical.message}" if critical.message else ""
        return Rival(Kind.THRESHOLD, critical.value, 0.0, detail=f"{kind} threshold{why}")
    t = own_threshold(critical.params, critical.solve_for, critical.side)
    if t is not None:
        if math.isfinite(t.value):
            return Rival(Kind.THRESHOLD, t.value, t.error, detail=f"{kind} {t.kind}")
        return None
    lost = math.nan if onset is None else onset.ranked.threshold  # the longer march's
    if math.isfinite(lost):
        return Rival(Kind.THRESHOLD, lost, None, detail="no axisymmetric state")
    return None


def _start(critical) -> float | None:
    """Where the march of ``critical``'s control starts (None where it has no path)."""
    try:
        return control_path(critical.params, critical.solve_for, critical.side)[0]
    except ElectrogrowthError:
        return None


def verdict_of(critical, *, finite=None, short_wave=None, one_mode=False) -> Verdict:
    """The verdict of a critical point (``critical_value`` or a scan's), the crease onset
    along the same control computed here. ``finite`` is the best finite mode when the
    critical point is the surface limit (a ModeValue); ``short_wave`` (value, error) the
    exact surface limit where a scan computed it after the wrinkle; ``one_mode``: the
    critical point is the one mode asked for, whose wrinkle is said to be that mode's only
    (ONE_MODE)."""
    try:
        onset = crease_onset(critical.params, critical.solve_for, side=critical.side)
        criterion = onset.criterion
    except ElectrogrowthError as exc:  # the linear result stands; say why there is no crease
        onset, criterion = None, f"crease criterion not evaluated: {exc}"
    wrinkle = surface = None
    if critical.kind == Kind.BIFURCATION:
        wrinkle = Rival(
            Kind.BIFURCATION,
            critical.value,
            critical.error_estimate,
            critical.m,
            critical.n,
            str(critical.family) if critical.family else None,
            detail=ONE_MODE if one_mode else None,
        )
    elif critical.kind == Kind.SURFACE:
        surface = Rival(Kind.SURFACE, critical.value, critical.error_estimate, face=critical.face)
    if finite is not None:
        est = finite.error_estimate  # a critical point's, moved among the runners-up
        wrinkle = Rival(Kind.BIFURCATION, finite.value, est, finite.m, finite.n, finite.family)
    if short_wave is not None and surface is None:
        surface = Rival(Kind.SURFACE, short_wave[0], short_wave[1])
    verdict = judge(
        critical.side,
        wrinkle=wrinkle,
        surface=surface,
        crease=crease_rival(onset),
        threshold=threshold_rival(critical, onset),
        criterion=criterion,
        name=control_symbol(critical.solve_for),
        field_crease=field_rival(onset),
        start=_start(critical),
    )
    if onset is None:
        return dataclasses.replace(verdict, meaning=verdict.meaning + " (crease not evaluated)")
    return verdict
