"""How big an energy's pieces are at the undeformed state, without computing them exactly.

The parser of model/energy_grammar.py asks, before sympy builds a power or an exponential,
how large it would be at I1 = I2 = 3, I4 = I5 = I6 = 0 (floating point, overflow as inf) and
how many digits sympy's exact rationals in it have (their log height): sympy would compute
``9**9**9`` exactly, 370 million digits, so it is refused from these sizes instead.
"""

from __future__ import annotations

import math

import sympy as sp

#: The invariants' values in the undeformed, unloaded state.
UNDEFORMED = {"I1": 3.0, "I2": 3.0, "I4": 0.0, "I5": 0.0, "I6": 0.0}


def as_float(number) -> float:
    try:
        return float(number)
    except (OverflowError, TypeError):
        return math.inf


def log_height(rational) -> float:
    """ln max(|p|, |q|) of the rational p/q: the size of the exact numbers sympy computes
    when it raises it to a power."""
    p, q = abs(int(rational.p)), int(rational.q)
    return max(_log_int(p), _log_int(q))


def _log_int(n: int) -> float:
    if n == 0:
        return 0.0
    bits = n.bit_length()
    if bits < 1000:
        return math.log(n)
    return math.log(n >> (bits - 53)) + (bits - 53) * math.log(2)


def log_size(value: float) -> float | None:
    """ln |value| (the size of value**e is about e^(e ln |value|)), 0 for 0 (0**e needs no
    big number), None if not finite."""
    if not math.isfinite(value):
        return None
    return 0.0 if value == 0 else math.log(abs(value))


_MATH = {
    sp.log: lambda x: math.log(x) if x > 0 else (-math.inf if x == 0 else math.nan),
    sp.exp: math.exp,
    sp.tanh: math.tanh,
    sp.atan: math.atan,
    sp.cosh: math.cosh,
    sp.sinh: math.sinh,
}


def undeformed_value(expr, value) -> float:
    """The value of the sympy node ``expr`` at the undeformed state, in floating point (inf
    or NaN where it is not finite), from its children's values ``value(child)``; sympy's
    numbers are never evaluated exactly."""
    try:
        if expr.is_Symbol:
            return UNDEFORMED[expr.name]
        if expr.is_Number or expr in (sp.pi, sp.E):
            return as_float(expr) if expr.is_finite else math.nan
        args = [value(a) for a in expr.args]
        if expr.is_Add:
            return math.fsum(args) if all(map(math.isfinite, args)) else sum(args)
        if expr.is_Mul:
            return math.prod(args)
        if expr.is_Pow:
            return _pow(*args)
        return _MATH[expr.func](*args)
    except OverflowError:
        return math.inf
    except (ValueError, ZeroDivisionError, KeyError, TypeError):
        return math.nan


def _pow(base: float, exponent: float) -> float:
    if base == 0 and exponent < 0:
        return math.inf
    try:
        return math.pow(base, exponent)
    except OverflowError:
        return math.inf
    except ValueError:  # a negative base to a fractional power: not real
        return math.nan
