"""Which controls the tube's amplitude equation covers, and which way each moves
(docs/derivation-koiter.md, "Other controls" and "Pressures on the faces").

The expansion c = c_c + c_2 eps^2 holds for any control c that the base state follows
smoothly: the energy is expanded about the base state at c, so A(c), and through it A'(c),
carry the whole dependence on c (growth, voltage, axial stretch, pressure alike). What
differs between controls is only which direction is "beyond onset": a growth or a voltage
increases from the unloaded tube, a sided control (the stretch, a pressure) moves to its
``side``; the branch is supercritical when c_2 has that direction's sign.
"""

from __future__ import annotations

from ..errors import ParameterError
from ..model.controls import check_side, parse_control

#: the kinds of control each family's expansion covers
COVERED = {
    "prismatic": ("growth", "voltage", "stretch", "pressure"),
    "axisymmetric": ("growth", "voltage", "stretch", "pressure"),
    "wrinkle": ("growth", "voltage", "stretch", "pressure"),
}


def check_control(family: str, control) -> str:
    """The kind of ``control`` when ``family``'s expansion covers it, else a one-line
    ParameterError naming what is covered."""
    kinds = COVERED[family]
    try:
        kind = parse_control(control).kind
    except (ParameterError, TypeError, AttributeError):
        kind = None
    if kind not in kinds:
        raise ParameterError(
            f"control = {control!r}: the {family} family's amplitude equation covers "
            f"{', '.join(kinds)} so far"
        )
    return kind


def direction(control: str, side: str | None) -> int:
    """+1 when the control increases past onset (a growth, a voltage, the extension side),
    -1 when it decreases (the compression side: the default of the stretch)."""
    return -1 if check_side(control, side) == "compression" else 1


def branch(coefficient: float, control: str, side: str | None) -> str:
    """ "supercritical" when the branch lies beyond onset (c_2 in the control's direction),
    else "subcritical"."""
    return "supercritical" if coefficient * direction(control, side) > 0 else "subcritical"
