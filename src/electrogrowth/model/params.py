"""The parameters of a grown, stretched, electrically loaded tube (paper Sec. 3.1).

Non-dimensional units: mu = eps = R_i = 1. Vary one field with ``dataclasses.replace``.
"""

from __future__ import annotations

import dataclasses
import math

from ..errors import ParameterError
from .materials import Material, neo_hookean


def _check(name: str, value: float, valid: str, ok) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError(f"{name} = {value!r} is not a number; valid range: {valid}")
    if not math.isfinite(value) or not ok(value):
        raise ParameterError(f"{name} = {value!r} is out of range; valid range: {valid}")


@dataclasses.dataclass(frozen=True)
class TubeParameters:
    """One tube and its loading.

    Parameters
    ----------
    outer_radius : float
        Rbar_o = R_o / R_i > 1, the undeformed outer radius (inner radius is 1).
    length : float
        L / R_i > 0, the undeformed length (sets the axial wavenumber k = n pi / (lambda_z L)).
    growth : float
        Isotropic growth factor g > 0 (F_g = g I).
    stretch : float
        Total axial stretch lambda_z = l / L > 0, growth included.
    voltage : float
        Vbar = V / (R_o - R_i) sqrt(eps / mu) >= 0, the radial voltage.
    material : Material
        The energy Omega(I1, I2, I4, I5, I6); default the ideal neo-Hookean dielectric.
    """

    outer_radius: float = 1.4
    length: float = 1.0
    growth: float = 1.0
    stretch: float = 1.0
    voltage: float = 0.0
    material: Material = dataclasses.field(default_factory=neo_hookean)

    def __post_init__(self):
        _check("outer radius Rbar_o", self.outer_radius, "1 < Rbar_o < inf", lambda v: v > 1)
        _check("length L", self.length, "0 < L < inf", lambda v: v > 0)
        _check("growth factor g", self.growth, "0 < g < inf", lambda v: v > 0)
        _check("axial stretch lambda_z", self.stretch, "0 < lambda_z < inf", lambda v: v > 0)
        _check("voltage Vbar", self.voltage, "0 <= Vbar < threshold", lambda v: v >= 0)
        if not isinstance(self.material, Material):
            raise ParameterError(f"material = {self.material!r} is not a Material")
        for f in ("outer_radius", "length", "growth", "stretch", "voltage"):
            object.__setattr__(self, f, float(getattr(self, f)))

    def at(self, name: str, value: float) -> TubeParameters:
        """This tube with the field ``name`` set to ``value`` (a control, or any field)."""
        return dataclasses.replace(self, **{name: float(value)})

    def reference(self) -> TubeParameters:
        """The unloaded tube (g = 1, lambda_z = 1, Vbar = 0): stress free, stable in every
        mode, where the stable sign of every target is read off."""
        return dataclasses.replace(self, growth=1.0, stretch=1.0, voltage=0.0)

    def as_dict(self) -> dict:
        """The tube as a JSON record: the material's name and the five fields."""
        return {
            "material": self.material.name,
            "outer_radius": self.outer_radius,
            "length": self.length,
            "growth": self.growth,
            "stretch": self.stretch,
            "voltage": self.voltage,
        }

    @property
    def physical_voltage(self) -> float:
        """V in units sqrt(mu/eps) R_i: V = Vbar (Rbar_o - 1)."""
        return self.voltage * (self.outer_radius - 1.0)


#: The control parameters a critical value can be solved for (fields of TubeParameters).
CONTROLS = ("growth", "stretch", "voltage")
#: The sides of a critical stretch: below or above lambda_z = g.
SIDES = ("compression", "extension")


def check_control(solve_for: str) -> str:
    """Return ``solve_for`` if it is a control, else raise ParameterError naming the choices."""
    if solve_for not in CONTROLS:
        raise ParameterError(
            f"solve_for = {solve_for!r} is unknown; choose growth, stretch or voltage"
        )
    return solve_for


#: The side a march takes by default: a stretch or an axial force compresses, a pressure
#: inflates (extension: the control increases; compression: it decreases).
DEFAULT_SIDE = {"stretch": "compression", "force": "compression", "pressure": "extension"}


def check_side(solve_for: str, side: str | None) -> str | None:
    """Validate ``side``; the default of DEFAULT_SIDE for the stretch, the axial force and
    the pressure, None otherwise (growth and voltage only increase)."""
    if side is not None and side not in SIDES:
        raise ParameterError(f"side = {side!r} is unknown; choose compression or extension")
    return side or DEFAULT_SIDE.get(str(solve_for))
