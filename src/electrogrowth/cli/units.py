"""Physical units on the command line: ``--inner-radius 2mm --shear-modulus 100kPa
--permittivity 4.7 --voltage 3kV``.

Without any of them nothing changes: every number is non-dimensional (mu = eps = R_i = 1).
With them, the options that take a length or a voltage accept a quantity as well as a number
(a number keeps its non-dimensional meaning): ``--outer-radius 2.8mm`` or ``1.4``,
``--length 10mm`` or ``5``, ``--voltage 3kV`` or ``0.0765``, ``--inner-pressure 5kPa`` or
``0.05``, ``--axial-force -0.1N`` or ``-0.25``. After parsing, :func:`resolve_units` turns
the quantities into Rbar_o, L, Vbar, P / mu and N / (mu R_i^2) (model/units.py) and
leaves ``args.scales`` (a :class:`Scales`, or None) for the output in physical units.
pint (the ``units`` extra) is imported only when a quantity is given.
"""

from __future__ import annotations

import argparse
import math
import re

from ..errors import ParameterError

_QUANTITY = re.compile(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[A-Za-z\u00b5\u03bc]")


class QuantityText(str):
    """An option value with a unit ("2mm"), converted by :func:`resolve_units`."""


class GivenNumber(float):
    """A number typed on the command line (a default is a plain float): a length the user
    gave is reported in physical units, the default L = 1 is not."""


def number_or_quantity(text: str) -> float | QuantityText:
    """A finite number (non-dimensional, as before; a :class:`GivenNumber`), or a quantity
    with its unit."""
    try:
        value = float(text)
    except ValueError:
        if not _QUANTITY.match(text):  # a quantity starts with its number: 3kV, 2.8 mm
            raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
        return QuantityText(text)
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return GivenNumber(value)


#: The unit options (dest, flag).
UNIT_OPTIONS = (
    ("inner_radius", "--inner-radius"),
    ("shear_modulus", "--shear-modulus"),
    ("permittivity", "--permittivity"),
)
#: Options that may carry a unit: dest -> (flag, kind, SI unit).
DIMENSIONAL = {
    "outer_radius": ("--outer-radius", "length", "m"),
    "length": ("--length", "length", "m"),
    "voltage": ("--voltage", "voltage", "V"),
    "inner_pressure": ("--inner-pressure", "pressure", "Pa"),
    "outer_pressure": ("--outer-pressure", "pressure", "Pa"),
    "axial_force": ("--axial-force", "force", "N"),
}
#: the loads: dest -> the scales their unit needs (in units mu and mu R_i^2)
LOADS = {
    "inner_pressure": ("--shear-modulus",),
    "outer_pressure": ("--shear-modulus",),
    "axial_force": ("--shear-modulus", "--inner-radius"),
}


def add_unit_options(parser: argparse.ArgumentParser) -> None:
    """The three scales of a tube in physical units (all optional)."""
    group = parser.add_argument_group(
        "physical units (optional; needs pip install 'electrogrowth[units]')",
        "Give the tube in physical units: --inner-radius sets the unit of length R_i, then"
        " --outer-radius and --length accept lengths (2.8mm) as well as Rbar_o and L;"
        " --shear-modulus and --permittivity with both radii (R_o from --outer-radius or"
        " the --tube file) let --voltage take a voltage"
        " (3kV), converted to Vbar = V / (R_o - R_i) sqrt(eps / mu); --shear-modulus lets"
        " --inner-pressure and --outer-pressure take a pressure (5kPa), with --inner-radius"
        " --axial-force a force (0.1N). Results are then also"
        " printed in these units (voltages in kV, stresses in kPa, lengths in mm, the axial"
        " force in N; a length only if you gave one).",
    )
    group.add_argument(
        "--inner-radius",
        metavar="LENGTH",
        help="R_i, the undeformed inner radius with its unit (e.g. 2mm): the unit of length",
    )
    group.add_argument(
        "--shear-modulus",
        metavar="PRESSURE",
        help="mu, the initial shear modulus with its unit (e.g. 100kPa): the unit of stress",
    )
    group.add_argument(
        "--permittivity",
        metavar="EPS",
        help="eps, the permittivity: a number is the relative permittivity eps_r"
        " (eps = eps_r eps_0, e.g. 4.7), or give it with its unit (e.g. 4.16e-11F/m)",
    )


def _outer_radius(args: argparse.Namespace) -> float | None:
    """Rbar_o of the tube the command will solve: --outer-radius, else the --tube file's
    outermost radius (a layered tube must not set --outer-radius, so the file is the only
    place it is given), else the command's default one-layer Rbar_o; None if there is none."""
    rbar_o = getattr(args, "outer_radius", None)
    if isinstance(rbar_o, float):
        return rbar_o
    if getattr(args, "tube", None) is not None:
        from ..model.tube_file import load_tube  # read again by tube_of: a small file

        return load_tube(args.tube).outer_radius
    default = getattr(args, "shared_defaults", {}).get("outer_radius")
    return default if isinstance(default, float) else None


def resolve_units(args: argparse.Namespace) -> None:
    """Convert the quantities of ``args`` to Rbar_o, L, Vbar in place; set ``args.scales``.

    Raises ParameterError (one line, naming the option) for a quantity of the wrong kind,
    a length without --inner-radius, a voltage without the four scales.
    """
    if not hasattr(args, "inner_radius"):
        return
    length_given = isinstance(getattr(args, "length", None), (GivenNumber, QuantityText))
    for dest in DIMENSIONAL:  # plain floats from here on
        if isinstance(getattr(args, dest, None), GivenNumber):
            setattr(args, dest, float(getattr(args, dest)))
    given = {dest: getattr(args, dest) for dest, _ in UNIT_OPTIONS}
    quantities = {
        dest: getattr(args, dest)
        for dest in DIMENSIONAL
        if isinstance(getattr(args, dest, None), QuantityText)
    }
    if all(v is None for v in given.values()) and not quantities:
        args.scales = None
        return
    from ..model.units import Scales, absolute_permittivity, magnitude

    r_i = math.nan
    if given["inner_radius"] is not None:
        r_i = magnitude(given["inner_radius"], "--inner-radius", "length", "m")
    for dest in ("outer_radius", "length"):
        if dest in quantities:
            flag, kind, unit = DIMENSIONAL[dest]
            value = magnitude(quantities[dest], flag, kind, unit)
            if math.isnan(r_i):
                raise ParameterError(
                    f"{flag} {quantities[dest]} is a length; give --inner-radius too (the unit"
                    " of length), or a non-dimensional value"
                )
            setattr(args, dest, value / r_i)
    rbar_o = _outer_radius(args)
    r_o = r_i * rbar_o if rbar_o is not None else math.nan
    mu = math.nan
    if given["shear_modulus"] is not None:
        mu = magnitude(given["shear_modulus"], "--shear-modulus", "pressure", "Pa")
    eps = (
        math.nan if given["permittivity"] is None else absolute_permittivity(given["permittivity"])
    )
    length = getattr(args, "length", None)
    known = length_given and isinstance(length, float) and not math.isnan(r_i)
    r_l = r_i * length if known else 0.0
    scales = Scales(r_i, r_o, mu, eps, r_l)
    if "voltage" in quantities:
        missing = [
            flag
            for flag, ok in (
                ("--inner-radius", not math.isnan(r_i)),
                ("--outer-radius", not math.isnan(r_o)),
                ("--shear-modulus", not math.isnan(mu)),
                ("--permittivity", not math.isnan(eps)),
            )
            if not ok
        ]
        if missing:
            raise ParameterError(
                f"--voltage {quantities['voltage']} is a voltage; Vbar = V / (R_o - R_i)"
                f" sqrt(eps / mu) needs {', '.join(missing)} as well"
            )
        volts = magnitude(quantities["voltage"], "--voltage", "voltage", "V", zero=True)
        args.voltage = scales.to_vbar(volts)
        args.voltage_text = quantities["voltage"]  # held as Vbar: check_held_voltage
    for dest in LOADS:
        if dest in quantities:
            setattr(args, dest, _load(dest, quantities[dest], r_i, mu))
    args.scales = scales


def _load(dest: str, text: str, r_i: float, mu: float) -> float:
    """A pressure in units mu, or the axial force in units mu R_i^2, from its quantity."""
    flag, kind, unit = DIMENSIONAL[dest]
    known = {"--shear-modulus": not math.isnan(mu), "--inner-radius": not math.isnan(r_i)}
    missing = [name for name in LOADS[dest] if not known[name]]
    if missing:
        raise ParameterError(
            f"{flag} {text} is a {kind}; give {' and '.join(missing)} too (the unit of"
            f" {'stress' if kind == 'pressure' else 'force, mu R_i^2'}), or a value in units"
            f" {'mu' if kind == 'pressure' else 'mu R_i^2'}"
        )
    from ..model.units import magnitude

    value = magnitude(text, flag, kind, unit, signed=True)
    return value / mu if kind == "pressure" else value / (mu * r_i * r_i)


def _key_unit(key: str) -> tuple[str, str] | None:
    """(kind, SI unit) of a value of the control or tube key ``key`` (Tube.at) that may be
    given with a unit, or None for a pure number (a growth, a stretch, a permittivity)."""
    from ..model.keys import layer_key

    lk = layer_key(key)
    field = key if lk is None else lk[1]
    if field in ("outer_radius", "length", "thickness"):
        return "length", "m"
    if field in ("pressure", "inner_pressure", "outer_pressure", "shear_modulus"):
        return "pressure", "Pa"
    if field in ("force", "axial_force"):
        return "force", "N"
    return ("voltage", "V") if field == "voltage" else None


def key_value(flag: str, key: str, text, scales) -> float:
    """The value of ``key`` typed as ``text`` after ``flag`` (--vary KEY LO HI, --from,
    --to): a number as it is (non-dimensional), or a quantity of the key's kind in units of
    the tube's ``scales`` (a length in R_i, a voltage in Vbar, a pressure or a layer's
    modulus in mu, a force in mu R_i^2). One line naming the value otherwise."""
    try:
        value = number_or_quantity(str(text)) if not isinstance(text, float) else text
    except argparse.ArgumentTypeError as exc:
        raise ParameterError(f"{flag} {key}: {exc}") from None
    if not isinstance(value, QuantityText):
        return float(value)
    unit = _key_unit(key)
    if unit is None:
        raise ParameterError(
            f"{flag} {key} {text}: {key} is a pure number; give it without a unit"
        )
    kind, si = unit
    needs = {
        "length": ("inner_radius",),
        "pressure": ("shear_modulus",),
        "force": ("shear_modulus", "inner_radius"),
        "voltage": ("inner_radius", "outer_radius", "shear_modulus", "permittivity"),
    }[kind]
    if scales is None or not scales.has(*needs):
        flags = ", ".join("--" + n.replace("_", "-") for n in needs)
        raise ParameterError(
            f"{flag} {key} {text} is a {kind}; give {flags} too (the tube's scales), or a"
            " non-dimensional value"
        )
    from ..model.units import magnitude

    signed = key in ("pressure", "inner_pressure", "outer_pressure", "force", "axial_force")
    got = magnitude(value, f"{flag} {key}", kind, si, zero=kind == "voltage", signed=signed)
    if kind == "voltage":
        return scales.to_vbar(got)
    mu, r_i = scales.shear_modulus, scales.inner_radius
    if kind == "length":
        return got / r_i
    return got / mu if kind == "pressure" else got / (mu * r_i * r_i)


def check_held_voltage(args: argparse.Namespace, keys, layers: int, varied=None) -> None:
    """Refuse a voltage given in volts (--voltage 3kV, or ``varied``: the text of a varied
    voltage's bound) beside a variable that moves the outer radius: Vbar = V / (R_o - R_i)
    sqrt(eps / mu) is converted once, at the given R_o; along such a variable the same Vbar
    is another V at every point (at twice the wall, twice the voltage), not the one asked."""
    text = varied or getattr(args, "voltage_text", None)
    moving = [key for key in keys if moves_outer_radius(key, layers)]
    if text is None or not moving:
        return
    given, held = (
        ("--vary voltage", "") if varied else ("--voltage", f" (here {args.voltage:.6g})")
    )
    raise ParameterError(
        f"{given} {text} is a voltage, but {moving[0]} changes the wall R_o - R_i along the"
        f" range and with it Vbar = V / (R_o - R_i) sqrt(eps / mu); give the voltage as Vbar"
        f"{held}, which is held as the wall changes"
    )


def moves_outer_radius(key: str, layers: int) -> bool:
    """Whether setting ``key`` (Tube.at) of a tube of ``layers`` layers moves its outer
    radius: outer_radius, the outermost layer's outer radius, any layer's thickness (the
    layers outside move with it)."""
    from ..model.keys import layer_key

    lk = layer_key(key)
    if lk is None:
        return key == "outer_radius"
    return lk[1] == "thickness" or (lk[1] == "outer_radius" and lk[0] == layers)
