"""Reading a tube file (TOML, stdlib ``tomllib``) into a layered :class:`~.layers.Tube`.

The format (docs/derivation-layered.md, "The tube file"; example: examples/bilayer.toml)::

    length = 3.0            # L / R_i
    stretch = 1.0           # lambda_z; or axial_force = 0.0 instead (closed_ends = true/false)
    voltage = 0.3           # Vbar = V / (R_o - R_i), R_o the outermost radius
    inner_pressure = 0.0    # follower pressure on the inner face, units of mu (outer_pressure too)
    [[layers]]              # from the inner face outward
    outer_radius = 1.1
    material = "gent"       # a built-in name (with its parameters, e.g. jm = 20), or
                            # energy = "(I1 - 3)/2 + I5/2"
    shear_modulus = 10.0    # mu_k / mu (default 1)
    permittivity = 1.0      # eps_k / eps (default 1)
    growth = 1.2            # g, or [g_r, g_theta, g_z], or {inner = ..., outer = ...} (linear)

Every mistake is one :class:`~electrogrowth.errors.ConfigError` naming the file, the line and
the key, e.g. ``tube.toml:9: layers.2.outer_radius: ... valid range: > 1.1 ...``. tomllib keeps
no positions, so the line is found by scanning the text (:func:`line_of`).
"""

from __future__ import annotations

import inspect
import re
from pathlib import Path
from typing import Any

from ..errors import ConfigError, MaterialError, ParameterError
from .layers import Layer, LinearGrowth, Tube
from .materials import BUILTIN, material_by_name
from .toml_input import finite, number, parse, read_text, typename

TOP = (
    "length",
    "stretch",
    "axial_force",
    "voltage",
    "inner_pressure",
    "outer_pressure",
    "closed_ends",
    "layers",
)
LAYER = ("outer_radius", "material", "energy", "shear_modulus", "permittivity", "growth")


def load_tube(path: str | Path) -> Tube:
    """Read and validate a tube file; raise :class:`ConfigError` naming file, line and key."""
    return parse_tube(read_text(path, "tube file"), source=str(path))


def parse_tube(text: str, *, source: str = "<tube>") -> Tube:
    """Validate the TOML ``text`` of a tube file (see the module docstring)."""
    return parse(
        text, source, tube_from_dict, line_of, what="tube file", example="examples/bilayer.toml"
    )


def tube_from_dict(raw: dict) -> Tube:
    """The Tube of a parsed tube file; ConfigError with the key path (layers counted from 1)."""
    for key in raw:
        if key not in TOP:
            raise ConfigError((key,), f"unknown key; a tube file takes {', '.join(TOP)}")
    if "layers" not in raw:
        raise ConfigError((), "missing [[layers]]: give at least one layer with outer_radius")
    if not isinstance(raw["layers"], list) or not raw["layers"]:
        raise ConfigError(("layers",), "expected one or more [[layers]] tables")
    layers, inner = [], 1.0
    for k, table in enumerate(raw["layers"], 1):
        layer = _layer(table, ("layers", str(k)), inner)
        layers.append(layer)
        inner = max(inner, layer.outer_radius)
    options = {}
    for key in TOP[:-1]:
        if key in raw:
            value = raw[key]
            if key == "closed_ends":
                if not isinstance(value, bool):
                    raise ConfigError((key,), f"expected true or false, got {typename(value)}")
            else:
                value = number(raw, (), key)
            options[key] = value
    return _checked(lambda: Tube(tuple(layers), **options), ())


def _layer(table, where: tuple[str, ...], inner: float) -> Layer:
    if not isinstance(table, dict):
        raise ConfigError(where, f"expected a [[layers]] table, got {typename(table)}")
    name = table.get("material", "neo-hookean")
    if not isinstance(name, str):
        raise ConfigError(where + ("material",), f"expected a string, got {typename(name)}")
    if name not in BUILTIN:
        raise ConfigError(
            where + ("material",), f"unknown material {name!r}; choose {', '.join(BUILTIN)}"
        )
    params = _parameters(name)
    for key in table:
        if key not in LAYER + params:
            raise ConfigError(
                where + (key,), _unknown_layer_key(key, name, params, "material" in table)
            )
    if "outer_radius" not in table:
        raise ConfigError(where, "missing outer_radius (R_k / R_i > 1)")
    b = number(table, where, "outer_radius")
    if "energy" in table:
        if "material" in table or any(p in table for p in params):
            raise ConfigError(where + ("energy",), "give either material or energy, not both")
        expr = table["energy"]
        if not isinstance(expr, str):
            raise ConfigError(where + ("energy",), f"expected a string, got {typename(expr)}")
        from .energy_text import energy_material  # sympy: only for an energy's text

        try:  # the whitelist grammar (model/energy_grammar.py): the text never runs
            material = energy_material(expr, name=expr)
        except MaterialError as exc:
            raise ConfigError(where + ("energy",), str(exc)) from None
    else:
        args = {p: number(table, where, p) for p in params if p in table}
        at = where + ((next(iter(args)),) if len(args) == 1 else ("material",))
        material = _checked(lambda: material_by_name(name, **args), at)
    fields: dict[str, Any] = {"outer_radius": b, "material": material}
    for key in ("shear_modulus", "permittivity"):
        if key in table:
            fields[key] = number(table, where, key)
    if "growth" in table:
        fields["growth"] = _growth(table["growth"], where + ("growth",), inner, b)
    return _checked(lambda: Layer(**fields), where)


def _parameters(name: str) -> tuple[str, ...]:
    """The parameters of the built-in material ``name`` (jm for gent, ...)."""
    return tuple(inspect.signature(BUILTIN[name]).parameters)


def _unknown_layer_key(key: str, name: str, params: tuple[str, ...], given: bool) -> str:
    """Why a layer's ``key`` is refused: a parameter of another built-in material is named
    as such (jm without material = "gent"), any other key gets the layer's list."""
    owners = [other for other in BUILTIN if key in _parameters(other)]
    if owners:
        which = " or ".join(f'material = "{other}"' for other in owners)
        own = f", which takes {', '.join(params)}" if params else ""
        return (
            f"{key} is a parameter of {which}, and this layer's material is {name}"
            f"{'' if given else ' (the default)'}{own}: set {which} or drop {key}"
        )
    extra = f" (and {', '.join(params)} for {name})" if params else ""
    return f"unknown key; a layer takes {', '.join(LAYER)}{extra}"


def _growth(value, where, inner: float, outer: float):
    """g, [g_r, g_theta, g_z] or {inner = ..., outer = ...} (linear from R_{k-1} to R_k)."""
    if isinstance(value, dict):
        for key in value:
            if key not in ("inner", "outer"):
                raise ConfigError(where + (key,), "unknown key; graded growth takes inner, outer")
        if set(value) != {"inner", "outer"}:
            raise ConfigError(
                where, "graded growth needs inner and outer (g or [g_r, g_theta, g_z])"
            )
        ends = [_growth(value[k], where + (k,), inner, outer) for k in ("inner", "outer")]
        if not outer > inner:
            raise ConfigError(where, f"the layer must end beyond R = {inner:g} for graded growth")
        return _checked(lambda: LinearGrowth(inner, outer, *ends), where)
    if isinstance(value, list):
        if len(value) != 3:
            raise ConfigError(
                where, f"expected g or [g_r, g_theta, g_z], got {len(value)} entries"
            )
        return tuple(finite(v, where) for v in value)
    return finite(value, where)


def _checked(make, where):
    """make(), a ParameterError turned into a ConfigError at the key it names: its ``key``
    where the check says it (the paper's tube names its numbers by symbol, "outer radius
    Rbar_o = 1e+300", and lost its line: check round 29 D5), else read off the message."""
    try:
        return make()
    except ConfigError:  # already at its key
        raise
    except ParameterError as exc:
        msg = str(exc)
        hit = re.match(r"(?:layers\[(\d+)\]\.)?([a-z_]+)(?: g_[a-z]+)?\s*=", msg)
        key = where
        if exc.key:
            key = where + exc.key
        elif hit and hit.group(1) is not None:  # layers[K], K = 1 innermost, as in the file
            key = ("layers", hit.group(1), hit.group(2))
        elif hit and hit.group(2) in LAYER + TOP:
            key = where + (hit.group(2),)
        raise ConfigError(key, msg) from None


# -- line numbers -------------------------------------------------------------------------------

_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.-]+)\s*\]\]?")
_KEY = re.compile(r"^\s*([A-Za-z0-9_-]+)\s*=")


def line_of(text: str, key: tuple[str, ...]) -> int | None:
    """The line of ``key`` in the tube file ``text``: a top-level key, ``("layers", k, name)``
    (the k-th ``[[layers]]`` table, from 1) or its table; None when absent."""
    if not key:
        return None
    lines = text.splitlines()
    if key[0] != "layers" or len(key) == 1:
        for n, line in enumerate(lines, 1):
            if header := _HEADER.match(line):
                if key[0] == "layers" and header.group(1) == "layers":
                    return n
                break
            if (hit := _KEY.match(line)) and hit.group(1) == key[0]:
                return n
        return None
    count, start = 0, None
    for n, line in enumerate(lines, 1):
        head = _HEADER.match(line)
        if head:
            if start is not None:
                break
            if head.group(1) == "layers":
                count += 1
                if count == int(key[1]):
                    start = n
            continue
        if start is not None and len(key) > 2 and (hit := _KEY.match(line)):
            if hit.group(1) == key[2]:
                return n
    return start
