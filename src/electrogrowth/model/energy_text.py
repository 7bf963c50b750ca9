"""A user's energy written as text: ``"(I1 - 3)/2 + 0.1*(I2 - 3) + I5/2"``.

The form the command line (``--energy``), a tube file's layer (``energy = "..."``) and a
sweep file (``[material] energy``) accept. The text is read by the whitelist grammar of
model/energy_grammar.py (numbers, the invariants I1, I2, I4, I5, I6, the functions below,
``+ - * / ** ^ ( )``; nothing of it is evaluated), so that a file from someone else cannot
run code, and it must be finite at the undeformed, unloaded state. Every failure is one
MaterialError line naming the problem (docs/security.md).

The package's units are mu = eps = 1: an energy whose initial shear modulus
2 (dOmega/dI1 + dOmega/dI2) or inverse permittivity 2 (dOmega/dI4 + dOmega/dI5 + dOmega/dI6)
at the undeformed state is not 1 is refused by :class:`~.materials.Material`, naming which
(``Material.normalized`` rescales one; a layer's own modulus goes in its shear_modulus).
"""

from __future__ import annotations

from ..errors import MaterialError
from .energy_grammar import CONSTANTS, parse_energy, shorten
from .energy_grammar import FUNCTIONS as _FUNCTIONS
from .invariants import check_finite_at_reference
from .materials import Material

#: Names an energy may use besides the invariants (sympy functions and constants).
FUNCTIONS = (*_FUNCTIONS, *CONSTANTS)


def energy_material(text: str, *, name: str | None = None) -> Material:
    """The Material of the energy ``text`` (in units mu = eps = 1).

    Raises MaterialError (one line) for a character or name that is not allowed, text
    beyond the grammar's limits, or an energy not finite at the undeformed state.

    >>> energy_material("0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2").name
    '0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2'
    >>> energy_material("(I1 - 3)/2 + import os")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    electrogrowth.errors.MaterialError: energy '...' at position 14: unknown name 'import'; ...
    """
    if not isinstance(text, str):
        raise MaterialError(f"energy = {shorten(repr(text))} is not a string")
    expr = parse_energy(text)
    label = " ".join(text.split())
    # Named by its text here (Material names it by ``name``, which a caller may set).
    check_finite_at_reference(expr, f"energy {shorten(label)!r}")
    return Material(name or label, expr)  # refuses moduli other than 1, naming which
