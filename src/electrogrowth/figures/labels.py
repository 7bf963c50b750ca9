r"""Axis labels of the controls and tube keys: words in the text font, the symbol in math,
and the unit (every quantity is non-dimensional, in units mu = eps = R_i = 1).

A curve or a sweep may run along a control of a layered tube (``growth[2].theta``) or one of
its keys (``layers[2].thickness``): :func:`axis_label` writes each as words a reader
understands ("growth g_θ of layer 2 (–)"), never as the code name in math italics.

>>> print(axis_label("growth[2].theta"))
growth $g_\theta$ of layer 2 (–)
>>> print(axis_label("voltage", critical=True))
critical voltage $\bar V_{\rm cr}$ (–)
"""

from __future__ import annotations

import re

from ..model.controls import KINDS

#: words, symbol (mathtext) and unit of each one-layer parameter, control and tube key
LABELS = {
    **{name: (k.words, k.symbol, k.unit) for name, k in KINDS.items()},  # the controls
    "outer_radius": ("outer radius", r"R_o", r"($R_i$)"),
    "length": ("length", "L", r"($R_i$)"),
    "outer_pressure": ("outer pressure", "P_o", r"($\mu$)"),
}
#: a layer's key: words, symbol with {k} for the layer, unit
LAYER_KEYS = {
    "outer_radius": ("outer radius of layer {k}", "R_{{{k}}}", r"($R_i$)"),
    "thickness": ("thickness of layer {k}", "H_{{{k}}}", r"($R_i$)"),
    "shear_modulus": ("shear modulus of layer {k}", r"\mu_{{{k}}}", r"($\mu$ of the reference)"),
    "permittivity": (
        "permittivity of layer {k}",
        r"\varepsilon_{{{k}}}",
        r"($\varepsilon$ of the reference)",
    ),
}
COMPONENT = {"r": "r", "theta": r"\theta", "z": "z"}
#: what the footnote of a non-dimensional axis says
UNITS_NOTE = (
    r"units $\mu = \varepsilon = R_i = 1$; $\bar V = V \sqrt{\varepsilon/\mu}\,/\,(R_o - R_i)$"
)

_GROWTH = re.compile(r"^growth(\[(?P<k>\d+)\])?(\.(?P<comp>[a-z+]+))?$")
_LAYER = re.compile(r"^layers\[(?P<k>\d+)\]\.(?P<field>[a-z_]+)$")


def parts(name: str) -> tuple[str, str, str]:
    """(words, mathtext symbol without $, unit) of a parameter name; an unknown name is its
    own words with no symbol."""
    if name in LABELS and name != "growth":
        return LABELS[name]
    growth = _GROWTH.match(name)
    if growth:
        k, comp = growth["k"], growth["comp"]
        of = f" of layer {k}" if k else ""
        if comp is None:
            return ("growth factor" + of, "g", "(–)")
        sub = ",".join(COMPONENT.get(c, c) for c in comp.split("+"))
        return ("growth" + of, f"g_{{{sub}}}" if "," in sub else f"g_{sub}", "(–)")
    layer = _LAYER.match(name)
    if layer and layer["field"] in LAYER_KEYS:
        words, symbol, unit = LAYER_KEYS[layer["field"]]
        return (words.format(k=layer["k"]), symbol.format(k=layer["k"]), unit)
    return (name.replace("_", " "), "", "")


def axis_label(name: str, *, critical: bool = False) -> str:
    """The label of an axis along ``name`` ("critical ..." with ``critical``)."""
    words, symbol, unit = parts(name)
    if critical:
        words = "critical " + words
        symbol = symbol and _critical(symbol)
    words = words if not symbol else _insert(words, f"${symbol}$")
    return f"{words} {unit}".strip()


def symbol_text(name: str) -> str:
    """The symbol of ``name`` in mathtext (``$g_\\theta$``), or its words if it has none."""
    words, symbol, _ = parts(name)
    return f"${symbol}$" if symbol else words


def _critical(symbol: str) -> str:
    r"""g -> g_{\rm cr}; g_\theta -> g_{\theta,\rm cr}; \lambda_z -> \lambda_{z,\rm cr}."""
    head, sep, sub = symbol.partition("_")
    if not sep:
        return symbol + r"_{\rm cr}"
    sub = sub[1:-1] if sub.startswith("{") else sub
    return f"{head}_{{{sub},\\rm cr}}"


def _insert(words: str, symbol: str) -> str:
    """The symbol after the quantity's name, before "of layer K": "growth g_θ of layer 2"."""
    head, sep, tail = words.partition(" of layer ")
    return f"{head} {symbol}" + (f"{sep}{tail}" if sep else "")
