"""What a tube is: one type, :class:`Tube` (:mod:`.layers`: a stack of bonded layers and its
loads; ``Tube.uniform`` the paper's tube; its checks in :mod:`.tube_checks`), its layers
(:mod:`.layer`), the keys and the controls a computation may vary (:mod:`.keys`,
:mod:`.controls`), the TOML tube file (:mod:`.tube_file`), the supported box (:mod:`.params`)
and the energy (:mod:`.materials`: the invariants, stresses, field and the 23 updated moduli
of any energy Omega(I1, I2, I4, I5, I6)).

Physics only, pure functions and frozen dataclasses. The bottom of the ladder: imports
nothing of the package but ``errors``.
"""

from typing import TYPE_CHECKING

from .. import _lazy

# Each name is imported on first use (PEP 562, _lazy.py): a tube built in code does not
# import the TOML reader.
_EXPORTS = {
    ".layers": ("Layer", "LinearGrowth", "Tube", "TubeParameters"),
    ".materials": ("Material", "gent", "material_by_name", "mooney_rivlin", "neo_hookean"),
    ".params": ("CONTROLS", "SIDES"),
    ".tube_file": ("load_tube",),
}
_MODULE_OF = _lazy.module_of(_EXPORTS)

if TYPE_CHECKING:  # the names as the type checker reads them
    from .layers import Layer, LinearGrowth, Tube, TubeParameters
    from .materials import Material, gent, material_by_name, mooney_rivlin, neo_hookean
    from .params import CONTROLS, SIDES
    from .tube_file import load_tube


def __getattr__(name: str):
    return _lazy.attribute(__name__, _MODULE_OF, name, globals())


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


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
