"""The crease competitor: where a face of the tube reaches the onset of creasing.

A crease is a sharp self-contacting fold of a free surface, a nonlinear instability with no
length scale that no linear (wrinkling) analysis finds. Having no length, its onset is
decided by the local state at the surface (docs/derivation-crease.md):

* mechanically, for an incompressible neo-Hookean solid, when the ratio of the stretch
  normal to the face to the smaller in-face stretch reaches CREASE_RATIO = 2.4 (Hong, Zhao
  & Suo 2009; plane-strain compression strain 0.35), against Biot's 3.38 for wrinkles. At
  a tube's face the normal stretch is lambda_r; a *prismatic* crease (fold lines along z)
  is driven by lambda_r / lambda_theta, an *axial* crease (rings) by lambda_r / lambda_z.
  The out-of-plane stretch scales the neo-Hookean plane problem by a constant modulus and
  drops out of the ratio;
* electrically, on a face that is an electrode, when the current field reaches
  E sqrt(eps / mu) = CREASE_FIELD = 1.03 (Wang, Zhang & Zhao 2011, a film bonded to a rigid
  electrode, no prestretch). The two are separate limits: their interaction (a field on a
  compressed or stretched face) is not known in closed form, and a face creases here when
  either is reached;
* at a bonded interface whose neighbour is much softer (crease_interface.py): the free
  face's ratio on the stiffer layer's face, which folds into that layer; the neighbour
  delays the onset, by an amount the error estimate carries.

For energies other than the neo-Hookean the neo-Hookean criterion is applied and the
result says so (``criterion``). The onset is the first root of the crease margin along the
march of the control from its stable start (model/controls.py KINDS), located by Brent's
method; its error estimate is the criterion's (its published digits), not the root's.
"""

from __future__ import annotations

import dataclasses
import functools
import math

from ..continuation.events import FULL, brent, threshold_between
from ..errors import (
    BaseStateError,
    BranchNotFollowed,
    ConvergenceError,
    ElectrogrowthError,
    ParameterError,
)
from ..model.builtin_energies import BuiltinEnergy
from ..model.layers import Tube
from ..outcomes import Kind, Outcome, Status, json_number
from .along import TubeAt
from .crease_interface import SOFT_NEIGHBOUR, interfaces, interfacial_biot_ratio, label
from .march import control_path
from .problem import Problem, as_problem
from .surface import ray_limit

#: the neo-Hookean plane-strain crease onset, lambda_normal / lambda_compressed (Hong, Zhao &
#: Suo 2009, Appl. Phys. Lett. 95, 111904: strain 0.35, ratio 2.4; Cao & Hutchinson 2012)
CREASE_RATIO = 2.4
#: its accuracy: the published onset strains 0.35 to 0.354 give ratios 2.37 to 2.40
CREASE_RATIO_ACCURACY = 0.03
#: Biot's plane-strain wrinkling (surface) ratio of the neo-Hookean half-space, 3.383
#: (the root of x^3 + x^2 + 3x - 1 = 0 is x = 1 / ratio; tests/bifurcation/test_crease.py)
BIOT_RATIO = 3.382975767906238
#: the electro-creasing field E sqrt(eps / mu) of an ideal neo-Hookean dielectric film
#: bonded to a rigid electrode (Wang, Zhang & Zhao 2011, Phys. Rev. Lett. 106, 118301)
CREASE_FIELD = 1.03
#: its accuracy (two published digits)
CREASE_FIELD_ACCURACY = 0.01
#: why a crease onset of a steeply stiffening energy is not established (energy_shift inf)
NO_BIOT = (
    "the neo-Hookean crease criteria are not established for this energy: it stiffens so"
    " steeply that its surface never wrinkles in compression (no Biot ratio), and it may not"
    " crease at all (Jin & Suo 2015); the value is the neo-Hookean criterion's alone"
)
#: the march's first, smallest and largest step, fractions of the control's scale: each
#: next step is half the secant's distance to the onset, within these bounds; where the
#: margin recedes, STEP_MAX of the distance marched if that is larger (_receding_step)
STEP, STEP_MIN, STEP_MAX = 0.02, 0.002, 0.1
#: the free faces, which may always crease; an interface may where its neighbour is much
#: softer (crease_interface.interfaces)
FACES = ("inner", "outer")
#: the mechanical triggers, and all of them: the field criterion is an early bound (a bonded,
#: unstretched film's, verdict.advisory), so where it is met first the mechanical onset is
#: marched on its own (probe 8b D1: met at the start, it hid a crease before the wrinkle)
MECHANICAL = ("prismatic", "axial")
TRIGGERS = (*MECHANICAL, "field")


def onset_strain(ratio: float = CREASE_RATIO) -> float:
    """The plane-strain compression strain 1 - lambda at which lambda_2 / lambda_1 =
    ``ratio`` (lambda_1 lambda_2 = 1): 1 - ratio^(-1/2).

    >>> round(onset_strain(), 4), round(onset_strain(BIOT_RATIO), 4)
    (0.3545, 0.4563)
    """
    return 1.0 - ratio**-0.5


@dataclasses.dataclass(frozen=True)
class FaceCrease:
    """How close one face is to creasing: the ratios lambda_r / lambda_theta
    (prismatic crease, fold lines along z) and lambda_r / lambda_z (axial crease, rings),
    and the field E sqrt(eps_k / mu_k) of the face's layer (its small-strain moduli,
    Layer.initial_moduli). At an interface ("interface-K") the stretches are the stiffer
    layer's, the field 0 (no electrode) and ``neighbour`` the soft neighbour's modulus as a
    fraction of that layer's (0: a free face)."""

    face: str
    hoop: float
    axial: float
    field: float
    neighbour: float = 0.0

    @property
    def drives(self) -> dict[str, float]:
        """Each trigger as the fraction of its onset reached (1 at the onset)."""
        return {
            "prismatic": self.hoop / CREASE_RATIO,
            "axial": self.axial / CREASE_RATIO,
            "field": abs(self.field) / CREASE_FIELD,
        }

    @property
    def trigger(self) -> str:
        """The trigger nearest its onset: "prismatic", "axial" or "field"."""
        return self.trigger_of(TRIGGERS)

    @property
    def margin(self) -> float:
        """max(drives) - 1: negative while the face is smooth, 0 at the crease onset."""
        return self.margin_of(TRIGGERS)

    def trigger_of(self, triggers: tuple[str, ...]) -> str:
        """The trigger nearest its onset among ``triggers``."""
        d = self.drives
        return max(triggers, key=d.__getitem__)

    def margin_of(self, triggers: tuple[str, ...]) -> float:
        """The margin of ``triggers`` alone (MECHANICAL: the field criterion left out)."""
        d = self.drives
        return max(d[t] for t in triggers) - 1.0


def face_creases(state) -> tuple[FaceCrease, ...]:
    """The inner and outer face of a base state (any tube: the State protocol), then every
    interface bonded to a much softer layer (crease_interface.interfaces)."""
    tube = state.tube
    out = []
    for face, R, layer in (
        ("inner", 1.0, tube.layers[0]),
        ("outer", tube.outer_radius, tube.layers[-1]),
    ):
        side = "outer" if face == "inner" else "inner"  # the wall's own layer at the face
        l1, l2, l3 = (float(v) for v in state.elastic_stretches(R, side=side))
        e = float(state.electric_field(R, side=side))
        mu, eps = layer.initial_moduli  # the energy's own moduli too (a text may carry them)
        scale = math.sqrt(eps / mu)
        out.append(FaceCrease(face, l1 / l2, l1 / l3, e * scale))
    for i in interfaces(tube):
        l1, l2, l3 = (float(v) for v in state.elastic_stretches(i.radius, side=i.side))
        out.append(FaceCrease(i.name, l1 / l2, l1 / l3, 0.0, i.neighbour))
    return tuple(out)


def neighbour_delay(neighbour: float) -> float:
    """How much a bonded neighbour ``neighbour`` times as stiff delays the linear analogue
    of the crease, Biot's interfacial wrinkle: its ratio over BIOT_RATIO, minus 1 (0 for a
    free face, neighbour = 0; crease_interface.interfacial_biot_ratio)."""
    return 0.0 if neighbour <= 0.0 else interfacial_biot_ratio(neighbour) / BIOT_RATIO - 1.0


def crease_margin(state, triggers: tuple[str, ...] = TRIGGERS) -> FaceCrease:
    """The face nearest its crease onset (largest margin of ``triggers``)."""
    return max(face_creases(state), key=lambda f: f.margin_of(triggers))


@functools.lru_cache(maxsize=64)
def ratio_is_exact(material) -> bool:
    """Is the neo-Hookean crease ratio exact for ``material``? For an ideal dielectric
    (of any permittivity) whose elastic energy is linear in I1 and I2 (neo-Hookean,
    Mooney-Rivlin, of any modulus): in the plane of a crease it is a neo-Hookean energy
    (docs/derivation-crease.md section 2)."""
    if isinstance(material.definition, BuiltinEnergy):  # known without sympy
        return material.definition.linear
    import sympy as sp

    from ..model.invariants import I1, I2, I4, I5, I6

    # W(I1, I2) + c I5 for any constant c: an ideal dielectric of any permittivity (a text
    # with its own, check_units=False, "(I1 - 3)/2 + 3*I5/2", is one too)
    energy = sp.expand(material.energy)
    elastic = energy.subs({I4: 0, I5: 0, I6: 0})
    electric = sp.expand(energy - elastic)
    if electric.free_symbols != {I5} or not electric.is_polynomial(I5):
        return False
    if sp.Poly(electric, I5).degree() != 1:
        return False
    if not elastic.free_symbols <= {I1, I2} or not elastic.is_polynomial(I1, I2):
        return False
    return sp.Poly(elastic, I1, I2).total_degree() <= 1


@functools.lru_cache(maxsize=64)
def biot_ratio(material) -> float:
    """Biot's wrinkling ratio lambda_r / lambda_z of ``material``: the short-wave limit of
    an ungrown, uncharged tube compressed axially, waves along z (surface.py's half-space
    solver); BIOT_RATIO for every energy linear in I1 and I2. inf where the faces never
    wrinkle before the state is lost (a solid that stiffens steeply), NaN if it fails.
    It measures how far the energy is from neo-Hookean near the crease onset."""
    tube = Tube.uniform(2.0, length=1.0, material=material)
    try:
        limit = ray_limit(tube, 0, 1, "stretch", side="compression")
    except ElectrogrowthError:
        return math.nan
    return limit.value**-1.5 if limit.kind == Kind.SURFACE else math.inf


def criterion_text(tube: Tube) -> str:
    """Which criterion is applied to the tube's face layers, in words; for an energy it is
    not exact for, how far that energy's own Biot ratio is from neo-Hookean's."""
    faces = (tube.layers[0].material, tube.layers[-1].material)
    faces += tuple(tube.layers[i.layer - 1].material for i in interfaces(tube))
    base = f"neo-Hookean crease ratio {CREASE_RATIO:g}, electro-crease field {CREASE_FIELD:g}"
    bonded = [i.label for i in interfaces(tube)]
    if bonded:
        base += (
            f"; {'; '.join(bonded)}: the free face's ratio, its neighbour at most"
            f" {SOFT_NEIGHBOUR:g} times as stiff (an early bound)"
        )
    other = sorted({m for m in faces if not ratio_is_exact(m)}, key=lambda m: m.name)
    if not other:
        return base
    notes = []
    for m in other:
        b = biot_ratio(m)
        how = (
            f"its Biot ratio {b:.4g} against {BIOT_RATIO:.4g}, {100 * (b / BIOT_RATIO - 1):+.1f} %"
            if math.isfinite(b)
            else "it has no Biot wrinkling in compression"
            if b == math.inf
            else "its Biot ratio not computed"
        )
        notes.append(f"{m.name} ({how})")
    return f"{base}, applied to {'; '.join(notes)}: not that energy's own onset"


@dataclasses.dataclass(frozen=True)
class CreaseOnset(Outcome):
    """Result of :func:`crease_onset`.

    ``kind`` is CREASE (``value``: the control where ``face`` reaches the onset through
    ``trigger``: "prismatic", "axial" or "field") or NONE (no crease before the end of the
    path or before the axisymmetric state is lost at ``threshold``). ``error_estimate`` is
    the change of the value over the criterion's accuracy (CREASE_RATIO_ACCURACY,
    CREASE_FIELD_ACCURACY; at an interface plus the neighbour's delay), linearised;
    ``criterion`` says which criterion was applied, ``label`` the face in words ("inner
    face", "interface 1|2 (R = 1.5), layer 1 folds"). ``threshold`` is where the march lost
    the axisymmetric state (NaN if it did not). Where the onset is by the field criterion
    (an early bound, verdict.advisory), ``mechanical`` is the first onset by the mechanical
    criteria alone along the same control (a CreaseOnset, of kind CREASE or NONE); else
    None (the onset is itself mechanical, or none is reached)."""

    solve_for: str
    value: float
    kind: str
    face: str | None
    trigger: str | None
    error_estimate: float
    side: str | None
    params: Tube
    criterion: str
    threshold: float = math.nan
    label: str | None = None
    status: Status = Status.OK
    message: str = ""
    remedy: str = ""
    mechanical: CreaseOnset | None = None

    @property
    def ranked(self) -> CreaseOnset:
        """The onset that ranks against a wrinkle: the mechanical one where this one is by
        the field criterion, else this one."""
        return self if self.mechanical is None else self.mechanical

    def as_dict(self) -> dict:
        out = {
            "kind": str(self.kind),
            "value": json_number(self.value),
            "face": self.face,
            "label": self.label,
            "trigger": self.trigger,
            "error_estimate": json_number(self.error_estimate),
            "criterion": self.criterion,
        }
        if self.mechanical is not None:
            out["mechanical"] = self.mechanical.as_dict()
        return out


def crease_onset(
    params: Tube | Problem,
    solve_for: str | None = None,
    *,
    side: str | None = None,
    rtol: float | None = None,
    until: float | None = None,
) -> CreaseOnset:
    """The control value at which a face of the tube first reaches the crease onset.

    The control ``solve_for`` (any of model/controls.py KINDS) is marched from its stable
    start along the base-state path, as for a critical value; the crease margin of the
    inner and outer face (:func:`crease_margin`) is followed and its first root found by
    Brent's method. A layered tube's interfaces bonded to a much softer layer count as
    faces too (crease_interface.py). Where the first onset is by the field criterion, the
    mechanical criteria are marched again on their own (``mechanical``): the field's is an
    early bound, and the mechanical crease it precedes is the one that ranks.

    Parameters
    ----------
    params : Tube or Problem
        As for :func:`~.critical.critical_value`.
    solve_for, side, rtol
        The control, its side and the base state's accuracy (Problem's defaults).
    until : float, optional
        March no further than this control value: past it the onset is not looked for
        (Kind.NONE, "none before until"), for a caller that needs a crease only before a
        rival (a design's margin).

    Returns
    -------
    CreaseOnset

    Raises
    ------
    ConvergenceError
        Where the march meets a base state that exists but is not resolved before any
        crease: neither a crease nor a loss of the state is established past it.

    >>> c = crease_onset(Tube.uniform(2.0, length=1.0), "stretch", side="compression")
    >>> str(c.kind), c.trigger, abs(c.value - CREASE_RATIO ** (-2 / 3)) < 1e-12
    ('crease', 'axial', True)
    """
    if until is not None and not math.isfinite(until):
        raise ParameterError(f"until = {until} must be a finite value of the control (or None)")
    problem = as_problem(params, solve_for, side=side, rtol=rtol)
    onset = _march(problem, TRIGGERS, until)
    if onset.kind == Kind.CREASE and onset.trigger == "field":
        return dataclasses.replace(onset, mechanical=_march(problem, MECHANICAL, until))
    return onset


def _march(problem: Problem, triggers: tuple[str, ...], until: float | None = None) -> CreaseOnset:
    """The first root of the crease margin of ``triggers`` along the problem's control,
    up to its end or ``until`` if that comes first (:func:`crease_onset`)."""
    tube, control, side, rtol = problem.tube, problem.control, problem.side, problem.rtol
    at = TubeAt(tube, control)
    start, end, scale = control_path(tube, control, side)
    path_end = end
    if until is not None and (end - until) * (end - start) > 0:  # until comes first
        end = until if (until - start) * (end - start) > 0 else start  # (no march: NONE)
    criterion = criterion_text(tube)

    def state(x):  # continued from the march's last state, not walked from the unloaded tube
        return at.solved(x, rtol)

    def margin(x) -> float:
        return crease_margin(state(x), triggers).margin_of(triggers)

    def result(value, kind, face=None, trigger=None, error=math.nan, threshold=math.nan):
        params_at = tube.at(control, value) if math.isfinite(value) else tube
        where = None if face is None else label(tube, face)
        return CreaseOnset(
            control,
            value,
            kind,
            face,
            trigger,
            error,
            side,
            params_at,
            criterion,
            threshold,
            where,
        )

    x, h = start, margin(start)
    if h >= 0:  # already past the onset where the march starts
        f = crease_margin(state(start), triggers)
        return result(start, Kind.CREASE, f.face, f.trigger_of(triggers), 0.0)
    sense = 1.0 if end > start else -1.0
    step = STEP * scale
    before = None  # the sample before (x, h), for the receding step's parabola
    while sense * (end - x) > 0:
        x_new = x + sense * step if sense * (end - x - sense * step) > 0 else end
        try:
            h_new = margin(x_new)
        except BranchNotFollowed as err:  # it may exist: no loss, as an unresolved state
            raise _unresolved(control, start, x, x_new, err) from err
        except BaseStateError:  # no state at x_new: where the states end is bisected
            lost = threshold_between(x, x_new, exists=_not_lost(state))
            return result(math.nan, Kind.NONE, threshold=math.nan if lost is None else lost)
        except ConvergenceError as err:  # a state that is not resolved is not a lost one
            raise _unresolved(control, start, x, x_new, err) from err
        if h_new >= 0:
            value = brent(margin, x, x_new, FULL)
            f = _creasing_face(tube, state(value), triggers)
            trigger = f.trigger_of(triggers)
            shift = energy_shift(tube, f.face)
            error = _criterion_error(margin, value, x, f, trigger, shift)
            onset = result(value, Kind.CREASE, f.face, trigger, error)
            if math.isinf(shift):  # the criteria say nothing for this energy
                return dataclasses.replace(onset, status=Status.INACCURATE, message=NO_BIOT)
            return onset
        slope = sense * (h_new - h) / abs(x_new - x)  # the margin's rise per unit of march
        ahead = -h_new / slope if slope > 0 else math.inf
        step = min(max(0.5 * ahead, STEP_MIN * scale), STEP_MAX * scale)
        if slope <= 0 and before is not None:  # receding: may grow past a few scales
            step = _receding_step((before, (x, h), (x_new, h_new)), sense, step, start)
        before, (x, h) = (x, h), (x_new, h_new)
    none = result(math.nan, Kind.NONE)
    return (
        none if end == path_end else dataclasses.replace(none, message=f"none before {end:.12g}")
    )


def _receding_step(samples, sense: float, base: float, start: float) -> float:
    """The step after a sample where the margin recedes from the onset: STEP_MAX of the
    distance marched (not of the scale) where the margin's own last three ``samples``
    (x, h) say it may, else ``base``, the scale's step. A path with no threshold runs to
    1e3 scales (model/controls.py), 1e4 steps of STEP_MAX of the scale, each a base state:
    a charged bilayer's mechanical margin, receding all the way, took 120 s (check round
    31, Doubt 3). The evidence is the parabola through the samples: over the step it
    closes at most half the gap to the onset, else the step is halved, down to ``base``."""
    x2, h2 = samples[-1]
    step = STEP_MAX * abs(x2 - start)
    while step > base:
        if _parabola_rise(samples, sense, step) <= -0.5 * h2:
            return step
        step *= 0.5
    return base


def _parabola_rise(samples, sense: float, step: float) -> float:
    """The largest rise, over ``step`` ahead of the last sample, of the parabola through
    the three ``samples`` (x, h), t = sense (x - x_last) measured in the march's sense."""
    (x0, h0), (x1, h1), (x2, h2) = samples
    t0, t1 = sense * (x0 - x2), sense * (x1 - x2)
    a = (h2 - h1) / -t1  # q(t) = h2 + a t + c t (t - t1) passes through all three
    c = (a - (h1 - h0) / (t1 - t0)) / -t0

    def rise(t):
        return a * t + c * t * (t - t1)

    tops = [step]
    if c < 0:  # a maximum: its vertex, where it lies within the step
        vertex = 0.5 * (t1 - a / c)
        if 0 < vertex < step:
            tops.append(vertex)
    return max(rise(t) for t in tops)


def _creasing_face(tube: Tube, state, triggers: tuple[str, ...] = TRIGGERS) -> FaceCrease:
    """The face that creases at the onset: the nearest its onset (:func:`crease_margin`),
    and of faces tied with it to rounding, the one whose criteria are the most exact
    (:func:`energy_shift`): an axially compressed tube of a Gent core and a neo-Hookean
    sheath reaches the ratio on both faces at once, where the Gent face "may not crease"
    and the neo-Hookean one creases (probe round 7a)."""
    faces = face_creases(state)
    top = max(f.margin_of(triggers) for f in faces)
    tied = [f for f in faces if f.margin_of(triggers) >= top - TIE]
    return min(tied, key=lambda f: energy_shift(tube, f.face))


#: margins this close to the largest are a tie (the margins are drives less 1)
TIE = 1e-12


def _not_lost(state):
    """Does a state exist at x? Only a failed state search (BaseStateError) says no: a state
    that does not resolve (ConvergenceError) exists, and cold solves of an exponential
    energy's states once failed and solved alternately, which a bisection for the loss
    settled between as a false edge (probe round 11a)."""

    def exists(x) -> bool:
        try:
            state(x)
        except BranchNotFollowed:  # it may exist, on a branch not followed
            pass
        except BaseStateError:
            return False
        except ConvergenceError:  # there, not resolved
            pass
        return True

    return exists


def _unresolved(control: str, start: float, x: float, x_bad: float, err: ElectrogrowthError):
    """The crease march ended at a state that exists but is not resolved: no crease up to
    x, and whether one (or the loss of the state) follows is not established (``err``: not
    resolved, or on a branch the package does not follow)."""
    out = ConvergenceError(
        f"no crease for {control} from {start:.12g} up to {x:.12g}, and the base state at"
        f" {x_bad:.12g} is not resolved: {err.args[0]}"
    )
    out.remedy = err.remedy
    return out


def _criterion_error(
    margin, value: float, x_before: float, face: FaceCrease, trigger: str, shift: float = 0.0
) -> float:
    """How far the onset moves over the criterion's accuracy: d(drive) = accuracy / onset
    (at an interface plus the neighbour's delay, :func:`neighbour_delay`; for an energy the
    criterion is not exact for, plus its ``shift``, :func:`energy_shift`), divided by the
    slope of the margin at the root (a secant over 1e-4 of the last step, on the side the
    march came from, where the state exists)."""
    near = value + 1e-4 * (x_before - value)
    slope = (margin(value) - margin(near)) / (value - near)
    rel = shift + (
        CREASE_FIELD_ACCURACY / CREASE_FIELD
        if trigger == "field"
        else CREASE_RATIO_ACCURACY / CREASE_RATIO + neighbour_delay(face.neighbour)
    )
    return abs(rel / slope) if slope != 0 and math.isfinite(rel) else math.inf


def energy_shift(tube: Tube, face: str) -> float:
    """The relative error to expect from the neo-Hookean criteria on the energy of the layer
    that creases at ``face``: 0 where they are exact (:func:`ratio_is_exact`), else how far
    its own Biot ratio is from neo-Hookean's (docs/derivation-crease.md section 2: +5.7 %
    for Gent J_m = 20); inf where it has none, a solid stiffening so steeply that it never
    wrinkles at its surface and may never crease (Jin & Suo 2015): there the criteria say
    nothing."""
    if face == "inner":
        material = tube.layers[0].material
    elif face == "outer":
        material = tube.layers[-1].material
    else:
        (bonded,) = (i for i in interfaces(tube) if i.name == face)
        material = tube.layers[bonded.layer - 1].material
    if ratio_is_exact(material):
        return 0.0
    b = biot_ratio(material)
    return abs(b / BIOT_RATIO - 1.0) if math.isfinite(b) else math.inf
