"""What a tube is: its parameters (:mod:`.params`: one homogeneous layer; :mod:`.layers`: a
stack of bonded layers with anisotropic or graded growth, pressures and axial force;
:mod:`.tube_file`: the TOML tube file) and its energy (:mod:`.materials`: the invariants,
stresses, field and the 23 updated moduli of any energy Omega(I1, I2, I4, I5, I6)).

Physics only, pure functions and frozen dataclasses. The bottom of the ladder: imports
nothing of the package but ``errors``.
"""

from .layers import Layer, LinearGrowth, Tube
from .materials import Material, gent, material_by_name, mooney_rivlin, neo_hookean
from .params import CONTROLS, SIDES
from .tube_file import load_tube

__all__ = [
    "Material",
    "gent",
    "material_by_name",
    "mooney_rivlin",
    "neo_hookean",
    "CONTROLS",
    "SIDES",
    "TubeParameters",
    "Layer",
    "LinearGrowth",
    "Tube",
    "load_tube",
]
