"""The voltage curve Vbar(lambda_i) of the traction-free tube and its threshold (paper Sec. 3.1).

For each inner stretch lambda_i = r_i the traction-free condition

    int_{r_i}^{r_o} (tau_2 - tau_1) dr / r = 0                                          (*)

fixes the charge c (D_r = c / r) and so Vbar = int_{r_i}^{r_o} E_r dr / (Rbar_o - 1). An ideal
dielectric has tau_1 = tau_1^mech + D_r^2, E_r = D_r, so (*) is linear in c^2:
c^2 = 2 M r_i^2 r_o^2 / (r_o^2 - r_i^2), M the mechanical integral, V = c ln(r_o / r_i); other
energies solve (*) for c^2 by a bracketed secant (Illinois). Integrals are Gauss-Legendre in R
on [1, Rbar_o]. The threshold is the largest Vbar on the branch rising from Vbar = 0 at
lambda_i0: a limit point, an asymptote, or none (locking). The generic route scans Vbar(lambda_i);
the ideal neo-Hookean tube needs no scan:

    Vbar / Vbar_inf = (s / sinh s) sqrt(m / ln Rbar_o),  y = (lambda_i0 / lambda_i)^2,   (NH-6)

with k = Rbar_o^2 - 1, kappa = k (1 - y) / (1 + k y), m = [log1p(kappa) + y kappa] / 2,
s = log1p(k y) / 2 = ln(r_o / r_i) and lambda_i0 = sqrt(g^3 / lambda_z) (the homogeneous state),
strictly increasing in lambda_i from 0 to 1. Derivations: docs/derivation-base-state.md.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..brent import brentq
from ..errors import OVERFLOW, BaseStateError, ConvergenceError, ParameterError, StartUnresolved
from ..model.materials import Material, shorten
from .ellipticity import check_in_plane
from .neo_hookean import nh_asymptote
from .start_probe import FIRST_STEP, probe_step, rounding

GAUSS_ORDERS = (16, 24, 32, 48, 64, 96, 128, 192, 256, 384)  # Gauss-Legendre node counts tried
_SCAN_RATIO, _SCAN_SPAN = 1.08, 1e3  # threshold scan: lambda_i0 1.08^k up to 1e3 lambda_i0
_QUIET = dict(invalid="ignore", divide="ignore", over="ignore")
_PROBE_MARGIN = 1.1  # node-count probes stay 10 % inside the energy's domain (_nodes)
#: the rounding floor of a stress integral relative to its stress scale (|tau_1| + |tau_2|):
#: below it, rules that agree are resolved (a Gent layer near its lock amplifies the
#: rounding of I1 by 1 / (1 - (I1 - 3) / jm), an exponential energy by its exponent)
STRESS_NOISE = 1e3 * np.finfo(float).eps


@functools.cache
def _gauss(n: int):
    return np.polynomial.legendre.leggauss(n)


@functools.lru_cache(maxsize=64)
def energy_kind(material: Material) -> str:
    """'neo-hookean', 'ideal' (W(I1, I2) + I5/2) or 'general', decided once per energy."""
    return material.kind()


@functools.lru_cache(maxsize=64)
def _energy(material: Material):
    """Numeric Omega(I1, ..., I6), or None for a polynomial energy (finite everywhere)."""
    return material.omega()


@dataclasses.dataclass(frozen=True)
class UniformWall:
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

    def _quadrature(self, lam_i, q, rule=None):
        """Nodes: r, stretches, D_r = sqrt(q) / r and weights of dr, shape lam_i.shape + (n,);
        rule (x, w) on [-1, 1], default Gauss-Legendre with self.nodes points."""
        x, w = _gauss(self.nodes) if rule is None else rule
        h = 0.5 * (self.outer_radius - 1.0)
        lam = np.asarray(lam_i, float)[..., None]
        r, stretches, drdR = self.kinematics(lam, 1.0 + h * (x + 1))
        return r, stretches, np.sqrt(np.asarray(q, float))[..., None] / r, h * w * drdR

    def hoop(self, lam_i, q):
        """(int (tau_2 - tau_1) dr / r, int (|tau_1| + |tau_2|) dr / r) at D_r = sqrt(q) / r."""
        return self.hoops(lam_i, q, (self.nodes,))[0]

    def hoops(self, lam_i, q, orders) -> list:
        """hoop(lam_i, q) with each Gauss-Legendre rule of ``orders``, in one stress call."""
        rule = tuple(np.concatenate(a) for a in zip(*(_gauss(n) for n in orders)))
        r, stretches, d, wdr = self._quadrature(lam_i, q, rule)
        tau1, tau2, _ = self.material.stress(*stretches, d)
        f, size = (tau2 - tau1) * wdr / r, (abs(tau2) + abs(tau1)) * wdr / r
        cut = np.cumsum((0,) + tuple(orders))
        return [(f[..., a:b].sum(-1), size[..., a:b].sum(-1)) for a, b in zip(cut, cut[1:])]

    def in_domain(self, lam_i) -> np.ndarray:
        """The energy is finite on both faces and at every node at D = 0 (False beyond a locking
        stretch, e.g. Gent's)."""
        if (energy := _energy(self.material)) is None:
            return np.ones(np.shape(lam_i), bool)
        R = np.concatenate(
            [
                [1.0],
                0.5 * (self.outer_radius - 1.0) * (_gauss(self.nodes)[0] + 1) + 1.0,
                [self.outer_radius],
            ]
        )  # faces and nodes
        _, (l1, l2, l3), _ = self.kinematics(np.asarray(lam_i, float)[..., None], R)
        with np.errstate(**_QUIET):
            w = energy(
                l1**2 + l2**2 + l3**2, (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2, 0, 0, 0
            )
        return np.all(np.isfinite(np.broadcast_to(w, l1.shape)), axis=-1)

    def charge_and_voltage(self, lam_i, *, rtol: float = 1e-13):
        """Charge c and Vbar solving (*) at each lambda_i (1-d arrays). Below lambda_i0 an ideal
        dielectric gives negative values (signed square root, monotone for root finding), a
        general energy the charge where its field raises the residual of (*) to 0 (the branch
        runs inward), else NaN; outside the energy's domain NaN."""
        lam_i = np.atleast_1d(np.asarray(lam_i, float))
        c, v = np.full_like(lam_i, np.nan), np.full_like(lam_i, np.nan)
        ok = self.in_domain(lam_i)
        delta = self.b * (self.outer_radius**2 - 1.0)  # r_o^2 - r_i^2, exact
        with np.errstate(**_QUIET):
            m0, scale = self._hoop_or_nan(lam_i[ok], 0.0)
            # the stresses overflow before the energy does (an exponential energy's
            # stresses ~ I1 exp(k I1)): no state is computed there, and an infinite scale
            # would zero M below, a false Vbar = 0 that ends the branch in a false peak
            finite = np.isfinite(scale)
            ok[ok] = finite
            lam, m0, scale = lam_i[ok], m0[finite], scale[finite]
            m0 = np.where(abs(m0) <= 1e-13 * scale, 0.0, m0)
            q = 2.0 * m0 * lam**2 * (lam**2 + delta) / delta
            if energy_kind(self.material) != "general":
                c[ok] = np.sign(q) * np.sqrt(abs(q))
                v[ok] = c[ok] * 0.5 * np.log1p(delta / lam**2)
            else:
                # above lambda_i0 the charge lowers the residual to 0; below it, only a field
                # that raises it balances the traction (an I6 term with a negative weight:
                # the branch runs inward), else NaN
                up = m0 > 0
                qs = np.where(m0 == 0, 0.0, np.nan)  # lambda_i0 (to rounding): uncharged
                qs[up] = self._solve_q(lam[up], m0[up], q[up], rtol)
                down = np.flatnonzero(m0 < 0)
                rises = self._hoop_or_nan(lam[down], -q[down])[0] > m0[down]
                if (at := down[rises]).size:
                    qs[at] = self._solve_q(lam[at], m0[at], -q[at], rtol, sign=-1)
                c[ok] = np.sqrt(qs)
                ok &= np.isfinite(c)  # else no charge balances the traction: NaN
                r, stretches, d, wdr = self._quadrature(lam_i[ok], c[ok] ** 2)
                v[ok] = (self.material.electric_field(*stretches, d) * wdr).sum(-1)
        return c, v / (self.outer_radius - 1.0)

    def voltage(self, lam_i) -> np.ndarray:
        return self.charge_and_voltage(lam_i)[1]

    def charge_at(self, lam_i: float, vbar: float) -> float:
        """The charge c giving the voltage Vbar at the solved lambda_i: from the voltage, not
        from (*). Near lambda_i0 the traction's mechanical part (*) is a difference of
        stresses that cancel, so c from (*) carries their rounding relative to
        lambda_i - lambda_i0 (a Gent tube at 1.3e-6 of it, next to its lock: 2e-10), while
        V = c int dr / r (ideal dielectrics) is well conditioned; a general energy's V(c) is
        monotone, solved by secant steps from c of (*)."""
        c0 = float(self.charge_and_voltage(lam_i)[0][0])
        delta = self.b * (self.outer_radius**2 - 1.0)
        target = vbar * (self.outer_radius - 1.0)
        if energy_kind(self.material) != "general":
            return target / (0.5 * math.log1p(delta / lam_i**2))
        return _secant(lambda c: self._voltage_of_charge(lam_i, c) - target, c0)

    def _voltage_of_charge(self, lam_i: float, c: float) -> float:
        """V = int E_r dr at lambda_i and charge c (a general energy's field)."""
        _, stretches, d, wdr = self._quadrature(np.array([lam_i]), c * c)
        return float((self.material.electric_field(*stretches, d) * wdr).sum(-1)[0])

    def _hoop_or_nan(self, lam_i, q):
        """hoop(lam_i, q), NaN where the energy or its stresses are not finite: a charge
        past what the energy allows is no state (an electro-mechanical coupling that
        stiffens with I1 may need a charge without bound as lambda_i nears the end of the
        branch), nor is a lambda_i of the threshold's scan whose stresses overflow (a
        Fung-type energy's ~ exp((I1 - 3)^2)); neither is the user's input."""
        try:
            return self.hoop(lam_i, q)
        except ParameterError:
            f, size = np.full(np.shape(lam_i), np.nan), np.full(np.shape(lam_i), np.nan)
            for j, (lam, qj) in enumerate(zip(lam_i, np.broadcast_to(q, np.shape(lam_i)))):
                try:
                    (f[j],), (size[j],) = self.hoop(np.array([lam]), qj)
                except ParameterError:
                    pass
            return f, size

    def _solve_q(self, lam_i, f_lo, q_hi, rtol, sign: int = 1):
        """q = c^2 solving hoop(lam_i, q) = 0, given sign f(0) >= 0: q doubled until
        sign f <= 0, then Illinois; NaN where no charge within the energy's domain balances
        the traction. sign -1: below lambda_i0, where the charge raises f."""
        q_lo, q_hi = np.zeros_like(q_hi), np.maximum(q_hi, 1e-300)
        f_hi = self._hoop_or_nan(lam_i, q_hi)[0]
        for _ in range(200):  # expand until sign f(q_hi) <= 0
            up = sign * f_hi > 0
            if not up.any():
                break
            q_lo, f_lo = np.where(up, q_hi, q_lo), np.where(up, f_hi, f_lo)
            q_hi = np.where(up, 2.0 * q_hi, q_hi)
            f_hi = self._hoop_or_nan(lam_i, q_hi)[0]
        q, live = np.full(q_hi.shape, np.nan), sign * f_hi <= 0
        if live.any():
            q[live] = self._illinois(
                lam_i[live], q_lo[live], f_lo[live], q_hi[live], f_hi[live], rtol, sign
            )
        return q

    def _illinois(self, lam_i, q_lo, f_lo, q_hi, f_hi, rtol, sign: int = 1):
        """Illinois (modified regula falsi) for hoop(lam_i, q) = 0 on [q_lo, q_hi], sign f
        >= 0 at q_lo."""
        side = np.zeros(q_hi.shape, int)
        for _ in range(100):
            q = np.where(f_hi == f_lo, q_hi, (q_lo * f_hi - q_hi * f_lo) / (f_hi - f_lo))
            f, scale = self.hoop(lam_i, q)
            done = (abs(f) <= 1e-14 * scale) | (abs(q_hi - q_lo) <= 1e-2 * rtol * abs(q))
            if np.all(done | ~np.isfinite(q)):
                return np.where(f_lo == 0, q_lo, q)
            hi = sign * f < 0  # replace the endpoint of f's sign; halve the kept one's f
            f_lo = np.where(hi & (side == 1), f_lo / 2, f_lo)
            f_hi = np.where(~hi & (side == -1), f_hi / 2, f_hi)
            q_hi, f_hi = np.where(hi, q, q_hi), np.where(hi, f, f_hi)
            q_lo, f_lo = np.where(hi, q_lo, q), np.where(hi, f_lo, f)
            side = np.where(hi, 1, -1)
        raise ConvergenceError(f"charge c not converged at lambda_i = {lam_i[~done][0]!r}")


def _secant(f, x0: float) -> float:
    """The root of a monotone f near x0 by secant steps, to rounding (x0 if f does not
    change: a step that would not move it)."""
    x1 = x0 * (1.0 + 1e-7) if x0 else 1e-7
    f0, f1 = f(x0), f(x1)
    for _ in range(30):
        if f1 == f0:
            break
        x0, x1, f0 = x1, x1 - f1 * (x1 - x0) / (f1 - f0), f1
        f1 = f(x1)
        if abs(x1 - x0) <= 4.0 * np.finfo(float).eps * abs(x1):
            break
    return x1


@dataclasses.dataclass(frozen=True)
class _Threshold:
    lambda_i0: float  # purely mechanical state, Vbar = 0
    value: float  # Vbar threshold (inf if none)
    kind: str  # "asymptote", "limit point", "locking", "none" (as a layered Threshold) or
    # "closing" (no charged state on either side of lambda_i0: value 0, lambda_i = lambda_i0)
    # or "unresolved" (which side is not resolved, start_probe.py: as closing otherwise)
    lambda_i: float  # lambda_i at the threshold (inf: asymptote; the branch's end: "locking")
    error: float  # estimated absolute error of value
    nodes: int  # Gauss-Legendre nodes meeting rtol (0: neo-Hookean closed form, no quadrature)
    grid: np.ndarray  # lambda_i on the monotone branch, from lambda_i0 (falling: inward) ...
    values: np.ndarray  # ... and Vbar there (increasing, starts at 0)


@functools.lru_cache(maxsize=4096)
def _mechanical(material, outer_radius, growth, stretch, rtol) -> tuple[float, int]:
    """lambda_i0 and the fewest Gauss-Legendre nodes meeting rtol. lambda_i0 = sqrt(g^3 / lz) is
    the homogeneous state: there l1 = l2 at every R, so tau_1 = tau_2 at D = 0 for any isotropic
    energy and (*) holds pointwise; under Baker-Ericksen ((tau_2 - tau_1)(l2 - l1) > 0) M has
    the sign of lambda_i - lambda_i0, so no other state has Vbar = 0 (docs Sec. 3)."""
    tube = UniformWall(material, outer_radius, growth, stretch, GAUSS_ORDERS[0])
    lam0 = math.sqrt(growth**3 / stretch)
    if (at := _overflow(tube, lam0)) is not None:
        err = ConvergenceError(
            f"the traction-free state at Vbar = 0 for g = {growth:g}, lambda_z = {stretch:g},"
            f" Rbar_o = {outer_radius:g} is not computed: the stresses of"
            f" {shorten(material.name)!r} overflow a double in it (I1 = {at:.6g})"
        )
        err.remedy = OVERFLOW  # neither a looser rtol nor collocation reaches it
        raise err
    if not tube.in_domain(np.array([lam0]))[0]:
        raise BaseStateError(
            f"no traction-free state at Vbar = 0 for g = {growth:g},"
            f" lambda_z = {stretch:g}, Rbar_o = {outer_radius:g}: the energy"
            f" of {material.name} is undefined in the homogeneous state"
        )
    return lam0, _nodes(tube, lam0 * np.array([1.0, 1.5, 3.0]), rtol)


def _overflow(tube: UniformWall, lam0: float) -> float | None:
    """I1 of the homogeneous state lambda_i0 if its stresses overflow a double: its energy
    +inf, or finite with stresses that are not (an exponential energy's, e.g.
    exp((I1 - 3)^2) from I1 ~ 29.6). That state exists, but the material's ParameterError
    there would blame the user's deformation, and "undefined" is for a lock's end (NaN)."""
    if (energy := _energy(tube.material)) is None:
        return None
    _, (l1, l2, l3), _ = tube.kinematics(np.array([lam0]), np.array([1.0]))
    I1 = float((l1**2 + l2**2 + l3**2)[0])
    with np.errstate(**_QUIET):
        w = float(
            np.ravel(energy(I1, (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2, 0, 0, 0))[0]
        )
    tau = tube.material.finite_stress(l1, l2, l3, 0.0)
    return I1 if w == math.inf or (math.isfinite(w) and not np.isfinite(tau).all()) else None


def _nodes(tube: UniformWall, lam: np.ndarray, rtol: float) -> int:
    """Fewest nodes whose M at lam agrees with the next rule to 1e-2 rtol of the stress scale
    (four successive rules per stress call). Probes within _PROBE_MARGIN of the energy's edge
    are left out: near a locking stretch (Gent) the stress has a pole just outside the inner
    face, which no Gauss rule in R resolves, and evaluating it there loses digits to
    cancellation in 1 - (I1 - 3) / Jm. The rule is only a start: the solved state raises the
    count until its own independent quadrature meets rtol (solve_base_state).

    Where no rule meets that at every probe, each probe takes its first rule that agrees
    with the next to rtol or to the stresses' rounding (STRESS_NOISE: an exponential
    energy's stresses at 3 lambda_i0 carry the rounding of exp(I1 / 2), ~1e-13 of their
    scale, above 1e-2 rtol), and a probe no rule resolves is left out, as in the layered
    choice (plies.choose_nodes); the probe nearest the state must be resolved."""
    lam = lam[tube.in_domain(lam * _PROBE_MARGIN)]
    gaps = []  # (n, |M_n - M_next| / scale) at each probe
    for start in range(0, len(GAUSS_ORDERS) - 1, 3):
        orders = GAUSS_ORDERS[start : start + 4]
        with np.errstate(over="ignore", invalid="ignore"):  # a probe whose stresses
            hoops = tube.hoops(lam, 0.0, orders)  # overflow resolves under no rule: left out
        for n, (a, s), (b, _) in zip(orders, hoops, hoops[1:]):
            if np.all(abs(a - b) <= 0.01 * rtol * s):
                return n
            gaps.append((n, abs(a - b) / s))
    first = np.zeros(lam.shape, int)  # each probe's first rule agreeing to rounding
    for n, gap in reversed(gaps):
        first = np.where(gap <= max(0.01 * rtol, STRESS_NOISE), n, first)
    if not first[0]:
        raise ConvergenceError(
            f"quadrature not converged to rtol = {rtol} with {GAUSS_ORDERS[-1]} nodes"
        )
    return int(first.max())


def cell_root(f, a: float, b: float) -> float:
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
    Vbar -> inf at a locking stretch ("locking"), or the asymptote (neo-Hookean closed form, else
    Richardson extrapolation in x = lambda_i^-2, whose order is measured)."""
    if energy_kind(material) == "neo-hookean":  # (NH-5, NH-6): nothing to scan
        lam0 = math.sqrt(growth**3 / stretch)
        return _Threshold(
            lam0,
            nh_asymptote(outer_radius, growth, stretch),
            "asymptote",
            math.inf,
            0.0,
            0,
            np.array([lam0]),
            np.array([0.0]),
        )
    lam0, nodes = _mechanical(material, outer_radius, growth, stretch, rtol)
    # the branch rises from lambda_i0 only where the in-plane shear modulus is positive
    # there (Baker-Ericksen): else its Vbar fell from 0 ("does not rise", even at V = 0)
    where = f"g = {growth:g}, lambda_z = {stretch:g}, Rbar_o = {outer_radius:g}"
    check_in_plane(material, stretch / growth, where)
    tube = UniformWall(material, outer_radius, growth, stretch, nodes)
    try:
        step, kind = 1 if _rises(tube, lam0) else -1 if _runs_inward(tube, lam0) else 0, "closing"
    except StartUnresolved:  # which side is not resolved: no charged state followed
        step, kind = 0, "unresolved"
    if not step:  # no charged state on either side of lambda_i0 (or not resolved)
        return _Threshold(lam0, 0.0, kind, lam0, 0.0, nodes, np.array([lam0]), np.zeros(1))
    k = np.arange(0, math.ceil(math.log(_SCAN_SPAN, _SCAN_RATIO)) + 1)
    lam = lam0 * _SCAN_RATIO ** (step * k)
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
    if end < v.size:  # the branch ends: Gent's locking stretch, or where the charge
        # that balances the traction leaves the energy's domain (a coupling stiffening with I1)
        a, b = lam[end - 1], lam[end]
        exists = tube.in_domain  # the energy's edge (cheap), else the charge's
        if exists(np.array([b]))[0]:
            exists = lambda x: np.isfinite(tube.voltage(x))  # noqa: E731
        while abs(b - a) > 1e-14 * b:  # 64-section of the branch's end
            x = np.linspace(a, b, 65)
            j = np.argmin(exists(x)) - 1
            a, b = x[j], x[j + 1]
        return _Threshold(value=math.inf, kind="locking", lambda_i=a, **out)
    if step < 0:  # the limits below are of lambda_i -> inf
        raise ConvergenceError(
            f"the voltage branch walked inward from lambda_i0 = {lam0:.12g} to {lam[-1]:.12g}"
            " met no threshold (its limit as lambda_i -> 0 is not computed)"
        )
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


#: why a "closing" threshold is 0 (:func:`_rises`, thresholds.opens)
CLOSING = (
    "this energy's field closes the bore and no charge balances it inward either (threshold"
    " 0, kind closing): no charged state is followed"
)


def _rises(tube: UniformWall, lam0: float) -> bool:
    """Does a charge balance the traction just above lambda_i0? Not where the energy's field
    closes the bore (an I6 term with a negative weight, `(I1-3)/2 + 0.2*I4 + 0.4*I5 -
    0.1*I6` at lambda_z <= 0.49: the charge raises the residual of (*) there): the branch
    rising in lambda_i does not exist; it may run inward (:func:`_runs_inward`), else the
    threshold is 0 (kind "closing"). The scan's steps of 8 % jumped that gap to states of
    another branch beyond it: a locking stretch, an unbounded branch, or a limit point
    whose interpolant met the gap ("internal error: LinAlgError", check round 24). Read
    at the first step whose residual is resolved (start_probe.probe_step)."""
    near = np.array([lam0 * (1.0 + _probe(tube, lam0, 1))])
    if not tube.in_domain(near)[0]:  # a lock right there (Gent), not a closing field
        return True
    return bool(np.isfinite(tube.voltage(near)[0]))


def _runs_inward(tube: UniformWall, lam0: float) -> bool:
    """Does a charge balance the traction just below lambda_i0, with Vbar > 0? Where the
    energy's field closes the bore above it (:func:`_rises`), a field that raises the
    residual of (*) balances it below (`(I1-3)/2 + 0.2*I4 + 0.4*I5 - 0.1*I6` at lambda_z
    0.45: Vbar rises as lambda_i falls, to a limit point 1.0309 at lambda_i 1.3193)."""
    v = tube.voltage(np.array([lam0 * (1.0 - _probe(tube, lam0, -1))]))[0]
    return bool(np.isfinite(v) and v > 0)


def _probe(tube: UniformWall, lam0: float, side: int) -> float:
    """The probe's step from lambda_i0 on ``side`` (+1 above, -1 below) whose residual M of
    (*) at q = 0 is resolved against its stress scale (start_probe.probe_step; NaN past
    the energy's domain, where the step stands). FIRST_STEP for an ideal dielectric: its
    charge, c^2 = 2 M r_i^2 r_o^2 / (r_o^2 - r_i^2), is finite whatever M reads, so the
    branch rises as it always read (where the in-plane modulus vanishes, lambda_z -> sqrt 6
    in tests/bifurcation/test_torsion_onset.py, M is flat and its limit point ~ sqrt of
    the distance is read on the scan's grid, resolved there)."""
    if energy_kind(tube.material) != "general":
        return FIRST_STEP

    def read(h: float) -> tuple[float, float]:
        lam = np.array([lam0 * (1.0 + side * h)])
        if not tube.in_domain(lam)[0]:
            return math.nan, math.nan
        with np.errstate(**_QUIET):
            m, scale = tube._hoop_or_nan(lam, 0.0)
        return float(m[0]), float(rounding(scale[0], 0.0))

    return probe_step(read, f"lambda_i0 = {lam0:.12g}")


def _limit_point(tube: UniformWall, lam0: float, lam: np.ndarray, v: np.ndarray) -> _Threshold:
    """Maximise Vbar between lam[-3] and lam[-1]: root of the derivative of a degree-24
    Chebyshev interpolant of Vbar^2 (analytic there), then Vbar evaluated exactly at that
    root. lam falls from lambda_i0 on a branch that runs inward."""

    def vsq(x):
        return np.sign(y := tube.voltage(x)) * y**2

    a, b = sorted((lam[-3], lam[-1]))
    with np.errstate(invalid="ignore"):
        poly = cheb.Chebyshev.interpolate(vsq, 24, domain=[a, b])
    if not np.isfinite(poly.coef).all():  # a gap in the branch between the scan's samples
        raise ConvergenceError(f"Vbar is not finite everywhere in [{a:.6g}, {b:.6g}]")
    crit = [x.real for x in poly.deriv().roots() if abs(x.imag) < 1e-9 and a <= x.real <= b]
    if not crit:
        raise ConvergenceError(f"limit point of Vbar not located in [{a:.6g}, {b:.6g}]")
    top = max(crit, key=poly)
    top_sq = float(vsq(top)[0])
    if not top_sq > 0:  # the branch fell below the start before its first maximum (check 21)
        raise ConvergenceError(f"Vbar(lambda_i) does not rise from lambda_i0 = {lam0:.12g}")
    value = math.sqrt(top_sq)
    keep = (lam - top) * (lam[-1] - lam[0]) < 0  # before the top, either way
    return _Threshold(
        lam0,
        value,
        "limit point",
        float(top),
        abs(poly(top) - value**2) / value,
        tube.nodes,
        np.append(lam[keep], top),
        np.append(v[keep], value),
    )


def threshold_info(params, rtol: float = 1e-12) -> _Threshold:
    return _threshold(params.material, params.outer_radius, params.growth, params.stretch, rtol)
