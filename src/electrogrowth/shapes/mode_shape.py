"""Mode shapes: the incremental displacement and potential through the wall at bifurcation.

At a critical point the incremental problem (paper eq. incremental-solutions)

    u_r = U_r cos(m th) cos(kz),  u_th = U_th sin(m th) cos(kz),  u_z = U_z cos(m th) sin(kz),
    phidot = Phi cos(m th) cos(kz),   k = n pi / (lambda_z L),

has a non-trivial solution, the Stroh vector eta = [U; S] (stroh.py),
U = [U_r, U_th, U_z, r Delta_r], S = [r Sigma_rr, r Sigma_rth, r Sigma_rz, -Phi], with
S(r_i) = S(r_o) = 0. Two independent routes compute it:

* "impedance" (paper eq. two_Riccati): integrate the Riccati equation for the conditional
  impedance z (S = z U, z(r_i) = 0) outwards, keeping z(r) as a dense interpolant; take
  U(r_o) in the null space of z(r_o); integrate dU/dr = (G1 + G2 z) U / r inwards from r_o
  and recover S = z U. Inwards is the stable direction: the inner-face subspace is
  dominated by solutions that grow outwards (like exp(k r)), so G1 + G2 z has mostly
  growing directions outwards and decaying ones inwards (tested in
  tests/shapes/test_mode_shape.py).
  z may have a pole inside the wall (the subspace is then not a graph over U); the
  integration fails there and the collocation route is used instead (``route``, ``note``).
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
from numpy.polynomial import chebyshev as cheb
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline

from .._types import FloatArray
from ..basestate.tube import BaseState, solve_base_state
from ..bifurcation.critical import CriticalPoint
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.collocation import mode_shape_collocation
from ..incremental.impedance import ALL_PAIRS, face_impedance, impedance_scale
from ..incremental.impedance_reference import impedance_rhs, kept_pairs
from ..incremental.stroh import stroh_matrix
from ..incremental.targets import Family, Method, check_method, check_mode, wavenumber
from ..model.layers import Tube
from ..model.materials import MODULI_INDEX
from ..model.params import TubeParameters
from ..outcomes import Kind

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
    params : TubeParameters at the critical point.
    route : "impedance" or "collocation", the route actually used.
    boundary_residual : max |S| on the faces over max |S| in the wall (0 at bifurcation).
    note : why the route differs from the one requested ("" otherwise).
    family : the mode family ("wrinkle", "prismatic", "torsional").
    """

    R: FloatArray
    r: FloatArray
    eta: FloatArray
    m: int
    n: int
    k: float
    params: TubeParameters
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
        return self.params.stretch * self.params.length

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
    critical : CriticalPoint or (TubeParameters, m, n[, family])
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

    Examples
    --------
    >>> from electrogrowth.bifurcation.critical import critical_value
    >>> crit = critical_value(TubeParameters(1.4, 1.0, voltage=0.4), 2, 1, "stretch")
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
    if isinstance(params, Tube):
        eta = normalise(layered_collocation_shape(state, m, n, R, nodes=nodes, pairs=pairs))
        note = "" if method is Method.COLLOCATION else "layered tube: shape from collocation"
        return ModeShape(
            R,
            state.radius(R),
            eta,
            m,
            n,
            k,
            params,
            Method.COLLOCATION.value,
            boundary_residual(eta, _face_impedances(state, m, k)),
            note,
            family,
            state.current_length,
        )
    note = ""
    if method is Method.IMPEDANCE:
        try:
            eta = impedance_shape(state, m, k, R, rtol=rtol, pairs=pairs)
        except _PoleError as exc:
            method, note = Method.COLLOCATION, f"{exc}; shape from collocation instead"
    if method is Method.COLLOCATION:
        eta = collocation_shape(state, m, n, R, nodes=nodes, pairs=pairs)
    eta = normalise(eta)
    return ModeShape(
        R,
        state.radius(R),
        eta,
        m,
        n,
        k,
        params,
        method.value,
        boundary_residual(eta),
        note,
        family,
    )


def _unpack(critical) -> tuple[TubeParameters, int, int, Family]:
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
    if not isinstance(params, (TubeParameters, Tube)):
        raise ParameterError(f"params = {params!r} is not a TubeParameters or a Tube")
    fam = check_mode(m, n, family[0] if family else None)
    return params, int(m), int(n), fam


# -- impedance route -------------------------------------------------------------------------


class _PoleError(ConvergenceError):
    """The Riccati integration for z stopped (a pole of the impedance inside the wall)."""


def stroh_at(state: BaseState, R: float, m: float, k: float) -> FloatArray:
    """The Stroh matrix G (8x8) at reference radius R (moduli and p of the base state)."""
    G = np.empty((8, 8))
    r = float(state.radius(R))
    mod = np.ascontiguousarray(state.moduli(np.array(R)), dtype=float)
    stroh_matrix(mod, float(state.pressure(np.array(R))), float(m), k * r, G)
    return G


def impedance_shape(
    state: BaseState,
    m: int,
    k: float,
    R: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Un-normalised eta at R by the paper's two-step impedance method (eq. two_Riccati).

    1. dz/dR = (dr/dR)(1/r)(G3 + G4 z - z G1 - z G2 z), z(1) = 0, to R = Rbar_o (dense).
    2. U(r_o): right singular vector of the smallest singular value of z(r_o).
    3. dU/dR = (dr/dR)(1/r)(G1 + G2 z) U from Rbar_o down to 1; S = z U.

    On the block of the kept ``pairs`` (a mode family); the other components are 0.
    Raises _PoleError when step 1 fails or z blows up (a pole of the impedance).
    """
    Ro = state.params.outer_radius
    z = impedance_profile(state, m, k, rtol=rtol, pairs=pairs)
    U_o = np.linalg.svd(z(Ro))[2][-1]
    U = transport(state, m, k, z, U_o, (Ro, 1.0), R[::-1], rtol=rtol, pairs=pairs)[:, ::-1]
    S = np.stack([z(x) @ U[:, j] for j, x in enumerate(R)], axis=1)
    keep = kept_pairs(pairs)
    eta = np.zeros((8, R.size))
    eta[keep], eta[[4 + j for j in keep]] = U, S
    return eta


def impedance_profile(
    state: BaseState, m: int, k: float, *, rtol: float = 1e-12, pairs: int = ALL_PAIRS
):
    """z(R) for R in [1, Rbar_o]: the Riccati equation (paper eq. Riccati) integrated by
    SciPy DOP853 from z(1) = 0, as a callable R -> symmetric d x d (dense output), d the
    number of kept ``pairs`` (4 for the paper's ansatz)."""
    Ro = state.params.outer_radius
    scale = impedance_scale(float(m), float(k), float(state.r_o))
    d = len(kept_pairs(pairs))
    with np.errstate(all="ignore"):
        ric = solve_ivp(
            impedance_rhs(state, m, k, pairs),
            (1.0, Ro),
            np.zeros(d * d),
            method="DOP853",
            rtol=rtol,
            atol=1e-3 * rtol,
            dense_output=True,
        )
    big = np.abs(ric.y).max() if ric.y.size else np.inf
    if ric.status != 0 or not np.isfinite(big) or big > 1e8 * scale**2:
        r_stop = float(state.radius(min(max(ric.t[-1], 1.0), Ro)))
        raise _PoleError(
            f"the impedance z has a pole near r = {r_stop:.6g}"
            f" (Riccati integration stopped: {ric.message})"
        )

    def z(x: float) -> FloatArray:
        zx = ric.sol(x).reshape(d, d)
        return 0.5 * (zx + zx.T)  # symmetric exactly (docs/derivation-stroh.md, sec. 4)

    return z


def transport(
    state: BaseState,
    m: int,
    k: float,
    z,
    U0: FloatArray,
    span: tuple[float, float],
    R_eval: FloatArray,
    *,
    rtol: float = 1e-12,
    pairs: int = ALL_PAIRS,
) -> FloatArray:
    """Solve dU/dR = (dr/dR)(1/r)(G1 + G2 z) U (paper eq. two_Riccati, second part) from
    U(span[0]) = U0 to span[1]; U at ``R_eval`` (in the order of integration), (d, len),
    on the block of the kept ``pairs`` (d of them; 4 for the paper's ansatz).

    Stable inwards (span = (Rbar_o, 1)); outwards errors grow like exp(2 k (r_o - r_i)).
    """
    b = state.params.growth**3 / state.params.stretch  # r dr/dR = b R
    keep = np.array(kept_pairs(pairs))

    def rhs(x, U):
        G = stroh_at(state, x, m, k)
        G1, G2 = G[np.ix_(keep, keep)], G[np.ix_(keep, 4 + keep)]
        return b * x / float(state.radius(x)) ** 2 * ((G1 + G2 @ z(x)) @ U)

    sol = solve_ivp(rhs, span, U0, method="DOP853", t_eval=R_eval, rtol=rtol, atol=1e-3 * rtol)
    if sol.status != 0:
        raise _PoleError(f"the integration of U failed: {sol.message}")
    return sol.y


# -- collocation route -----------------------------------------------------------------------


def collocation_shape(
    state: BaseState, m: int, n: int, R: FloatArray, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> FloatArray:
    """Un-normalised eta at R from the collocation null vector.

    U_r, U_th, U_z, Phi and P are the nodal values of polynomials in r (degree nodes - 1;
    P from the collocation's interior interpolation); they are interpolated, differentiated
    where needed, and the rest of eta follows from the incremental law (stroh.py rows 1, 2,
    7 for r Sigma_rth, r Sigma_rz, r Delta_r; S_rr from docs/derivation-stroh.md):

        r Sigma_rr = r [(A1111 + p) U_r' + A1122 (U_r + m U_th)/r + A1133 k U_z
                        + Gamma111 Delta_r - P].

    ``pairs``: the block of a mode family (collocation.py); the other fields are 0.
    """
    shape = mode_shape_collocation(state, m, n, nodes=nodes, pairs=pairs)
    return _eta_from_nodes(state, shape, m, wavenumber(state.params, n), R)


# -- normalisation ---------------------------------------------------------------------------


def normalise(eta: FloatArray) -> FloatArray:
    """eta / c with c such that max |U_r, U_th, U_z| = 1 over the samples and the
    largest-|.| sample of U_r is positive (of the displacement when U_r = 0, torsion)."""
    disp = eta[:3]
    big = disp.flat[np.argmax(np.abs(disp))]
    if big == 0.0:
        raise ParameterError("the mode shape vanishes identically")
    ur = disp[0, np.argmax(np.abs(disp[0]))]
    sign = math.copysign(1.0, ur if abs(ur) > 1e-9 * abs(big) else big)
    return eta * (sign / abs(big))


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


def _face_impedances(state, m: float, k: float):
    """z_P of the faces of a layered state (incremental/impedance.py ``face_impedance``)."""
    return tuple(
        face_impedance(P, float(m), k * r, ALL_PAIRS, 1.0)
        for P, r in zip(state.face_pressures, (state.r_i, state.r_o))
    )


# -- layered tubes ---------------------------------------------------------------------------


def layered_collocation_shape(
    state, m: int, n: int, R: FloatArray, *, nodes: int = 40, pairs: int = ALL_PAIRS
) -> FloatArray:
    """Un-normalised eta at R of a layered state (basestate.layered.LayeredState), from the
    multi-domain collocation null vector: :func:`collocation_shape` layer by layer (each
    layer's nodal values are its own polynomial; a sample on an interface is taken from the
    layer inside it, eta being continuous there)."""
    shape = mode_shape_collocation(state, m, n, nodes=nodes, pairs=pairs)
    radii = state.tube.radii
    layer_of = np.clip(np.searchsorted(np.array(radii[1:-1]), R, side="left"), 0, len(radii) - 2)
    k = n * math.pi / state.current_length
    eta = np.empty((8, R.size))
    for j in range(len(radii) - 1):
        sel = layer_of == j
        if not sel.any():
            continue
        part = {f: v[j * nodes : (j + 1) * nodes] for f, v in shape.items()}
        side = "inner" if j < len(radii) - 2 else "outer"  # R on the outer end is this layer's
        eta[:, sel] = _eta_from_nodes(state, part, m, k, R[sel], side)
    return eta


def _eta_from_nodes(state, part: dict, m: float, k: float, R: FloatArray, side=None):
    """eta at R (one layer: ``side`` picks it at an interface of a layered state) from its
    nodal U_r, U_th, U_z, Phi, P (see collocation_shape)."""
    r_nodes = part["r"]
    domain = [r_nodes.min(), r_nodes.max()]
    poly = {
        f: cheb.Chebyshev.fit(r_nodes, part[f], len(r_nodes) - 1, domain=domain)
        for f in ("U_r", "U_th", "U_z", "Phi", "P")
    }
    where = {} if side is None else {"side": side}
    r = state.radius(R, **where)
    mod = state.moduli(R, **where)
    p = state.pressure(R, **where)
    val = {f: q(r) for f, q in poly.items()}
    der = {f: poly[f].deriv()(r) for f in ("U_r", "U_th", "U_z", "Phi")}
    eta = np.empty((8, R.size))
    eta[0], eta[1], eta[2], eta[7] = val["U_r"], val["U_th"], val["U_z"], -val["Phi"]
    G = np.empty((8, 8))
    for j in range(R.size):
        stroh_matrix(np.ascontiguousarray(mod[j]), float(p[j]), float(m), k * r[j], G)
        e = eta[:, j]
        # row 7: r (-Phi)' = G70 U_r + G71 U_th + G72 U_z + G73 r Delta_r
        e[3] = (-r[j] * der["Phi"][j] - G[7, :3] @ e[:3]) / G[7, 3]
        # rows 1, 2: r U' = G[i, :4] U + G[i, 5 or 6] r Sigma + G[i, 7] (-Phi)
        e[5] = (r[j] * der["U_th"][j] - G[1, :4] @ e[:4] - G[1, 7] * e[7]) / G[1, 5]
        e[6] = (r[j] * der["U_z"][j] - G[2, :4] @ e[:4] - G[2, 7] * e[7]) / G[2, 6]
    a = {name: mod[..., MODULI_INDEX[name]] for name in ("A1111", "A1122", "A1133", "G111")}
    eta[4] = r * (
        (a["A1111"] + p) * der["U_r"]
        + a["A1122"] * (eta[0] + m * eta[1]) / r
        + a["A1133"] * k * eta[2]
        + a["G111"] * eta[3] / r
        - val["P"]
    )
    return eta
