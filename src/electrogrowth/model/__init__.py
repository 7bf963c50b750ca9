"""What a tube is: its parameters (:mod:`.params`) and its energy (:mod:`.materials`: the
invariants, stresses, field and the 23 updated moduli of any energy Omega(I1, I2, I4, I5, I6)).

Physics only, pure functions and frozen dataclasses. The bottom of the ladder: imports
nothing of the package but ``errors``.
"""

from .materials import Material, gent, material_by_name, mooney_rivlin, neo_hookean
from .params import CONTROLS, SIDES, TubeParameters

__all__ = [
    "Material",
    "gent",
    "material_by_name",
    "mooney_rivlin",
    "neo_hookean",
    "CONTROLS",
    "SIDES",
    "TubeParameters",
]
