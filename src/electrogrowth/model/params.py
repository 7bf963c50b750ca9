"""The ranges of a tube's numbers and the names of its controls (paper Sec. 3.1).

Non-dimensional units: mu = eps = R_i = 1. The tube itself is :class:`model.layers.Tube`;
the paper's tube is ``Tube.uniform(...)``.
"""

from __future__ import annotations

import math

from ..errors import ParameterError
from .controls import SIDES, check_side  # noqa: F401  (the sides live with the controls)


def given(value: float) -> str:
    """A number as given, for a refusal: the shortest text that reads back to it (its
    repr, or a ``g`` format: 300, 1.1e+08), so a value just past a bound never prints as
    the bound (1.0999999 after 1.1 read "= 1.1 ... valid range: > 1.1" with 6 digits,
    check round 29)."""
    v = float(value)
    if not math.isfinite(v):
        return repr(v)
    short = next(text for p in range(1, 18) if float(text := f"{v:.{p}g}") == v)
    exact = repr(v).removesuffix(".0")
    return short if len(short) < len(exact) else exact


def _check(name: str, valid: str, ok, value: float, key: tuple[str, ...] = ()) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError(f"{name} = {value!r} is not a number; valid range: {valid}", key=key)
    if not math.isfinite(value) or not ok(value):
        raise ParameterError(f"{name} = {value!r} is out of range; valid range: {valid}", key=key)


#: The box in which every solver is supported (Rbar_o max, L min and max, g min and max,
#: lambda_z / g min and max); it holds every march (stretch 0.05 g to 8 g, growth 1 to 6).
SUPPORTED = (100.0, 1e-2, 1e3, 1e-2, 1e2, 0.02, 50.0)
SUPPORTED_WHY = (
    "outside it the elastic stretches exceed 50, or the waves a scan resolves are over 1e3"
    " times shorter than the tube's radius or length, beyond the kernel's step budget"
    " (a search would run for hours or lose all digits)"
)

#: The supported range of a layer's shear modulus and permittivity, relative to the
#: reference (mu = eps = 1, the units of the pressures, forces and voltage), and of the
#: ratio of the largest to the smallest over the layers.
MODULI = (1e-8, 1e8)
MODULI_WHY = (
    "beyond it the pressures and voltages in units of the reference under- or overflow, or"
    " the layers' stiffnesses differ so much that the wall's equations lose their digits"
    " (a substrate 1e-20 as stiff gave spurious roots, 1e-300 a division by zero)"
)


def check_uniform(outer_radius, length, growth, stretch, voltage) -> None:
    """Check the five numbers of the paper's tube (:meth:`model.layers.Tube.uniform`) against
    their physical ranges and the supported box, naming each in the paper's symbols."""
    five = dict(
        outer_radius=outer_radius, length=length, growth=growth, stretch=stretch, voltage=voltage
    )
    for name, value in five.items():
        _physical(name, value)
    for name, value in five.items():
        _supported(name, value)
    _elastic_stretch(five)


def check_uniform_number(name: str, five: dict) -> None:
    """Check the number ``name`` of the paper's tube's ``five`` (Tube.uniform's keywords),
    the others being checked: a march that sets one number of a tube checks that one alone
    (and the elastic stretch lambda_z / g, if it is the growth or the stretch)."""
    _physical(name, five[name])
    _supported(name, five[name])
    if name in ("growth", "stretch"):
        _elastic_stretch(five)


def _physical(name: str, value) -> None:
    _check(*_UNIFORM_CHECKS[name], value, _UNIFORM_KEYS[name])


def _supported(name: str, value: float) -> None:
    if name in _UNIFORM_BOX:
        _check_box(_UNIFORM_CHECKS[name][0], value, *_UNIFORM_BOX[name], _UNIFORM_KEYS[name])


def _elastic_stretch(five: dict) -> None:
    lo, hi = SUPPORTED[5:7]
    ratio = five["stretch"] / five["growth"]
    _check_box("elastic axial stretch lambda_z / g", ratio, lo, hi, ("stretch",))


def _check_box(symbol: str, value: float, lo: float, hi: float, key=()) -> None:
    if not value <= hi or not lo <= value:
        raise ParameterError(
            f"{symbol} = {given(value)} is outside the supported range {lo:g} to {hi:g}:"
            f" {SUPPORTED_WHY}",
            key=key,
        )


#: each of the five numbers: (symbol, valid range, physical check)
_UNIFORM_CHECKS = {
    "outer_radius": ("outer radius Rbar_o", f"1 < Rbar_o <= {SUPPORTED[0]:g}", lambda v: 1 < v),
    "length": ("length L", f"{SUPPORTED[1]:g} <= L <= {SUPPORTED[2]:g}", lambda v: v > 0),
    "growth": ("growth factor g", f"{SUPPORTED[3]:g} <= g <= {SUPPORTED[4]:g}", lambda v: v > 0),
    "stretch": ("axial stretch lambda_z", "0 < lambda_z < inf", lambda v: v > 0),
    "voltage": ("voltage Vbar", "0 <= Vbar < threshold", lambda v: v >= 0),
}
#: where each of the five sits in the paper's tube, a Tube of one layer (as in a tube file)
_UNIFORM_KEYS = {
    "outer_radius": ("layers", "1", "outer_radius"),
    "length": ("length",),
    "growth": ("layers", "1", "growth"),
    "stretch": ("stretch",),
    "voltage": ("voltage",),
}
#: the supported box of the numbers that have one (SUPPORTED)
_UNIFORM_BOX = {
    "outer_radius": (1.0, SUPPORTED[0]),
    "length": SUPPORTED[1:3],
    "growth": SUPPORTED[3:5],
}


#: The control parameters of the paper's tube (Tube.uniform); a layered tube adds pressure
#: and force (model/controls.py).
CONTROLS = ("growth", "stretch", "voltage")
