"""Physical units at the edge: quantities in, the non-dimensional tube out, and back.

The core works in units mu = eps = R_i = 1 (initial shear modulus, permittivity, undeformed
inner radius; docs/conventions.md). A tube given in physical units is converted here, once,
and results are converted back here, once:

    Rbar_o = R_o / R_i,    L = length / R_i,    Vbar = V / (R_o - R_i) sqrt(eps / mu),

so the scales of the results are R_i for lengths, mu for stresses and pressures, mu R_i^2
for forces (the axial force N), (R_o - R_i) sqrt(mu / eps) for the voltage (V = Vbar times
it), sqrt(mu eps) for the electric displacement and sqrt(mu / eps) for the electric field.
The permittivity is the absolute one, eps = eps_r eps_0; a plain number is read as the
relative permittivity eps_r.

Quantities are ``pint`` quantities or strings such as ``"2 mm"`` (pint is the ``units``
extra and imported only here, only when a quantity is converted). :class:`Scales` keeps the
SI magnitudes as plain floats, so it pickles and compares without pint.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re

from ..errors import MissingDependencyError, ParameterError
from .layers import Tube
from .materials import Material

#: The vacuum permittivity eps_0 in F/m (CODATA 2018).
EPSILON_0 = 8.8541878128e-12

#: A quantity's text: a number, then units multiplied, divided or raised to a one-digit
#: power ("2 mm", "4.16e-11 F/m", "3 N/m^2"). Checked before pint reads it: pint evaluates
#: arithmetic, so "2 m*9**9**9" ran forever (docs/security.md).
_UNIT = r"[^\W\d]+(?:\s*(?:\*\*|\^)\s*-?\d)?"
_QUANTITY_TEXT = re.compile(
    rf"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
    rf"(?:\s*{_UNIT}(?:\s*[*/]\s*{_UNIT}|\s+{_UNIT})*)?\s*"
)


@functools.lru_cache(maxsize=1)
def registry():
    """The one pint UnitRegistry of the package (the ``units`` extra)."""
    try:
        import pint
    except ImportError:
        raise MissingDependencyError(
            "physical units need the optional package pint; install it with"
            " pip install 'electrogrowth[units]'"
        ) from None
    return pint.UnitRegistry()


def magnitude(
    value, name: str, kind: str, unit: str, *, zero: bool = False, signed: bool = False
) -> float:
    """``value`` (a pint quantity or a string like "2 mm") in ``unit``, a float; a
    ParameterError names the value when it is no quantity, has no unit or is not a ``kind``
    (a word: "length", "pressure", ...) of the dimension of ``unit``, or is not positive
    (or zero, with ``zero``; any finite value with ``signed``: a load)."""
    if isinstance(value, str) and not (len(value) <= 100 and _QUANTITY_TEXT.fullmatch(value)):
        raise ParameterError(
            f"{name} = {value[:100]!r} is not a quantity: write a number and its unit, e.g."
            f" '2 {unit}' (units may be multiplied, divided and raised to a one-digit power)"
        )
    ureg = registry()
    try:
        q = ureg.Quantity(value) if isinstance(value, str) else value
    except Exception:  # noqa: BLE001 -- pint raises several kinds of parse errors
        raise ParameterError(f"{name} = {value!r} is not a quantity (e.g. '2 {unit}')") from None
    if not isinstance(q, ureg.Quantity) or q.dimensionless:
        raise ParameterError(f"{name} = {value!r} has no unit; give a {kind}, e.g. '2 {unit}'")
    if q.dimensionality != ureg.Quantity(1.0, unit).dimensionality:
        raise ParameterError(f"{name} = {value!r} is not a {kind} (its unit is {q.units:~})")
    out = float(q.to(unit).magnitude)
    if signed:  # a load: either sign
        if not math.isfinite(out):
            raise ParameterError(f"{name} = {value!r} is not a finite {kind}")
        return out
    if not (math.isfinite(out) and (out > 0 or (zero and out == 0))):
        bound = "0 <=" if zero else "0 <"
        raise ParameterError(f"{name} = {value!r} is out of range; need {bound} {name} < inf")
    return out


def absolute_permittivity(value) -> float:
    """The absolute permittivity eps in F/m: a number is eps_r (times eps_0), a quantity is
    eps itself (e.g. "4.16e-11 F/m")."""
    if isinstance(value, bool):
        raise ParameterError(f"permittivity = {value!r} is not a number")
    if isinstance(value, (int, float)) or (isinstance(value, str) and _is_number(value)):
        eps_r = float(value)
        if not (math.isfinite(eps_r) and eps_r > 0):
            raise ParameterError(
                f"relative permittivity eps_r = {value!r} is out of range; need 0 < eps_r < inf"
            )
        return eps_r * EPSILON_0
    return magnitude(value, "permittivity", "permittivity", "F/m")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


@dataclasses.dataclass(frozen=True)
class Scales:
    """The physical scales of a tube: SI magnitudes, NaN where not given.

    Parameters
    ----------
    inner_radius : float
        R_i in m, the unit of length.
    outer_radius : float
        R_o in m (with R_i, the wall thickness R_o - R_i in the voltage scale).
    shear_modulus : float
        mu in Pa, the unit of stress and pressure.
    permittivity : float
        eps = eps_r eps_0 in F/m.
    given_length : float
        The undeformed length in m, if one was given (0: none was, and none is reported;
        the non-dimensional L = 1 of a default tube is no length of the user's tube).

    Examples
    --------
    >>> s = Scales(2e-3, 2.8e-3, 1e5, 4.7 * EPSILON_0)
    >>> round(s.voltage_scale)            # (R_o - R_i) sqrt(mu / eps), in V
    39216
    >>> round(s.to_vbar(3000.0), 6)       # 3 kV
    0.076499
    """

    inner_radius: float = math.nan
    outer_radius: float = math.nan
    shear_modulus: float = math.nan
    permittivity: float = math.nan
    given_length: float = 0.0

    def __post_init__(self):
        if not (math.isfinite(self.given_length) and self.given_length >= 0):
            raise ParameterError(f"length = {self.given_length!r} m is out of range; need > 0")
        for name in ("inner_radius", "outer_radius", "shear_modulus", "permittivity"):
            value = float(getattr(self, name))
            if not (math.isnan(value) or (math.isfinite(value) and value > 0)):
                raise ParameterError(f"{name} = {value!r} is out of range; need 0 < value < inf")
            object.__setattr__(self, name, value)
        if self.outer_radius <= self.inner_radius:
            raise ParameterError(
                f"outer radius {self.outer_radius:g} m <= inner radius {self.inner_radius:g} m;"
                " need R_o > R_i"
            )

    @property
    def voltage_scale(self) -> float:
        """(R_o - R_i) sqrt(mu / eps) in V: V = Vbar times it (NaN without the four)."""
        return (self.outer_radius - self.inner_radius) * math.sqrt(
            self.shear_modulus / self.permittivity
        )

    def has(self, *names: str) -> bool:
        """Whether the scales ``names`` (field names) are all known."""
        return all(not math.isnan(getattr(self, n)) for n in names)

    def to_vbar(self, volts: float) -> float:
        """Vbar = V / (R_o - R_i) sqrt(eps / mu) of a voltage in V."""
        self._need("voltage", "inner_radius", "outer_radius", "shear_modulus", "permittivity")
        return volts / self.voltage_scale

    def voltage(self, vbar: float, unit: str = "kV"):
        """The physical voltage of Vbar, a pint quantity in ``unit``."""
        self._need("voltage", "inner_radius", "outer_radius", "shear_modulus", "permittivity")
        return registry().Quantity(vbar * self.voltage_scale, "V").to(unit)

    def length(self, x: float, unit: str = "mm"):
        """A length x R_i (a non-dimensional length x) as a pint quantity in ``unit``."""
        self._need("length", "inner_radius")
        return registry().Quantity(x * self.inner_radius, "m").to(unit)

    def stress(self, x: float, unit: str = "kPa"):
        """A stress or pressure x mu as a pint quantity in ``unit``."""
        self._need("stress", "shear_modulus")
        return registry().Quantity(x * self.shear_modulus, "Pa").to(unit)

    def force(self, x: float, unit: str = "N"):
        """A force x mu R_i^2 (the axial force N of the base state) as a pint quantity.

        >>> round(Scales(2e-3, 2.8e-3, 1e5).force(-0.25).to("N").magnitude, 12)
        -0.1
        """
        self._need("force", "shear_modulus", "inner_radius")
        return registry().Quantity(x * self.shear_modulus * self.inner_radius**2, "N").to(unit)

    def _need(self, what: str, *names: str) -> None:
        missing = [n for n in names if math.isnan(getattr(self, n))]
        if missing:
            raise ParameterError(
                f"a physical {what} needs the {', '.join(n.replace('_', ' ') for n in missing)}"
            )


def tube_from_quantities(
    inner_radius,
    outer_radius,
    *,
    shear_modulus=None,
    permittivity=None,
    length=None,
    voltage=0.0,
    growth: float = 1.0,
    stretch: float = 1.0,
    material: Material | None = None,
) -> tuple[Tube, Scales]:
    """The non-dimensional tube of a tube in physical units, and its :class:`Scales`.

    Parameters
    ----------
    inner_radius, outer_radius : quantity
        R_i and R_o, lengths ("2 mm"); Rbar_o = R_o / R_i.
    shear_modulus : quantity, optional
        mu, a pressure ("100 kPa"); needed for a voltage in volts and stresses in Pa.
    permittivity : float or quantity, optional
        eps_r (a number, times eps_0) or eps ("4.16e-11 F/m").
    length : quantity, optional
        The undeformed length; L = length / R_i (default L = 1).
    voltage : float or quantity
        A voltage ("3 kV"): Vbar = V / (R_o - R_i) sqrt(eps / mu); a number is Vbar itself.
    growth, stretch : float
        g and lambda_z, non-dimensional.
    material : Material, optional
        The energy in units mu = eps = 1 (default neo-Hookean).

    Returns
    -------
    (Tube, Scales)

    Examples
    --------
    >>> tube, scales = tube_from_quantities(
    ...     "2 mm", "2.8 mm", shear_modulus="100 kPa", permittivity=4.7, voltage="3 kV")
    >>> tube.outer_radius, round(tube.voltage, 6)
    (1.4, 0.076499)
    >>> print(f"{scales.voltage(0.1):.4g~P}")
    3.922 kV
    """
    r_i = magnitude(inner_radius, "inner radius", "length", "m")
    r_o = magnitude(outer_radius, "outer radius", "length", "m")
    mu = (
        math.nan
        if shear_modulus is None
        else magnitude(shear_modulus, "shear modulus", "pressure", "Pa")
    )
    eps = math.nan if permittivity is None else absolute_permittivity(permittivity)
    r_l = 0.0 if length is None else magnitude(length, "length", "length", "m")
    scales = Scales(r_i, r_o, mu, eps, r_l)
    if isinstance(voltage, (int, float)):
        vbar = voltage
    else:
        vbar = scales.to_vbar(magnitude(voltage, "voltage", "voltage", "V", zero=True))
    fields = {} if material is None else {"material": material}
    tube = Tube.uniform(
        outer_radius=r_o / r_i,
        length=1.0 if length is None else r_l / r_i,
        growth=growth,
        stretch=stretch,
        voltage=vbar,
        **fields,
    )
    return tube, scales
