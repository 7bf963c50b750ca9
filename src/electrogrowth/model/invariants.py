"""The invariants of an isotropic electro-elastic energy and its derivatives in them.

    I1 = tr C,  I2 = [(tr C)^2 - tr C^2] / 2,  I4 = D~.D~,  I5 = D~.C D~,  I6 = D~.C^2 D~

(paper Sec. 2, eq. 8; C = F_e^T F_e, D~ the electric displacement in the virtual
configuration) as sympy symbols, their values at principal stretches (l1, l2, l3) and a
radial current displacement d, and an energy's first and second derivatives in them,
lambdified once per energy and process (:class:`.materials.Material` reads them). Also the
reference-state moduli mu and eps of an energy, and a cheap proof that an expression is not
identically zero.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import numpy as np
import sympy as sp

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


_NO_HESSIAN = [0.0] * 25  # placeholder W for the forms that do not read it (stress, field)


@functools.lru_cache(maxsize=64)
def _energy_value(energy: sp.Expr) -> Callable:
    return sp.lambdify(INVARIANTS, energy, "numpy")


def reference_moduli(energy: sp.Expr) -> tuple[float, float]:
    """(mu, eps) of an energy in the reference state I1 = I2 = 3, I4 = I5 = I6 = 0: the
    small-strain shear modulus mu = 2 (Omega_1 + Omega_2) and the small-field permittivity
    eps = 1 / (2 (Omega_4 + Omega_5 + Omega_6)) (all three electric invariants equal D.D
    there). NaN where a derivative is not finite."""
    at = {I1: 3, I2: 3, I4: 0, I5: 0, I6: 0}
    try:
        w = [complex(sp.diff(energy, s).subs(at).evalf()) for s in INVARIANTS]
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


def _all_finite(values) -> bool:
    """Every entry of every value finite (a lambdified function returns plain numbers for
    constant derivatives, arrays for the others)."""
    return all(
        math.isfinite(v) if isinstance(v, (int, float)) else bool(np.isfinite(v).all())
        for v in values
    )


def _invariants(l1, l2, l3, d):
    dt2 = (d / l1) ** 2
    return (
        l1**2 + l2**2 + l3**2,
        (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2,
        dt2,
        dt2 * l1**2,
        dt2 * l1**4,
    )
