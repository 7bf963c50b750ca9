"""The bifurcation target f(state, modes): one name per method, one call for many modes.

A mode (m, n) of a base state is at bifurcation when the incremental problem has a
non-trivial solution. Two independent methods give a real target that changes sign exactly
there, without poles:

* ``Method.IMPEDANCE``: the compiled Riccati kernel (impedance.py) on the Chebyshev tables
  of the base state (radial_table.py), batched over modes;
* ``Method.COLLOCATION``: Chebyshev collocation of the full incremental equations
  (collocation.py), one mode at a time.

:func:`targets_for` turns a method and an :class:`~.accuracy.Accuracy` into a function
``targets(state, modes) -> f``, which the march (bifurcation/march.py) evaluates.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable

import numpy as np

from ..errors import ConvergenceError, ParameterError
from .accuracy import Accuracy
from .collocation import collocation_target
from .impedance import STATUS_TEXT, target_batch, target_serial
from .radial_table import build_table, stack_tables

PARALLEL_FROM = 16  # batches smaller than this run on one thread (thread launch costs more)

#: targets(state, modes (k, 2) array) -> (k,) array of target values
Targets = Callable[[object, np.ndarray], np.ndarray]


class Method(enum.StrEnum):
    """How the incremental problem is solved: the one choice behind every ``method``."""

    IMPEDANCE = "impedance"
    COLLOCATION = "collocation"


METHODS = tuple(m.value for m in Method)


def check_method(method: str) -> Method:
    """The Method named ``method``, or ParameterError listing the valid names."""
    try:
        return Method(method)
    except ValueError:
        raise ParameterError(f"method = {method!r} is unknown; choose one of {METHODS}") from None


def wavenumber(params, n: float) -> float:
    """Axial wavenumber k = n pi / (lambda_z L) in the current configuration."""
    return n * math.pi / (params.stretch * params.length)


def check_mode(m, n) -> None:
    """Raise ParameterError unless m >= 0 and n >= 1 are integers."""
    if m < 0 or n < 1 or int(m) != m or int(n) != n:
        raise ParameterError(
            f"mode (m, n) = ({m}, {n}) is invalid; need integers m >= 0, n >= 1")


def impedance_targets(state, modes, *, rtol: float = 1e-12,
                      max_steps: int = 20000) -> np.ndarray:
    """Kernel target f for many modes (rows (m, n)) on one base state."""
    modes = np.atleast_2d(np.asarray(modes, dtype=float))
    tables = stack_tables([build_table(state, tol=Accuracy(rtol).table)])
    count = modes.shape[0]
    k = modes[:, 1] * math.pi / (state.params.stretch * state.params.length)
    m = np.ascontiguousarray(modes[:, 0])
    kernel = target_batch if count >= PARALLEL_FROM else target_serial
    f, status, _ = kernel(m, k, np.zeros(count, dtype=np.int64), tables, rtol, max_steps)
    bad = status != 0
    if bad.any():
        i = int(np.argmax(bad))
        raise ConvergenceError(
            f"impedance integration failed for mode (m, n) = ({modes[i, 0]:g}, "
            f"{modes[i, 1]:g}): {STATUS_TEXT[int(status[i])]}"
        )
    return f


def targets_for(method: str, rtol: float) -> Targets:
    """targets(state, modes) of the impedance kernel or of the collocation method."""
    method = check_method(method)
    if method is Method.IMPEDANCE:
        return lambda state, modes: impedance_targets(state, modes, rtol=rtol)
    nodes = Accuracy(rtol).collocation_nodes
    return lambda state, modes: np.array(
        [collocation_target(state, int(m), int(n), nodes=nodes) for m, n in modes])
