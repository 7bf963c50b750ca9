"""The linearised (incremental) problem on a base state: is mode (m, n) at bifurcation?

The Stroh matrix (:mod:`.stroh`), the Chebyshev tables of the base state that feed the
compiled kernels (:mod:`.radial_table`), the compiled Riccati impedance kernel
(:mod:`.impedance`, its charts in :mod:`.charts`, tableau in :mod:`.dop853`) and its slow
SciPy twin (:mod:`.impedance_reference`), the independent Chebyshev collocation
(:mod:`.collocation`), the short-wave half-space problem at a face (:mod:`.halfspace`),
the accuracy policy (:mod:`.accuracy`) and the named targets ``ImpedanceTarget`` and
``CollocationTarget``, ``target(state, modes)``, one picked by ``targets_for(method, rtol)``
(:mod:`.targets`).

May import ``basestate``, ``model`` and ``errors``.
"""

from .accuracy import Accuracy
from .targets import (
    METHODS,
    CollocationTarget,
    Family,
    ImpedanceTarget,
    Method,
    impedance_targets,
    targets_for,
    wavenumber,
)

__all__ = [
    "Accuracy",
    "METHODS",
    "Family",
    "Method",
    "ImpedanceTarget",
    "CollocationTarget",
    "impedance_targets",
    "targets_for",
    "wavenumber",
]
