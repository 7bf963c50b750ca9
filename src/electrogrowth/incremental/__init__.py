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

from typing import TYPE_CHECKING

from .. import _lazy

# Each name is imported on first use (PEP 562, _lazy.py): the accuracy policy alone (the
# command line's checks) does not load the compiled kernels.
_EXPORTS = {
    ".accuracy": ("Accuracy",),
    ".targets": (
        "METHODS",
        "CollocationTarget",
        "Family",
        "ImpedanceTarget",
        "Method",
        "impedance_targets",
        "targets_for",
        "wavenumber",
    ),
}
_MODULE_OF = _lazy.module_of(_EXPORTS)

if TYPE_CHECKING:  # the names as the type checker reads them
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


def __getattr__(name: str):
    return _lazy.attribute(__name__, _MODULE_OF, name, globals())


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


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
