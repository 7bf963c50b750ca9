"""The strain energy's derivatives in (I1, I2) to fourth order, at no electric field: the
Taylor coefficients the amplitude equation of a wrinkle needs (docs/derivation-koiter.md,
"Any strain energy").

With no field (D = 0, so I4 = I5 = I6 = 0) the energy of a layer is the mechanical part
W(I1, I2) = Omega(I1, I2, 0, 0, 0); an ideal dielectric, Omega = W(I1, I2) + I5 / 2, has the
same W under a voltage, its electric part not depending on it. The Koiter coefficient needs
W's expansion in the displacement gradient to fourth order, hence

    W_ab = d^(a+b) W / dI1^a dI2^b,  1 <= a + b <= 4,

differentiated by sympy from the energy's expression (a built-in energy's is built when
asked for; a user's energy is one) and lambdified once per energy and process. sympy
costs a fresh process 0.5 s, which the amplitude equation (seconds) carries; the solvers
of the base state and of onset never import this module.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import numpy as np

from .materials import Material

#: (a, b) of W_ab, 1 <= a + b <= 4, by total order.
ORDERS = tuple((a, n - a) for n in range(1, 5) for a in range(n, -1, -1))


def strain_derivatives(material: Material, I1, I2) -> dict[tuple[int, int], np.ndarray]:
    """{(a, b): W_ab at (I1, I2)} for 1 <= a + b <= 4, W = Omega(I1, I2, 0, 0, 0), as
    arrays of the broadcast shape of I1 and I2 (zero where W is linear in them).

    >>> from electrogrowth.model.materials import mooney_rivlin
    >>> w = strain_derivatives(mooney_rivlin(0.7), 3.0, 3.0)
    >>> float(w[1, 0]), float(w[0, 1]), float(w[2, 0])
    (0.35, 0.15, 0.0)
    """
    I1, I2 = np.broadcast_arrays(np.asarray(I1, float), np.asarray(I2, float))
    values = _derivative_function(material.definition)(I1, I2)
    return {k: np.broadcast_to(np.asarray(v, float), I1.shape) for k, v in zip(ORDERS, values)}


def taylor_weight(a: int, b: int) -> float:
    """1 / (a! b!): the weight of W_ab d1^a d2^b in the Taylor series of W."""
    return 1.0 / (math.factorial(a) * math.factorial(b))


@functools.lru_cache(maxsize=64)
def _derivative_function(definition) -> Callable:
    """Lambdify the W_ab of one energy (a BuiltinEnergy or a sympy expression), once."""
    import sympy as sp

    from .builtin_energies import BuiltinEnergy
    from .invariants import I1, I2, I4, I5, I6

    energy = definition.expression() if isinstance(definition, BuiltinEnergy) else definition
    W = energy.subs({I4: 0, I5: 0, I6: 0})
    derivatives = [sp.diff(W, *([I1] * a + [I2] * b)) for a, b in ORDERS]
    return sp.lambdify((I1, I2), derivatives, "numpy")
