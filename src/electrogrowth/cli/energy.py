"""``--energy "0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2"``: a user's energy on the command line.

The text is read by model/energy_text.py (numbers, I1, I2, I4, I5, I6 and a few functions
only; one error line naming the problem, exit status 2). An energy whose initial shear
modulus or permittivity is not 1 is refused the same way (model/materials.py): every result
would be in the wrong units.
"""

from __future__ import annotations

from ..errors import ParameterError
from ..model.materials import Material


def energy_from_args(args) -> Material:
    """The Material of ``--energy`` (``--jm`` and ``--alpha`` belong to a --material)."""
    for flag, name in (("--jm", "jm"), ("--alpha", "alpha")):
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(
                f"{flag} = {value:g} is a parameter of a built-in --material, not of --energy;"
                " write it into the expression"
            )
    from ..model.energy_text import energy_material  # sympy: only for a user's energy

    return energy_material(args.energy)
