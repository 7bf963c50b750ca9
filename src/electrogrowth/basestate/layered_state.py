"""The solved base state of a layered tube (:class:`LayeredState`): its fields through the
wall, profiles and JSON record (derivations in docs/derivation-layered.md).

A state is built from the root (r_i, c, lambda_z) that :mod:`.layered` solved for, and
re-integrated with Chebyshev interpolants per layer, independently of the Gauss-Legendre
quadrature that fixed the root (the profile

    sigma_rr(R) = -P_i + int_{r_i}^{r(R)} (tau_2 - tau_1) dr / r,  sigma_ii = tau_i - p,
    p = tau_1 - sigma_rr,

and the residuals in ``quadrature_error``, which the solve checks).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import ParameterError
from ..labelled import layered_state_dataset
from ..model.layers import Layer, Tube
from ..outcomes import json_number
from .chebyshev_series import ChebyshevSeries
from .plies import Wall, chebyshev, stalled_noise

__all__ = ["LayeredState"]

#: the resolution asked of the stress scale int (|tau_1| + |tau_2|) dr / r, a magnitude that
#: only divides the residuals: its integrand has a kink where a stress changes sign in the
#: layer, so its series converges like 1 / degree^2 and no degree resolves it to 1e-2 rtol
#: (an I2-softening layer grown radially, g_r = 4.3158: a tail of 1.1e-8 at 4096, "not
#: resolved", between states that were; check round 24, case 2-108)
SCALE_TOL = 1e-3


@dataclasses.dataclass(frozen=True)
class LayeredState:
    """The solved base state of a layered tube; methods take the reference radius R in
    [1, R_N] (vectorised; at an interface, ``side`` "outer" or "inner" picks the layer).

    Attributes: lambda_i = r_i, lambda_o = r_o / R_N, r_i, r_o, radii (r at every face and
    interface, R = 1, R_1, ..., R_N), charge c (D_r = c / r), stretch lambda_z (solved under force
    control), axial_force N = 2 pi int sigma_zz r dr (the wall's resultant), end_force (N less
    the pressure load on closed ends: what the ends carry besides it), the voltage threshold of
    the voltage branch, its kind and lambda_i (inf for an asymptote), and quadrature_error, the
    residuals (outer traction over the stress scale, voltage, axial force) of an independent
    Chebyshev quadrature per layer.
    """

    tube: Tube
    lambda_i: float
    lambda_o: float
    r_i: float
    r_o: float
    radii: tuple[float, ...]
    charge: float
    stretch: float
    axial_force: float
    end_force: float
    quadrature_error: float = 0.0
    # the resolution of that check: its residuals' share of a Chebyshev series that stopped
    # at the noise of its integrand (next to a Gent lock), 0 where every series converged
    quadrature_noise: float = 0.0
    _wall: Wall = dataclasses.field(default=None, repr=False, compare=False)
    # per layer: (antiderivative of d sigma_rr / dR from R_{k-1}, sigma_rr(R_{k-1}))
    _sigma: tuple = dataclasses.field(default=(), repr=False, compare=False)
    # the tube without its voltage, prepared: the voltage branch's threshold, walked on demand
    _prep: object = dataclasses.field(default=None, repr=False, compare=False)
    # a continued state's direction of rising load along its branch (warm.py), for the next
    _rise: object = dataclasses.field(default=None, repr=False, compare=False)

    @property
    def voltage_threshold(self) -> float:
        """Vbar where the voltage branch at the tube's pressures is lost (walked when first
        asked for: a solve itself walks the branch only up to the tube's Vbar)."""
        return self._prep.voltage.value

    @property
    def threshold_kind(self) -> str:
        """limit point, asymptote, locking or none (basestate/thresholds.py Threshold)."""
        return self._prep.voltage.kind

    @property
    def threshold_lambda_i(self) -> float:
        """lambda_i at the voltage threshold (inf for an asymptote)."""
        return self._prep.voltage.lambda_i

    @classmethod
    def _build(cls, tube, wall, prep, x, lz, c, rtol, compiled: bool = False) -> LayeredState:
        """Chebyshev interpolants per layer (degree doubled until the tail < 1e-2 rtol) of the
        integrands of sigma_rr, its scale, V and Nint: a quadrature independent of the Gauss one
        that fixed (r_i, c, lambda_z). With ``compiled`` (a march's continued state, whose
        Newton solve used them too) the closed forms of its neo-Hookean layers of constant
        growth instead (neo_hookean_wall.py): sigma_rr through such a layer is
        :class:`~.neo_hookean_wall.TractionProfile`, and the residuals below check Newton's
        convergence."""
        sigma, s_a, totals = [], -tube.inner_pressure, np.zeros(3)
        noise = np.zeros(4)  # (T, scale, V, Nint): what the check's series do not resolve
        r2 = wall.radii2(x, lz)
        for k, ply in enumerate(wall.plies):
            if compiled and wall.closed_form[k]:
                from .neo_hookean_wall import TractionProfile  # numba: loaded by the march

                layer = ply.layer
                prof = TractionProfile(
                    float(r2[k]), float(lz), float(c), ply.a, tuple(layer.growth),
                    layer.shear_modulus, layer.permittivity,
                )  # fmt: skip
                T, *rest = prof.profile(np.array([ply.b]))[:, 0]
                totals += rest
                sigma.append((prof, s_a))
                s_a = s_a + float(T)
                continue

            def f(R, ply=ply):
                g = ply.layer.growth_at(R)
                r, r2, ls, d = ply.kinematics(R, g, ply.G(R), x, lz, c)
                tau = ply.stress(*ls, d)
                jr = np.prod(g, 0) * R / lz
                return np.stack(
                    [
                        (tau[1] - tau[0]) * jr / r2,
                        (abs(tau[1]) + abs(tau[0])) * jr / r2,
                        ply.field(*ls, d) * jr / r,
                        math.pi * (2.0 * tau[2] - tau[0] - tau[1]) * jr,
                    ],
                    axis=-1,
                )

            mu, eps = ply.layer.shear_modulus, ply.layer.permittivity
            unit = np.array([mu, mu, math.sqrt(mu / eps), mu])  # stress, field: the layer's
            tol = np.array([0.01 * rtol, SCALE_TOL, 0.01 * rtol, 0.01 * rtol])
            coef = chebyshev(f, ply.a, ply.b, tol, "base-state profile", unit)
            noise += (ply.b - ply.a) * stalled_noise(coef, tol, unit)
            antider = ChebyshevSeries(coef[:, 0], domain=[ply.a, ply.b]).integ(lbnd=ply.a)
            weights = np.zeros(coef.shape[0])  # int_a^b T_k = (b - a) / (1 - k^2), k even
            weights[::2] = (ply.b - ply.a) / (1.0 - np.arange(0, coef.shape[0], 2) ** 2)
            totals += weights @ coef[:, 1:]
            sigma.append((antider, s_a))
            s_a = s_a + float(antider(ply.b))
        scale, volt, nint = totals
        r = np.sqrt(r2)
        P_i, P_o = tube.inner_pressure, tube.outer_pressure
        ends = math.pi * (P_i * r2[0] - P_o * r2[-1])
        N = float(nint + ends)
        applied = N - ends if tube.closed_ends else N
        thick = tube.outer_radius - 1.0
        errors = [
            abs(s_a + P_o) / max(1.0, abs(scale)),
            abs(volt / thick - tube.voltage) / max(1.0, tube.voltage),
        ]
        floors = [noise[0] / max(1.0, abs(scale)), noise[2] / thick / max(1.0, tube.voltage)]
        if tube.control == "force":
            # the wall's axial stress scale: scale is int (|tau_rr| + |tau_tt|) dr / r, and
            # a stress uniform in r carries pi (r_o^2 - r_i^2) / ln(r_o / r_i) times that in
            # int tau 2 pi r dr. At free ends N_int is ~0 while its integrand is ~mu times
            # the wall's area: measured against |N_int|, a stiff core's rounding (1000 : 1)
            # refused every node count
            # (its limit 2 pi r^2 where the wall is thin against r: an inflated tube next to
            # its asymptote, r_i ~ 1e9, where the quotient was 0 / 0 and numpy warned)
            d, r2_i = float(r2[-1] - r2[0]), float(r2[0])
            half_log = 0.5 * math.log1p(d / r2_i)
            area = math.pi * d / half_log if half_log > 0 else 2.0 * math.pi * r2_i
            axial = max(1.0, abs(nint), abs(ends), abs(scale) * area)
            errors.append(abs(applied - tube.axial_force) / axial)
            floors.append(noise[3] / axial)
        return cls(
            tube,
            float(x),
            float(r[-1]) / tube.outer_radius,
            float(x),
            float(r[-1]),
            tuple(float(v) for v in r),
            float(c),
            float(lz),
            N,
            float(applied),
            float(max(errors)),
            float(max(floors)),
            wall,
            tuple(sigma),
            prep,
        )

    @property
    def face_pressures(self) -> tuple[float, float]:
        """(P_i, P_o), the follower pressures on the inner and outer face."""
        return self.tube.inner_pressure, self.tube.outer_pressure

    @property
    def current_length(self) -> float:
        """l / R_i = lambda_z L, the deformed length (sets k = n pi / l)."""
        return self.stretch * self.tube.length

    @property
    def interface_radii(self) -> tuple[float, ...]:
        """r at the interfaces between layers (inner to outer; empty for one layer)."""
        return self.radii[1:-1]

    @property
    def hoop_stretches(self) -> tuple[float, ...]:
        """r / R at every face and interface."""
        return tuple(r / R for r, R in zip(self.radii, self.tube.radii))

    # -- fields through the wall ---------------------------------------------------------------

    def _fields(self, R, side: str = "outer", moduli: bool = False) -> dict:
        R = np.asarray(R, float)
        radii = self.tube.radii
        if np.any((R < 1.0 - 1e-12) | (R > radii[-1] * (1.0 + 1e-12))):
            raise ParameterError(f"R outside the wall [1, {radii[-1]:g}]")
        if side not in ("outer", "inner"):
            raise ParameterError(f"side = {side!r} is unknown; choose outer or inner")
        which = np.searchsorted(
            np.array(radii[1:-1]), R, side="right" if side == "outer" else "left"
        )
        out: dict = {}
        for k in range(len(self._wall.plies)):
            mask = which == k
            if not mask.any():
                continue
            for key, v in self.layer_fields(R[mask], k, moduli).items():
                if key not in out:
                    out[key] = np.zeros(R.shape + np.shape(v)[1:])
                out[key][mask] = v
        return out

    def layer_fields(self, R, k: int, moduli: bool = False) -> dict:
        """The fields of layer k (0-based) at reference radii R inside it (1-d array): r,
        l1, l2, l3, d, E, sigma_rr, tau1..3, g_r, g_theta, g_z (and the moduli)."""
        ply = self._wall.plies[k]
        Rk = np.clip(R, ply.a, ply.b)
        g = ply.layer.growth_at(Rk)
        r, _, ls, d = ply.kinematics(Rk, g, ply.G(Rk), self.r_i, self.stretch, self.charge)
        antider, s_a = self._sigma[k]
        vals = {
            "r": r,
            "l1": ls[0],
            "l2": ls[1],
            "l3": ls[2],
            "d": d,
            "E": ply.field(*ls, d),
            "sigma_rr": s_a + antider(Rk),
        }
        vals.update(zip(("tau1", "tau2", "tau3"), ply.stress(*ls, d)))
        vals["g_r"], vals["g_theta"], vals["g_z"] = g
        if moduli:
            vals["moduli"] = ply.moduli(*ls, d)
        return vals

    def radius(self, R, *, side: str = "outer") -> np.ndarray:
        """r(R) = sqrt(r_i^2 + 2 G(R) / lambda_z)."""
        return self._fields(R, side)["r"]

    def reference_radius(self, r, *, layer: int) -> np.ndarray:
        """R(r) in layer ``layer`` (0-based), the inverse of :meth:`radius` there: closed form
        R^2 = R_{k-1}^2 + lambda_z (r^2 - r_{k-1}^2) / J for constant growth, bisection to
        rounding for graded growth (r(R) increases)."""
        r = np.asarray(r, float)
        a, b = self.tube.radii[layer], self.tube.radii[layer + 1]
        ply = self.tube.layers[layer]
        if not ply.graded:
            J = float(np.prod(ply.growth))
            R2 = a * a + self.stretch * (r * r - self.radii[layer] ** 2) / J
            return np.clip(np.sqrt(np.maximum(R2, 0.0)), a, b)
        lo, hi = np.full(r.shape, a), np.full(r.shape, b)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            below = self.radius(mid) < r  # r is continuous across interfaces
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        return 0.5 * (lo + hi)

    def elastic_stretches(self, R, *, side: str = "outer"):
        """(l1, l2, l3) = (1 / (l2 l3), r / (g_theta R), lambda_z / g_z)."""
        f = self._fields(R, side)
        return f["l1"], f["l2"], f["l3"]

    def displacement(self, R, *, side: str = "outer") -> np.ndarray:
        """Radial current electric displacement D_r = c / r (continuous across interfaces)."""
        return self._fields(R, side)["d"]

    def electric_field(self, R, *, side: str = "outer") -> np.ndarray:
        """Radial current field E_r (d / eps_k for an ideal dielectric: jumps at interfaces)."""
        return self._fields(R, side)["E"]

    def sigma_rr(self, R, *, side: str = "outer") -> np.ndarray:
        """sigma_rr(R) = -P_i + int_{r_i}^{r(R)} (tau_2 - tau_1) dr / r (continuous)."""
        return self._fields(R, side)["sigma_rr"]

    def stresses(self, R, *, side: str = "outer"):
        """(sigma_rr, sigma_tt, sigma_zz), sigma_ii = tau_i - p with p = tau_1 - sigma_rr."""
        f = self._fields(R, side)
        p = f["tau1"] - f["sigma_rr"]
        return f["sigma_rr"], f["tau2"] - p, f["tau3"] - p

    def pressure(self, R, *, side: str = "outer") -> np.ndarray:
        """Lagrange multiplier p = tau_1 - sigma_rr (jumps at interfaces with tau_1)."""
        f = self._fields(R, side)
        return f["tau1"] - f["sigma_rr"]

    def moduli(self, R, *, side: str = "outer") -> np.ndarray:
        """Updated moduli (moduli.MODULI_NAMES order) with the layer's scaling (A mu_k,
        Gamma sqrt(mu_k / eps_k), K / eps_k), shape R.shape + (23,)."""
        return self._fields(R, side, moduli=True)["moduli"]

    def to_xarray(self, points: int = 101):
        """The through-wall profiles (:meth:`profiles`) as an ``xarray.Dataset`` on dimension
        point (R and layer are coordinates), units and descriptions in attributes."""
        return layered_state_dataset(self, points)

    def profiles(self, n: int = 101) -> dict[str, np.ndarray]:
        """Through-wall profiles at about n points, spread over the layers by thickness, each
        layer's grid with both its faces (an interface appears twice: inner, then outer side).
        Keys: layer, R, r, lambda, sigma_rr, sigma_tt, sigma_zz, p, D_r, E_r."""
        parts = []
        radii = self.tube.radii
        for k, (a, b) in enumerate(zip(radii, radii[1:])):
            m = max(2, round(n * (b - a) / (radii[-1] - 1.0)))
            R = np.linspace(a, b, m)
            side = np.where(np.arange(m) == m - 1, "inner", "outer")
            for s in ("outer", "inner"):
                sel = side == s
                if sel.any():
                    parts.append((k, R[sel], self._fields(R[sel], s)))
        cat = lambda key: np.concatenate([f[key] for _, _, f in parts])  # noqa: E731
        R = np.concatenate([R for _, R, _ in parts])
        order = np.lexsort((np.concatenate([np.full(len(R_), k) for k, R_, _ in parts]), R))
        p = cat("tau1") - cat("sigma_rr")
        out = {
            "layer": np.concatenate([np.full(len(R_), k) for k, R_, _ in parts]),
            "R": R,
            "r": cat("r"),
            "lambda": cat("r") / R,
            "sigma_rr": cat("sigma_rr"),
            "sigma_tt": cat("tau2") - p,
            "sigma_zz": cat("tau3") - p,
            "p": p,
            "D_r": cat("d"),
            "E_r": cat("E"),
        }
        return {key: v[order] for key, v in out.items()}

    def as_dict(self) -> dict:
        """The JSON record (inf -> null): the tube, every face and interface, charge, threshold,
        stretch, axial and end force, extremes of the principal Cauchy stresses (401 points)."""
        t = self.tube
        prof = self.profiles(401)
        record = {
            "material": " / ".join(layer.material.name for layer in t.layers),
            "layers": [_layer_record(layer) for layer in t.layers],
            "outer_radius": t.outer_radius,
            "length": t.length,
            "control": t.control,
            "voltage": t.voltage,
            "inner_pressure": t.inner_pressure,
            "outer_pressure": t.outer_pressure,
            "closed_ends": t.closed_ends,
            "lambda_i": self.lambda_i,
            "lambda_o": self.lambda_o,
            "r_i": self.r_i,
            "r_o": self.r_o,
            "interface_radii": list(self.interface_radii),
            "radii": list(self.radii),
            "charge": self.charge,
            "stretch": self.stretch,
            "current_length": self.current_length,
            "voltage_threshold": json_number(self.voltage_threshold),
            "threshold_kind": self.threshold_kind,
            "threshold_lambda_i": json_number(self.threshold_lambda_i),
            "axial_force": self.axial_force,
            "end_force": self.end_force,
            "quadrature_error": self.quadrature_error,
        }
        for key in ("sigma_rr", "sigma_tt", "sigma_zz"):
            record[f"{key}_min"] = float(prof[key].min())
            record[f"{key}_max"] = float(prof[key].max())
        return record


def _layer_record(layer: Layer) -> dict:
    g = layer.growth
    if layer.graded:
        g = {"inner": list(g.inner), "outer": list(g.outer)} if hasattr(g, "inner") else repr(g)
    else:
        g = list(g)
    return {
        "outer_radius": layer.outer_radius,
        "material": layer.material.name,
        "shear_modulus": layer.shear_modulus,
        "permittivity": layer.permittivity,
        "growth": g,
    }
