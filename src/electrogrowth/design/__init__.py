"""Which tube gives which pattern: the first mode along one design variable
(:mod:`.sequence`) or over two (:mod:`.mode_map`, its boundaries traced in
:mod:`.map_trace`, its record in :mod:`.map_record`), the region, widest-margin design and
sensitivities of a target pattern (:mod:`.prescribe`, :mod:`.prescribe_map`,
:mod:`.sensitivity`), the target patterns themselves (:mod:`.targets`), and the
growth-voltage map of an electro-active tube (:mod:`.growth_voltage`).

May import ``bifurcation``, ``incremental``, ``basestate``, ``model``, ``outcomes`` and
``errors``; only ``cli`` and the package's ``__init__`` import it.
"""

from .growth_voltage import GrowthVoltageMap, VoltageRegion, growth_voltage_map
from .map_record import Boundary, ModeMap, TriplePoint
from .mode_map import mode_map
from .prescribe import Design, prescribe
from .prescribe_map import MapDesign, prescribe_map
from .sensitivity import sensitivities
from .sequence import Interval, ModeSequence, SequenceSwitch, mode_sequence

__all__ = [
    "Boundary",
    "ModeMap",
    "TriplePoint",
    "mode_map",
    "MapDesign",
    "prescribe_map",
    "Design",
    "prescribe",
    "sensitivities",
    "Interval",
    "ModeSequence",
    "SequenceSwitch",
    "mode_sequence",
    "GrowthVoltageMap",
    "VoltageRegion",
    "growth_voltage_map",
]
