"""Mode shapes: the incremental displacement and potential through the wall at bifurcation.

At a critical point the incremental problem (paper eq. incremental-solutions)

    u_r = U_r cos(m th) cos(kz),  u_th = U_th sin(m th) cos(kz),  u_z = U_z cos(m th) sin(kz),
    phidot = Phi cos(m th) cos(kz),   k = n pi / (lambda_z L),

has a non-trivial solution, the Stroh vector eta = [U; S] (stroh.py),
U = [U_r, U_th, U_z, r Delta_r], S = [r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi], with
S(r_i) = S(r_o) = 0. Two independent routes compute it (riccati.py, null_vector.py):

* "impedance" (paper eq. two_Riccati): integrate the Riccati equation for the conditional
  impedance z (S = z U, z(r_i) = 0) outwards, keeping z(r) as a dense interpolant; take
  U(r_o) in the null space of z(r_o); integrate dU/dr = (G1 + G2 z) U / r inwards from r_o
  and recover S = z U. Inwards is the stable direction: the inner-face subspace is
  dominated by solutions that grow outwards (like exp(k r)), so G1 + G2 z has mostly
  growing directions outwards and decaying ones inwards (tested in
  tests/shapes/test_mode_shape.py). The same is done from the outer face (z(r_o) = 0,
  U(r_i) in the null space of z(r_i), U carried outwards), and the face whose z is the
  more nearly singular gives the null vector: a mode living at the inner face (a thin
  stiff film's folds, decaying like (r_i / r)^m into the substrate) is exponentially small
  at r_o, where z(r_o) is then not singular to working accuracy (riccati.py).
  z may have a pole inside the wall (the subspace is then not a graph over U); where both
  integrations fail, the collocation route is used instead (``route``, ``note``).
* "collocation": the null vector of the Chebyshev collocation matrix (collocation.py),
  interpolated by its polynomial; S follows from the constitutive law.

Mode families (incremental.targets.Family; docs/derivation-families.md): a prismatic mode
(n = 0, k = 0: a plane-strain wrinkle, the wall a 2D cross-section, U_z = r Sigma_rz = 0)
and a torsional mode (m = 0: u_th = U_th(r) cos kz alone, every other component 0) are
computed by both routes on their own block of the Stroh system (the kept pairs; the
left-out components are exactly zero); so are the axisymmetric modes (m = 0 wrinkles,
U_th = r Sigma_rth = 0). Note that shapes/wall.py draws the paper's ansatz, in which
u_th carries sin(m th): a torsional mode there needs its own factor cos(kz).

Both are sampled at ``points`` reference radii R equally spaced in [1, Rbar_o] and
normalised alike: max |U_r|, |U_th|, |U_z| over the samples is 1, and the largest-|.|
sample of U_r is positive (where the wall moves most, it moves outwards at th = 0, z = 0;
for a pure torsion, U_r = 0, the largest displacement sample is positive). Lengths are in
units of R_i; U is a shape, its amplitude is arbitrary in the linear theory.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.interpolate import CubicSpline

from .._types import FloatArray
from ..basestate.tube import solve_base_state
from ..bifurcation.critical import CriticalPoint
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError, Remedy
from ..incremental.targets import Family, Method, check_method, check_mode
from ..model.layers import Tube
from ..outcomes import Kind
from .null_vector import collocation_shape
from .riccati import _RouteFailed, face_impedances, impedance_shape

#: Components of the Stroh vector eta, in order (stroh.py, SIGN_PHI = -1).
ETA_NAMES = (
    "U_r",
    "U_th",
    "U_z",
    "r_Delta_r",
    "r_Sigma_rr",
    "r_Sigma_rth",
    "r_Sigma_rz",
    "minus_Phi",
)


@dataclasses.dataclass(frozen=True, eq=False)
class ModeShape:
    """A normalised mode shape through the wall (see the module docstring).

    Attributes
    ----------
    R, r : (points,) arrays
        Reference radius R in [1, Rbar_o] (equally spaced) and current radius r(R).
    U_r, U_th, U_z, Phi : (points,) arrays
        Amplitudes of paper eq. incremental-solutions (max |U| = 1, U_r > 0 where largest).
    eta : (8, points) array
        The whole Stroh vector [U_r, U_th, U_z, r Delta_r, r Sigma_rr, r Sigma_rth,
        r Sigma_rz, -Phi] (``ETA_NAMES``), same normalisation.
    m, n, k : mode numbers and axial wavenumber k = n pi / (lambda_z L) (0 for n = 0).
    params : the Tube at the critical point.
    route : "impedance" or "collocation", the route actually used.
    boundary_residual : max |S| on the faces over max |S| in the wall (0 at bifurcation).
    note : why the route differs from the one requested, and that a collocation shape at
        parameters given as (tube, m, n) leaves its faces loaded ("" otherwise).
    family : the mode family ("wrinkle", "prismatic", "torsional").
    """

    R: FloatArray
    r: FloatArray
    eta: FloatArray
    m: int
    n: int
    k: float
    params: Tube
    route: str
    boundary_residual: float
    note: str = ""
    family: str = Family.WRINKLE
    current_length: float | None = None  # l = lambda_z L (set for a layered Tube)

    @property
    def U_r(self) -> FloatArray:
        return self.eta[0]

    @property
    def U_th(self) -> FloatArray:
        return self.eta[1]

    @property
    def U_z(self) -> FloatArray:
        return self.eta[2]

    @property
    def Phi(self) -> FloatArray:
        return -self.eta[7]

    @property
    def length(self) -> float:
        """Current length l = lambda_z L of the tube."""
        if self.current_length is not None:
            return self.current_length
        return self.params.value_of("stretch") * self.params.length

    def at(self, R) -> FloatArray:
        """eta at reference radii R in [1, Rbar_o] (cubic spline of the samples), (8, ...)."""
        R = np.asarray(R, float)
        return CubicSpline(self.R, self.eta, axis=1)(R)

    def table(self) -> tuple[tuple[str, ...], FloatArray]:
        """(column names, rows) for a CSV: R, r, U_r, U_th, U_z, Phi, then the rest of eta."""
        cols = (
            "R",
            "r",
            "U_r",
            "U_th",
            "U_z",
            "Phi",
            "r_Delta_r",
            "r_Sigma_rr",
            "r_Sigma_rth",
            "r_Sigma_rz",
        )
        data = np.column_stack(
            [self.R, self.r, self.U_r, self.U_th, self.U_z, self.Phi, *self.eta[3:7]]
        )
        return cols, data + 0.0  # no negative zeros


def mode_shape(
    critical: CriticalPoint | tuple,
    *,
    method: str = "impedance",
    points: int = 101,
    rtol: float = 1e-12,
    nodes: int = 40,
) -> ModeShape:
    """The mode shape at a critical point: the amplitudes of the paper's incremental fields,
    by its two-step surface-impedance method or by collocation.

    Parameters
    ----------
    critical : CriticalPoint or (Tube, m, n[, family])
        A bifurcation from ``bifurcation.critical_value`` / ``scan.scan_modes`` (of any
        family: wrinkle, prismatic or torsional), or the parameters at (the caller's)
        critical point with the mode numbers (and the family; default the natural one of
        (m, n)).
    method : {"impedance", "collocation"}
        Riccati route of the paper (falls back to collocation when the impedance has a
        pole in the wall; see ``ModeShape.route``) or Chebyshev collocation.
    points : int
        Number of equally spaced reference radii R in [1, Rbar_o] (>= 2).
    rtol : float
        Relative tolerance of the two SciPy DOP853 integrations (impedance route).
    nodes : int
        Chebyshev-Lobatto points of the collocation route.

    Returns
    -------
    ModeShape
        Normalised: max |U| = 1, the largest-|.| sample of U_r positive.

    Raises
    ------
    ParameterError
        Bad method, points, mode numbers or family.
    NoBifurcationFound
        ``critical`` is a voltage threshold, not a bifurcation (it has no mode).
    ConvergenceError
        Both routes failed to give a displacement (internal; not expected), or, at a
        CriticalPoint, the collocation shape (requested or the fallback) leaves its faces
        loaded: boundary residual above ``COLLOCATION_RESIDUAL_LIMIT`` (1e-3), not the mode.
        At parameters given as (tube, m, n) that is a ``note`` instead (they may not be
        critical).

    Examples
    --------
    >>> from electrogrowth.bifurcation.critical import critical_value
    >>> crit = critical_value(Tube.uniform(1.4, 1.0, voltage=0.4), 2, 1, "stretch")
    >>> shape = mode_shape(crit, points=21)
    >>> shape.route, float(abs(shape.eta[:3]).max()), bool(shape.U_r.max() > 0)
    ('impedance', 1.0, True)
    """
    params, m, n, family = _unpack(critical)
    pairs = family.pairs(m)
    method = check_method(method)
    if isinstance(points, bool) or not isinstance(points, (int, np.integer)) or points < 2:
        raise ParameterError(f"points = {points!r} is invalid; need an integer >= 2")
    state = solve_base_state(params)
    R = np.linspace(1.0, params.outer_radius, int(points))
    k = n * math.pi / state.current_length
    note = ""
    if method is Method.IMPEDANCE:
        try:
            eta = impedance_shape(state, m, k, R, rtol=rtol, pairs=pairs)
        except _RouteFailed as exc:
            method, note = Method.COLLOCATION, f"{exc}; shape from collocation instead"
    if method is Method.COLLOCATION:
        eta = collocation_shape(state, m, n, R, nodes=nodes, pairs=pairs)
    eta = normalise(eta)
    residual = boundary_residual(eta, face_impedances(state, m, k))
    if method is Method.COLLOCATION:
        note = _check_collocation(residual, nodes, note, isinstance(critical, CriticalPoint))
    return ModeShape(
        R,
        state.radius(R),
        eta,
        m,
        n,
        k,
        params,
        method.value,
        residual,
        note,
        family,
        state.current_length,
    )


#: Largest boundary residual of a collocation shape that is returned (at a CriticalPoint).
#: Shapes that are the mode give 5e-13 .. 1.4e-8 (uniform tubes; films 1/100 of the wall,
#: 100 times as stiff; 40 .. 80 nodes), up to 1.5e-5 and 4.2e-5 for films 1/1000 of the wall,
#: 1e4 and 1e3 times as stiff (their S, differentiated through a steep polynomial, is the
#: least accurate); a null vector that is not the mode leaves its faces loaded at O(1)
#: (0.31 .. 1.0, probe10a D1). 1e-3, 24x the largest good one, separates them.
COLLOCATION_RESIDUAL_LIMIT = 1e-3

_COLLOCATION_REMEDY = Remedy(
    "use --method impedance (the default); if that falls back to collocation, report it",
    python="use method='impedance' (the default), or collocation with other nodes=",
)


def _check_collocation(residual: float, nodes: int, note: str, certified: bool) -> str:
    """The note of a collocation shape, or ConvergenceError: a shape whose faces are loaded
    is never returned silently (by request or as the impedance route's fallback).

    At a CriticalPoint (a bifurcation to its error estimate) a loaded face is the method's
    failure: ConvergenceError. At parameters the caller gave as (tube, m, n), it may be
    theirs (they need not be critical; docs/modes.md): a note says so, the shape is kept."""
    if residual <= COLLOCATION_RESIDUAL_LIMIT:
        return note
    loaded = (
        f"the collocation mode shape ({nodes} nodes) is not the mode: its faces carry"
        f" {residual:.1e} of the wall's largest traction (limit {COLLOCATION_RESIDUAL_LIMIT:g})"
    )
    if not certified:
        return "; ".join(filter(None, (note, loaded + ", or the parameters are not critical")))
    err = ConvergenceError(loaded + (f" ({note})" if note else ""))
    err.remedy = _COLLOCATION_REMEDY
    raise err


def _unpack(critical) -> tuple[Tube, int, int, Family]:
    if isinstance(critical, CriticalPoint):
        if critical.kind != Kind.BIFURCATION:
            why = (
                "the axisymmetric state is lost before any wrinkling"
                if critical.kind == Kind.THRESHOLD
                else "it has no finite mode (m, n)"
            )
            raise NoBifurcationFound(
                f"the critical point is a {critical.kind} ({critical.solve_for} ="
                f" {critical.value:.12g}): {why}, so there is no mode shape"
            )
        fam = check_mode(critical.m, critical.n, critical.family)
        return critical.params, critical.m, critical.n, fam
    try:
        params, m, n, *family = critical
        if len(family) > 1:
            raise ValueError
    except (TypeError, ValueError):
        raise ParameterError(
            f"critical = {critical!r} is neither a CriticalPoint nor (params, m, n[, family])"
        ) from None
    if not isinstance(params, Tube):
        raise ParameterError(f"params = {params!r} is not a Tube")
    fam = check_mode(m, n, family[0] if family else None)
    return params, int(m), int(n), fam


# -- normalisation ---------------------------------------------------------------------------


def normalise(eta: FloatArray) -> FloatArray:
    """eta / c with c such that max |U_r, U_th, U_z| = 1 over the samples and the
    largest-|.| sample of U_r is positive (of the displacement when U_r = 0, torsion)."""
    disp = eta[:3]
    big = disp.flat[np.argmax(np.abs(disp))]
    if big == 0.0:
        # an internal failure (a route's null vector without displacement), not the user's
        raise ConvergenceError("the computed mode shape has no displacement")
    ur = disp[0, np.argmax(np.abs(disp[0]))]
    sign = math.copysign(1.0, ur if abs(ur) > 1e-9 * abs(big) else big)
    return eta / (sign * abs(big))  # a division: the largest sample is then exactly +-1


def boundary_residual(eta: FloatArray, faces=(None, None)) -> float:
    """max(|S - z_P U| at r_i and r_o) / max |S| over the wall: 0 for an exact mode.

    ``faces``: the follower-pressure impedances z_P (4x4, S = z_P U on the face) of the
    inner and outer face, None for a traction-free face.
    """
    S = np.abs(eta[4:])
    top = S.max()
    if not top > 0:
        return 0.0
    ends = []
    for col, zp in zip((0, -1), faces):
        res = eta[4:, col] - (0.0 if zp is None else zp @ eta[:4, col])
        ends.append(np.abs(res).max())
    return float(max(ends) / top)
