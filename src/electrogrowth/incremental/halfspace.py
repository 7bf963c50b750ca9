"""The short-wave limit of the Stroh system: a half-space at a face of the tube.

A wrinkle with m, k -> infinity (wave vector in the face fixed in direction) decays within
a distance ~ 1 / |(m / r, k)| of a face, where the base state is frozen: the tube looks
like a homogeneous, pre-stressed, pre-polarised half-space. Derivation and checks:
docs/derivation-surface.md.

The limit matrix N(psi) and the decaying solutions by an ordered Schur form are in
stroh_limit.py (derived there); the compiled spectral-projector route in
decaying_subspace.py. This module holds the half-space problems and their targets.

**Face conditions** (as the finite-mode solvers, stroh.py section 5): traction-free and
earthed increment of potential, Sigma_rr = Sigma_rth = Sigma_rz = Phi = 0, i.e. S = 0. A
decaying solution Q a satisfies them iff Y a = 0: the 4x4 boundary matrix is Y and the
half-space bifurcates when det Y = 0. The real, bounded target

    f = sign(det X) det Y / sqrt(det(M^T M)) = det(z) / sqrt(det(I + z^T z)),
    M = [X; Y] any basis,   z = Y X^-1 (S = z U),

depends only on the subspace (not on the basis) and vanishes exactly at bifurcation. It
has no poles: det X = 0 would be a decaying solution with U = 0 on the face, excluded by
strong ellipticity (its energy, a boundary term U.S, is 0).
On the unloaded tube z is negative (inner face) or positive (outer face) definite, so
f > 0 there for both faces and every psi.

**Loss of ellipticity.** When the four decaying nu cannot be split off (an eigenvalue
reaches the imaginary axis: a real wave vector solves the incremental equations, the
margin min |Re nu| / max |nu| <= ELLIPTICITY_TOL), the half-space problem is not
defined: the target is NaN and :func:`ellipticity_margin` says how far a state is.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import ParameterError
from .decaying_subspace import _interface_kernel, _targets_kernel
from .stroh_limit import (
    ELLIPTICITY_TOL,
    FACES,
    FloatArray,
    _weights,
    check_face,
    decaying_solutions,
    limit_expansion,
    limit_matrix,
)


def _direction_weights(psi: float) -> FloatArray:
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[1.0, c, s, c * c, s * s, c * s]])


def _margins(N) -> FloatArray:
    """min |Re nu| / max |nu| over the eigenvalues nu of each matrix N[..., 8, 8]."""
    ev = np.linalg.eigvals(N)
    return np.min(np.abs(ev.real), -1) / np.maximum(np.max(np.abs(ev), -1), 1e-300)


def _masked(problem, psi) -> FloatArray:
    """problem.target over an array of psi: NaN where the margin is below ELLIPTICITY_TOL."""
    psi = np.asarray(psi, float)
    if psi.ndim == 0:
        return np.float64(problem.target_scalar(float(psi)))
    f, margin = problem.target_and_margin(psi.reshape(-1))
    return np.where(margin > ELLIPTICITY_TOL, f, np.nan).reshape(psi.shape)


@dataclasses.dataclass(frozen=True)
class FaceProblem:
    """The half-space at one face: N(psi) = sum_k w_k(psi) E_k and its target.

    Build with :meth:`from_state` (a solved base state) or :meth:`from_moduli`; then
    :meth:`target` and :meth:`margin` are vectorised over psi. ``pressure`` is the follower
    pressure P on the face (sigma_rr = -P there; P_i at the inner face, P_o at the outer):
    the face condition is S~ = Z U~, Z = -P [[0, c, s, 0], [c, 0, 0, 0], [s, 0, 0, 0], 0]
    (docs/derivation-layered-modes.md), and the target sign(det X) det(Y - Z X) /
    sqrt(det M^T M).
    """

    face: str
    expansion: FloatArray  # (6, 8, 8), see limit_expansion
    radius: float = math.nan  # current radius of the face (for k r / m), if known
    pressure: float = 0.0  # follower pressure on the face

    @property
    def name(self) -> str:
        return self.face

    @classmethod
    def from_moduli(
        cls, mod, p, face: str, radius: float = math.nan, pressure: float = 0.0
    ) -> FaceProblem:
        return cls(
            check_face(face),
            limit_expansion(np.asarray(mod, float).reshape(23), float(p)),
            float(radius),
            float(pressure),
        )

    @classmethod
    def from_state(cls, state, face: str) -> FaceProblem:
        mod, p, r = face_data(state, face)
        return cls.from_moduli(mod, p, face, r, face_pressure(state, face))

    def matrix(self, psi) -> FloatArray:
        """N(psi), shape psi.shape + (8, 8)."""
        return np.einsum("...k,kij->...ij", _weights(psi), self.expansion)

    def margin(self, psi) -> FloatArray:
        """Ellipticity margin min |Re nu| / max |nu| of N(psi) (0: not strongly elliptic)."""
        psi = np.asarray(psi, float)
        return _margins(self.matrix(psi.reshape(-1))).reshape(psi.shape)

    def target(self, psi) -> FloatArray:
        """f = sign(det X) det(Y - Z X) / sqrt(det(M^T M)) for a basis M = [X; Y] of the
        decaying subspace (module docstring; Z = 0 without pressure), NaN where the
        decaying split fails.

        The basis is M = P [0; I], P = (I -+ sign N) / 2 the spectral projector on the
        decaying subspace (sign N by Newton's iteration, vectorised over psi): its columns
        span the subspace because no growing solution has U = 0 on the face (strong
        ellipticity, the argument that excludes poles)."""
        return _masked(self, psi)

    def target_scalar(self, psi: float) -> float:
        """:meth:`target` for one direction, as a float (less overhead)."""
        f, margin = np.empty(1), np.empty(1)
        _targets_kernel(
            self.expansion, _direction_weights(psi), self.face == "inner", self.pressure, f, margin
        )
        return float(f[0]) if margin[0] > ELLIPTICITY_TOL else math.nan

    def target_and_margin(self, psi) -> tuple[FloatArray, FloatArray]:
        """(f, margin) for a 1-D array of psi, f not masked (NaN only if no split at all);
        margin of the decaying eigenvalues as in :meth:`margin`."""
        flat = np.ascontiguousarray(np.asarray(psi, float).reshape(-1))
        f = np.empty(flat.size)
        margin = np.empty(flat.size)
        _targets_kernel(
            self.expansion, _weights(flat), self.face == "inner", self.pressure, f, margin
        )
        return f, margin


@dataclasses.dataclass(frozen=True)
class InterfaceProblem:
    """The short-wave problem at a bonded interface: two half-spaces, the layer below
    (moduli and p on its side, solutions decaying as r decreases, like an outer face) and
    the layer above (decaying as r increases, like an inner face), with eta~ continuous.

    With z_b = Y_b X_b^-1, z_a = Y_a X_a^-1 the interface bifurcates iff det(z_b - z_a) = 0;
    the target

        f = det(z_b - z_a) / sqrt(det(I + z_b^T z_b) det(I + z_a^T z_a))
          = sign(det X_b det X_a) det [M_b M_a] / sqrt(det(M_b^T M_b) det(M_a^T M_a))

    depends on the subspaces only, |f| <= 1 (Hadamard), and has no poles (X_b, X_a are
    invertible under strong ellipticity). On the unloaded tube z_b > 0 and z_a < 0, so
    f > 0. docs/derivation-layered-modes.md.
    """

    name: str
    below: FloatArray  # (6, 8, 8) expansion of the layer inside the interface
    above: FloatArray  # (6, 8, 8) expansion of the layer outside it
    radius: float = math.nan

    @classmethod
    def from_moduli(
        cls, mod_below, p_below, mod_above, p_above, name: str = "interface", radius=math.nan
    ) -> InterfaceProblem:
        return cls(
            name,
            limit_expansion(np.asarray(mod_below, float).reshape(23), float(p_below)),
            limit_expansion(np.asarray(mod_above, float).reshape(23), float(p_above)),
            float(radius),
        )

    @classmethod
    def from_state(cls, state, name: str) -> InterfaceProblem:
        k = _interface_index(state, name)
        R = state.tube.radii[k]
        return cls.from_moduli(
            np.asarray(state.moduli(R, side="inner"), float),
            float(state.pressure(R, side="inner")),
            np.asarray(state.moduli(R, side="outer"), float),
            float(state.pressure(R, side="outer")),
            name,
            float(state.radii[k]),
        )

    def margin(self, psi) -> FloatArray:
        """The smaller ellipticity margin of the two layers' N(psi)."""
        psi = np.asarray(psi, float)
        out = []
        for E in (self.below, self.above):
            N = np.einsum("...k,kij->...ij", _weights(psi.reshape(-1)), E)
            ev = np.linalg.eigvals(N)
            out.append(np.min(np.abs(ev.real), -1) / np.maximum(np.max(np.abs(ev), -1), 1e-300))
        return np.minimum(*out).reshape(psi.shape)

    def target(self, psi) -> FloatArray:
        """f(psi) (class docstring), NaN where either decaying split fails."""
        return _masked(self, psi)

    def target_scalar(self, psi: float) -> float:
        f, margin = np.empty(1), np.empty(1)
        _interface_kernel(self.below, self.above, _direction_weights(psi), f, margin)
        return float(f[0]) if margin[0] > ELLIPTICITY_TOL else math.nan

    def target_and_margin(self, psi) -> tuple[FloatArray, FloatArray]:
        flat = np.ascontiguousarray(np.asarray(psi, float).reshape(-1))
        f = np.empty(flat.size)
        margin = np.empty(flat.size)
        _interface_kernel(self.below, self.above, _weights(flat), f, margin)
        return f, margin


def surfaces(state_or_tube) -> tuple[str, ...]:
    """The surfaces where short waves can live: ("inner", "outer") for a homogeneous tube,
    and "interface-1", ..., "interface-(N-1)" (between layers k and k + 1) for a tube of N
    layers (a base state or a Tube)."""
    tube = getattr(state_or_tube, "tube", state_or_tube)
    return FACES + tuple(f"interface-{k}" for k in range(1, len(tube.layers)))


def _interface_index(state, name: str) -> int:
    n = len(state.tube.layers)
    prefix = "interface-"
    if isinstance(name, str) and name.startswith(prefix) and name[len(prefix) :].isdigit():
        k = int(name[len(prefix) :])
        if 1 <= k < n:
            return k
    raise ParameterError(
        f"surface = {name!r} is unknown; choose one of {', '.join(surfaces(state))}"
    )


def surface_radius(state, name: str) -> float:
    """Current radius of the surface ``name`` of a solved base state."""
    if name in FACES:
        return state.r_i if name == "inner" else state.r_o
    return float(state.radii[_interface_index(state, name)])


def surface_problem(state, name: str) -> FaceProblem | InterfaceProblem:
    """The short-wave problem at the surface ``name`` (:func:`surfaces`) of a solved base
    state: a FaceProblem (with the face's follower pressure) or an InterfaceProblem."""
    if name in FACES:
        return FaceProblem.from_state(state, name)
    return InterfaceProblem.from_state(state, name)


def target_from_moduli(mod, p, psi, face: str) -> FloatArray:
    """f(psi) of the half-space with moduli ``mod`` and multiplier ``p`` at ``face``.

    Bounded by 1 in modulus, continuous, zero exactly when the half-space bifurcates in
    direction psi, NaN where it is not strongly elliptic (:meth:`FaceProblem.target`).
    """
    return FaceProblem.from_moduli(mod, p, face).target(psi)


def schur_target(mod, p, psi: float, face: str) -> float:
    """The same f from the ordered real Schur basis of :func:`decaying_solutions` (one
    direction; slower, an independent route used to test :meth:`FaceProblem.target`)."""
    Q, _, _ = decaying_solutions(limit_matrix(mod, p, psi), face)
    if np.isnan(Q[0, 0]):
        return math.nan
    return math.copysign(1.0, np.linalg.det(Q[:4])) * float(np.linalg.det(Q[4:]))


def face_radius(state, face: str) -> float:
    """Reference radius R of the face: 1 (inner) or the outer radius (Rbar_o, R_N)."""
    if check_face(face) == "inner":
        return 1.0
    return state.tube.outer_radius


def face_data(state, face: str) -> tuple[FloatArray, float, float]:
    """(moduli (23,), p, current radius r) of a solved base state at ``face`` (for a layered
    state, of the layer at that face)."""
    R = face_radius(state, face)
    r = state.r_i if face == "inner" else state.r_o
    side = "outer" if face == "inner" else "inner"  # the layer on the wall's side
    return (
        np.asarray(state.moduli(R, side=side), float).reshape(23),
        float(state.pressure(R, side=side)),
        r,
    )


def face_pressure(state, face: str) -> float:
    """The follower pressure on ``face`` (P_i inner, P_o outer)."""
    return float(state.face_pressures[0 if check_face(face) == "inner" else 1])


def surface_target(state, face: str, psi) -> FloatArray:
    """The half-space target f(state, face, psi) (:meth:`FaceProblem.target`) at a face
    of a solved base state (any State), vectorised over psi."""
    return FaceProblem.from_state(state, face).target(psi)


def ellipticity_margin(state, face: str, psi) -> FloatArray:
    """min |Re nu| / max |nu| of N(psi) at a face (0 where strong ellipticity fails)."""
    return FaceProblem.from_state(state, face).margin(psi)


#: where a wall's strong ellipticity is read (:func:`not_elliptic`): this many radii of each
#: layer, evenly from face to face (a stretch is extreme at a face of a layer, where the
#: loss begins), and this many wave directions psi in [0, pi/2]
WALL_RADII = 5
WALL_DIRECTIONS = 91
#: an eigenvalue of N(psi) on the imaginary axis this close to 0 (times the largest) is at
#: the edge of ellipticity, not past it (:func:`not_elliptic`)
EDGE = math.sqrt(1e-9)


def not_elliptic(state) -> tuple[int, float] | None:
    """(layer, R): the first layer (1-based) and reference radius at which the wall of a
    solved base state is not strongly elliptic beyond rounding, read at WALL_RADII radii of
    each layer and WALL_DIRECTIONS directions; None where it is elliptic at all of them.

    Lost: an eigenvalue nu of N(psi) on the imaginary axis (|Re nu| <= ELLIPTICITY_TOL
    max |nu|: a real wave vector solves the incremental equations) and not at its origin
    (|nu| >= EDGE max |nu|). A modulus past its zero by a share d of the layer's puts nu
    ~ sqrt(d) off the origin, so EDGE = sqrt(1e-9) is basestate/ellipticity.py's LOST: a
    state at the edge (A1313 = 0 exactly at a torsional onset, or -8.9e-16 where one is
    located) keeps its fallback as the axes' test lets it, and a matrix that divides by a
    vanished shear modulus (not finite) is left to that test."""
    psi = np.linspace(0.0, 0.5 * math.pi, WALL_DIRECTIONS)
    for k in range(len(state.tube.layers)):
        R, mod, p = _layer_points(state, k)
        with np.errstate(divide="ignore", invalid="ignore"):
            N = np.einsum("pk,rkij->rpij", _weights(psi), limit_expansion(mod, p))
        finite = np.isfinite(N).all((-2, -1))
        lost = np.zeros(N.shape[:2], dtype=bool)
        ev = np.linalg.eigvals(N[finite])
        top = np.max(np.abs(ev), -1, keepdims=True)
        axis = (np.abs(ev.real) <= ELLIPTICITY_TOL * top) & (np.abs(ev) >= EDGE * top)
        lost[finite] = axis.any(-1)
        where = np.nonzero(lost.any(-1))[0]
        if where.size:
            return k + 1, float(R[where[0]])
    return None


def _layer_points(state, k: int):
    """(R, moduli, p) at WALL_RADII reference radii of layer k (0-based), from its inner
    face to its outer one, each face on the layer's own side."""
    a, b = state.tube.radii[k], state.tube.radii[k + 1]
    R = np.linspace(a, b, WALL_RADII)
    mod, p = np.empty((R.size, 23)), np.empty(R.size)
    for side, sel in (("outer", R < b), ("inner", R >= b)):
        mod[sel] = np.reshape(state.moduli(R[sel], side=side), (-1, 23))
        p[sel] = state.pressure(R[sel], side=side)
    return R, mod, p
