"""The amplitude equation at onset: the Koiter coefficient of a wrinkle and whether its
branch is super- or subcritical (docs/derivation-koiter.md).

Covered so far: the flat film on a half-space (both incompressible neo-Hookean, plane
strain, uniaxial compression of the film alone or of the whole bilayer), the limit of a
thin stiff film on a thick tube; and a tube's prismatic modes (m, 0) (neo-Hookean layers,
constant growth, axial stretch prescribed, no voltage or pressure) in a growth control,
c = c_c + c_2 eps^2 with eps = max |u_r| / R_i, supercritical when c_2 > 0. Other cases
raise a one-line :class:`~electrogrowth.errors.ParameterError`.

For the flat film, near the critical stretch lambda_c the bifurcated branch of the mode
with the critical reference wavenumber K_c is

    lambda = lambda_c + lambda_2 eps^2 + O(eps^4),   eps = K_c w,

w the amplitude of the vertical displacement of the free face (its peak), K_c w the
amplitude per reference wavelength / 2 pi: the cubic term lambda_1 eps vanishes by the
wrinkle's symmetry. Compression grows as lambda falls, so the branch is
``supercritical`` (stable, grows gradually with the compression) when lambda_2 < 0 and
``subcritical`` (it bends back: a jump to large amplitude at onset) when lambda_2 > 0.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import scipy.linalg
import scipy.optimize

from .._types import FloatArray
from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.plane_forms import Forms, Segment, Space
from ..incremental.polar_forms import PolarForms, rings
from ..model.layers import Tube
from .critical import critical_value
from .verdict import Verdict

#: The unknowns of the mode (harmonic 1) and of the second-order correction (0 and 2).
MODE = ((0, 1), (1, 1), (2, 1))
SECOND = ((0, 2), (1, 0), (1, 2), (2, 0), (2, 2))
#: In a tube the even field is u_r (cos), the odd one u_theta (sin).
POLAR_SECOND = ((0, 0), (0, 2), (1, 2), (2, 0), (2, 2))

SUBSTRATES = ("compressed", "unstressed")


@dataclasses.dataclass(frozen=True)
class FilmOnHalfSpace:
    """A film of reference thickness 1 (lengths in film thicknesses) bonded to a half-space.

    Parameters
    ----------
    modulus_ratio : float
        mu_f / mu_s > 0.
    substrate : str
        "compressed" (default): the whole bilayer is compressed to the stretch lambda
        (Cao & Hutchinson 2012); "unstressed": only the film is (a film grown on a substrate,
        the flat limit of docs/derivation-film.md).
    nodes : int
        Chebyshev-Lobatto points of the film; the substrate, truncated at ``depth`` film
        thicknesses and clamped there, has three segments of ``substrate_nodes`` points,
        graded to resolve the decay near the interface.
    """

    modulus_ratio: float
    substrate: str = "compressed"
    nodes: int = 16
    substrate_nodes: int = 24
    depth: float = 40.0

    def __post_init__(self):
        r = self.modulus_ratio
        if not (isinstance(r, (int, float)) and math.isfinite(r) and r > 0):
            raise ParameterError(f"modulus_ratio = {r!r} must be a number > 0")
        if self.substrate not in SUBSTRATES:
            raise ParameterError(f"substrate = {self.substrate!r}: one of {', '.join(SUBSTRATES)}")
        if not self.depth >= 10:
            raise ParameterError(f"depth = {self.depth} must be >= 10 film thicknesses")

    def segments(self) -> tuple[Segment, ...]:
        """Bottom to top: the substrate in [-depth, -depth / 5, -2, 0] (depth 40: -8), the
        film [0, 1]."""
        follows = self.substrate == "compressed"
        edges = (-self.depth, -self.depth / 5, -2.0, 0.0)
        n = self.substrate_nodes
        sub = tuple(Segment(a, b, 1.0, follows, n) for a, b in zip(edges, edges[1:]))
        return (*sub, Segment(0.0, 1.0, float(self.modulus_ratio), True, self.nodes))

    def refined(self, factor: float) -> FilmOnHalfSpace:
        """The same film with the node counts scaled by ``factor``."""
        return dataclasses.replace(
            self,
            nodes=round(self.nodes * factor),
            substrate_nodes=round(self.substrate_nodes * factor),
        )


@dataclasses.dataclass(frozen=True)
class KoiterResult:
    """The amplitude equation c = c_c + coefficient * eps^2 of one mode, c the control.

    Flat film: c = lambda, the compressive stretch; eps = K_c w (w the amplitude of the
    vertical displacement of the free face, K_c the reference wavenumber, both in film
    thicknesses); ``wavenumber`` K_c. Tube: c the growth control; eps = max_R |u_r| / R_i
    of the mode (R_i = 1, the undeformed inner radius); ``wavenumber`` m.
    ``branch`` is "supercritical" when the branch exists beyond onset, in the direction
    the control moves to reach it (lambda_2 < 0 for the compressive stretch, > 0 for
    growth), else "subcritical"; ``error_estimate`` the change of the coefficient from a
    resolution 3/4 as fine (spectral convergence: it bounds the error of the finer)."""

    coefficient: float
    critical_value: float
    wavenumber: float
    branch: str
    error_estimate: float
    normalisation: str = "eps = K_c w, w the amplitude of the free face's deflection"

    def as_dict(self) -> dict:
        return dataclasses.asdict(self)


# ---- the linear problem ---------------------------------------------------------------


def _nearest_zero(A: FloatArray, start: FloatArray | None = None) -> tuple[float, FloatArray]:
    """The eigenvalue of the symmetric A nearest zero and its unit eigenvector: inverse
    iteration from ``start`` (a neighbouring solve's mode) when it converges in a few
    steps, else the full spectrum."""
    if start is not None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)
            lu = scipy.linalg.lu_factor(A, check_finite=False)
        v = start / np.linalg.norm(start)
        for _ in range(6 if lu is not None else 0):
            x = scipy.linalg.lu_solve(lu, v, check_finite=False)
            if not np.all(np.isfinite(x)):  # exactly singular: the full spectrum below
                break
            x /= np.linalg.norm(x)
            sigma = float(x @ A @ x)
            if np.linalg.norm(A @ x - sigma * x) <= 1e-10 * np.abs(A).max():
                return sigma, x
            v = x
    w, V = np.linalg.eigh(A)
    i = int(np.argmin(np.abs(w)))
    return float(w[i]), V[:, i]


def _sign(forms: Forms, K: float, lam: float) -> float:
    return float(np.linalg.slogdet(forms.stiffness(K, lam))[0])


def _first_crossing(forms: Forms, K: float) -> tuple[float, float]:
    """A bracket (lo, hi) of the largest lambda < 1 at which det A(K, lambda) changes sign:
    compressive strains 1 - lambda from 1e-4 to 0.7, geometric (a stiff film folds at a
    small strain)."""
    grid = 1.0 - np.geomspace(1e-4, 0.7, 90)
    prev = _sign(forms, K, grid[0])
    for a, b in zip(grid, grid[1:]):
        s = _sign(forms, K, b)
        if s != prev:
            return float(b), float(a)
        prev = s
    raise NoBifurcationFound(f"no bifurcation of wavenumber K = {K:.6g} for stretches in [0.3, 1)")


def _bracket_near(forms: Forms, K: float, lam: float) -> tuple[float, float]:
    """A sign change of det A(K, .) around a neighbour's critical stretch, widened by 3."""
    delta = 1e-4 * (1 - lam) + 1e-7
    while delta < 0.5:
        lo, hi = max(lam - delta, 0.3), min(lam + delta, 1 - 1e-6)
        if _sign(forms, K, lo) != _sign(forms, K, hi):
            return lo, hi
        delta *= 3
    return _first_crossing(forms, K)


@dataclasses.dataclass(frozen=True)
class _Critical:
    """A critical stretch of one wavenumber, its mode and d lambda_c / dK."""

    K: float
    lam: float
    phi: FloatArray

    def slope(self, forms: Forms) -> float:
        """d lambda_c / dK = -phi^T A_K phi / phi^T A_lambda phi (symmetric A)."""
        p = self.phi
        num = p @ forms.stiffness(self.K, self.lam, wrt="K") @ p
        return -num / (p @ forms.stiffness(self.K, self.lam, wrt="lambda") @ p)


def critical_stretch(forms: Forms, K: float, near: _Critical | None = None) -> _Critical:
    """The largest lambda < 1 at which the mode of reference wavenumber K bifurcates: a
    scan of det A for its sign change (or a bracket around the neighbour ``near``), then
    Newton on the eigenvalue of A(K, lambda) nearest zero with its derivative
    phi^T A_lambda phi, safeguarded by bisection of the bracket."""
    if near is None:
        lo, hi = _first_crossing(forms, K)
        phi = None
    else:
        lo, hi = _bracket_near(forms, K, near.lam)
        phi = near.phi
    s_lo = _sign(forms, K, lo)
    lam = 0.5 * (lo + hi)
    for _ in range(60):
        sigma, phi = _nearest_zero(forms.stiffness(K, lam), phi)
        new = lam - sigma / (phi @ forms.stiffness(K, lam, wrt="lambda") @ phi)
        step = abs(new - lam)
        if step < 1e-12 * (1 - lam) or hi - lo < 1e-13:
            return _Critical(K, new, _nearest_zero(forms.stiffness(K, new), phi)[1])
        if not lo < new < hi:
            new = 0.5 * (lo + hi)
        if _sign(forms, K, new) == s_lo:
            lo = new
        else:
            hi = new
        lam = new
    raise ConvergenceError(f"the critical stretch of K = {K:.6g} did not converge")


def critical_mode(film: FilmOnHalfSpace) -> tuple[float, float]:
    """(K_c, lambda_c): the reference wavenumber that maximises the critical stretch (the
    first mode reached as the compression grows) and that stretch, where d lambda_c / dK = 0.

    Raises NoBifurcationFound when the maximum is not at a finite K in [0.1, 10] (a film
    softer than the substrate folds at the shortest or longest waves)."""
    forms = Forms.build(Space(film.segments(), MODE))
    c = _critical_mode(forms)
    return c.K, c.lam


def _critical_mode(forms: Forms) -> _Critical:
    """A scan of K on a geometric grid for the sign change of d lambda_c / dK (from rising
    to falling), then Brent's method on that slope, each solve started from the last."""
    state: dict = {}

    def slope(k: float) -> float:
        state["c"] = critical_stretch(forms, k, state["c"])
        return state["c"].slope(forms)

    Ks = np.geomspace(0.1, 10.0, 15)
    prev = critical_stretch(forms, Ks[0])
    if prev.slope(forms) <= 0:
        raise NoBifurcationFound(
            "the critical stretch has no maximum for K in [0.1, 10] per film thickness: it "
            "rises towards longer waves (a film softer than ~ its substrate, or one stiffer "
            "than ~ 3000 times, whose folds the truncated substrate does not resolve)"
        )
    for K in Ks[1:]:
        cur = critical_stretch(forms, K, prev)
        if prev.slope(forms) > 0 >= cur.slope(forms):
            state["c"] = prev
            Kc = scipy.optimize.brentq(slope, prev.K, K, xtol=1e-12, rtol=1e-12)
            return critical_stretch(forms, Kc, state["c"])
        prev = cur
    raise NoBifurcationFound(
        "the critical stretch has no maximum at a finite wavenumber (K in [0.1, 10] per "
        "film thickness): a film this soft folds at the shortest or longest waves"
    )


# ---- the second order -----------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Expansion:
    """The weakly nonlinear expansion of a stack's critical wrinkle: K_c, lambda_c, the mode
    phi (harmonic 1, scaled to K_c w = 1), the correction psi (harmonics 0 and 2) and
    lambda_2, with the forms they were computed with."""

    K: float
    lam: float
    phi: FloatArray
    psi: FloatArray
    lambda_2: float
    first: Forms
    second: Forms


def expansion(segments: tuple[Segment, ...], *, forms: type[Forms] = Forms) -> Expansion:
    """The Koiter expansion of the critical wrinkle of a stack of segments (the film is
    the top one): phi from A(lambda_c) phi = 0, psi from A(lambda_c) psi = -C[phi, phi, .] / 2
    on harmonics 0 and 2, lambda_2 = 2 A(lambda_c)[psi, psi] / A'(lambda_c)[phi, phi].
    ``forms`` builds the quadratic and cubic forms (another parametrisation of the energy,
    for checks)."""
    first = forms.build(Space(segments, MODE))
    crit = _critical_mode(first)
    Kc, lam = crit.K, crit.lam
    top = first.space._layout[0][1].stop - 1  # b at the free face
    phi = crit.phi / (Kc * crit.phi[top])  # eps = K_c w
    second = forms.build(Space(segments, SECOND))
    f1 = first.fields(phi, Kc)
    A2 = second.stiffness(Kc, lam)
    psi = np.linalg.solve(A2, -0.5 * second.cubic_gradient(f1, f1, Kc))
    curvature = phi @ first.stiffness(Kc, lam, wrt="lambda") @ phi
    lam2 = float(2 * (psi @ A2 @ psi) / curvature)
    return Expansion(Kc, lam, phi, psi, lam2, first, second)


def _coefficient(film: FilmOnHalfSpace) -> tuple[float, float, float]:
    """(lambda_2, lambda_c, K_c) at the film's resolution."""
    e = expansion(film.segments())
    return e.lambda_2, e.lam, e.K


@dataclasses.dataclass(frozen=True)
class TubeExpansion:
    """The expansion of a tube's prismatic mode (m, 0) in a growth control c:
    c = c_c + coefficient eps^2, eps = max_R |u_r| / R_i of the mode (R_i = 1)."""

    control_value: float
    coefficient: float
    impedance_value: float
    inner_face: float  # u_r of the mode at R_i over its peak


def tube_expansion(tube: Tube, m: int, control: str, *, nodes: int = 24) -> TubeExpansion:
    """The Koiter coefficient of the prismatic mode (m, 0) of a neo-Hookean tube at fixed
    axial stretch, in a growth control (docs/derivation-koiter.md): the critical value from
    the package's impedance route, refined where A(c) of incremental/polar_forms.py is
    singular (Newton on its eigenvalue nearest zero, dA/dc by central differences of the
    base state), the mode, the correction at harmonics 0 and 2m, and
    c_2 = 2 A[psi, psi] / A'[phi, phi]."""
    first = PolarForms.build(rings(tube, m, nodes), m, MODE)
    second = PolarForms.build(rings(tube, m, nodes), m, POLAR_SECOND)

    def A(form, c):
        return form.stiffness(solve_base_state(tube.at(control, c)))

    def dA(form, c):  # central differences, Richardson-extrapolated: error O(h^4)
        h = 2e-3 * max(1.0, abs(c))
        d = [(A(form, c + s) - A(form, c - s)) / (2 * s) for s in (h, h / 2)]
        return (4 * d[1] - d[0]) / 3

    start = critical_value(tube, m, 0, control, rtol=1e-12).value
    c, phi = start, None
    for _ in range(20):
        sigma, phi = _nearest_zero(A(first, c), phi)
        step = sigma / (phi @ dA(first, c) @ phi)
        c -= step
        if abs(step) < 1e-12 * max(1.0, abs(c)):
            break
    else:
        raise ConvergenceError(f"the critical {control} of mode ({m}, 0) did not converge")
    sigma, phi = _nearest_zero(A(first, c), phi)
    phi = phi / first.peak_radial(phi, first.slices[0])[1]  # eps = max |u_r| / R_i
    inner_face = float(phi[first.slices[0]][0])
    state = solve_base_state(tube.at(control, c))
    f1 = first.fields(phi)
    A2 = second.stiffness(state)
    psi = np.linalg.solve(A2, -0.5 * second.cubic_gradient(f1, f1, state.stretch))
    c2 = 2 * (psi @ A2 @ psi) / (phi @ dA(first, c) @ phi)
    return TubeExpansion(float(c), float(c2), float(start), inner_face)


def koiter_coefficient(problem, mode=None, control: str = "stretch") -> KoiterResult:
    """The Koiter coefficient of a critical mode (docs/derivation-koiter.md): the control
    on the bifurcated branch is c = c_c + c_2 eps^2 (``KoiterResult`` says which eps),
    from the mode phi, the second-order correction psi (harmonics 0 and 2) of
    A(c_c) psi = -C[phi, phi, .] / 2 and

        c_2 = 2 A(c_c)[psi, psi] / A'(c_c)[phi, phi].

    Parameters
    ----------
    problem : FilmOnHalfSpace or Tube
        A flat film on a half-space, or a tube (neo-Hookean layers with constant growth,
        the axial stretch prescribed, no voltage or pressure: its prismatic modes).
    mode : None or (m, 0)
        The film: None (K_c maximises lambda_c). A tube: the prismatic mode (m, 0), m >= 2.
    control : str
        The film: "stretch", the compressive stretch lambda. A tube: a growth control
        ("growth", "growth[K]", "growth[K].theta", ...).

    Returns
    -------
    KoiterResult

    Raises
    ------
    ParameterError
        For any other problem, mode or control (one line naming what is covered).
    NoBifurcationFound
        When no wrinkle of finite wavelength is critical (mu_f / mu_s too small).

    >>> r = koiter_coefficient(FilmOnHalfSpace(5.0, nodes=12, substrate_nodes=16))
    >>> r.branch
    'supercritical'
    """
    if isinstance(problem, Tube):
        return _tube_result(problem, mode, control)
    if not isinstance(problem, FilmOnHalfSpace):
        raise ParameterError(
            f"the amplitude equation covers a flat film on a half-space (FilmOnHalfSpace) "
            f"and a tube's prismatic modes so far, not {type(problem).__name__}"
        )
    if mode is not None or control != "stretch":
        raise ParameterError(
            f"mode = {mode!r}, control = {control!r}: only the critical wrinkle under the "
            "compressive stretch is covered (mode=None, control='stretch')"
        )
    fine, lam, Kc = _coefficient(problem)
    coarse = _coefficient(problem.refined(0.75))[0]
    return KoiterResult(
        coefficient=fine,
        critical_value=float(lam),
        wavenumber=Kc,
        branch="supercritical" if fine < 0 else "subcritical",
        error_estimate=abs(fine - coarse),
    )


def _tube_result(tube: Tube, mode, control: str) -> KoiterResult:
    """The tube's case of :func:`koiter_coefficient`, with its one-line refusals."""
    if not (isinstance(mode, tuple) and len(mode) == 2 and mode[1] == 0 and mode[0] >= 2):
        raise ParameterError(
            f"mode = {mode!r}: the tube's amplitude equation covers prismatic modes (m, 0), "
            "m >= 2, so far (not the axisymmetric family or wrinkles)"
        )
    if not (isinstance(control, str) and control.startswith("growth")):
        raise ParameterError(f"control = {control!r}: only a growth control is covered so far")
    why = _tube_not_covered(tube)
    if why:
        raise ParameterError(f"the tube's amplitude equation needs {why}")
    m = int(mode[0])
    fine = tube_expansion(tube, m, control, nodes=24)
    coarse = tube_expansion(tube, m, control, nodes=18)
    return KoiterResult(
        coefficient=fine.coefficient,
        critical_value=fine.control_value,
        wavenumber=float(m),
        branch="supercritical" if fine.coefficient > 0 else "subcritical",
        error_estimate=abs(fine.coefficient - coarse.coefficient),
        normalisation="eps = max_R |u_r| / R_i of the mode (R_i = 1)",
    )


def _tube_not_covered(tube: Tube) -> str:
    """What the tube lacks for the expansion, in words ("" when covered)."""
    if tube.stretch is None:
        return "the axial stretch prescribed (not the axial force)"
    if tube.voltage != 0 or tube.inner_pressure != 0 or tube.outer_pressure != 0:
        return "no voltage and no pressure"
    for ply in tube.layers:
        if ply.graded:
            return "constant growth in every layer"
        if ply.material.name != "neo-hookean":
            return f"neo-Hookean layers (not {ply.material.name})"
    return ""


def sign_change_ratio(lo: float = 1.5, hi: float = 2.0, *, xtol: float = 1e-7, **film) -> float:
    """The modulus ratio mu_f / mu_s in (lo, hi) at which lambda_2 changes sign (the
    super/subcritical boundary), by Brent's method on the coefficient."""
    f = lambda r: _coefficient(FilmOnHalfSpace(r, **film))[0]  # noqa: E731
    return float(scipy.optimize.brentq(f, lo, hi, xtol=xtol))


def with_branch(verdict: Verdict, tube: Tube, solve_for: str) -> tuple[Verdict, str | None]:
    """``verdict`` with its slot ``branch``/``koiter`` filled from the amplitude equation of
    its wrinkle, and None; or unchanged with the one-line reason it is not computed (no
    wrinkle, or a case the expansion does not cover yet). The meaning gains what the
    branch means for a user: folds that grow gradually, or a jump at onset."""
    w = verdict.wrinkle
    if w is None or w.m is None or w.n is None:
        return verdict, "no wrinkle was found, so there is no amplitude equation"
    try:
        k = koiter_coefficient(tube, (int(w.m), int(w.n)), solve_for)
    except (ParameterError, NoBifurcationFound, ConvergenceError) as exc:
        return verdict, str(exc)
    words = {
        "supercritical": "supercritical: the folds grow gradually past onset",
        "subcritical": "subcritical: the tube jumps to large folds at onset",
    }
    meaning = f"{verdict.meaning}; the wrinkle is {words[k.branch]}"
    out = dataclasses.replace(verdict, branch=k.branch, koiter=k.coefficient, meaning=meaning)
    return out, None
