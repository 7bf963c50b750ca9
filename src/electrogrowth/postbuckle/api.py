"""``postbuckle``: from the package's linear onset to the finite-element post-buckled branch
of one prismatic mode m (plane strain), and its result record."""

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
from .newton import newton
from .onset import fe_onset, lowest_eigenvalue, start_value
from .section import MeshSize, Section, mesh_size

#: the amplitudes of the branch's curvature estimate, units R_i (Richardson on a and 2a)
CURVATURE_AMPLITUDE = 1e-3


@dataclasses.dataclass(frozen=True)
class PostbuckleResult:
    """The post-buckled branch of mode (m, 0).

    ``onset_linear`` the package's critical value, ``onset_fe`` the sign change of the FE
    tangent's lowest eigenvalue on the unperturbed path; ``control``, ``amplitude``,
    ``energy`` the branch (amplitude a: the cos(m Theta) radial displacement of ``face``,
    the face where the critical mode is larger, units R_i; energy: the whole ring's per
    unit reference length, units mu R_i^2), ``curvature``
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

    def as_dict(self) -> dict:
        """The JSON record."""
        return {
            "solve_for": self.solve_for,
            "m": self.m,
            "n": 0,
            "onset_linear": self.onset_linear,
            "onset_fe": self.onset_fe,
            "onset_relative_difference": (self.onset_fe - self.onset_linear)
            / abs(self.onset_linear),
            "curvature": self.curvature,
            "amplitude_face": self.face,
            "imperfection": self.imperfection,
            "mesh": {
                "radial_elements": list(self.mesh.radial),
                "hoop_elements": self.mesh.hoop,
                "elements": self.mesh.elements,
                "unknowns": self.unknowns,
                "sector": f"pi/{self.m}",
            },
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
                "onset_linear": self.onset_linear,
                "onset_fe": self.onset_fe,
                "curvature": self.curvature,
            },
        )


def postbuckle(
    tube: Tube,
    m: int,
    solve_for: str,
    *,
    amplitude: float = 0.05,
    points: int = 10,
    density: float = 20.0,
    hoop: int | None = None,
    imperfection: float = 0.0,
    progress: Callable[[str], None] | None = None,
) -> PostbuckleResult:
    """The post-buckled branch of the prismatic mode (m, 0) of ``tube`` along ``solve_for``.

    The package's onset (``critical_value(tube, m, 0, solve_for)``) guides the march of the
    FE model's unperturbed path (:func:`~.onset.fe_onset`) to the sign change of its lowest
    eigenvalue; the branch is then followed in the fold amplitude a (the cos(m Theta)
    radial displacement of the inner face, or the outer where the mode is larger) in
    ``points`` equal steps up to ``amplitude`` (units R_i), from the onset state plus a
    times the FE critical mode, with a load imperfection ``imperfection`` mu M z in the
    shape of that mode (0: the perfect branch).

    Parameters
    ----------
    density : float
        Elements per unit reference length across the wall (at least 2 per layer).
    hoop : int, optional
        Elements along the sector pi / m (default from ``density``, at least 4).

    Returns
    -------
    PostbuckleResult

    Raises
    ------
    ParameterError, NoBifurcationFound, ConvergenceError, Interrupted (with the finished
    points in ``partial``)
    """
    if not (isinstance(m, int) and m >= 2):
        raise ParameterError(f"m = {m!r} is out of range; valid range: an integer m >= 2")
    if not (math.isfinite(amplitude) and amplitude > 0):
        raise ParameterError(f"amplitude = {amplitude!r} is out of range; valid range: > 0")
    if not (isinstance(points, int) and 1 <= points <= 1000):
        raise ParameterError(f"points = {points!r} is out of range; valid range: 1 to 1000")
    if not (math.isfinite(imperfection) and imperfection >= 0):
        raise ParameterError(f"imperfection = {imperfection!r} is out of range; valid: >= 0")
    if not (math.isfinite(density) and 0 < density <= 2000):
        raise ParameterError(f"density = {density!r} is out of range; valid range: 0 to 2000")
    if hoop is not None and not (isinstance(hoop, int) and 1 <= hoop <= 1000):
        raise ParameterError(f"hoop = {hoop!r} is out of range; valid range: 1 to 1000")
    say = progress or (lambda text: None)
    control = str(tube.check_control(solve_for))
    start_value(tube, control)  # a control the model follows
    size = mesh_size(tube, m, density, hoop=hoop)
    section = Section(tube, m, size)  # refuses what the model does not cover, before solving
    say(f"linear onset of mode ({m}, 0) and of its multiples")
    linear = critical_value(tube, m, 0, control).value
    _check_first_in_sector(tube, m, control, linear)
    say(f"finite-element onset on {size.elements} elements ({section.free.size} unknowns)")
    onset = fe_onset(section, tube, control, linear)
    # the amplitude is read on the face where the critical mode is larger
    faces = {f: amplitude_vector(section, f) for f in ("inner", "outer")}
    face = max(faces, key=lambda f: abs(faces[f] @ onset.mode))
    a = faces[face]
    mode = onset.mode / (a @ onset.mode)
    perfect = AmplitudeBranch(section, tube, control, face=face)
    start = BranchPoint(onset.value, 0.0, section.energy(onset.x), onset.x)
    start.eigenvalue = lowest_eigenvalue(section, onset.x)  # zero to the onset's tolerance
    say("initial curvature of the branch")
    near = perfect.follow(start, [CURVATURE_AMPLITUDE, 2 * CURVATURE_AMPLITUDE], direction=mode)
    q = [(p.control - onset.value) / p.amplitude**2 for p in near]
    curvature = (4 * q[0] - q[1]) / 3
    amps = amplitude * np.arange(1, points + 1) / points
    record = functools.partial(
        _record, tube, control, m, linear, onset.value, size, section, curvature, imperfection
    )
    record = functools.partial(_with_face, record, face)
    if imperfection > 0:
        force = np.zeros(section.basis.N)
        force[section.free] = imperfection * (section.M @ mode)[section.free]
        branch = AmplitudeBranch(section, tube, control, force, eigenvalues=True, face=face)
        # the imperfect path from 90 % of the way to onset, in the amplitude
        c0 = onset.value - 0.1 * (onset.value - start_value(tube, control))
        section.set_tube(tube.at(control, c0))
        x0, _ = newton(section, onset.x)
        x0 = _with_imperfection(section, x0, force)
        first = BranchPoint(c0, float(a @ x0), section.energy(x0), x0)
        first.eigenvalue = lowest_eigenvalue(section, x0)
        head, follow_from, direction = [first], first, mode
        amps = amps[amps > first.amplitude]
    else:
        branch = AmplitudeBranch(section, tube, control, eigenvalues=True, face=face)
        head, follow_from, direction = [start], near[-1], mode
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


#: the multiples j m (j = 2 .. SECTOR_MULTIPLES) checked to come after mode m
SECTOR_MULTIPLES = 3


def _check_first_in_sector(tube, m, control, linear):
    """ParameterError if a mode j m, which the sector pi / m holds too, comes before m on the
    path from the start value: the FE onset and branch would be of that mode."""
    start = start_value(tube, control)
    for j in range(2, SECTOR_MULTIPLES + 1):
        try:
            other = critical_value(tube, j * m, 0, control).value
        except NoBifurcationFound:
            continue
        if abs(other - start) < abs(linear - start):
            raise ParameterError(
                f"mode ({j * m}, 0) comes before ({m}, 0) ({control} = {other:.8g} against"
                f" {linear:.8g}); the sector pi/{m} holds both and would follow it: ask for"
                f" mode {j * m}"
            )


def _with_face(record, face, pts):
    return dataclasses.replace(record(pts), face=face)


def _record(tube, control, m, linear, onset, size, section, curvature, imperfection, pts):
    full = 2 * m  # the ring is 2 m sectors
    return PostbuckleResult(
        tube=tube,
        solve_for=control,
        m=m,
        onset_linear=float(linear),
        onset_fe=onset,
        mesh=size,
        unknowns=int(section.free.size),
        control=np.array([p.control for p in pts]),
        amplitude=np.array([p.amplitude for p in pts]),
        energy=full * np.array([p.energy for p in pts]),
        eigenvalue=np.array([p.eigenvalue for p in pts]),
        curvature=float(curvature),
        imperfection=float(imperfection),
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
