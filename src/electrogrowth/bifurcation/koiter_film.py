"""The amplitude equation of a flat film on a half-space (both incompressible neo-Hookean,
plane strain): its critical mode and the exact cubic expansion on Chebyshev collocation
(docs/derivation-koiter.md). koiter.py is the door (``koiter_coefficient``).

Near the critical stretch lambda_c the bifurcated branch of the mode with the critical
reference wavenumber K_c is

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
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.plane_forms import Forms, Segment, Space

#: The unknowns of the mode (harmonic 1) and of the second-order correction (0 and 2).
MODE = ((0, 1), (1, 1), (2, 1))
SECOND = ((0, 2), (1, 0), (1, 2), (2, 0), (2, 2))
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
    wavenumbers : (float, float)
        The window of reference wavenumbers K (per film thickness) searched for the
        critical one: a film 1e4 times as stiff folds at K ~ 0.067, below the default
        window, and needs a substrate deep enough for its decay (``depth`` ~ 400).
    """

    modulus_ratio: float
    substrate: str = "compressed"
    nodes: int = 16
    substrate_nodes: int = 24
    depth: float = 40.0
    wavenumbers: tuple[float, float] = (0.1, 10.0)

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

    Raises NoBifurcationFound when the maximum is not at a finite K in the film's window
    (default [0.1, 10]: a film softer than the substrate folds at the shortest or longest
    waves)."""
    forms = Forms.build(Space(film.segments(), MODE))
    c = _critical_mode(forms, film.wavenumbers)
    return c.K, c.lam


def _critical_mode(forms: Forms, window=(0.1, 10.0)) -> _Critical:
    """A scan of K on a geometric grid for the sign change of d lambda_c / dK (from rising
    to falling), then Brent's method on that slope, each solve started from the last."""
    state: dict = {}

    def slope(k: float) -> float:
        state["c"] = critical_stretch(forms, k, state["c"])
        return state["c"].slope(forms)

    Ks = np.geomspace(*window, 15)
    where = f"K in [{window[0]:g}, {window[1]:g}] per film thickness"
    prev = critical_stretch(forms, Ks[0])
    if prev.slope(forms) <= 0:
        raise NoBifurcationFound(
            f"the critical stretch has no maximum for {where}: it "
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
        f"the critical stretch has no maximum at a finite wavenumber ({where}): a film "
        "this soft folds at the shortest or longest waves"
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


def expansion(
    segments: tuple[Segment, ...], *, forms: type[Forms] = Forms, window=(0.1, 10.0)
) -> Expansion:
    """The Koiter expansion of the critical wrinkle of a stack of segments (the film is
    the top one): phi from A(lambda_c) phi = 0, psi from A(lambda_c) psi = -C[phi, phi, .] / 2
    on harmonics 0 and 2, lambda_2 = 2 A(lambda_c)[psi, psi] / A'(lambda_c)[phi, phi].
    ``forms`` builds the quadratic and cubic forms (another parametrisation of the energy,
    for checks)."""
    first = forms.build(Space(segments, MODE))
    crit = _critical_mode(first, window)
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
    e = expansion(film.segments(), window=film.wavenumbers)
    return e.lambda_2, e.lam, e.K


def sign_change_ratio(lo: float = 1.5, hi: float = 2.0, *, xtol: float = 1e-7, **film) -> float:
    """The modulus ratio mu_f / mu_s in (lo, hi) at which lambda_2 changes sign (the
    super/subcritical boundary), by Brent's method on the coefficient."""
    f = lambda r: _coefficient(FilmOnHalfSpace(r, **film))[0]  # noqa: E731
    return float(scipy.optimize.brentq(f, lo, hi, xtol=xtol))
