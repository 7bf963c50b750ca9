"""One state of a layered tube's wall at (r_i, lambda_z, c): each layer's kinematics, stresses,
field and moduli, and their integrals through the wall (docs/derivation-layered.md).

Kinematics (F = F_e F_g, F_g = diag(g_r, g_theta, g_z), det F_e = 1):

    r dr / (R dR) = J / lambda_z,  J = g_r g_theta g_z,  r(R)^2 = r_i^2 + 2 G(R) / lambda_z,
    G(R) = int_1^R J R' dR',  l2 = r / (g_theta R),  l3 = lambda_z / g_z,  l1 = 1 / (l2 l3).

Layer k with shear modulus mu_k and permittivity eps_k has the energy
mu_k Omega(F_e, D~ / s_k), s_k = sqrt(mu_k eps_k), so tau = mu_k tau^(d / s_k) and
E_r = sqrt(mu_k / eps_k) E^(d / s_k) (= d / eps_k for an ideal dielectric). Maxwell: D_r = c / r
through every layer, V = int E_r dr. Equilibrium: d sigma_rr / dr = (tau_2 - tau_1) / r,
sigma_rr continuous, sigma_rr(r_i) = -P_i, sigma_rr(r_o) = -P_o, i.e.

    T := int_{r_i}^{r_o} (tau_2 - tau_1) dr / r = P_i - P_o,                            (*)

and N = 2 pi int sigma_zz r dr = pi int (2 tau_3 - tau_1 - tau_2) r dr + pi (P_i r_i^2 - P_o r_o^2)

Integrals are Gauss-Legendre in R per layer (node count chosen by comparing successive rules
at representative states); for ideal dielectrics Q = int dr / (eps r^3) and
Lambda = int dr / (eps r) are in closed form, for general energies c solves (*) or the voltage
by Illinois iteration.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..errors import ConvergenceError
from ..model.layers import Layer, Tube
from ..model.materials import Material
from ..model.moduli import MODULI_NAMES, neo_hookean_moduli
from .chebyshev_series import ChebyshevSeries, chebinterpolate
from .voltage import STRESS_NOISE, energy_kind

ORDERS = (8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256)  # Gauss-Legendre nodes per layer
_QUIET = dict(invalid="ignore", divide="ignore", over="ignore")
_EPS = np.finfo(float).eps
_SCALE = {"A": 0, "G": 1, "K": 2}  # moduli family -> power of 1 / s_k applied with mu_k


@functools.cache
def _gauss(n: int):
    return np.polynomial.legendre.leggauss(n)


@functools.lru_cache(maxsize=64)
def numeric_energy(material: Material):
    """Numeric Omega(I1, ..., I6), or None for a polynomial energy (finite everywhere)."""
    return material.omega()


def chebyshev(f, a: float, b: float, tol, what: str, unit=1.0) -> np.ndarray:
    """Chebyshev coefficients of the vectorised f (values on the last axis) on [a, b], degree
    doubled until, in every column, the last three are below tol (a number, or one per
    column) of its size, or have stopped
    falling (the noise floor of f, e.g. next to a locking stretch) below 1e-8 of it. Up to
    degree 4096: a Gent layer within ~0.5 % of its lock needs 1024-4096 (its stress has a
    pole just outside the wall); the test suite's other profiles resolve by 512.

    A column's size is the larger of its largest coefficient and ``unit`` (per column), the
    scale of the quantity it holds: a column that cancels to rounding (tau_2 - tau_1 of a
    stress-free layer is mu_k times rounding) is measured against its units, never against
    its own noise nor against a constant that is rounding-small for a stiff layer."""
    last = None
    for deg in (16, 32, 64, 128, 256, 512, 1024, 2048, 4096):
        coef = chebinterpolate(lambda x: f(a + 0.5 * (b - a) * (x + 1.0)), deg)
        size = np.maximum(abs(coef).max(0), unit)
        tail = abs(coef[-3:]).max(0) / size
        if last is not None and (~np.isfinite(tail) & ~np.isfinite(last)).any():
            # NaN at nodes of two rules: the state lies outside the energy's domain (a
            # root past a lock), no degree resolves it (degrees to 4096 cost seconds)
            raise ConvergenceError(
                f"{what} on [{a:g}, {b:g}] is not finite at the Chebyshev points of degrees"
                f" {deg // 2} and {deg}: the state lies where the energy is not defined"
            )
        if np.all(tail <= tol) or (
            last is not None
            and np.all(tail <= 1e-8)
            and np.all((tail <= tol) | (tail > 0.1 * last))  # each column resolved or at noise
        ):
            return coef
        last = tail
    worst = int(np.argmax(tail / tol))  # what was observed: the column, by how much
    raise ConvergenceError(
        f"{what} on [{a:g}, {b:g}] not resolved by Chebyshev degree 4096 (its series'"
        f" tail is {np.ravel(tail)[worst]:.2g} of its size, above"
        f" {np.ravel(np.broadcast_to(tol, np.shape(tail)))[worst]:.2g})"
    )


def stalled_noise(coef: np.ndarray, tol: float, unit=1.0) -> np.ndarray:
    """Per column of :func:`chebyshev`'s coefficients, its tail (the last three, in the
    column's units) where it stopped at a noise floor above ``tol``, else 0: how well the
    series resolves that column. Next to a Gent lock the integrand's own rounding, ~eps I1
    / (jm s) for s = 1 - (I1 - 3) / jm, is such a floor (a core within 1.1e-3 of its lock:
    ~1e-12 of its size)."""
    size = np.maximum(abs(coef).max(0), unit)
    tail = abs(coef[-3:]).max(0)
    return np.where(tail > tol * size, tail, 0.0)


# -- one layer -------------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Ply:
    """One layer's numerics: its R range [a, b], G(a) and, when graded, int_a^R J R' dR'."""

    layer: Layer
    a: float
    b: float
    G0: float
    graded_integral: cheb.Chebyshev | None = None

    @classmethod
    def stack(cls, tube: Tube) -> tuple[Ply, ...]:
        plies, G0 = [], 0.0
        for a, layer in zip(tube.radii, tube.layers):
            b, integral = layer.outer_radius, None
            if layer.graded:
                coef = chebyshev(
                    lambda R, lay=layer: np.prod(lay.growth_at(R), axis=0) * R,
                    a,
                    b,
                    1e-14,
                    "graded growth",
                )
                integral = ChebyshevSeries(coef, domain=[a, b]).integ(lbnd=a)
            plies.append(cls(layer, a, b, G0, integral))
            G0 += plies[-1].dG
        return tuple(plies)

    @property
    def dG(self) -> float:
        """G(b) - G(a), not as a difference of the sums G (which loses the digits of a thin
        layer outside a thick one): J (b - a) (b + a) / 2 for constant growth."""
        if self.graded_integral is None:
            return math.prod(self.layer.growth) * (self.b - self.a) * (self.b + self.a) / 2.0
        return float(self.graded_integral(self.b))

    @property
    def kind(self) -> str:
        return energy_kind(self.layer.material)

    @property
    def G1(self) -> float:
        return float(self.G(self.b))

    def G(self, R):
        """G(R) = int_1^R J R' dR' (closed form for constant growth)."""
        if self.graded_integral is None:
            return self.G0 + math.prod(self.layer.growth) * (R - self.a) * (R + self.a) / 2.0
        return self.G0 + self.graded_integral(R)

    def kinematics(self, R, g, G, r_i, lz, c):
        """r, r^2, elastic stretches, D_r at R (last axis) for r_i, lz, c (shape S + (1,))."""
        r2 = r_i * r_i + 2.0 * G / lz
        r = np.sqrt(r2)
        l2 = r / (g[1] * R)
        l3 = np.broadcast_to(lz / g[2], l2.shape)
        return r, r2, (1.0 / (l2 * l3), l2, l3), c / r

    def trial_stress(self, l1, l2, l3, d):
        """:meth:`stress`, NaN where the energy or the stress is not finite (beyond a locking
        stretch; where an exponential energy's stresses overflow a double, which they do a
        little before the energy itself; where the state is not, e.g. no charge balances the
        traction past another layer's lock, c NaN). For the wall's integrals at trial and
        probe states: such a point is no state to use, never the user's deformation (a
        node-count probe at 3 times the guess once raised the material's ParameterError for
        a state far inside the double range)."""
        mu, eps = self.layer.shear_modulus, self.layer.permittivity
        with np.errstate(**_QUIET):  # a trial state's infinities become NaN below, quietly
            if self.kind == "neo-hookean":  # NaN only where the state is
                tau = self.stress(l1, l2, l3, d)
            else:
                s = math.sqrt(mu * eps)
                tau = mu * self.layer.material.finite_stress(l1, l2, l3, d / s)
        return np.where(np.isfinite(tau).all(0), tau, np.nan)  # mu tau may overflow too

    def trial_field(self, l1, l2, l3, d):
        """:meth:`field`, NaN where it is not finite (as :meth:`trial_stress`)."""
        mu, eps = self.layer.shear_modulus, self.layer.permittivity
        if self.kind != "general":
            return np.broadcast_to(d / eps, l1.shape)
        s = math.sqrt(mu * eps)
        with np.errstate(**_QUIET):
            field = mu / s * self.layer.material.finite_electric_field(l1, l2, l3, d / s)
        return np.where(np.isfinite(field), field, np.nan)

    def stress(self, l1, l2, l3, d):
        """tau_i = mu_k tau^_i(l, d / s_k), shape (3,) + l1.shape (Maxwell part included)."""
        mu, eps = self.layer.shear_modulus, self.layer.permittivity
        if self.kind == "neo-hookean":
            return np.array([mu * l1 * l1 + d * d / eps, mu * l2 * l2, mu * l3 * l3])
        return mu * self.layer.material.stress(l1, l2, l3, d / math.sqrt(mu * eps))

    def field(self, l1, l2, l3, d):
        """E_r = sqrt(mu_k / eps_k) E^(l, d / s_k); d / eps_k for an ideal dielectric."""
        mu, eps = self.layer.shear_modulus, self.layer.permittivity
        if self.kind != "general":
            return np.broadcast_to(d / eps, l1.shape)
        s = math.sqrt(mu * eps)
        return mu / s * self.layer.material.electric_field(l1, l2, l3, d / s)

    def moduli(self, l1, l2, l3, d):
        """Updated moduli of the layer: A mu_k, Gamma sqrt(mu_k / eps_k), K / eps_k."""
        mu, eps = self.layer.shear_modulus, self.layer.permittivity
        s = math.sqrt(mu * eps)
        if self.kind == "neo-hookean":
            m = neo_hookean_moduli(l1, l2, l3, d / s)
        else:
            m = self.layer.material.moduli(l1, l2, l3, d / s)
        return m * np.array([mu / s ** _SCALE[name[0]] for name in MODULI_NAMES])


# -- the wall: Gauss-Legendre integrals at (r_i, lambda_z, c) ----------------------------------


@dataclasses.dataclass(frozen=True)
class Wall:
    tube: Tube
    plies: tuple[Ply, ...]
    nodes: int
    grids: tuple  # per ply (R, w, g, J, G): Gauss nodes plus both faces (weight 0)

    @classmethod
    def build(cls, tube: Tube, nodes: int, plies=None) -> Wall:
        plies = plies or Ply.stack(tube)
        x, w = _gauss(nodes)
        grids = []
        for ply in plies:
            h = 0.5 * (ply.b - ply.a)
            R = np.concatenate([[ply.a], ply.a + h * (x + 1.0), [ply.b]])
            g = ply.layer.growth_at(R)
            grids.append((R, np.concatenate([[0.0], h * w, [0.0]]), g, np.prod(g, 0), ply.G(R)))
        return cls(tube, plies, nodes, tuple(grids))

    @functools.cached_property
    def ideal(self) -> bool:
        return all(p.kind != "general" for p in self.plies)

    @functools.cached_property
    def faces_G(self) -> np.ndarray:
        return np.array([p.G0 for p in self.plies] + [self.plies[-1].G1])

    @functools.cached_property
    def layer_G(self) -> np.ndarray:
        """G_k - G_{k-1} per layer (Ply.dG)."""
        return np.array([p.dG for p in self.plies])

    def radii2(self, r_i, lz):
        """r^2 at every face and interface, shape S + (N + 1,)."""
        return np.asarray(r_i)[..., None] ** 2 + 2.0 * self.faces_G / np.asarray(lz)[..., None]

    def electric(self, r_i, lz):
        """Q = int dr / (eps r^3) and Lambda = int dr / (eps r) in closed form, per layer from
        r^2 at its faces and r_b^2 - r_a^2 = 2 (G_b - G_a) / lambda_z (no subtraction)."""
        r2 = self.radii2(r_i, lz)
        dr2 = 2.0 * self.layer_G / np.asarray(lz)[..., None]
        inv_eps = np.array([1.0 / p.layer.permittivity for p in self.plies])
        Q = (inv_eps * dr2 / (2.0 * r2[..., :-1] * r2[..., 1:])).sum(-1)
        Lam = (inv_eps * 0.5 * np.log1p(dr2 / r2[..., :-1])).sum(-1)
        return Q, Lam

    @functools.cached_property
    def closed_form(self) -> np.ndarray:
        """Per ply: are its integrals elementary (neo-Hookean, constant growth)?"""
        return np.array([p.kind == "neo-hookean" and not p.layer.graded for p in self.plies])

    def _closed_form_integrals(self, r_i, lz, c, out) -> None:
        """Add the closed-form plies' (T, scale, V, N_int) to ``out`` (neo_hookean_wall.py)."""
        # here: only a march's continuation, which has loaded numba for its modes anyway
        from .neo_hookean_wall import ply_integrals

        r2 = self.radii2(r_i, lz).reshape(-1, len(self.plies) + 1)
        lz, c = np.ravel(lz), np.ravel(c)
        flat = out.reshape(4, -1)  # a view: out is C-contiguous
        for k in np.flatnonzero(self.closed_form):
            ply = self.plies[k]
            layer = ply.layer
            ply_integrals(
                np.ascontiguousarray(r2[:, k]),
                lz,
                c,
                ply.a,
                ply.b,
                np.asarray(layer.growth, float),
                layer.shear_modulus,
                layer.permittivity,
                flat,
            )

    def overflow(self, r_i: float, lz: float) -> float | None:
        """I1 at the first node (uncharged, at r_i and lambda_z) where a layer's stresses
        overflow a double: its energy is +inf there, or finite with stresses that are not (an
        exponential energy's, e.g. exp((I1 - 3)^2) from I1 ~ 29.6); None if nowhere. Not a
        lock's end, where the energy is NaN: that is the user's deformation."""
        for ply, (R, _, g, _, G) in zip(self.plies, self.grids):
            if (energy := numeric_energy(ply.layer.material)) is None:
                continue  # a polynomial: finite wherever its stretches are
            _, _, (l1, l2, l3), d = ply.kinematics(R, g, G, np.array([r_i]), lz, 0.0)
            I1 = l1**2 + l2**2 + l3**2
            with np.errstate(**_QUIET):
                w = np.broadcast_to(energy(I1, (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2,
                                           0.0, 0.0, 0.0), I1.shape)  # fmt: skip
            tau = ply.trial_stress(l1, l2, l3, d)
            over = (w == math.inf) | (np.isfinite(w) & ~np.isfinite(tau).all(0))
            if over.any():
                return float(I1[over][0])
        return None

    def peak_invariant(self, r_i: float, lz: float) -> float:
        """The largest I1 (uncharged, at r_i and lambda_z) over the nodes of the layers whose
        energy can end (a Gent layer's lock I1 = 3 + jm); -inf where none can. Its minimum
        over r_i is the least-stretched state, where a lock's window of finite states lies."""
        peak = -math.inf
        for ply, (R, _, g, _, G) in zip(self.plies, self.grids):
            if numeric_energy(ply.layer.material) is not None:
                _, _, (l1, l2, l3), _ = ply.kinematics(R, g, G, np.array([r_i]), lz, 0.0)
                peak = max(peak, float((l1**2 + l2**2 + l3**2).max()))
        return peak

    def integrals(self, r_i, lz, c, compiled: bool = False):
        """(T, scale, V, Nint): T = int (tau_2 - tau_1) dr / r, scale = int (|tau_1| + |tau_2|)
        dr / r, V = int E_r dr, Nint = pi int (2 tau_3 - tau_1 - tau_2) r dr; NaN where an
        energy is not finite (faces included).

        By the Gauss rule, or with ``compiled`` by the closed form (neo_hookean_wall.py) for
        the neo-Hookean plies of constant growth: ~2 us a ply against ~50 us, for a march's
        continuation (warm.py), where the compiled kernels are loaded anyway; a cold solve
        keeps the Gauss rule and does not load numba (a `state` command, issue 25). The two
        agree to ~1e-14 of the stress scale (tests/basestate/test_neo_hookean_wall.py), as a
        continued and a cold state do anyway (two Newton starts of one root)."""
        r_i, lz, c = (np.asarray(v, float)[..., None] for v in np.broadcast_arrays(r_i, lz, c))
        out = np.zeros((4,) + r_i.shape[:-1])
        bad = np.zeros(r_i.shape[:-1], bool)
        closed = self.closed_form if compiled else np.zeros(len(self.plies), bool)
        if closed.any():
            self._closed_form_integrals(r_i[..., 0], lz[..., 0], c[..., 0], out)
        for ply, (R, w, g, J, G), skip in zip(self.plies, self.grids, closed):
            if skip:
                continue
            r, r2, (l1, l2, l3), d = ply.kinematics(R, g, G, r_i, lz, c)
            tau = ply.trial_stress(l1, l2, l3, d)  # NaN where not finite: that state is bad
            ok = np.isfinite(tau).all(0)
            jr = w * J * R / lz  # r dr = J R dR / lambda_z
            out[0] += ((tau[1] - tau[0]) * jr / r2).sum(-1)
            out[1] += ((abs(tau[1]) + abs(tau[0])) * jr / r2).sum(-1)
            if np.any(c):
                field = ply.trial_field(l1, l2, l3, d)
                ok &= np.isfinite(field)
                out[2] += (field * jr / r).sum(-1)
            out[3] += math.pi * ((2.0 * tau[2] - tau[0] - tau[1]) * jr).sum(-1)
            bad |= ~ok.all(-1)
        out[:, bad] = np.nan
        return out


def illinois(f, a, b, fa, fb):
    """Vectorised Illinois (modified regula falsi) for f(x) = 0 with fa, fb of opposite signs;
    f returns (value, noise scale). Stops at |f| <= 1e-15 scale or a bracket of 1e-15 |x|."""
    side = np.zeros(np.shape(a), int)
    result = np.full(np.shape(a), np.nan)
    done = np.zeros(np.shape(a), bool)
    for _ in range(300):
        with np.errstate(**_QUIET):
            x = np.where(fb == fa, b, (a * fb - b * fa) / (fb - fa))
        fx, size = f(x)
        now = ~done & (
            (abs(fx) <= 1e-15 * size) | (abs(b - a) <= 1e-15 * abs(x)) | ~np.isfinite(fx)
        )
        result, done = np.where(now, x, result), done | now
        if done.all():
            return result
        same = np.sign(fx) == np.sign(fb)  # x replaces b
        fa = np.where(same & (side == 1), fa / 2, fa)
        fb = np.where(~same & (side == -1), fb / 2, fb)
        a, fa = np.where(same, a, x), np.where(same, fa, fx)
        b, fb = np.where(same, x, b), np.where(same, fx, fb)
        side = np.where(same, 1, -1)
    raise ConvergenceError("charge c not converged (bracketed secant, 300 iterations)")


# -- the node count: successive Gauss-Legendre rules at representative states -----------------


def choose_nodes(tube: Tube, rtol: float, plies) -> int:
    """Fewest Gauss nodes per layer whose T (and V) agree with the next rule to 1e-3 rtol (or
    64 eps, rounding) of the stress scale (of max(1, |V|)) at representative states: r_i = 0.6,
    0.8, 1, 1.5, 3 times the guess (the integrands are the least smooth at the smallest r_i),
    c = 0 and r_i / 2.

    A representative no rule resolves (a Gent layer just short of its lock at 1.5 or 3 times
    the guess) is left out rather than refusing the tube: the rule is only a start, the
    solved state checks its own quadrature error and asks for more nodes. The guess is
    resolved to the tolerance, or else to its rounding floor (:func:`_stall`), or left out
    too: it is no state of the tube (a Gent layer grown 5 times on a core grown 1.2 has its
    guess within 1 % of the lock, its state at twice the guess's r_i resolved by 12 nodes).
    Only where no representative is resolved is the tube refused."""
    x0, lz0 = start_guess(Wall.build(tube, 16, plies))
    r = x0 * np.tile([0.6, 0.8, 1.0, 1.5, 3.0], 2)
    c = np.where(np.arange(10) < 5, 0.0, 0.5 * r)
    first = np.full(r.shape, -1)  # the first agreeing rule of each representative
    prev, gaps = None, []  # gaps: (n, each representative's difference with the next rule)
    for n in ORDERS:
        cur = Wall.build(tube, n, plies).integrals(r, lz0, c)
        if prev is not None:
            ok = np.isfinite(cur[0]) & np.isfinite(prev[1][0])
            err = np.maximum(
                abs(cur[0] - prev[1][0]) / np.maximum(cur[1], 1.0),
                abs(cur[2] - prev[1][2]) / np.maximum(abs(cur[2]), 1.0),
            )
            good = ~ok | (err <= max(1e-3 * rtol, 64 * _EPS))  # not below rounding
            if np.all(good):
                return prev[0]
            first = np.where((first < 0) & good, prev[0], first)
            gaps.append((prev[0], np.where(ok, err, 0.0)))
        prev = (n, cur)
    for k in (2, 7):  # the guess: resolved to rounding if not to tolerance
        if first[k] < 0:
            first[k] = _stall([n for n, _ in gaps], [gap[k] for _, gap in gaps])
    if np.all(first < 0):
        raise ConvergenceError(
            f"quadrature not converged to rtol = {rtol} with {ORDERS[-1]} nodes"
        )
    return int(first.max())


def _stall(orders, gaps) -> int:
    """The first rule whose difference with the next is at most the stresses' rounding
    (STRESS_NOISE) and from which the differences have stopped falling (neither of the next
    two is below a tenth of it), or -1. An exponential energy's stresses at the guess reach
    ~1e19 times its modulus and carry the rounding of their exponent, ~1e-13 of their scale:
    successive rules then differ by rounding alone, above 64 eps, and a rule agreeing to 64
    eps is luck (the profile's Chebyshev tail accepts such a stall the same way)."""
    for k in range(len(gaps) - 2):
        stalled = min(gaps[k + 1], gaps[k + 2]) > 0.1 * gaps[k]
        if gaps[k] <= STRESS_NOISE and stalled:
            return orders[k]
    return -1


def start_guess(wall: Wall) -> tuple[float, float]:
    """The homogeneous-growth guess: r_i^2 = 2 G(R_N) / (lambda_z (R_N^2 - 1)), lambda_z the
    prescribed stretch or, under force control, the stretch at which the layers' small-strain
    axial forces mu A (lambda_z / g_z - 1) (A the grown section) cancel: a stiff skin's g_z
    sets it (an area-weighted mean put a skin 1000 times as stiff growing to g_z = 2.1 on a
    soft Gent layer at 1.08, from which no free state was found: the layer's lock lies
    between)."""
    tube = wall.tube
    if tube.control == "stretch":
        lz = tube.stretch
    else:
        weights = [
            ply.layer.shear_modulus * w * R * g[0] * g[1]
            for ply, (R, w, g, _, _) in zip(wall.plies, wall.grids)
        ]
        num = sum(a.sum() for a in weights)
        lz = num / sum((a / g[2]).sum() for a, (_, _, g, _, _) in zip(weights, wall.grids))
    return math.sqrt(2.0 * wall.faces_G[-1] / (lz * (tube.outer_radius**2 - 1.0))), lz
