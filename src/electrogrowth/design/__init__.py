"""Which tube gives which pattern: the first mode along one design variable
(:mod:`.sequence`), the region, widest-margin design and sensitivities of a target pattern
(:mod:`.prescribe`, :mod:`.sensitivity`), the target patterns themselves (:mod:`.targets`).

May import ``bifurcation``, ``incremental``, ``basestate``, ``model``, ``outcomes`` and
``errors``; only ``cli`` and the package's ``__init__`` import it.
"""

from .prescribe import Design, prescribe
from .sensitivity import sensitivities
from .sequence import Interval, ModeSequence, SequenceSwitch, mode_sequence

__all__ = [
    "Design",
    "prescribe",
    "sensitivities",
    "Interval",
    "ModeSequence",
    "SequenceSwitch",
    "mode_sequence",
]
