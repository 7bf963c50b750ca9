"""The control parameters of a layered tube: what a critical value can be solved for.

A control is named by a string that travels unchanged through scans, curves, sweeps and
JSON records:

==========================  =====================================================
``"growth"``                the growth of the only layer, all components (g I)
``"growth[K]"``             layer K's growth (1 = innermost), all components
``"growth[K].theta"``       one component r, theta or z of layer K's growth ...
``"growth[K].r+theta"``     ... or several, varied together (cross-section growth)
``"stretch"``               the axial stretch lambda_z (stretch-controlled tubes)
``"voltage"``               Vbar
``"pressure"``              the inner pressure P_i
``"force"``                 the axial end force (force-controlled tubes)
==========================  =====================================================

:func:`parse_control` reads one into a :class:`Control`; ``str(control)`` writes it back in
the canonical form above, and :meth:`Control.apply` sets its value on a tube.
"""

from __future__ import annotations

import dataclasses
import re

from ..errors import ParameterError

#: the kinds of control of a layered tube (model/layers.py Tube)
TUBE_CONTROLS = ("growth", "stretch", "voltage", "pressure", "force")
#: the components of a layer's growth tensor diag(g_r, g_theta, g_z)
COMPONENTS = ("r", "theta", "z")

_SYNTAX = re.compile(r"^(?P<kind>[a-z_]+)(\[(?P<layer>\d+)\])?(\.(?P<comp>[a-z+]+))?$")


@dataclasses.dataclass(frozen=True)
class Control:
    """One control parameter: its kind, and for growth the layer (1-based) and the
    components varied (None: all three, isotropic growth of that layer)."""

    kind: str
    layer: int | None = None
    components: tuple[str, ...] | None = None

    def __post_init__(self):
        # The messages quote the control as written, not "solve_for": the same name is an
        # --along of a curve or a [grid] key of a sweep.
        if self.kind not in TUBE_CONTROLS:
            raise ParameterError(
                f"control {self.kind!r} is unknown; choose one of {', '.join(TUBE_CONTROLS)}"
            )
        if self.kind != "growth" and (self.layer is not None or self.components is not None):
            raise ParameterError(
                f"control {str(self)!r}: a layer or growth component applies to growth only,"
                f" not {self.kind}"
            )
        if self.components is not None:
            comps = tuple(c for c in COMPONENTS if c in self.components)
            bad = [c for c in self.components if c not in COMPONENTS]
            if bad or not comps:
                raise ParameterError(
                    f"growth component {'+'.join(self.components)!r} is unknown; choose r,"
                    " theta or z, or several joined by + (e.g. r+theta)"
                )
            object.__setattr__(self, "components", None if len(comps) == 3 else comps)

    def __str__(self) -> str:
        out = self.kind
        if self.layer is not None:
            out += f"[{self.layer}]"
        if self.components is not None:
            out += "." + "+".join(self.components)
        return out


def parse_control(solve_for, layer: int | None = None, component: str | None = None) -> Control:
    """The Control named by ``solve_for`` (a string of the table above, or a Control), with
    ``layer`` and ``component`` (``"theta"``, ``"r+theta"``) given apart, as the CLI does.

    >>> str(parse_control("growth", layer=2, component="theta+r"))
    'growth[2].r+theta'
    """
    if isinstance(solve_for, Control):
        text = str(solve_for)
    elif isinstance(solve_for, str):
        text = solve_for.strip()
    else:
        raise ParameterError(f"{solve_for!r} is not a control name")
    match = _SYNTAX.match(text)
    if match is None:
        raise ParameterError(
            f"{text!r} is not a control; write e.g. growth, growth[2],"
            " growth[2].theta, stretch, voltage, pressure or force"
        )
    kind, lay, comp = match["kind"], match["layer"], match["comp"]
    if layer is not None:
        if lay is not None and int(lay) != layer:
            raise ParameterError(f"layer {layer} contradicts the control {text!r}")
        lay = layer
    if component is not None:
        if comp is not None and comp != component:
            raise ParameterError(f"component {component!r} contradicts the control {text!r}")
        comp = component
    if lay is not None and (isinstance(lay, bool) or int(lay) != float(lay)):
        raise ParameterError(f"layer = {lay!r} is not a whole number")
    return Control(
        kind,
        None if lay is None else int(lay),
        None if comp is None else tuple(comp.split("+")),
    )
