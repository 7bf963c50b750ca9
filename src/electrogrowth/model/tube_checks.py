"""What a tube must satisfy (:class:`~electrogrowth.model.layers.Tube`): its fields checked
and normalised, the box in which every solver is supported, and a control named for it.

Every check raises a one-line ParameterError quoting the bad value and the valid range. The
fields: at least one Layer, listed from R = 1 outward with outer radii increasing (a graded
growth evaluated through its layer), the length and the stretch positive, the stretch or
the axial force (not both), the voltage not negative, the pressures finite. The supported
box (model/params.py): the paper's five numbers for the paper's tube, the outer radius, the
length, every layer's elastic axial stretch and the ratios of the layers' moduli and
permittivities otherwise. A control (model/controls.py) is
one of this tube: its layer exists, is named when there are several, and has constant
growth; the stretch or the force is the one the tube prescribes.
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from .controls import Control, parse_control
from .layer import Layer, _number
from .params import MODULI, MODULI_WHY, SUPPORTED, SUPPORTED_WHY, check_uniform, given


def checked_fields(tube) -> dict:
    """The fields of ``tube`` checked and normalised, by name: the layers as a tuple, the
    numbers as floats, the stretch 1 when neither it nor an axial force is given."""
    fields: dict = {}
    layers = tube.layers
    if isinstance(layers, Layer):
        layers = (layers,)
    if not isinstance(layers, (list, tuple)) or not layers:
        raise ParameterError(f"layers = {layers!r} is invalid; give at least one Layer")
    inner = 1.0
    for k, layer in enumerate(layers):
        if not isinstance(layer, Layer):  # named layers[K], K = 1 innermost, as in Tube.at
            raise ParameterError(f"layers[{k + 1}] = {layer!r} is not a Layer")
        if not layer.outer_radius > inner:
            raise ParameterError(
                f"layers[{k + 1}].outer_radius = {given(layer.outer_radius)} is out of range;"
                f" valid range: > {given(inner)}, the layer's inner radius (layers are listed"
                " from R = 1 outward, radii increasing; layers[1] is the innermost)",
                key=("layers", str(k + 1), "outer_radius"),
            )
        if layer.graded:
            layer.growth_at(np.linspace(inner, layer.outer_radius, 17))
        inner = layer.outer_radius
    fields["layers"] = tuple(layers)
    fields["length"] = _number("length", tube.length, "0 < L < inf", lambda v: v > 0)
    if tube.axial_force is None:
        stretch = 1.0 if tube.stretch is None else tube.stretch
        fields["stretch"] = _number("stretch", stretch, "0 < lambda_z < inf", lambda v: v > 0)
    elif tube.stretch is not None:
        raise ParameterError(
            f"stretch = {tube.stretch!r} and axial_force = {tube.axial_force!r} are both"
            " given; prescribe one of them"
        )
    else:
        fields["axial_force"] = _number("axial_force", tube.axial_force, "finite", lambda v: True)
    if not isinstance(tube.closed_ends, bool):
        raise ParameterError(f"closed_ends = {tube.closed_ends!r} is not true or false")
    fields["voltage"] = _number("voltage", tube.voltage, "0 <= Vbar < threshold", lambda v: v >= 0)
    for f in ("inner_pressure", "outer_pressure"):
        fields[f] = _number(f, getattr(tube, f), "finite (units mu)", lambda v: True)
    return fields


def check_supported(tube) -> None:
    """The box in which every solver is supported (params.SUPPORTED), in the paper's
    symbols for the paper's tube, per layer otherwise."""
    if tube.is_uniform:
        check_uniform(tube.outer_radius, tube.length, tube.growth, tube.stretch, tube.voltage)
        return
    ro_max, l_lo, l_hi, _, _, e_lo, e_hi = SUPPORTED
    outermost = ("layers", str(len(tube.layers)), "outer_radius")
    checks = [
        ("outer_radius", tube.outer_radius, 1.0, ro_max, outermost),
        ("length", tube.length, l_lo, l_hi, ("length",)),
    ]
    if tube.stretch is not None:
        checks += [
            (
                f"layers[{k}]: elastic axial stretch lambda_z / g_z",
                tube.stretch / la.growth[2],
                e_lo,
                e_hi,
                ("stretch",),
            )
            for k, la in enumerate(tube.layers, 1)
            if not la.graded
        ]
    for name, value, lo, hi, key in checks:
        if not lo <= value <= hi:
            raise ParameterError(
                f"{name} = {given(value)} is outside the supported range {lo:g} to {hi:g}:"
                f" {SUPPORTED_WHY}",
                key=key,
            )
    for field in ("shear_modulus", "permittivity"):
        _check_ratio(tube.layers, field)


def _check_ratio(layers, field: str) -> None:
    """The largest over the smallest ``field`` of the layers inside MODULI's upper bound:
    each layer in range is not enough, as a film 1e8 on a substrate 1e-8 is, in the
    wall's equations, a substrate 1e-16 as stiff as its film."""
    values = [getattr(la, field) for la in layers]
    hi, lo = max(values), min(values)
    if hi / lo > MODULI[1]:
        k, j = values.index(hi) + 1, values.index(lo) + 1
        raise ParameterError(
            f"layers[{k}].{field} / layers[{j}].{field} = {given(hi / lo)} is outside the"
            f" supported range 1 to {MODULI[1]:g}: {MODULI_WHY}"
        )


def checked_control(tube, solve_for) -> Control:
    """The Control named by ``solve_for`` (model/controls.py), checked against ``tube``
    (:meth:`Tube.check_control <electrogrowth.model.layers.Tube.check_control>`)."""
    c = parse_control(solve_for)
    n = len(tube.layers)
    if c.kind == "growth":
        if c.layer is None and n > 1:
            raise ParameterError(
                f"solve_for = growth needs a layer for a tube of {n} layers; name one of"
                f" 1..{n} (--layer K, or growth[K])"
            )
        layer = 1 if c.layer is None else c.layer
        if not 1 <= layer <= n:
            raise ParameterError(
                f"layer = {layer} does not exist; this tube has layers 1..{n} (1 innermost)"
            )
        if tube.layers[layer - 1].graded:
            raise ParameterError(
                f"layer {layer} has graded growth, which is not a single control"
                " parameter; give it constant growth to solve for it"
            )
        return Control("growth", layer if n > 1 or c.layer else None, c.components)
    if c.kind in ("stretch", "force") and tube.control != c.kind:
        remedy = {
            "force": "prescribe an axial force (axial_force in the tube file,"
            " --axial-force F) to solve for it",
            "stretch": "prescribe the stretch instead (stretch in the tube file,"
            " --stretch) to solve for it",
        }[c.kind]
        have = "an axial force" if tube.control == "force" else "the axial stretch"
        raise ParameterError(
            f"solve_for = {c.kind} is not a control of this tube, which prescribes"
            f" {have}; {remedy}"
        )
    return c
