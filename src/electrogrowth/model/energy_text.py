"""A user's energy written as text: ``"(I1 - 3)/2 + 0.1*(I2 - 3) + I5/2"``.

The form the command line (``--energy``) and the sweep file (``[material] energy``) accept.
The text is checked before sympy reads it: only numbers, the invariants I1, I2, I4, I5, I6,
the functions below, ``+ - * / ** ^ ( ) ,`` and spaces, so that a file from someone else
cannot run code; it must be finite at the undeformed, unloaded state. Every failure is one
MaterialError line naming the problem.

The package's units are mu = eps = 1: an energy whose initial shear modulus
2 (dOmega/dI1 + dOmega/dI2) or inverse permittivity 2 (dOmega/dI4 + dOmega/dI5 + dOmega/dI6)
at the undeformed state is not 1 is refused by :class:`~.materials.Material`, naming which
(``Material.normalized`` rescales one; a layer's own modulus goes in its shear_modulus).
"""

from __future__ import annotations

import math
import re

import sympy as sp

from ..errors import MaterialError
from .materials import I1, I2, I4, I5, I6, Material

#: Names an energy may use besides the invariants (sympy functions and constants).
FUNCTIONS = ("log", "exp", "sqrt", "tanh", "atan", "cosh", "sinh", "pi", "E")
_TOKEN = re.compile(
    r"\s*(?:(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)|([A-Za-z_]\w*)|(\*\*|[-+*/^(),]))"
)


def energy_material(text: str, *, name: str | None = None) -> Material:
    """The Material of the energy ``text`` (in units mu = eps = 1).

    Raises MaterialError (one line) for a character or name that is not allowed, an
    expression sympy cannot read, or an energy not finite at the undeformed state.

    >>> energy_material("0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2").name
    '0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2'
    >>> energy_material("(I1 - 3)/2 + import os")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    electrogrowth.errors.MaterialError: energy '...' has the unknown name 'import'; use ...
    """
    if not isinstance(text, str):
        raise MaterialError(f"energy = {text!r} is not a string")
    label = " ".join(text.split())
    if not label:
        raise MaterialError("energy is empty; write Omega in I1, I2, I4, I5, I6")
    _check_tokens(label)
    text = label.replace("^", "**")
    try:
        parsed = Material(name or label, text, check_units=False)
    except MaterialError as exc:
        reason = "it does not parse" if "parse" in str(exc) or "Syntax" in str(exc) else exc
        raise MaterialError(
            _one_line(f"energy {label!r} is not a valid expression: {reason}")
        ) from None
    _reference_values(parsed.energy, label)
    return Material(name or label, text)  # refuses moduli other than 1, naming which


def _check_tokens(text: str) -> None:
    pos = 0
    allowed = {"I1", "I2", "I4", "I5", "I6", *FUNCTIONS}
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if match is None or match.end() == pos:
            bad = text[pos:].strip()[:1]
            raise MaterialError(
                f"energy {text!r} has the character {bad!r} at {pos + 1}; use numbers,"
                " I1, I2, I4, I5, I6, + - * / ** ( ) and " + ", ".join(FUNCTIONS[:-2])
            )
        word = match.group(2)
        if word is not None and word not in allowed:
            raise MaterialError(
                f"energy {text!r} has the unknown name {word!r}; use I1, I2, I4, I5, I6,"
                f" {', '.join(FUNCTIONS)} (parameters as numbers)"
            )
        pos = match.end()
    if text.count("(") != text.count(")"):
        raise MaterialError(f"energy {text!r} has unbalanced parentheses")


def _reference_values(energy: sp.Expr, label: str) -> tuple[float, float]:
    """(mu, 1 / eps) of the energy at the undeformed state: 2 (Omega_1 + Omega_2) and
    2 (Omega_4 + Omega_5 + Omega_6); MaterialError if it or they are not finite there."""
    at = {I1: 3, I2: 3, I4: 0, I5: 0, I6: 0}
    try:
        value = float(energy.subs(at))
        mu = float(2 * (sp.diff(energy, I1) + sp.diff(energy, I2)).subs(at))
        inv_eps = float(
            2 * (sp.diff(energy, I4) + sp.diff(energy, I5) + sp.diff(energy, I6)).subs(at)
        )
    except (TypeError, ValueError):
        value = mu = inv_eps = math.nan
    if not all(math.isfinite(x) for x in (value, mu, inv_eps)):
        raise MaterialError(
            f"energy {label!r} or its derivatives are not finite real numbers at the"
            " undeformed state I1 = I2 = 3, I4 = I5 = I6 = 0"
        )
    return mu, inv_eps


def _one_line(text: str) -> str:
    return " ".join(text.split())
