"""The keys of a tube besides its controls: the numbers a curve, a sweep or a design may
vary (``length``, ``outer_pressure``, ``outer_radius`` and ``layers[K].outer_radius``,
``.thickness``, ``.shear_modulus``, ``.permittivity``; K = 1 innermost), set and read in
the user's terms (:meth:`Tube.at`, :meth:`Tube.value_of`)."""

from __future__ import annotations

import dataclasses
import math
import re

from ..errors import ParameterError
from .layer import _number, modulus

#: the keys of a tube that a curve or sweep may vary besides its controls (:meth:`Tube.at`)
KEYS_TEXT = (
    "length, outer_pressure, outer_radius, layers[K].outer_radius, layers[K].thickness,"
    " layers[K].shear_modulus, layers[K].permittivity"
)
_LAYER_KEY = re.compile(r"layers\[(\d+)\]\.(\w+)")


def with_key(tube, name: str, value: float):
    """``tube`` with the key ``name`` (length, outer_pressure, layers[K].field) set."""
    match = _LAYER_KEY.fullmatch(name)
    if match is None:
        if name not in ("length", "outer_pressure"):
            raise ParameterError(f"{name!r} is not a key of a tube; valid: {KEYS_TEXT}")
        return dataclasses.replace(tube, **{name: value})
    k, field = int(match[1]), match[2]
    if not 1 <= k <= len(tube.layers):
        raise ParameterError(
            f"{name}: layer {k} does not exist; this tube has layers 1..{len(tube.layers)}"
        )
    if field not in ("outer_radius", "thickness", "shear_modulus", "permittivity"):
        raise ParameterError(f"{name!r} is not a key of a tube; valid: {KEYS_TEXT}")
    _check_key(name, value, field, tube.radii, k)
    layers = list(tube.layers)
    if field == "thickness":  # every layer outside moves out with it
        inner = tube.radii[k - 1]
        shift = inner + value - layers[k - 1].outer_radius
        for j in range(k - 1, len(layers)):
            if layers[j].graded:
                raise ParameterError(f"{name}: layer {j + 1} has graded growth")
            layers[j] = dataclasses.replace(layers[j], outer_radius=layers[j].outer_radius + shift)
    else:
        layers[k - 1] = dataclasses.replace(layers[k - 1], **{field: value})
    return dataclasses.replace(tube, layers=tuple(layers))


def layer_key(name) -> tuple[int, str] | None:
    """(K, field) of a key ``layers[K].field``, or None for any other name."""
    match = _LAYER_KEY.fullmatch(str(name))
    return None if match is None else (int(match[1]), match[2])


def key_value(tube, name) -> float | None:
    """The current value of the key ``name`` (as :func:`with_key` sets it), None if
    ``name`` is not a key (then it may be a control)."""
    if name == "outer_radius":
        return tube.outer_radius
    if name in ("length", "outer_pressure"):
        return float(getattr(tube, name))
    match = _LAYER_KEY.fullmatch(str(name))
    if match is None:
        return None
    k = int(match[1])
    if not 1 <= k <= len(tube.layers):
        raise ParameterError(f"{name}: layer {k} does not exist")
    if match[2] == "thickness":
        return tube.radii[k] - tube.radii[k - 1]
    return float(getattr(tube.layers[k - 1], match[2]))


def _check_key(name: str, value: float, field: str, radii: tuple[float, ...], k: int) -> None:
    """Refuse a value of the key ``name`` (layers[K].field) in its own terms: the layer
    would otherwise report a radius the user never gave (a thickness moves the radii)."""
    if field == "thickness":  # and a radius distinct from the inner one in floating point
        inner = radii[k - 1]
        least = f">= {math.ulp(inner):.1g} (distinct radii next to R = {inner:g})"
        valid = least if value > 0 else "> 0"
        _number(name, value, valid, lambda v: v > 0 and inner + v > inner)
    elif field == "outer_radius":
        inner = radii[k - 1]
        outer = radii[k + 1] if k + 1 < len(radii) else math.inf
        valid = f"{inner:g} < R < {outer:g} (the layer's inner radius, the next one's outer)"
        _number(
            name,
            value,
            valid if k + 1 < len(radii) else f"> {inner:g}",
            lambda v: inner < v < outer,
        )
    else:  # shear_modulus, permittivity
        modulus(name, value)
