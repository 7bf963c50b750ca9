"""The solved base state of the paper's uniform tube (:func:`.uniform.solve_uniform`): the
through-wall profile sigma_rr(R) = int_{r_i}^{r} (tau_2 - tau_1) dr / r, the fields, stresses
and moduli at any R, and their tables for the incremental kernels.

Two routes, as in ``uniform.py``: the ideal neo-Hookean dielectric in closed form (sigma_rr
by (NH-1), N by (NH-4), moduli by ``moduli.neo_hookean_moduli``); every other energy by a
Chebyshev antiderivative of Gauss-Legendre-solved state, exact to quadrature accuracy at any
R and re-integrated independently (its ``quadrature_error``). docs/derivation-base-state.md.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..errors import ConvergenceError, ParameterError
from ..labelled import base_state_dataset
from ..model.layers import Tube
from ..model.moduli import neo_hookean_moduli
from ..summary import base_state_html
from . import neo_hookean
from .chebyshev_series import ChebyshevSeries, chebinterpolate
from .voltage import STRESS_NOISE, UniformWall, energy_kind

#: the rounding floor of the integrands' trailing coefficients, relative to _tail_scale
#: (voltage.STRESS_NOISE); above it, a tail that no longer falls from degree 256 to 512 is
#: rounding noise too
_NOISE = STRESS_NOISE


def _tail_scale(coef) -> np.ndarray:
    """What the trailing Chebyshev coefficients of the four integrands of
    :meth:`UniformState._build` are measured against where they stall: the stress scale
    (|tau_1| + |tau_2|) for the stress differences, whose cancellation in a near-homogeneous
    state (a tube compressed towards a Gent lock: stresses ~4e4, differences ~1e-12) leaves
    the rounding noise of the stresses, not of their difference; max(|V|, 1) for the field."""
    mag = abs(coef).max(0)
    stress = max(mag[1], 1.0)
    return np.array([stress, stress, max(mag[2], stress), max(mag[3], 1.0)])


@dataclasses.dataclass(frozen=True)
class UniformState:
    """The solved base state; methods take the reference radius R in [1, Rbar_o] (vectorised).

    Attributes: lambda_i = r_i, lambda_o = r_o / Rbar_o, r_i, r_o, charge c (D_r = c / r), the
    Vbar threshold and its kind, the axial force N = 2 pi int sigma_zz r dr holding lambda_z,
    and quadrature_error, the residuals (outer traction over the stress scale, voltage) of an
    independent Chebyshev quadrature of the solved state (neo-Hookean: the traction residual
    of (*) at the solved lambda_i and c, rounding level).
    """

    tube: Tube
    lambda_i: float
    lambda_o: float
    r_i: float
    r_o: float
    charge: float
    voltage_threshold: float
    threshold_kind: str
    axial_force: float
    quadrature_error: float = 0.0
    threshold_lambda_i: float = math.inf
    _wall: UniformWall = dataclasses.field(default=None, repr=False, compare=False)
    # sigma_rr(R) on the generic route; None: the neo-Hookean closed form (NH-1)
    _sigma: cheb.Chebyshev | None = dataclasses.field(default=None, repr=False, compare=False)

    @classmethod
    def _build(cls, tube, wall, lam, info, rtol) -> UniformState:
        """Chebyshev interpolants (degree doubled until the tail < rtol) of the integrands of
        sigma_rr = int_1^R (tau_2 - tau_1) dr/r, of N = pi int (2 tau_3 - tau_1 - tau_2) r dr
        (sigma_rr vanishes on both faces, so int sigma_rr r dr = -int (tau_2 - tau_1) r dr / 2)
        and of V = int E_r dr: a second quadrature, independent of the Gauss one that fixed
        lambda_i and c, whose residuals sigma_rr(Rbar_o) and V - Vbar (Rbar_o - 1) give
        quadrature_error."""
        c = wall.charge_at(lam, tube.voltage) if tube.voltage > 0 else 0.0
        Ro, mat = tube.outer_radius, tube.material

        def integrands(x):
            r, stretches, drdR = wall.kinematics(lam, 1.0 + 0.5 * (Ro - 1.0) * (x + 1.0))
            tau = mat.stress(*stretches, c / r)
            e = mat.electric_field(*stretches, c / r) if energy_kind(mat) == "general" else c / r
            return np.stack(
                [
                    (tau[1] - tau[0]) * drdR / r,
                    (tau[1] + tau[0]) * drdR / r,
                    (2 * tau[2] - tau[0] - tau[1]) * r * drdR,
                    e * drdR,
                ],
                axis=-1,
            )

        tails = []
        for deg in (32, 64, 128, 256, 512):
            coef = chebinterpolate(integrands, deg)
            if np.all(abs(coef[-4:]).max(0) <= 0.01 * rtol * np.maximum(abs(coef).max(0), 1.0)):
                break
            tails.append(abs(coef[-4:]).max(0) / _tail_scale(coef))
        else:  # resolved down to the rounding of the stresses? (the residuals below judge)
            if not np.all((tails[-1] <= _NOISE) | (tails[-1] >= 0.1 * tails[-2])):
                raise ConvergenceError(f"base-state profile not resolved to rtol = {rtol}")
        sigma = ChebyshevSeries(coef[:, 0], domain=[1.0, Ro]).integ(lbnd=1.0)
        weights = np.zeros(coef.shape[0])  # int_1^Ro T_k = (Ro - 1) / (1 - k^2), k even
        weights[::2] = (Ro - 1.0) / (1.0 - np.arange(0, coef.shape[0], 2) ** 2)
        scale, force, volt = weights @ coef[:, 1:]
        r_o = math.sqrt(lam**2 + wall.b * (Ro**2 - 1.0))
        error = max(
            abs(sigma(Ro)) / max(1.0, abs(scale)),
            abs(volt / (Ro - 1.0) - tube.voltage) / max(1.0, tube.voltage),
        )
        return cls(
            tube,
            float(lam),
            r_o / Ro,
            float(lam),
            r_o,
            c,
            info.value,
            info.kind,
            float(math.pi * force),
            float(error),
            float(info.lambda_i),
            wall,
            sigma,
        )

    @classmethod
    def _neo_hookean(cls, tube, wall, lam, info) -> UniformState:
        """The closed forms at lambda_i = lam (neo_hookean.py)."""
        c, r_o, force, error = neo_hookean.state_at(tube, wall.b, lam)
        return cls(
            tube, lam, r_o / tube.outer_radius, lam, r_o, c, info.value, info.kind, force,
            error, float(info.lambda_i), wall, None,
        )  # fmt: skip

    def _inside(self, R) -> np.ndarray:
        """R as a float array, or ParameterError if it leaves the wall."""
        R = np.asarray(R, float)
        if np.any((R < 1.0 - 1e-12) | (R > self.tube.outer_radius * (1.0 + 1e-12))):
            raise ParameterError(f"R outside the wall [1, {self.tube.outer_radius:g}]")
        return R

    def _local(self, R):
        R = self._inside(R)
        r, stretches, _ = self._wall.kinematics(self.lambda_i, R)
        return R, r, stretches, self.charge / r

    def _tau(self, stretches, d) -> np.ndarray:
        """tau_i (Maxwell included); neo-Hookean (l1^2 + d^2, l2^2, l3^2)."""
        if self._sigma is not None:
            return self.tube.material.stress(*stretches, d)
        l1, l2, l3 = stretches
        return np.array([l1**2 + d**2, l2**2, l3**2])

    def _sigma_rr(self, R, r) -> np.ndarray:
        """sigma_rr: the quadrature's antiderivative, or the closed form (NH-1)."""
        if self._sigma is not None:
            return self._sigma(R)
        return neo_hookean.sigma_rr(self.tube, self._wall.b, self.r_i, self.r_o, R, r)

    # -- the State protocol (_types.State): one layer, so ``side`` changes nothing ------------

    @property
    def stretch(self) -> float:
        """lambda_z, prescribed."""
        return self.tube.stretch

    @property
    def radii(self) -> tuple[float, float]:
        """(r_i, r_o): the current faces (a uniform tube has no interface)."""
        return (self.r_i, self.r_o)

    @property
    def interface_radii(self) -> tuple[float, ...]:
        return ()

    @property
    def hoop_stretches(self) -> tuple[float, float]:
        """r / R at the inner and outer face."""
        return (self.lambda_i, self.lambda_o)

    @property
    def end_force(self) -> float:
        """The force the ends carry: N (no pressure on them)."""
        return self.axial_force

    def reference_radius(self, r, *, layer: int = 0) -> np.ndarray:
        """R(r) = sqrt(1 + lambda_z (r^2 - r_i^2) / g^3) (paper eq. 15, R_i = 1)."""
        t = self.tube
        return np.sqrt(1.0 + t.stretch * (np.asarray(r) ** 2 - self.r_i**2) / t.growth**3)

    @property
    def face_pressures(self) -> tuple[float, float]:
        """(P_i, P_o): no follower pressure on the faces of the paper's tube."""
        return 0.0, 0.0

    @property
    def current_length(self) -> float:
        """l / R_i = lambda_z L, the deformed length (sets k = n pi / l)."""
        return self.tube.stretch * self.tube.length

    def radius(self, R, *, side: str = "outer") -> np.ndarray:
        """r(R) = sqrt(r_i^2 + g^3 (R^2 - 1) / lambda_z)."""
        return self._local(R)[1]

    def elastic_stretches(
        self, R, *, side: str = "outer"
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(l1, l2, l3) = (g^2 R / (r lambda_z), r / (g R), lambda_z / g)."""
        return self._local(R)[2]

    def displacement(self, R, *, side: str = "outer") -> np.ndarray:
        """Radial current electric displacement D_r = c / r."""
        return self._local(R)[3]

    def electric_field(self, R, *, side: str = "outer") -> np.ndarray:
        """Radial current electric field E_r = dOmega/dD~ / l1 (= D_r for ideal dielectrics)."""
        _, _, stretches, d = self._local(R)
        if self._sigma is None:
            return d
        return self.tube.material.electric_field(*stretches, d)

    def sigma_rr(self, R, *, side: str = "outer") -> np.ndarray:
        """Radial Cauchy stress sigma_rr(R) = int_{r_i}^{r(R)} (tau_2 - tau_1) dr / r."""
        R, r, _, _ = self._local(R)
        return self._sigma_rr(R, r)

    def stresses(self, R, *, side: str = "outer") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(sigma_rr, sigma_tt, sigma_zz), sigma_ii = tau_i - p with p = tau_1 - sigma_rr."""
        R, r, stretches, d = self._local(R)
        tau = self._tau(stretches, d)
        srr = self._sigma_rr(R, r)
        return srr, tau[1] - tau[0] + srr, tau[2] - tau[0] + srr

    def pressure(self, R, *, side: str = "outer") -> np.ndarray:
        """Lagrange multiplier p = tau_1 - sigma_rr."""
        R, r, stretches, d = self._local(R)
        return self._tau(stretches, d)[0] - self._sigma_rr(R, r)

    def moduli(self, R, *, side: str = "outer") -> np.ndarray:
        """Updated moduli (moduli.MODULI_NAMES order), shape R.shape + (23,)."""
        _, _, stretches, d = self._local(R)
        if self._sigma is None:
            return neo_hookean_moduli(*stretches, d)
        return self.tube.material.moduli(*stretches, d)

    def table_fields(self, R) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(r, moduli, p) at the radii R (1-d) in one evaluation: the same arrays as
        :meth:`radius`, :meth:`moduli` and :meth:`pressure` (the Chebyshev table's input,
        incremental/radial_table.py, built at every step of a march)."""
        if self._sigma is None:  # the closed form, compiled; its NumPy twin: the three calls
            R = self._inside(R)
            t = self.tube
            b = self._wall.b
            return _closed_form_fields().nh_fields(
                R, self.r_i, b, t.growth, t.stretch, self.charge, t.outer_radius, self.r_o
            )
        R, r, stretches, d = self._local(R)
        return (
            r,
            self.tube.material.moduli(*stretches, d),
            self._tau(stretches, d)[0] - self._sigma_rr(R, r),
        )

    def table_block(self, R, J: float) -> np.ndarray:
        """The (n, 26) array [23 moduli, p, r, w] at the radii R (1-d), w = (dr/dR) / r =
        J R / (lambda_z r^2) (J = det F_g): the rows of the Chebyshev table
        (incremental/radial_table.py), the same bits as :meth:`table_fields` stacked with w
        in NumPy; the closed form in one compiled pass."""
        if self._sigma is None:
            t = self.tube
            return _closed_form_fields().nh_table_block(
                R, self.r_i, self._wall.b, t.growth, t.stretch, self.charge, t.outer_radius,
                self.r_o, J,
            )  # fmt: skip
        r, moduli, p = self.table_fields(R)
        return np.column_stack([moduli, p, r, J * R / (self.stretch * r * r)])

    def as_dict(self) -> dict:
        """The JSON record of the state (inf -> null): geometry, charge, threshold, axial
        force and the extremes of the three principal Cauchy stresses over 401 points of
        the wall."""
        p = self.tube
        prof = self.profiles(401)
        record = {
            "material": p.material.name,
            "outer_radius": p.outer_radius,
            "growth": p.growth,
            "stretch": p.stretch,
            "voltage": p.voltage,
            "length": p.length,
            "lambda_i": self.lambda_i,
            "lambda_o": self.lambda_o,
            "r_i": self.r_i,
            "r_o": self.r_o,
            "charge": self.charge,
            "voltage_threshold": (
                float(self.voltage_threshold) if math.isfinite(self.voltage_threshold) else None
            ),
            "threshold_kind": self.threshold_kind,
            "threshold_lambda_i": (
                float(self.threshold_lambda_i) if math.isfinite(self.threshold_lambda_i) else None
            ),
            "axial_force": self.axial_force,
        }
        for key in ("sigma_rr", "sigma_tt", "sigma_zz"):
            record[f"{key}_min"] = float(prof[key].min())
            record[f"{key}_max"] = float(prof[key].max())
        return record

    def to_xarray(self, points: int = 101):
        """The through-wall profiles (:meth:`profiles`) as an ``xarray.Dataset`` on dimension
        R, with units and descriptions in attributes (labelled.py; needs xarray)."""
        return base_state_dataset(self, points)

    def _repr_html_(self) -> str:
        return base_state_html(self)

    def profiles(self, n: int = 101) -> dict[str, np.ndarray]:
        """Through-wall profiles at n equally spaced R in [1, Rbar_o]: keys R, r, lambda
        (= r / R), sigma_rr, sigma_tt, sigma_zz, p, D_r, E_r."""
        R = np.linspace(1.0, self.tube.outer_radius, n)
        r = self.radius(R)
        srr, stt, szz = self.stresses(R)
        return {
            "R": R,
            "r": r,
            "lambda": r / R,
            "sigma_rr": srr,
            "sigma_tt": stt,
            "sigma_zz": szz,
            "p": self.pressure(R),
            "D_r": self.displacement(R),
            "E_r": self.electric_field(R),
        }


def _closed_form_fields():
    """The module closed_form_fields, imported at the first table (numba only for tables:
    a base state alone, the ``state`` command, never loads it) and remembered (a march
    builds a table at every evaluation)."""
    global _CLOSED_FORM_FIELDS
    if _CLOSED_FORM_FIELDS is None:
        from . import closed_form_fields

        _CLOSED_FORM_FIELDS = closed_form_fields
    return _CLOSED_FORM_FIELDS


_CLOSED_FORM_FIELDS = None
