"""The built-in energies (neo-Hookean, Gent, Mooney-Rivlin) evaluated without sympy.

A built-in energy is a family and its parameter. Its derivatives in the invariants ship as
generated code (:mod:`._builtin_energies`, written by tools/derive_energies.py from the
sympy expressions of :meth:`BuiltinEnergy.expression`), so a process that only uses
built-in energies never imports sympy (0.5-0.6 s of a fresh process); the sympy expression
is built when something asks for it (``Material.energy``).

The generated functions are sympy's own ``lambdify`` output for the energy, with the
parameter's numbers as arguments. sympy computes those numbers in binary floating point at
53 bits (a Float parameter) and prints them with 15 significant digits; :func:`printed`
reproduces that printing and :meth:`BuiltinEnergy.form` the arithmetic, so the generated
functions do the same floating-point operations on the same doubles as the lambdified
expression, and every result is unchanged to the bit (tests/model/test_builtin_energies.py
compares them at random parameters and points). An integer Gent parameter is an exact
rational for sympy, printed as Python fractions (``100/97``), which Python divides
correctly rounded, as :meth:`BuiltinEnergy.form` does. Parameters whose lambdified form
differs (Gent's jm = 1, 2, 3, Mooney-Rivlin's alpha = 1) have their own generated
functions; an integer jm of 2**40 or more goes through sympy (whose nsimplify rounds one
above ~1e15 to 15 digits).
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable
from fractions import Fraction

from . import _builtin_energies

FAMILIES = ("neo-hookean", "gent", "mooney-rivlin")
_EXACT_INTEGERS = 2**40  # sympy keeps an integer Gent jm below this exact (nsimplify)
_OWN_FORMS = {("gent", 1.0), ("gent", 2.0), ("gent", 3.0), ("mooney-rivlin", 1.0)}


def printed(x: float) -> float:
    """The double of the literal sympy prints for the 53-bit Float ``x``.

    mpmath's ``to_str`` at 15 digits: the decimal digits of x truncated after the 16th
    significant one, then rounded half up on that 16th digit (exactly, in integers).
    """
    if x == 0 or not math.isfinite(x):
        return x
    exact = abs(Fraction(x))
    exponent = math.floor(math.log10(abs(x)))
    while exact >= Fraction(10) ** (exponent + 1):  # log10 may be off by one near powers
        exponent += 1
    while exact < Fraction(10) ** exponent:
        exponent -= 1
    digits, sixteenth = divmod(math.floor(exact * Fraction(10) ** (15 - exponent)), 10)
    digits += sixteenth >= 5
    return math.copysign(float(f"{digits}e{exponent - 14}"), x)


@dataclasses.dataclass(frozen=True)
class BuiltinEnergy:
    """A built-in energy: ``family`` in FAMILIES and its parameter (Gent's jm, Mooney-Rivlin's
    alpha, None for neo-Hookean), validated by the constructors in materials.py."""

    family: str
    parameter: float | None = None

    def expression(self):
        """The energy as a sympy expression in the invariants (imports sympy)."""
        return _expression(self)

    @property
    def kind(self) -> str:
        """'neo-hookean' (Omega = (I1 - 3)/2 + I5/2, sympy's cancellation agrees for
        Mooney-Rivlin alpha = 1) or 'ideal' (W(I1, I2) + I5/2)."""
        if self.family == "neo-hookean" or (self.family, self.parameter) == ("mooney-rivlin", 1):
            return "neo-hookean"
        return "ideal"

    @property
    def polynomial(self) -> bool:
        """Omega is a polynomial in the invariants (finite everywhere): all but Gent."""
        return self.family != "gent"

    @property
    def linear(self) -> bool:
        """Omega - I5/2 is linear in I1 and I2 (neo-Hookean, Mooney-Rivlin; Gent is not)."""
        return self.family != "gent"

    def form(self) -> tuple[str, tuple] | None:
        """(name of the generated functions, the numbers they take), or None where the
        energy has no generated form (an integer Gent jm >= 2**40)."""
        p = self.parameter
        if self.family == "neo-hookean":
            return "neo_hookean", ()
        if (self.family, p) in _OWN_FORMS:
            return f"{self.family.replace('-', '_')}_{int(p)}", ()
        if self.family == "mooney-rivlin":
            # (alpha (I1 - 3) + (1 - alpha)(I2 - 3)) / 2 + I5 / 2, Floats distributed
            rest = 1.0 - p
            return "mooney_rivlin", (
                printed(p / 2),
                printed(rest / 2),
                printed((3.0 * p + 3.0 * rest) / 2),
            )
        if float(p).is_integer():
            if p >= _EXACT_INTEGERS:
                return None
            n = int(p)  # sympy: -(n/2) log((n + 3)/n - I1/n), exact rationals
            return "gent_integer", (n / 2, (n + 3) / n, 1 / n, n + 3)
        inverse = 1.0 / p  # sympy: -(jm/2) log(1 + 3/jm - I1/jm) with Floats
        half = p / 2
        return "gent_float", (
            printed(half),
            printed(1.0 + 3.0 * inverse),
            printed(inverse),
            printed(half * inverse),
            printed(half * inverse * inverse),
        )

    def numeric(self) -> tuple[Callable, Callable, Callable] | None:
        """(Omega, [dOmega/dI_k], ([dOmega/dI_k], [[d2Omega/dI_k dI_l]])) as functions of
        (I1, I2, I4, I5, I6), from the generated code; None without a generated form."""
        return _numeric(self)


@functools.lru_cache(maxsize=64)
def _numeric(energy: BuiltinEnergy):
    form = energy.form()
    if form is None:
        return None
    name, numbers = form
    return tuple(
        functools.partial(getattr(_builtin_energies, f"{name}_{what}"), k=numbers)
        for what in ("value", "gradient", "derivatives")
    )


@functools.lru_cache(maxsize=64)
def _expression(energy: BuiltinEnergy):
    """The sympy expression each constructor built before the generated code (and still
    builds for tools/derive_energies.py and for anyone asking for ``Material.energy``)."""
    import sympy as sp

    from .invariants import I1, I2, I5

    p = energy.parameter
    if energy.family == "neo-hookean":
        return (I1 - 3) / 2 + I5 / 2
    if energy.family == "gent":
        jm = sp.nsimplify(p) if float(p).is_integer() else sp.Float(p)
        return -jm / 2 * sp.log(1 - (I1 - 3) / jm) + I5 / 2
    a = sp.Float(p)
    return (a * (I1 - 3) + (1 - a) * (I2 - 3)) / 2 + I5 / 2
