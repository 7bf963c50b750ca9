"""Where the tube first wrinkles: the march of a control parameter from the stable unloaded
tube to the first sign change of the targets (:mod:`.march`), one mode's critical value
(:mod:`.critical`) of a :class:`~.problem.Problem` (tube, control, side, accuracy, scan
options; its targets and march functions are named objects, :mod:`.along`), the scan over
all modes (:mod:`.scan`; the modes of its batch in :mod:`.scan_grid`, its result in
:mod:`.scan_record`), critical curves with located mode switches (:mod:`.curves`) and the
exact short-wave limit (:mod:`.surface`, its worst wave direction at a state in
:mod:`.directions`), the crease competitor (:mod:`.crease`) and the verdict of what comes
first (:mod:`.verdict`).

May import ``incremental``, ``basestate``, ``model``, ``outcomes`` and ``errors``.
"""

from typing import TYPE_CHECKING

from .. import _lazy

# Each name is imported on first use (PEP 562, _lazy.py): a critical value imports
# critical.py and what it needs, not the crease, the curves or the scan.
_EXPORTS = {
    ".crease": ("CreaseOnset", "crease_onset"),
    ".critical": ("CriticalPoint", "critical_value", "stable_sign"),
    ".curves": ("Curve", "critical_curve"),
    ".problem": ("Problem",),
    ".scan": ("ScanOptions", "scan_modes"),
    ".scan_record": ("ScanResult",),
    ".verdict": ("Verdict",),
}
_MODULE_OF = _lazy.module_of(_EXPORTS)

if TYPE_CHECKING:  # the names as the type checker reads them
    from .crease import CreaseOnset, crease_onset
    from .critical import CriticalPoint, critical_value, stable_sign
    from .curves import Curve, critical_curve
    from .problem import Problem
    from .scan import ScanOptions, scan_modes
    from .scan_record import ScanResult
    from .verdict import Verdict


def __getattr__(name: str):
    return _lazy.attribute(__name__, _MODULE_OF, name, globals())


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


__all__ = [
    "CriticalPoint",
    "critical_value",
    "stable_sign",
    "Curve",
    "critical_curve",
    "Problem",
    "ScanOptions",
    "ScanResult",
    "scan_modes",
    "CreaseOnset",
    "crease_onset",
    "Verdict",
]
