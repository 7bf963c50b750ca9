"""The worst wave direction at the surfaces of one state: the signed half-space target
h = min over surfaces and directions psi in [0, pi/2] of s_face f(state, face, psi), with
s_face its sign on the unloaded (stable) tube. The surfaces are the faces "inner" and
"outer" and, for a layered tube, the interfaces "interface-1", ... (halfspace.surfaces).

f (incremental/halfspace.py) is evaluated on a grid of psi (endpoints included), then
minimised by a bounded 1-D search between the neighbours of the lowest grid minima; an
endpoint minimum is kept exactly when f is flat to rounding there. ``past_surface`` asks
whether a loaded state is already beyond its short-wave instability (a few ms), which is
how a scan decides whether the exact limit (surface.py) is worth locating.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError
from ..incremental import direction_search
from ..incremental.halfspace import (
    FaceProblem,
    InterfaceProblem,
    surface_problem,
    surface_radius,
    surfaces,
)
from ..incremental.stroh_limit import _weights

HALF_PI = 0.5 * math.pi
ENDPOINT_SLACK = direction_search.ENDPOINT_SLACK  # f equal to rounding: the exact endpoint
MARCH_REFINE = 0.05  # march: refine the psi minimum only where the grid minimum is below
FACE_TIE = 1e-13  # faces whose targets agree this closely (homogeneous tube): the first


@dataclasses.dataclass(frozen=True)
class Resolution:
    grid: int  # psi grid points on [0, pi/2]
    psi_tol: float  # absolute tolerance of the psi minimisation
    rtol: float  # base state and Brent


@dataclasses.dataclass(frozen=True)
class Sample:
    value: float  # h: min over faces (and psi) of the signed target; NaN: not elliptic
    face: str | None
    psi: float | None


def stable_signs(params, faces=None) -> dict[str, float]:
    """Sign of the half-space target at each surface (default: every face and interface,
    halfspace.surfaces) on the unloaded tube ``params.reference()`` (g = 1, lambda_z = 1,
    no voltage or pressure), which is stable (the same for every psi; checked on a grid)."""
    state = solve_base_state(params.reference())
    out = {}
    for face in surfaces(state) if faces is None else faces:
        f = surface_problem(state, face).target(np.linspace(0.0, HALF_PI, 7))
        if not (np.all(np.isfinite(f)) and (np.all(f > 0) or np.all(f < 0))):
            raise ConvergenceError(
                f"half-space target undefined or of mixed sign on the "
                f"unloaded tube at the {face} face: {f}"
            )
        out[face] = math.copysign(1.0, f[0])
    return out


@functools.lru_cache(maxsize=64)
def _unloaded_signs(reference) -> dict[str, float]:
    """stable_signs of every surface, shared by every state of one tube (keyed by its
    unloaded reference, a hashable Tube)."""
    return stable_signs(reference)


def reference_signs(params) -> dict[str, float]:
    """stable_signs of every surface of ``params``, cached by ``params.reference()``."""
    return _unloaded_signs(params.reference())


def past_surface(params, faces=None) -> bool:
    """Whether a surface (face or interface) of this loaded tube is beyond its short-wave
    instability in some wave direction (the signed half-space target is <= 0 there): then
    the exact limit, reached earlier along any path from the unloaded tube, is worth
    locating."""
    return surface_past(params, faces) is not None


def surface_past(params, faces=None) -> str | None:
    """The first surface (face or interface) of this loaded tube beyond its short-wave
    instability in some wave direction, or where strong ellipticity is lost (the signed
    half-space target is <= 0 or NaN), or None."""
    signs = reference_signs(params)
    state = solve_base_state(params)
    for face in surfaces(state) if faces is None else faces:
        problem = surface_problem(state, face)
        v, _ = worst_direction(problem, signs[face], psi_tol=None)
        if v < MARCH_REFINE:
            v, _ = worst_direction(problem, signs[face])
        if not v > 0:
            return face
    return None


def worst_direction(
    problem: FaceProblem | InterfaceProblem,
    sign: float = 1.0,
    *,
    grid: int = 25,
    psi_tol: float | None = 1e-10,
    refine_below: float = math.inf,
) -> tuple[float, float]:
    """(min over psi in [0, pi/2] of sign * f, its psi) at one face or interface.

    A grid of ``grid`` directions (both endpoints included), then a bounded minimisation
    between the neighbours of each of the (up to three) lowest grid minima; an endpoint
    minimum is kept exactly when no interior point is lower (psi_tol None: the grid
    minimum alone; ``refine_below``: the grid minimum alone where it is above this).
    Returns (NaN, psi) if the half-space is not strongly elliptic in some grid direction
    psi. Compiled (incremental/direction_search.py); :func:`worst_direction_numpy` is its
    twin, to the last bit.
    """
    psi, w = _grid(grid)
    if isinstance(problem, InterfaceProblem):
        below, above, inner, pressure = problem.below, problem.above, False, 0.0
    else:
        below = above = problem.expansion
        inner, pressure = problem.face == "inner", problem.pressure
    v, p = direction_search.worst_direction(
        below,
        above,
        isinstance(problem, InterfaceProblem),
        inner,
        float(pressure),
        float(sign),
        psi,
        w,
        0.0 if psi_tol is None else float(psi_tol),
        float(refine_below),
    )
    return float(v), float(p)


@functools.lru_cache(maxsize=8)
def _grid(grid: int) -> tuple[np.ndarray, np.ndarray]:
    """The grid of ``grid`` directions on [0, pi/2] and its weights (stroh_limit._weights),
    computed as the twin computes them, once (read-only)."""
    psi = np.linspace(0.0, HALF_PI, grid)
    w = np.ascontiguousarray(_weights(psi))
    psi.setflags(write=False)
    w.setflags(write=False)
    return psi, w


def worst_direction_numpy(
    problem: FaceProblem | InterfaceProblem,
    sign: float = 1.0,
    *,
    grid: int = 25,
    psi_tol: float | None = 1e-10,
) -> tuple[float, float]:
    """:func:`worst_direction` by NumPy on the grid and SciPy's bounded minimiser: the slow
    twin the compiled route is tested against."""
    psi = np.linspace(0.0, HALF_PI, grid)
    F = sign * problem.target(psi)
    if np.isnan(F).any():
        return math.nan, float(psi[np.argmax(np.isnan(F))])
    lower = np.r_[True, F[1:] <= F[:-1]]  # F[i] <= left neighbour
    upper = np.r_[F[:-1] <= F[1:], True]  # F[i] <= right neighbour
    minima = np.nonzero(lower & upper)[0]
    minima = minima[np.argsort(F[minima], kind="stable")][:3]  # ties: the first index
    best_v, best_p = float(F[minima[0]]), float(psi[minima[0]])

    if psi_tol is None:  # the grid alone
        i = int(np.argmin(F))
        return float(F[i]), float(psi[i])

    def one(x):
        v = sign * problem.target_scalar(x)
        return v if math.isfinite(v) else math.inf

    from scipy.optimize import minimize_scalar  # 0.5 s of imports: only where it is used

    for i in minima:
        a, b = psi[max(i - 1, 0)], psi[min(i + 1, grid - 1)]
        res = minimize_scalar(
            one, bounds=(a, b), method="bounded", options={"xatol": psi_tol, "maxiter": 200}
        )
        x, v = float(res.x), float(res.fun)
        for end, fe in ((0.0, F[0]), (HALF_PI, F[-1])):
            # a minimum at an endpoint: f is flat to rounding within psi_tol of it
            if abs(x - end) <= 1e3 * psi_tol and fe <= v + ENDPOINT_SLACK:
                x, v = end, float(fe)
        if v < best_v:
            best_v, best_p = v, x
    if not math.isfinite(best_v):
        return math.nan, best_p
    return best_v, best_p


@dataclasses.dataclass(frozen=True)
class FixedDirection:
    """The wave direction psi at every state and face (short_wave_limit(psi=...))."""

    psi: float

    def __call__(self, state, face) -> float:
        return self.psi


@dataclasses.dataclass(frozen=True)
class RayDirection:
    """The direction tan psi = k r / m of the ray of modes (j m, j n) at a face of radius
    r, k = n pi / (lambda_z L): it follows the state (ray_limit)."""

    m: float
    n: float

    def __call__(self, state, face) -> float:
        length = getattr(state, "current_length", None)  # a layered state
        if length is None:
            length = state.tube.stretch * state.tube.length
        return math.atan2(self.n * math.pi * surface_radius(state, face) / length, self.m)


@dataclasses.dataclass(frozen=True, eq=False)
class Sampler:
    """h(state) -> Sample: min over ``faces`` (faces and interfaces) of the target signed by
    ``signs``, in the worst direction (``direction`` None) or in the direction
    direction(state, face) of a ray. With ``refine_below``, a face whose grid minimum is
    above it is not refined (the march)."""

    faces: tuple[str, ...]
    signs: dict[str, float]
    res: Resolution
    direction: Callable | None = None
    refine_below: float = math.inf

    def __call__(self, state) -> Sample:
        res, signs, direction = self.res, self.signs, self.direction
        best = Sample(math.inf, None, None)
        for face in self.faces:
            problem = surface_problem(state, face)
            if direction is None:  # refined where close to zero (or NaN)
                v, psi = worst_direction(
                    problem,
                    signs[face],
                    grid=res.grid,
                    psi_tol=res.psi_tol,
                    refine_below=self.refine_below,
                )
            else:
                psi = direction(state, face)
                v = float(signs[face] * problem.target(psi))
            if math.isnan(v):
                return Sample(math.nan, face, psi)
            if v < best.value - FACE_TIE:
                best = Sample(v, face, psi)
            elif v < best.value:  # a tie: keep the earlier face, with the lower value
                best = Sample(v, best.face, best.psi)
        return best


def sampler(faces, signs, res: Resolution, direction=None, refine_below=math.inf) -> Sampler:
    """The :class:`Sampler` of ``faces`` (kept for callers of the function form)."""
    return Sampler(tuple(faces), signs, res, direction, refine_below)
