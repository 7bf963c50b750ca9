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
from ..errors import NoBifurcationFound, ParameterError
from ..interrupts import Interrupted
from ..model.layers import Tube
from .branch import AmplitudeBranch, BranchPoint, amplitude_vector
from .meridian import Meridian, meridian_size, window
from .newton import newton
from .onset import fe_onset, lowest_eigenvalue, start_value
from .section import MeshSize, Section, mesh_size

#: the amplitudes of the branch's curvature estimate, units R_i (Richardson on a and 2a)
CURVATURE_AMPLITUDE = 1e-3


@dataclasses.dataclass(frozen=True)
class PostbuckleResult:
    """The post-buckled branch of mode (m, 0) (cross-section) or (0, n) (meridian).

    ``onset_linear`` the package's critical value, ``onset_fe`` the sign change of the FE
    tangent's lowest eigenvalue on the unperturbed path; ``control``, ``amplitude``,
    ``energy`` the branch (amplitude a: the cos(m Theta) radial displacement of ``face``,
    the face where the critical mode is larger, units R_i; for the meridian the cos(k z)
    radial displacement; energy: the whole tube's per unit reference length (the ring's;
    the meridian's averaged over a wavelength), units mu R_i^2), ``curvature``
    d(control) / d(a^2) at onset on the perfect branch; ``imperfection`` the load
    imperfection's size (0: the perfect bifurcated branch); ``eigenvalue`` the lowest
    eigenvalue of the tangent at fixed control at each point (< 0: unstable; NaN at the
    onset itself); ``ended`` why the branch stopped short of the amplitude asked ("" if it
    did not); ``states`` the unknowns of each point, ``section`` the FE model (for shapes
    and VTK)."""

    tube: Tube
    solve_for: str
    m: int
    onset_linear: float
    onset_fe: float
    mesh: MeshSize
    unknowns: int
    control: np.ndarray
    amplitude: np.ndarray
    energy: np.ndarray
    curvature: float
    imperfection: float
    eigenvalue: np.ndarray
    states: tuple = dataclasses.field(repr=False, compare=False)
    section: object = dataclasses.field(repr=False, compare=False)
    ended: str = ""
    face: str = "inner"
    n: int = 0

    @property
    def mode(self) -> tuple[int, int]:
        return (self.m, self.n)

    def _mesh_record(self) -> dict:
        along = (
            {"hoop_elements": self.mesh.hoop, "sector": f"pi/{self.m}"}
            if self.n == 0
            else {"axial_elements": self.mesh.hoop, "window": f"L/{self.n}"}
        )
        return {
            "radial_elements": list(self.mesh.radial),
            **along,
            "elements": self.mesh.elements,
            "unknowns": self.unknowns,
        }

    def as_dict(self) -> dict:
        """The JSON record."""
        return {
            "solve_for": self.solve_for,
            "m": self.m,
            "n": self.n,
            "onset_linear": self.onset_linear,
            "onset_fe": self.onset_fe,
            "onset_relative_difference": (self.onset_fe - self.onset_linear)
            / abs(self.onset_linear),
            "curvature": self.curvature,
            "amplitude_face": self.face,
            "imperfection": self.imperfection,
            "mesh": self._mesh_record(),
            "branch": {
                "control": self.control.tolist(),
                "amplitude": self.amplitude.tolist(),
                "energy": self.energy.tolist(),
                "lowest_eigenvalue": [None if np.isnan(v) else v for v in self.eigenvalue],
            },
            "ended": self.ended or None,
            "tube": self.tube.record(),
        }

    def to_xarray(self):
        """The branch as an ``xarray.Dataset`` on dimension ``point``."""
        import xarray as xr

        return xr.Dataset(
            {
                "control": ("point", self.control, {"long_name": self.solve_for}),
                "energy": ("point", self.energy, {"units": "mu R_i^2"}),
                "lowest_eigenvalue": ("point", self.eigenvalue, {"units": "mu / R_i^2"}),
            },
            coords={"amplitude": ("point", self.amplitude, {"units": "R_i"})},
            attrs={
                "m": self.m,
                "n": self.n,
                "onset_linear": self.onset_linear,
                "onset_fe": self.onset_fe,
                "curvature": self.curvature,
            },
        )


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

    Parameters
    ----------
    density : float
        Elements per unit reference length across the wall (at least 2 per layer).
    hoop : int, optional
        Prismatic modes: elements along the sector pi / m (default from ``density``, at
        least 4).
    axial : int, optional
        Axisymmetric modes: elements along the window L / n, half an axial wavelength
        (default from ``density``, at least 4).

    Returns
    -------
    PostbuckleResult

    Raises
    ------
    ParameterError, NoBifurcationFound, ConvergenceError, Interrupted (with the finished
    points in ``partial``)
    """
    m, n = _mode(mode)
    if not (math.isfinite(amplitude) and amplitude > 0):
        raise ParameterError(f"amplitude = {amplitude!r} is out of range; valid range: > 0")
    if not (isinstance(points, int) and 1 <= points <= 1000):
        raise ParameterError(f"points = {points!r} is out of range; valid range: 1 to 1000")
    if not (math.isfinite(imperfection) and imperfection >= 0):
        raise ParameterError(f"imperfection = {imperfection!r} is out of range; valid: >= 0")
    if not (math.isfinite(density) and 0 < density <= 2000):
        raise ParameterError(f"density = {density!r} is out of range; valid range: 0 to 2000")
    for name, value in (("hoop", hoop), ("axial", axial)):
        if value is not None and not (isinstance(value, int) and 1 <= value <= 1000):
            raise ParameterError(f"{name} = {value!r} is out of range; valid range: 1 to 1000")
    say = progress or (lambda text: None)
    control = str(tube.check_control(solve_for))
    start_value(tube, control)  # a control the model follows
    # refuses what the model does not cover, before solving
    section, size = _model(tube, m, n, density, hoop, axial)
    say(f"linear onset of mode ({m}, {n}) and of its multiples")
    linear = critical_value(tube, m, n, control).value
    _check_first_in_window(tube, m, n, control, linear)
    say(f"finite-element onset on {size.elements} elements ({section.free.size} unknowns)")
    onset = fe_onset(section, tube, control, linear)
    say("initial curvature of the branch")
    start, near, curvature, face, direction = initial_curvature(section, tube, control, onset)
    a = amplitude_vector(section, face)
    amps = amplitude * np.arange(1, points + 1) / points
    record = functools.partial(
        _record, tube, control, (m, n), linear, onset.value, size, section, curvature
    )
    record = functools.partial(_with_face, record, face, imperfection)
    if imperfection > 0:
        force = np.zeros(section.basis.N)
        force[section.free] = imperfection * (section.M @ direction)[section.free]
        branch = AmplitudeBranch(section, tube, control, force, eigenvalues=True, face=face)
        # the imperfect path from 90 % of the way to onset, in the amplitude
        c0 = onset.value - 0.1 * (onset.value - start_value(tube, control))
        section.set_tube(tube.at(control, c0))
        x0, _ = newton(section, onset.x)
        x0 = _with_imperfection(section, x0, force)
        first = BranchPoint(c0, float(a @ x0), section.energy(x0), x0)
        first.eigenvalue = lowest_eigenvalue(section, x0)
        head, follow_from = [first], first
        amps = amps[amps > first.amplitude]
    else:
        branch = AmplitudeBranch(section, tube, control, eigenvalues=True, face=face)
        head, follow_from = [start], near[-1]
        amps = amps[amps > near[-1].amplitude]
    try:
        pts = head + branch.follow(
            follow_from,
            amps,
            direction=direction,
            progress=_reporter(say, control),
            keep_going=True,
        )
    except Interrupted as stop:  # the finished points, as a result
        raise Interrupted(stop.signum, str(stop), partial=record(head + stop.partial)) from None
    return dataclasses.replace(record(pts), ended=branch.ended)


def initial_curvature(section, tube: Tube, control: str, onset):
    """d(control) / d(a^2) at ``onset`` (an :class:`~.onset.FEOnset` of ``section``) on the
    perfect branch, Richardson-extrapolated from the amplitudes a = CURVATURE_AMPLITUDE and
    twice that: (c(a) - c_c) / a^2 = c_2 + O(a^2). The amplitude is read on the face where
    the critical mode is larger. Returns (the onset point, the two points, c_2, the face,
    the mode scaled to unit amplitude)."""
    faces = {f: amplitude_vector(section, f) for f in ("inner", "outer")}
    face = max(faces, key=lambda f: abs(faces[f] @ onset.mode))
    direction = onset.mode / (faces[face] @ onset.mode)
    perfect = AmplitudeBranch(section, tube, control, face=face)
    start = BranchPoint(onset.value, 0.0, section.energy(onset.x), onset.x)
    start.eigenvalue = lowest_eigenvalue(section, onset.x)  # zero to the onset's tolerance
    near = perfect.follow(
        start, [CURVATURE_AMPLITUDE, 2 * CURVATURE_AMPLITUDE], direction=direction
    )
    q = [(p.control - onset.value) / p.amplitude**2 for p in near]
    return start, near, (4 * q[0] - q[1]) / 3, face, direction


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


def _model(tube, m, n, density, hoop, axial):
    """The finite-element model of mode (m, n) and its mesh size."""
    if n == 0:
        if axial is not None:
            raise ParameterError("axial counts elements along the meridian: give hoop for (m, 0)")
        size = mesh_size(tube, m, density, hoop=hoop)
        return Section(tube, m, size), size
    if hoop is not None:
        raise ParameterError("hoop counts elements along the sector: give axial for (0, n)")
    size = meridian_size(tube, n, density, axial=axial)
    return Meridian(tube, n, size), size


#: the multiples j m, or j n (j = 2 .. MULTIPLES), checked to come after the mode
MULTIPLES = 3


def _check_first_in_window(tube, m, n, control, linear):
    """ParameterError if a mode (j m, j n), which the sector pi / m (the window L / n) holds
    too, comes before (m, n) on the path from the start value: the FE onset and branch
    would be of that mode."""
    start = start_value(tube, control)
    where = f"the sector pi/{m}" if n == 0 else f"the window L/{n}"
    for j in range(2, MULTIPLES + 1):
        try:
            other = critical_value(tube, j * m, j * n, control).value
        except NoBifurcationFound:
            continue
        if abs(other - start) < abs(linear - start):
            ask = j * m if n == 0 else f"0 {j * n}"
            raise ParameterError(
                f"mode ({j * m}, {j * n}) comes before ({m}, {n}) ({control} = {other:.8g}"
                f" against {linear:.8g}); {where} holds both and would follow it: ask for"
                f" mode {ask}"
            )


def _with_face(record, face, imperfection, pts):
    return dataclasses.replace(record(pts), face=face, imperfection=float(imperfection))


def _record(tube, control, mode, linear, onset, size, section, curvature, pts):
    m, n = mode
    # the whole tube per unit reference length: the ring is 2 m sectors; the meridian's
    # energy is per radian of a window L / n
    full = 2 * m if n == 0 else 2 * math.pi / window(tube, n)
    return PostbuckleResult(
        tube=tube,
        solve_for=control,
        m=m,
        n=n,
        onset_linear=float(linear),
        onset_fe=onset,
        mesh=size,
        unknowns=int(section.free.size),
        control=np.array([p.control for p in pts]),
        amplitude=np.array([p.amplitude for p in pts]),
        energy=full * np.array([p.energy for p in pts]),
        eigenvalue=np.array([p.eigenvalue for p in pts]),
        curvature=float(curvature),
        imperfection=0.0,
        states=tuple(p.x for p in pts),
        section=section,
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
