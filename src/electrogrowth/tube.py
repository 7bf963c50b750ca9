"""Axisymmetric base state of a grown, axially stretched, radially charged tube (paper Sec. 3.1).

Units mu = eps = R_i = 1. The reference tube 1 <= R <= Rbar_o grows isotropically (F_g = g I)
and deforms (det F_e = 1) into r_i <= r <= r_o at total axial stretch lambda_z (eqs. 14-15):

    r(R)^2 = r_i^2 + b (R^2 - 1),   b = g^3 / lambda_z,   dr/dR = b R / r,

with elastic stretches l2 = r / (g R), l3 = lambda_z / g, l1 = 1 / (l2 l3). Maxwell's equation
gives D_r = c / r and the voltage is V = Vbar (Rbar_o - 1) = int_{r_i}^{r_o} E_r dr. Radial
equilibrium d sigma_rr / dr = (sigma_tt - sigma_rr) / r = (tau_2 - tau_1) / r with both faces
traction-free (eq. 25) fixes c for each lambda_i = r_i:

    int_{r_i}^{r_o} (tau_2 - tau_1) dr / r = 0.                                          (*)

For an ideal dielectric tau_1 = tau_1^mech + D_r^2 and E_r = D_r, so (*) is linear in c^2:
c^2 = 2 M r_i^2 r_o^2 / (r_o^2 - r_i^2), M the purely mechanical integral, V = c ln(r_o/r_i).
Other energies solve (*) for c^2 by a bracketed secant (Illinois) iteration. Integrals are
Gauss-Legendre in R on [1, Rbar_o] (analytic integrands); the profile sigma_rr(R) is a Chebyshev
antiderivative, exact to quadrature accuracy at any R. Derivation, neo-Hookean closed forms and
the paper's typos: docs/derivation-base-state.md.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np
import sympy as sp
from numpy.polynomial import chebyshev as cheb
from scipy.optimize import brentq

from .errors import BaseStateError, ConvergenceError, ParameterError
from .materials import I1, I5, INVARIANTS, Material
from .params import TubeParameters

_ORDERS = (16, 24, 32, 48, 64, 96, 128, 192, 256, 384)  # Gauss-Legendre node counts tried
_SCAN_RATIO, _SCAN_SPAN = 1.08, 1e3  # threshold scan: lambda_i0 1.08^k up to 1e3 lambda_i0
_QUIET = dict(invalid="ignore", divide="ignore", over="ignore")


@functools.lru_cache(maxsize=None)
def _gauss(n: int):
    return np.polynomial.legendre.leggauss(n)


@functools.lru_cache(maxsize=64)
def _kind(material: Material) -> str:
    """'neo-hookean', 'ideal' (W(I1, I2) + I5/2) or 'general', decided once per energy."""
    if sp.expand(material.energy - (I1 - 3) / 2 - I5 / 2) == 0:
        return "neo-hookean"
    return "ideal" if material.is_ideal_dielectric() else "general"


@functools.lru_cache(maxsize=64)
def _energy(material: Material):
    """Numeric Omega(I1, ..., I6), or None for a polynomial energy (finite everywhere)."""
    if material.energy.is_polynomial(*INVARIANTS):
        return None
    return sp.lambdify(INVARIANTS, material.energy, "numpy")


@dataclasses.dataclass(frozen=True)
class _Tube:
    """Geometry and quadrature of one (material, Rbar_o, g, lambda_z); vectorised in lambda_i."""

    material: Material
    outer_radius: float
    growth: float
    stretch: float
    nodes: int = 32

    @property
    def b(self) -> float:
        return self.growth**3 / self.stretch

    def kinematics(self, lam_i, R):
        """r, elastic stretches (l1, l2, l3) and dr/dR at R (lam_i and R broadcast)."""
        r = np.sqrt(lam_i**2 + self.b * (R**2 - 1.0))
        l2 = r / (self.growth * R)
        l3 = np.full_like(l2, self.stretch / self.growth)
        return r, (1.0 / (l2 * l3), l2, l3), self.b * R / r

    def _quadrature(self, lam_i, q):
        """Nodes: r, stretches, D_r = sqrt(q) / r and weights of dr, shape lam_i.shape + (n,)."""
        x, w = _gauss(self.nodes)
        h = 0.5 * (self.outer_radius - 1.0)
        r, stretches, drdR = self.kinematics(np.asarray(lam_i, float)[..., None], 1.0 + h * (x + 1))
        return r, stretches, np.sqrt(np.asarray(q, float))[..., None] / r, h * w * drdR

    def hoop(self, lam_i, q):
        """(int (tau_2 - tau_1) dr / r, int (|tau_1| + |tau_2|) dr / r) at D_r = sqrt(q) / r."""
        r, stretches, d, wdr = self._quadrature(lam_i, q)
        tau1, tau2, _ = self.material.stress(*stretches, d)
        return ((tau2 - tau1) * wdr / r).sum(-1), ((abs(tau2) + abs(tau1)) * wdr / r).sum(-1)

    def in_domain(self, lam_i) -> np.ndarray:
        """The energy is finite on both faces and at every node at D = 0 (False beyond a locking
        stretch, e.g. Gent's)."""
        if (energy := _energy(self.material)) is None:
            return np.ones(np.shape(lam_i), bool)
        R = np.concatenate([[1.0], 0.5 * (self.outer_radius - 1.0) * (_gauss(self.nodes)[0] + 1)
                            + 1.0, [self.outer_radius]])  # faces and nodes
        _, (l1, l2, l3), _ = self.kinematics(np.asarray(lam_i, float)[..., None], R)
        with np.errstate(**_QUIET):
            w = energy(l1**2 + l2**2 + l3**2, (l1 * l2)**2 + (l2 * l3)**2 + (l3 * l1)**2, 0, 0, 0)
        return np.all(np.isfinite(np.broadcast_to(w, l1.shape)), axis=-1)

    def charge_and_voltage(self, lam_i, *, rtol: float = 1e-13):
        """Charge c and Vbar solving (*) at each lambda_i (1-d arrays). Below lambda_i0 an ideal
        dielectric gives negative values (signed square root, monotone for root finding), a
        general energy NaN; outside the energy's domain NaN."""
        lam_i = np.atleast_1d(np.asarray(lam_i, float))
        c, v = np.full_like(lam_i, np.nan), np.full_like(lam_i, np.nan)
        ok = self.in_domain(lam_i)
        lam = lam_i[ok]
        delta = self.b * (self.outer_radius**2 - 1.0)  # r_o^2 - r_i^2, exact
        with np.errstate(**_QUIET):
            m0, scale = self.hoop(lam, 0.0)
            m0 = np.where(abs(m0) <= 1e-13 * scale, 0.0, m0)
            q = 2.0 * m0 * lam**2 * (lam**2 + delta) / delta
            if _kind(self.material) != "general":
                c[ok] = np.sign(q) * np.sqrt(abs(q))
                v[ok] = c[ok] * 0.5 * np.log1p(delta / lam**2)
            else:
                up = m0 >= 0  # else below lambda_i0: NaN
                ok[ok] = up
                c[ok] = np.sqrt(self._solve_q(lam[up], m0[up], q[up], rtol))
                r, stretches, d, wdr = self._quadrature(lam[up], c[ok] ** 2)
                v[ok] = (self.material.electric_field(*stretches, d) * wdr).sum(-1)
        return c, v / (self.outer_radius - 1.0)

    def voltage(self, lam_i) -> np.ndarray:
        return self.charge_and_voltage(lam_i)[1]

    def _solve_q(self, lam_i, f_lo, q_hi, rtol):
        """Illinois (modified regula falsi) for hoop(lam_i, q) = 0 in q = c^2, given f(0) >= 0."""
        q_lo, q_hi = np.zeros_like(q_hi), np.maximum(q_hi, 1e-300)
        f_hi = self.hoop(lam_i, q_hi)[0]
        for _ in range(200):  # expand until f(q_hi) <= 0
            up = f_hi > 0
            if not up.any():
                break
            q_lo, f_lo = np.where(up, q_hi, q_lo), np.where(up, f_hi, f_lo)
            q_hi = np.where(up, 2.0 * q_hi, q_hi)
            f_hi = self.hoop(lam_i, q_hi)[0]
        side = np.zeros(q_hi.shape, int)
        for _ in range(100):
            q = np.where(f_hi == f_lo, q_hi, (q_lo * f_hi - q_hi * f_lo) / (f_hi - f_lo))
            f, scale = self.hoop(lam_i, q)
            done = (abs(f) <= 1e-14 * scale) | (abs(q_hi - q_lo) <= 1e-2 * rtol * abs(q))
            if np.all(done | ~np.isfinite(q)):
                return np.where(f_lo == 0, q_lo, q)
            hi = f < 0  # replace the endpoint of f's sign; halve the kept one's f (Illinois)
            f_lo = np.where(hi & (side == 1), f_lo / 2, f_lo)
            f_hi = np.where(~hi & (side == -1), f_hi / 2, f_hi)
            q_hi, f_hi = np.where(hi, q, q_hi), np.where(hi, f, f_hi)
            q_lo, f_lo = np.where(hi, q_lo, q), np.where(hi, f_lo, f)
            side = np.where(hi, 1, -1)
        raise ConvergenceError(f"charge c not converged at lambda_i = {lam_i[~done][0]!r}")


@dataclasses.dataclass(frozen=True)
class _Threshold:
    lambda_i0: float  # purely mechanical state, Vbar = 0
    value: float  # Vbar threshold (inf if none)
    kind: str  # "asymptote", "limit point" or "none"
    lambda_i: float  # lambda_i at the threshold (inf: asymptote; locking stretch: "none")
    error: float  # estimated absolute error of value
    nodes: int  # Gauss-Legendre nodes meeting rtol
    grid: np.ndarray  # lambda_i on the monotone branch, from lambda_i0 ...
    values: np.ndarray  # ... and Vbar there (increasing, starts at 0)


@functools.lru_cache(maxsize=4096)
def _mechanical(material, outer_radius, growth, stretch, rtol) -> tuple[float, int]:
    """lambda_i0, solving (*) at c = 0, and the fewest Gauss-Legendre nodes meeting rtol."""
    tube = _Tube(material, outer_radius, growth, stretch, _ORDERS[0])
    lam0 = _lambda_i0(tube)
    nodes = _nodes(tube, lam0 * np.array([1.0, 1.5, 3.0]), rtol)
    if nodes != tube.nodes:
        lam0 = _lambda_i0(dataclasses.replace(tube, nodes=nodes))
    return lam0, nodes


def _lambda_i0(tube: _Tube) -> float:
    """Root of M(lambda_i), bracketed on a grid around the homogeneous lambda^2 lz = g^3."""
    guess = tube.growth**1.5 / math.sqrt(tube.stretch)
    for span in (2.0, 8.0, 64.0):
        lam = guess * span ** np.linspace(-1.0, 1.0, 33)
        f = np.full_like(lam, np.nan)
        ok = tube.in_domain(lam)
        f[ok] = tube.hoop(lam[ok], 0.0)[0]
        k = np.flatnonzero((f[:-1] < 0) & (f[1:] >= 0))
        if k.size:
            return _cell_root(lambda x: tube.hoop(x, 0.0)[0], lam[k[0]], lam[k[0] + 1])
    raise BaseStateError(f"no traction-free state at Vbar = 0 for g = {tube.growth:g},"
                         f" lambda_z = {tube.stretch:g}, Rbar_o = {tube.outer_radius:g}")


def _nodes(tube: _Tube, lam: np.ndarray, rtol: float) -> int:
    """Fewest nodes whose M at lam agrees with the next rule to 1e-2 rtol of the stress scale."""
    lam = lam[tube.in_domain(lam)]
    for n, n2 in zip(_ORDERS, _ORDERS[1:]):
        (a, s), (b, _) = (dataclasses.replace(tube, nodes=k).hoop(lam, 0.0) for k in (n, n2))
        if np.all(abs(a - b) <= 0.01 * rtol * s):
            return n
    raise ConvergenceError(f"quadrature not converged to rtol = {rtol} with {n2} nodes")


def _cell_root(f, a: float, b: float) -> float:
    """Root of an analytic vectorised f changing sign on [a, b]: root of its degree-12 Chebyshev
    interpolant, polished by one Newton step with the interpolant's slope (relative accuracy
    ~1e-15); brentq (xtol 1e-15 a, rtol 1e-14) when the interpolant is not resolved."""
    with np.errstate(**_QUIET):
        poly = cheb.Chebyshev.interpolate(f, 12, domain=[a, b])
    tol = 1e-12 * (b - a)
    roots = [x.real for x in poly.roots() if abs(x.imag) < tol and a - tol <= x.real <= b + tol]
    size = abs(poly.coef).max()
    if len(roots) == 1 and np.isfinite(size) and abs(poly.coef[-2:]).max() <= 1e-14 * size:
        x = roots[0] - float(f(np.array([roots[0]]))[0]) / poly.deriv()(roots[0])
        if a - tol <= x <= b + tol:
            return float(x)
    return brentq(lambda x: float(f(np.array([x]))[0]), a, b, xtol=1e-15 * a, rtol=1e-14)


@functools.lru_cache(maxsize=4096)
def _threshold(material, outer_radius, growth, stretch, rtol) -> _Threshold:
    """Scan Vbar(lambda_i) geometrically from lambda_i0 for the first local maximum; without one,
    Vbar -> inf at a locking stretch ("none"), or the asymptote (neo-Hookean closed form, else
    Richardson extrapolation in x = lambda_i^-2, whose order is measured)."""
    lam0, nodes = _mechanical(material, outer_radius, growth, stretch, rtol)
    tube = _Tube(material, outer_radius, growth, stretch, nodes)
    lam = lam0 * _SCAN_RATIO ** np.arange(0, math.ceil(math.log(_SCAN_SPAN, _SCAN_RATIO)) + 1)
    v = np.concatenate([[0.0], tube.voltage(lam[1:])])
    bad = np.flatnonzero(~np.isfinite(v))
    end = bad[0] if bad.size else v.size
    rises = np.diff(v[:end]) > 0
    peak = np.flatnonzero(rises[:-1] & ~rises[1:])
    if peak.size:
        return _limit_point(tube, lam0, lam[: peak[0] + 3], v[: peak[0] + 3])
    if not rises.all():
        raise ConvergenceError(f"Vbar(lambda_i) does not rise from lambda_i0 = {lam0:.12g}")
    out = dict(lambda_i0=lam0, error=0.0, nodes=nodes, grid=lam[:end], values=v[:end])
    if end < v.size:  # the energy ends (e.g. Gent): locate the locking stretch
        a, b = lam[end - 1], lam[end]
        while b - a > 1e-14 * b:  # 64-section of the domain's edge
            x = np.linspace(a, b, 65)
            j = np.argmin(tube.in_domain(x)) - 1
            a, b = x[j], x[j + 1]
        return _Threshold(value=math.inf, kind="none", lambda_i=a, **out)
    if _kind(material) == "neo-hookean":
        value = neo_hookean_asymptote(TubeParameters(outer_radius, 1.0, growth, stretch))
        return _Threshold(value=value, kind="asymptote", lambda_i=math.inf, **out)
    # Richardson: Vbar = V_inf + a x^p + b x^(p+1) + ..., x = lambda_i^-2 (p = 2 for nH, MR)
    t = tube.voltage(100.0 * lam0 * 2.0 ** np.arange(5))  # x shrinks 4x per step
    d = np.diff(t)
    if not (np.all(d > 0) and d[-2] > d[-1]):  # not converging: Vbar unbounded
        return _Threshold(value=math.inf, kind="none", lambda_i=math.inf, **out)
    p = math.log(d[-2] / d[-1], 4.0)  # observed order in x
    p = round(p) if abs(p - round(p)) < 0.05 else p
    for j in range(3):
        prev, t = t[-1], t[1:] + (t[1:] - t[:-1]) / (4.0 ** (p + j) - 1.0)
    out["error"] = abs(t[-1] - prev)
    return _Threshold(value=float(t[-1]), kind="asymptote", lambda_i=math.inf, **out)


def _limit_point(tube: _Tube, lam0: float, lam: np.ndarray, v: np.ndarray) -> _Threshold:
    """Maximise Vbar on [lam[-3], lam[-1]]: root of the derivative of a degree-24 Chebyshev
    interpolant of Vbar^2 (analytic there), then Vbar evaluated exactly at that root."""
    def vsq(x):
        return np.sign(y := tube.voltage(x)) * y**2
    a, b = lam[-3], lam[-1]
    poly = cheb.Chebyshev.interpolate(vsq, 24, domain=[a, b])
    crit = [x.real for x in poly.deriv().roots() if abs(x.imag) < 1e-9 and a <= x.real <= b]
    if not crit:
        raise ConvergenceError(f"limit point of Vbar not located in [{a:.6g}, {b:.6g}]")
    top = max(crit, key=poly)
    value = math.sqrt(float(vsq(top)[0]))
    keep = lam < top
    return _Threshold(lam0, value, "limit point", float(top), abs(poly(top) - value**2) / value,
                      tube.nodes, np.append(lam[keep], top), np.append(v[keep], value))


def neo_hookean_asymptote(params: TubeParameters) -> float:
    """Neo-Hookean lim_{lambda_i -> inf} Vbar (material ignored), derived in the docs:

    Vbar_inf = g^2 / (lambda_z (Rbar_o - 1)) sqrt((Rbar_o^2 - 1) ln(Rbar_o) / 2).

    >>> round(neo_hookean_asymptote(TubeParameters(outer_radius=2.0)), 6)
    1.019667
    """
    Ro = params.outer_radius
    return params.growth**2 / (params.stretch * (Ro - 1.0)) * math.sqrt(
        (Ro**2 - 1.0) * math.log(Ro) / 2.0)


def _info(params: TubeParameters, rtol: float = 1e-12) -> _Threshold:
    return _threshold(params.material, params.outer_radius, params.growth, params.stretch, rtol)


def voltage_threshold(params: TubeParameters) -> tuple[float, str, float]:
    """Largest Vbar on the branch of Vbar(lambda_i) continuous from Vbar = 0.

    Returns
    -------
    (Vbar_threshold, kind, lambda_i) : tuple[float, str, float]
        kind "asymptote": Vbar -> Vbar_threshold as lambda_i -> inf (lambda_i = inf);
        "limit point": first local maximum of Vbar(lambda_i), a snap-through; "none": Vbar
        rises without bound (Vbar_threshold = inf), lambda_i = the locking stretch of the
        energy (e.g. Gent) or inf. ``params.voltage`` is ignored.

    >>> round(voltage_threshold(TubeParameters(outer_radius=2.0, growth=1.1))[0], 6)
    1.233797
    """
    info = _info(params)
    return float(info.value), info.kind, float(info.lambda_i)


def voltage_curve(params: TubeParameters, lambda_i) -> np.ndarray:
    """Vbar(lambda_i) of the traction-free tube (paper eq. dimensionless-voltage), vectorised.

    ``params.voltage`` is ignored. Raises BaseStateError for lambda_i below the mechanical
    lambda_i0 (no real voltage) or where the energy is undefined (beyond a locking stretch).
    """
    lam = np.asarray(lambda_i, float)
    if not np.all(np.isfinite(lam) & (lam > 0)):
        raise ParameterError(f"lambda_i = {lam[~(np.isfinite(lam) & (lam > 0))].flat[0]!r}"
                             " is invalid; need 0 < lambda_i < inf")
    info = _info(params)
    low = lam < info.lambda_i0 * (1.0 - 1e-12)
    if low.any():
        raise BaseStateError(f"lambda_i = {lam[low].flat[0]:.12g} is below the Vbar = 0 value"
                             f" {info.lambda_i0:.12g}; no real voltage there")
    tube = _Tube(params.material, params.outer_radius, params.growth, params.stretch, info.nodes)
    v = tube.voltage(lam.ravel())
    if not np.all(np.isfinite(v)):
        raise BaseStateError(f"energy of {params.material.name} undefined at lambda_i ="
                             f" {lam.ravel()[~np.isfinite(v)][0]:.12g} (beyond locking)")
    return np.maximum(v, 0.0).reshape(lam.shape)


def solve_base_state(params: TubeParameters, *, rtol: float = 1e-12) -> "BaseState":
    """Solve the base state (paper Sec. 3.1) at the requested Vbar = ``params.voltage``.

    lambda_i solves Vbar(lambda_i) = Vbar (brentq) on the monotone branch from lambda_i0
    (Vbar = 0) to the threshold of :func:`voltage_threshold`.

    Parameters
    ----------
    params : TubeParameters
        Rbar_o, g, lambda_z, Vbar and the energy.
    rtol : float, keyword-only
        Relative accuracy of quadratures and root finding (default 1e-12).

    Raises
    ------
    BaseStateError
        If Vbar >= the threshold for these parameters.

    >>> state = solve_base_state(TubeParameters(outer_radius=2.0, voltage=0.5))
    >>> round(state.lambda_i, 6), state.threshold_kind
    (1.151387, 'asymptote')
    """
    info = _info(params, rtol)
    target = params.voltage
    if not target < info.value:
        raise BaseStateError(
            f"Vbar = {target:.12g} is at or above the threshold Vbar = {info.value:.12g}"
            f" ({info.kind}) for g = {params.growth:g}, lambda_z = {params.stretch:g},"
            f" Rbar_o = {params.outer_radius:g}, {params.material.name}; no axisymmetric state")
    tube = _Tube(params.material, params.outer_radius, params.growth, params.stretch, info.nodes)
    if target == 0:
        return BaseState._build(params, tube, info.lambda_i0, info, rtol)
    grid, v = info.grid, info.values
    if target > v[-1]:  # beyond the scan: towards an asymptote or a locking stretch
        far = info.lambda_i
        tail = (grid[-1] * 4.0 ** np.arange(1, 21) if math.isinf(far)
                else far - (far - grid[-1]) * 4.0 ** -np.arange(1, 21))
        grid, v = np.append(grid[-1], tail), np.append(v[-1], tube.voltage(tail))
    k = np.flatnonzero(v >= target)
    if not k.size:
        raise BaseStateError(f"Vbar = {target:.12g} is within rounding of the threshold"
                             f" {info.value:.12g}; no base state resolved")
    a, b = grid[k[0] - 1], grid[k[0]]
    for n in _ORDERS[_ORDERS.index(tube.nodes):]:
        tube = dataclasses.replace(tube, nodes=n)
        lam = _cell_root(lambda x: np.sign(v := tube.voltage(x)) * v**2 - target**2, a, b)
        state = BaseState._build(params, tube, lam, info, rtol)
        if state.quadrature_error <= max(rtol, 1e-14):
            return state
    raise ConvergenceError(f"base state at Vbar = {target:.12g} not resolved to rtol = {rtol}")


@dataclasses.dataclass(frozen=True)
class BaseState:
    """The solved base state; methods take the reference radius R in [1, Rbar_o] (vectorised).

    Attributes: lambda_i = r_i, lambda_o = r_o / Rbar_o, r_i, r_o, charge c (D_r = c / r), the
    Vbar threshold and its kind, the axial force N = 2 pi int sigma_zz r dr holding lambda_z,
    and quadrature_error, the residuals (outer traction over the stress scale, voltage) of an
    independent Chebyshev quadrature of the solved state.
    """

    params: TubeParameters
    lambda_i: float
    lambda_o: float
    r_i: float
    r_o: float
    charge: float
    voltage_threshold: float
    threshold_kind: str
    axial_force: float
    quadrature_error: float = 0.0
    _tube: _Tube = dataclasses.field(default=None, repr=False, compare=False)
    _sigma: cheb.Chebyshev = dataclasses.field(default=None, repr=False, compare=False)

    @classmethod
    def _build(cls, params, tube, lam, info, rtol) -> "BaseState":
        """Chebyshev interpolants (degree doubled until the tail < rtol) of the integrands of
        sigma_rr = int_1^R (tau_2 - tau_1) dr/r, of N = pi int (2 tau_3 - tau_1 - tau_2) r dr
        (sigma_rr vanishes on both faces, so int sigma_rr r dr = -int (tau_2 - tau_1) r dr / 2)
        and of V = int E_r dr: a second quadrature, independent of the Gauss one that fixed
        lambda_i and c, whose residuals sigma_rr(Rbar_o) and V - Vbar (Rbar_o - 1) give
        quadrature_error."""
        c = float(tube.charge_and_voltage(lam)[0][0]) if params.voltage > 0 else 0.0
        Ro, mat = params.outer_radius, params.material

        def integrands(x):
            r, stretches, drdR = tube.kinematics(lam, 1.0 + 0.5 * (Ro - 1.0) * (x + 1.0))
            tau = mat.stress(*stretches, c / r)
            e = mat.electric_field(*stretches, c / r) if _kind(mat) == "general" else c / r
            return np.stack([(tau[1] - tau[0]) * drdR / r, (tau[1] + tau[0]) * drdR / r,
                             (2 * tau[2] - tau[0] - tau[1]) * r * drdR, e * drdR], axis=-1)

        for deg in (32, 64, 128, 256, 512):
            coef = cheb.chebinterpolate(integrands, deg)
            if np.all(abs(coef[-4:]).max(0) <= 0.01 * rtol * np.maximum(abs(coef).max(0), 1.0)):
                break
        else:
            raise ConvergenceError(f"base-state profile not resolved to rtol = {rtol}")
        sigma, scale, force, volt = (cheb.Chebyshev(k, domain=[1.0, Ro]).integ(lbnd=1.0)
                                     for k in coef.T)
        r_o = math.sqrt(lam**2 + tube.b * (Ro**2 - 1.0))
        error = max(abs(sigma(Ro)) / max(1.0, abs(scale(Ro))),
                    abs(volt(Ro) / (Ro - 1.0) - params.voltage) / max(1.0, params.voltage))
        return cls(params, float(lam), r_o / Ro, float(lam), r_o, c, info.value, info.kind,
                   float(math.pi * force(Ro)), float(error), tube, sigma)

    def _local(self, R):
        R = np.asarray(R, float)
        if np.any((R < 1.0 - 1e-12) | (R > self.params.outer_radius * (1.0 + 1e-12))):
            raise ParameterError(f"R outside the wall [1, {self.params.outer_radius:g}]")
        r, stretches, _ = self._tube.kinematics(self.lambda_i, R)
        return R, r, stretches, self.charge / r

    def radius(self, R) -> np.ndarray:
        """r(R) = sqrt(r_i^2 + g^3 (R^2 - 1) / lambda_z)."""
        return self._local(R)[1]

    def elastic_stretches(self, R) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(l1, l2, l3) = (g^2 R / (r lambda_z), r / (g R), lambda_z / g)."""
        return self._local(R)[2]

    def displacement(self, R) -> np.ndarray:
        """Radial current electric displacement D_r = c / r."""
        return self._local(R)[3]

    def electric_field(self, R) -> np.ndarray:
        """Radial current electric field E_r = dOmega/dD~ / l1 (= D_r for ideal dielectrics)."""
        _, _, stretches, d = self._local(R)
        return self.params.material.electric_field(*stretches, d)

    def sigma_rr(self, R) -> np.ndarray:
        """Radial Cauchy stress sigma_rr(R) = int_{r_i}^{r(R)} (tau_2 - tau_1) dr / r."""
        return self._sigma(self._local(R)[0])

    def stresses(self, R) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(sigma_rr, sigma_tt, sigma_zz), sigma_ii = tau_i - p with p = tau_1 - sigma_rr."""
        R, _, stretches, d = self._local(R)
        tau = self.params.material.stress(*stretches, d)
        srr = self._sigma(R)
        return srr, tau[1] - tau[0] + srr, tau[2] - tau[0] + srr

    def pressure(self, R) -> np.ndarray:
        """Lagrange multiplier p = tau_1 - sigma_rr."""
        R, _, stretches, d = self._local(R)
        return self.params.material.stress(*stretches, d)[0] - self._sigma(R)

    def moduli(self, R) -> np.ndarray:
        """Updated moduli (materials.MODULI_NAMES order), shape R.shape + (23,)."""
        _, _, stretches, d = self._local(R)
        return self.params.material.moduli(*stretches, d)

    def profiles(self, n: int = 101) -> dict[str, np.ndarray]:
        """Through-wall profiles at n equally spaced R in [1, Rbar_o]: keys R, r, lambda
        (= r / R), sigma_rr, sigma_tt, sigma_zz, p, D_r, E_r."""
        R = np.linspace(1.0, self.params.outer_radius, n)
        r = self.radius(R)
        srr, stt, szz = self.stresses(R)
        return {"R": R, "r": r, "lambda": r / R, "sigma_rr": srr, "sigma_tt": stt,
                "sigma_zz": szz, "p": self.pressure(R), "D_r": self.displacement(R),
                "E_r": self.electric_field(R)}

