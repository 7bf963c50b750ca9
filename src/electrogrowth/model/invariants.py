"""The invariants of an isotropic electro-elastic energy as sympy symbols, and what sympy does
with a user's energy in them.

    I1 = tr C,  I2 = [(tr C)^2 - tr C^2] / 2,  I4 = D~.D~,  I5 = D~.C D~,  I6 = D~.C^2 D~

(paper Sec. 2, eq. 8; C = F_e^T F_e, D~ the electric displacement in the virtual
configuration). An energy's first and second derivatives in them, lambdified once per energy
and process (:class:`.materials.Material` reads them; built-in energies use generated code
instead, model/builtin_energies.py), the checks of an energy (its symbols, mu = eps = 1 in the
reference state), its rescaling to those units, its kind (neo-Hookean, ideal, general), and a
cheap proof that an expression is not identically zero. Imported only for a user's energy
or when a sympy expression is asked for: sympy costs a fresh process 0.5-0.6 s.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import numpy as np
import sympy as sp

from ..errors import MaterialError
from .energy_grammar import parse_energy, shorten

I1, I2, I4, I5, I6 = INVARIANTS = sp.symbols("I1 I2 I4 I5 I6", real=True)


_ORDER = (1, 2, 4, 5, 6)


@functools.lru_cache(maxsize=64)
def _energy_derivatives(energy: sp.Expr) -> Callable:
    """Lambdify (dOmega/dI_k, d2Omega/dI_k dI_l) of one energy, once per energy."""
    first = [sp.diff(energy, INVARIANTS[k]) for k in range(5)]
    second = [[sp.diff(energy, INVARIANTS[a], INVARIANTS[b]) for b in range(5)] for a in range(5)]
    return sp.lambdify(INVARIANTS, (first, second), "numpy")


@functools.lru_cache(maxsize=64)
def _energy_gradient(energy: sp.Expr) -> Callable:
    """Lambdify dOmega/dI_k alone: all that stress and field need (no Hessian)."""
    return sp.lambdify(INVARIANTS, [sp.diff(energy, s) for s in INVARIANTS], "numpy")


@functools.lru_cache(maxsize=64)
def _energy_value(energy: sp.Expr) -> Callable:
    return sp.lambdify(INVARIANTS, energy, "numpy")


#: The reference (undeformed, unloaded) state, kept exact for sympy.
_REFERENCE = {I1: 3, I2: 3, I4: 0, I5: 0, I6: 0}


def check_finite_at_reference(energy: sp.Expr, subject: str) -> None:
    """MaterialError unless the energy and each of its first derivatives are finite real
    numbers at the reference state. Every computation starts there, whatever the units: an
    infinity left in would surface later as sympy's lambdify printer's KeyError
    ('ComplexInfinity') or a ZeroDivisionError inside a solver. ``subject`` names the energy
    ("energy 'text'" or "energy of 'name'")."""
    parts = [energy, *(sp.diff(energy, s) for s in INVARIANTS)]
    try:
        values = [complex(p.subs(_REFERENCE).evalf()) for p in parts]
    except (TypeError, ValueError, OverflowError, ZeroDivisionError):
        values = [complex(math.nan)]
    if not all(v.imag == 0 and math.isfinite(v.real) for v in values):
        raise MaterialError(
            f"{subject} or its derivatives are not finite real numbers at the"
            " undeformed state I1 = I2 = 3, I4 = I5 = I6 = 0"
        )


def reference_moduli(energy: sp.Expr) -> tuple[float, float]:
    """(mu, eps) of an energy in the reference state I1 = I2 = 3, I4 = I5 = I6 = 0: the
    small-strain shear modulus mu = 2 (Omega_1 + Omega_2) and the small-field permittivity
    eps = 1 / (2 (Omega_4 + Omega_5 + Omega_6)) (all three electric invariants equal D.D
    there). NaN where a derivative is not finite."""
    try:
        w = [complex(sp.diff(energy, s).subs(_REFERENCE).evalf()) for s in INVARIANTS]
    except (TypeError, ValueError, ZeroDivisionError):
        return math.nan, math.nan
    if any(abs(x.imag) > 0 or not np.isfinite(x.real) for x in w):
        return math.nan, math.nan
    mu, e = 2.0 * (w[0].real + w[1].real), 2.0 * (w[2].real + w[3].real + w[4].real)
    return mu, (1.0 / e if e != 0 else math.inf)


#: A point near the reference state, exact, inside every built-in energy's domain.
_WITNESS = {I1: sp.Rational(31, 10), I2: sp.Rational(61, 20), I4: sp.Rational(1, 5)}


_WITNESS.update({I5: sp.Rational(1, 4), I6: sp.Rational(3, 10)})


def _nonzero_at_witness(expr: sp.Expr) -> bool:
    """True if expr is a finite real number clearly away from 0 at _WITNESS (30 digits):
    proof that it is not identically zero. False says nothing (zero, not finite there, or a
    rounding residue of float coefficients, which simplify then judges as before)."""
    try:
        value = complex(expr.subs(_WITNESS).evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        return False
    return value.imag == 0 and math.isfinite(value.real) and abs(value.real) > 1e-12


def numeric_forms(energy: sp.Expr) -> tuple[Callable, Callable, Callable]:
    """(Omega, gradient, (gradient, Hessian)) of a sympy energy as numeric functions of the
    invariants, each lambdified when first called (the Hessian only if needed)."""
    return (
        lambda *inv: _energy_value(energy)(*inv),
        lambda *inv: _energy_gradient(energy)(*inv),
        lambda *inv: _energy_derivatives(energy)(*inv),
    )


def energy_kind(energy: sp.Expr) -> str:
    """'neo-hookean', 'ideal' (W(I1, I2) + I5/2) or 'general'."""
    if sp.expand(energy - (I1 - 3) / 2 - I5 / 2) == 0:
        return "neo-hookean"
    electric = {I4, I5, I6}
    rest = energy - I5 / 2
    # Cheap answers first (simplify takes up to a second per energy): sympy's automatic
    # cancellation settles the built-in energies (simplify cannot add a symbol), and a
    # derivative of rest in I4, I5 or I6 that is non-zero at one point proves that rest
    # depends on the field (simplify cannot remove that symbol).
    if not (rest.free_symbols & electric):
        return "ideal"
    if any(_nonzero_at_witness(rest.diff(s)) for s in (I4, I5, I6)):
        return "general"
    return "general" if sp.simplify(rest).free_symbols & electric else "ideal"


def checked_energy(name: str, energy, check_units: bool) -> sp.Expr:
    """The sympy expression of a Material's ``energy`` (an expression or its text), checked:
    symbols, finite in the reference state and (check_units) mu = eps = 1 there;
    MaterialError if not."""
    # Text is read by the whitelist grammar, never by sympify (data never executes);
    # invariants are matched by name, so sp.Symbol("I1") works too.
    names = {str(s): s for s in INVARIANTS}
    if isinstance(energy, str):
        expr = parse_energy(energy)
    elif isinstance(energy, sp.Expr):
        expr = energy
    else:
        raise MaterialError(
            f"energy of {shorten(name)!r} is {type(energy).__name__}; give a sympy"
            ' expression in I1, I2, I4, I5, I6 or its text, e.g. "(I1 - 3)/2 + I5/2"'
        )
    expr = expr.subs({s: names[str(s)] for s in expr.free_symbols if str(s) in names})
    extra = expr.free_symbols - set(INVARIANTS)
    if extra:
        raise MaterialError(
            f"energy of {shorten(name)!r} has unknown symbols {sorted(map(str, extra))};"
            " use only I1, I2, I4, I5, I6 with parameters substituted"
        )
    # Finiteness first and always: check_units=False keeps a scaled energy, not a singular
    # one, and an infinite energy's moduli would otherwise be misreported (mu = 0 or nan).
    check_finite_at_reference(expr, f"energy of {shorten(name)!r}")
    if check_units:
        mu, eps = reference_moduli(expr)
        for what, value, why in (
            ("shear modulus mu = 2 (dOmega/dI1 + dOmega/dI2)", mu, "stresses"),
            ("permittivity eps = 1 / (2 (dOmega/dI4 + dOmega/dI5 + dOmega/dI6))", eps, "D"),
        ):
            if not abs(value - 1.0) <= 1e-12:
                raise MaterialError(
                    f"energy of {shorten(name)!r} has {what} = {value:.12g} in the"
                    f" reference state, not 1: every result is in units mu = eps = 1, so {why}"
                    " would be in the wrong units; rescale it, or build it with"
                    " Material.normalized(name, energy)"
                )
    return expr


def normalized_energy(name: str, raw: sp.Expr) -> sp.Expr:
    """``raw`` rescaled to mu = eps = 1 (Material.normalized); MaterialError if its mu or
    eps is not finite and positive."""
    mu, eps = reference_moduli(raw)
    for what, value in (("shear modulus", mu), ("permittivity", eps)):
        if not (math.isfinite(value) and value > 0):
            raise MaterialError(
                f"energy of {shorten(name)!r} has {what} {value:.6g} in the reference state;"
                " need a finite positive value to rescale to it"
            )
    at = {I1: 3, I2: 3, I4: 0, I5: 0, I6: 0}  # the same values, kept exact for sympy
    mu = sp.nsimplify(2 * (sp.diff(raw, I1) + sp.diff(raw, I2)).subs(at))
    s = mu / sp.nsimplify(2 * sum(sp.diff(raw, x) for x in (I4, I5, I6)).subs(at))
    scaled = raw.subs({I4: s * I4, I5: s * I5, I6: s * I6}, simultaneous=True) / mu
    return sp.expand(scaled) if raw.is_polynomial(*INVARIANTS) else scaled
