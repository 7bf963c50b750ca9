"""``postbuckle``: from the package's linear onset to the finite-element post-buckled branch
of one prismatic mode (m, 0) (the cross-section, plane strain) or one axisymmetric mode
(0, n) (the meridian), and its result record."""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable

import numpy as np

from ..bifurcation.critical import critical_value
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..interrupts import Interrupted
from ..model.layers import Tube
from .branch import AmplitudeBranch, BranchPoint, amplitude_vector, with_stability
from .harmonics import face_harmonic
from .meridian import Meridian, meridian_size, window
from .newton import fe_error, newton
from .onset import fe_onset, start_value
from .result import PostbuckleResult
from .section import Section, mesh_size
from .stability import secondaries
from .wall import check_periods


def postbuckle(
    tube: Tube,
    mode: int | tuple[int, int],
    solve_for: str,
    *,
    amplitude: float = 0.05,
    points: int = 10,
    density: float = 20.0,
    hoop: int | None = None,
    axial: int | None = None,
    imperfection: float = 0.0,
    periods: int = 1,
    side: str | None = None,
    progress: Callable[[str], None] | None = None,
) -> PostbuckleResult:
    """The post-buckled branch of ``mode`` of ``tube`` along ``solve_for``: a prismatic mode
    (m, 0) (given as m or (m, 0), m >= 2) on the cross-section, or an axisymmetric mode
    (0, n) (n >= 1) on the meridian.

    The package's onset (``critical_value(tube, m, n, solve_for)``) guides the march of the
    FE model's unperturbed path (:func:`~.onset.fe_onset`) to the sign change of its lowest
    eigenvalue; the branch is then followed in the fold amplitude a (the cos(m Theta), or
    cos(k z), radial displacement of the inner face, or the outer where the mode is larger)
    in ``points`` equal steps up to ``amplitude`` (units R_i), from the onset state plus a
    times the FE critical mode, with a load imperfection ``imperfection`` mu M z in the
    shape of that mode (0: the perfect branch).

    Each point's stability is the lowest eigenvalue of the tangent at fixed control and the
    pattern of its eigenvector; where the eigenvalue changes sign on the branch, Brent's
    method on the amplitude locates a ``secondary`` point. A model of one half wavelength
    holds the mode's own family alone; ``periods`` = k computes on k half wavelengths
    (the sector k pi / m, the window k L / n), which also holds the patterns of k
    wavelengths' period: k = 2 lets period doubling appear.

    Parameters
    ----------
    density : float
        Elements per unit reference length across the wall (at least 2 per layer).
    hoop : int, optional
        Prismatic modes: elements along each pi / m of the sector (default from
        ``density``, at least 4).
    axial : int, optional
        Axisymmetric modes: elements along each L / n of the window, half an axial
        wavelength (default from ``density``, at least 4).
    periods : int
        Half wavelengths of the mode in the sector or window, a divisor of m (of n).
    side : {"compression", "extension"}, optional
        The pressure control's direction (:func:`~electrogrowth.bifurcation.critical
        .critical_value`): the default inflates, ``"compression"`` lowers the inner
        pressure below the outer (collapse under an external pressure).

    Returns
    -------
    PostbuckleResult

    Raises
    ------
    ParameterError, NoBifurcationFound, ConvergenceError, Interrupted (with the finished
    points in ``partial``)
    """
    m, n = _mode(mode)
    _check_amplitude(amplitude, tube)
    if not (isinstance(points, int) and 1 <= points <= 1000):
        raise ParameterError(f"points = {points!r} is out of range; valid range: 1 to 1000")
    if not (math.isfinite(imperfection) and imperfection >= 0):
        raise ParameterError(f"imperfection = {imperfection!r} is out of range; valid: >= 0")
    if not (math.isfinite(density) and 0 < density <= 2000):
        raise ParameterError(
            f"density = {density!r} is out of range; valid range: > 0 and <= 2000"
        )
    for name, value in (("hoop", hoop), ("axial", axial)):
        if value is not None and not (isinstance(value, int) and 1 <= value <= 1000):
            raise ParameterError(f"{name} = {value!r} is out of range; valid range: 1 to 1000")
    say = progress or (lambda text: None)
    control = str(tube.check_control(solve_for))
    start_value(tube, control)  # a control the model follows
    # refuses what the model does not cover, before solving
    section, size = _model(tube, m, n, density, hoop, axial, periods)
    say(f"linear onset of mode ({m}, {n}) and of the modes its {_where(m, n, periods)} holds")
    linear = critical_value(tube, m, n, control, side=side).value
    _check_first_in_window(tube, m, n, control, linear, periods, side)
    say(f"finite-element onset on {size.elements} elements ({section.unknowns} unknowns)")
    onset = fe_onset(section, tube, control, linear)
    _check_onset_pattern(section, onset, linear, (m, n), control)
    say("initial curvature of the branch")
    start, near, curvature, face, direction = initial_curvature(section, tube, control, onset)
    a = amplitude_vector(section, face)
    amps = amplitude * np.arange(1, points + 1) / points
    record = functools.partial(
        _record, tube, control, (m, n), linear, onset.value, size, section, curvature
    )
    record = functools.partial(_with_face, record, face, imperfection)
    if imperfection > 0:
        # on the displacements alone (M), zero where they are prescribed
        force = section.with_fixed(imperfection * (section.M @ direction))
        branch = AmplitudeBranch(section, tube, control, force, eigenvalues=True, face=face)
        # the imperfect path from 90 % of the way to onset, in the amplitude
        c0 = onset.value - 0.1 * (onset.value - start_value(tube, control))
        section.set_tube(tube.at(control, c0))
        x0, _ = newton(section, onset.x, invariant=True)
        x0 = _with_imperfection(section, x0, force)
        first = with_stability(section, BranchPoint(c0, float(a @ x0), section.energy(x0), x0))
        head, legs = [first], [(first, amps[amps > first.amplitude])]
        skipped = amps[amps <= first.amplitude]
    else:
        branch = AmplitudeBranch(section, tube, control, eigenvalues=True, face=face)
        # the amplitudes up to the curvature's points from the onset itself, the rest from
        # the last of those (probe 12a D2: they were dropped without a word)
        last = near[-1].amplitude
        head, legs = [start], [(start, amps[amps <= last]), (near[-1], amps[amps > last])]
        skipped = amps[:0]
    try:
        pts = head + _follow(branch, legs, direction, _reporter(say, control))
    except Interrupted as stop:  # the finished points, as a result
        raise Interrupted(stop.signum, str(stop), partial=record(head + stop.partial)) from None
    # the onset itself (eigenvalue zero to its tolerance, either sign) is no sign change
    say("the lowest eigenvalue's sign changes on the branch")
    found = secondaries(branch, pts if imperfection > 0 else pts[1:])
    # a zero located in a pattern of the elements' size is the mesh's, not a secondary
    unresolved = [p.amplitude for p in pts if p.unresolved]
    unresolved += [s.amplitude for s in found if s.element_scale]
    return dataclasses.replace(
        record(pts),
        ended=branch.ended or _skipped_note(skipped, head[0].amplitude),
        secondary=tuple(s for s in found if not s.element_scale),
        unresolved_from=min(unresolved, default=math.nan),
    )


def _check_amplitude(amplitude, tube: Tube) -> None:
    """ParameterError unless 0 < ``amplitude`` < the outer radius R_N (units R_i): a fold
    as deep as the tube's radius would bring a face to the axis (probe 12a: 1e9 ran, and
    the branch ended without a word on why)."""
    outer = tube.radii[-1]
    if not (math.isfinite(amplitude) and 0 < amplitude < outer):
        raise ParameterError(
            f"amplitude = {amplitude!r} is out of range; valid range: > 0 and < {outer:g}"
            " (the outer radius, units R_i: a fold as deep as the tube's radius would bring"
            " a face to the axis)"
        )


def _follow(branch, legs, direction, progress) -> list:
    """The points of each leg (a start point, its amplitudes) in turn; a leg that ends
    early (``branch.ended``) ends the branch. Interrupted carries every finished point."""
    done: list = []
    for first, amplitudes in legs:
        if len(amplitudes) == 0:
            continue
        try:
            done += branch.follow(
                first, amplitudes, direction=direction, progress=progress, keep_going=True
            )
        except Interrupted as stop:
            raise Interrupted(stop.signum, str(stop), partial=done + stop.partial) from None
        if branch.ended:
            break
    return done


def _skipped_note(skipped, first: float) -> str:
    """Why the imperfect path has no point at the amplitudes ``skipped`` ("" if none)."""
    if len(skipped) == 0:
        return ""
    shown = ", ".join(f"{a:.4g}" for a in skipped)
    return (
        f"no point at amplitude {shown}: the imperfect path starts at amplitude {first:.4g}"
        " (90 % of the way to onset), and amplitudes below it lie before its start"
    )


@dataclasses.dataclass(frozen=True)
class Curvature:
    """d(control) / d(a^2) at onset: ``value`` from the perfect branch's points at
    ``amplitude``, 2 and 4 times it; ``error`` its change from the scale ten times larger
    (NaN when only one scale was taken)."""

    value: float
    error: float
    amplitude: float


def initial_curvature(section, tube: Tube, control: str, onset):
    """d(control) / d(a^2) at ``onset`` (an :class:`~.onset.FEOnset` of ``section``) on the
    perfect branch, from its points at a, 2a and 4a alone: with
    c(a) = c_c + c_2 a^2 + c_4 a^4 + ..., the difference quotients
    D_1 = (c(2a) - c(a)) / (3 a^2) = c_2 + 5 c_4 a^2 and
    D_2 = (c(4a) - c(2a)) / (12 a^2) = c_2 + 20 c_4 a^2 give c_2 = (4 D_1 - D_2) / 3 + O(a^4).
    The onset value c_c, Brent's zero of a Lanczos eigenvalue (to ~1e-9), does not enter:
    (c(a) - c_c) / a^2 would multiply its error by 1 / a^2 = 1e6. The amplitude scale starts
    at CURVATURE_AMPLITUDE and is cut tenfold until two scales agree to CURVATURE_RTOL (at
    most CURVATURE_SCALES scales); the larger of the two is kept. Where other modes lie
    close to the critical one, a^2 terms are not yet dominant at a = 1e-3 (the charged
    bilayer of docs/postbuckling.md: -13100 there, -481.0 at 1e-4, -481.3 at 1e-5). The
    amplitude is read on the face where the critical mode is larger. Returns (the onset
    point, the points at a and 2a, the :class:`Curvature`, the face, the mode scaled to
    unit amplitude)."""
    faces = {f: amplitude_vector(section, f) for f in ("inner", "outer")}
    face = max(faces, key=lambda f: abs(faces[f] @ onset.mode))
    direction = onset.mode / (faces[face] @ onset.mode)
    perfect = AmplitudeBranch(section, tube, control, face=face)
    start = BranchPoint(onset.value, 0.0, section.energy(onset.x), onset.x)
    with_stability(section, start)  # eigenvalue zero to the onset's tolerance
    a, previous, error = CURVATURE_AMPLITUDE, math.nan, math.nan
    near: list[BranchPoint] = []
    for _ in range(CURVATURE_SCALES):
        pts = perfect.follow(start, [a, 2 * a, 4 * a], direction=direction)
        c = [p.control for p in pts]
        value = (4 * (c[1] - c[0]) / (3 * a**2) - (c[2] - c[1]) / (12 * a**2)) / 3
        error = abs(value - previous)
        if error <= CURVATURE_RTOL * abs(value):
            # the larger scale's: its a^4 term is bounded by the agreement, and its
            # differences of branch points carry a hundredth of the smaller one's rounding
            value, a = previous, a * 10
            pts = near
            break
        previous, near, a = value, pts, a / 10
    else:
        a *= 10  # the last scale taken
    return start, pts[:2], Curvature(value, error, a), face, direction


#: the curvature's amplitude scales: the first, the agreement asked of two scales a tenth
#: apart, and how many scales at most
CURVATURE_AMPLITUDE = 1e-3
CURVATURE_RTOL = 1e-2
CURVATURE_SCALES = 3


def _check_onset_pattern(section, onset, linear: float, mode, control: str) -> None:
    """ConvergenceError unless the mesh's first instability has the mode's own pattern on
    the faces (:func:`~.harmonics.face_harmonic`: ``periods`` half wavelengths along the
    sector or window). A mesh too coarse along a face can lose stability first in a pattern
    of its elements' size, which the linear analysis puts later: the grown bilayer of
    docs/postbuckling.md on 4 elements along pi / 24, in cos(96 Theta) at its outer face
    at Vbar = 1.0862, where the linear onset of (24, 0) is 1.1816 and of (96, 0) 1.1844."""
    i, share = face_harmonic(section, onset.mode)
    if share >= PATTERN_SHARE and i == section.periods:
        return
    if share == 0.0:
        what = "a mode of the elements' size that leaves the faces still"
    else:
        where = _where(mode[0], mode[1], section.periods)
        what = f"a pattern of {i} half wavelengths along the {where}"
    raise fe_error(
        ConvergenceError,
        f"on this mesh the tube loses stability first at {control} = {onset.value:.6g} in"
        f" {what}, not in the mode {mode} (its linear onset {linear:.6g}): the mesh is too"
        " coarse here",
    )


#: the share of the face's squared amplitude an onset's pattern carries (1 for the mode
#: of a Theta- or Z-invariant state on a uniform mesh, up to rounding)
PATTERN_SHARE = 0.5


def _mode(mode) -> tuple[int, int]:
    """(m, n) of ``mode`` (an int m, or a pair), ParameterError unless a model covers it."""
    pair = (mode, 0) if isinstance(mode, int) else tuple(mode)
    ok = len(pair) == 2 and all(isinstance(k, int) and not isinstance(k, bool) for k in pair)
    if ok and ((pair[0] >= 2 and pair[1] == 0) or (pair[0] == 0 and pair[1] >= 1)):
        return pair[0], pair[1]
    raise ParameterError(
        f"mode {mode!r} is out of range; valid: m >= 2 or (m, 0) (the cross-section), (0, n)"
        " with n >= 1 (the meridian)"
    )


def _model(tube, m, n, density, hoop, axial, periods):
    """The finite-element model of mode (m, n) on ``periods`` half wavelengths and its mesh
    size."""
    if n == 0:
        check_periods(periods, m, "m", largest=m // 2)
    else:
        check_periods(periods, n, "n")
    if n == 0:
        if axial is not None:
            raise ParameterError("axial counts elements along the meridian: give hoop for (m, 0)")
        size = mesh_size(tube, m, density, hoop=hoop, periods=periods)
        return Section(tube, m, size, periods=periods), size
    if hoop is not None:
        raise ParameterError("hoop counts elements along the sector: give axial for (0, n)")
    size = meridian_size(tube, n, density, axial=axial, periods=periods)
    return Meridian(tube, n, size, periods=periods), size


def _where(m, n, periods) -> str:
    k = "" if periods == 1 else str(periods)
    return f"sector {k}pi/{m}" if n == 0 else f"window {k}L/{n}"


#: the modes j m / k, or j n / k (j = 1 .. k MULTIPLES but k), checked to come after the mode
MULTIPLES = 3


def _check_first_in_window(tube, m, n, control, linear, periods=1, side=None):
    """ParameterError if a mode (j m / k, j n / k), which the sector k pi / m (the window
    k L / n) holds too, comes before (m, n) on the path from the start value: the FE onset
    and branch would be of that mode."""
    start = start_value(tube, control)
    where = f"the {_where(m, n, periods)}"
    for j in range(1, periods * MULTIPLES + 1):
        if j == periods:
            continue
        mj, nj = j * m // periods, j * n // periods
        try:
            other = critical_value(tube, mj, nj, control, side=side).value
        except NoBifurcationFound:
            continue
        if abs(other - start) < abs(linear - start):
            ask = mj if n == 0 else f"0 {nj}"
            raise ParameterError(
                f"mode ({mj}, {nj}) comes before ({m}, {n}) ({control} = {other:.8g}"
                f" against {linear:.8g}); {where} holds both and would follow it: ask for"
                f" mode {ask}"
            )


def _with_face(record, face, imperfection, pts):
    return dataclasses.replace(record(pts), face=face, imperfection=float(imperfection))


def _record(tube, control, mode, linear, onset, size, section, curvature, pts):
    m, n = mode
    k = section.periods
    # the whole tube per unit reference length: the ring is 2 m / k sectors; the
    # meridian's energy is per radian of a window k L / n
    full = 2 * m / k if n == 0 else 2 * math.pi / (k * window(tube, n))
    return PostbuckleResult(
        tube=tube,
        solve_for=control,
        m=m,
        n=n,
        onset_linear=float(linear),
        onset_fe=onset,
        mesh=size,
        unknowns=section.unknowns,
        control=np.array([p.control for p in pts]),
        amplitude=np.array([p.amplitude for p in pts]),
        energy=full * np.array([p.energy for p in pts]),
        # the tube's stability is unknown where the lowest mode is the mesh's artefact
        eigenvalue=np.array([math.nan if p.unresolved else p.eigenvalue for p in pts]),
        element_scale=np.array([p.element_scale for p in pts]),
        curvature=float(curvature.value),
        curvature_error=float(curvature.error),
        imperfection=0.0,
        states=tuple(p.x for p in pts),
        section=section,
        periods=k,
        subharmonic=np.array([p.subharmonic for p in pts]),
        pattern=np.array([p.pattern for p in pts], dtype=int),
    )


def _with_imperfection(section, x, force):
    """The equilibrium with the imperfection at the section's current control."""
    branch_residual = section.residual

    class _Imperfect:
        def __getattr__(self, name):
            return getattr(section, name)

        def residual(self, y):
            return branch_residual(y) - force

    x, _ = newton(_Imperfect(), x)
    return x


def _reporter(say, control):
    def report(point):
        say(f"amplitude {point.amplitude:.4g}: {control} = {point.control:.8g}")

    return report
