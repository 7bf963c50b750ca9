"""electrogrowth: growth, voltage and wrinkling of soft electro-elastic tubes."""

from .errors import (BaseStateError, ConvergenceError, ElectrogrowthError, MaterialError,
                     NoBifurcationFound, ParameterError)
from .model.materials import Material, gent, material_by_name, mooney_rivlin, neo_hookean
from .model.params import TubeParameters

__all__ = [
    "BaseStateError", "ConvergenceError", "ElectrogrowthError", "MaterialError",
    "NoBifurcationFound", "ParameterError",
    "Material", "gent", "material_by_name", "mooney_rivlin", "neo_hookean",
    "TubeParameters",
]
__version__ = "0.1.0"
