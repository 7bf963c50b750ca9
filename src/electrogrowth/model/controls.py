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
the canonical form above.

Each kind of control is one entry of :data:`KINDS`, a :class:`ControlKind`: the tube field
it sets, its default side, its path (where a march starts, where it may end, the scale of
its steps), its words, symbol and unit. The lists of controls, the sides, the checks that a
side belongs to the control and the axis labels are read from there: a new load is one
entry (and its physics in basestate/ and incremental/).
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Callable
from typing import Any

from ..errors import ParameterError

#: the sides of a control that may move both ways: it decreases (compression) or
#: increases (extension)
SIDES = ("compression", "extension")


@dataclasses.dataclass(frozen=True)
class ControlKind:
    """One kind of control.

    ``field`` is the Tube field it sets (None: a layer's growth, set through its layer and
    components); ``default_side`` the side a march takes (None: the control only
    increases, and a side is refused); ``path(tube, up, base)`` the march's (start, end,
    scale), given ``base``, the base-state door (``free_stretch``, ``threshold`` and
    ``load_in_box``, where a force-controlled tube's lambda_z leaves the supported box
    first: the model itself solves nothing); ``words``, ``symbol`` (mathtext) and ``unit``
    name it on an axis, ``help`` on the command line."""

    name: str
    field: str | None
    default_side: str | None
    path: Callable[[Any, bool, Any], tuple[float, float, float]]
    words: str
    symbol: str
    unit: str
    help: str

    @property
    def sided(self) -> bool:
        return self.default_side is not None


def _wall_sum(tube, term) -> float:
    return sum(
        layer.initial_moduli[0] * term(a, b)
        for layer, a, b in zip(tube.layers, tube.radii, tube.radii[1:])
    )


def initial_modulus(material) -> float:
    """The small-strain shear modulus of a material's energy, in units of its layer's
    ``shear_modulus`` (:meth:`Material.initial_moduli`): 1 for the built-in energies; an
    energy text need not be in those units (check_units=False: "3*(-45/2*log(1 - (I1 -
    3)/45)) + I5/2" is a Gent layer three times as stiff), and a load's scale read off
    ``shear_modulus`` alone then cut its march's range 6x short."""
    return material.initial_moduli()[0]


def _growth_path(tube, up, base):
    return 1.0, 6.0, 1.0  # from the ungrown tube


def _stretch_path(tube, up, base):
    lz = base.free_stretch(tube)  # the free length at the tube's growth, no load
    return (lz, 8.0 * lz, lz) if up else (lz, 0.05 * lz, lz)


def _voltage_path(tube, up, base):
    """From 0 up to the voltage threshold, its scale; where a stiffening energy has none
    (inf), up to 1e3 times the wall's own voltage scale (:func:`voltage_scale`). That scale
    was 1 whatever the moduli: with every modulus times 1e-3 (Vbar_cr times sqrt(1e-3)) the
    march sampled a mode every 0.25 and stepped over an unstable window [0.0425, 0.0528]
    (probe round 8a)."""
    thr = base.threshold(tube, "voltage").value
    box = base.load_in_box(tube, "voltage")  # lambda_z leaves the box first (force control)
    if math.isfinite(thr):
        return 0.0, thr * (1 - 1e-12) if box is None else box, thr
    scale = voltage_scale(tube)
    return 0.0, 1e3 * scale if box is None else min(box, 1e3 * scale), scale


def voltage_scale(tube) -> float:
    """sqrt(mu / eps) of the wall in Vbar's units: a voltage whose field's stress eps E^2 is
    the wall's stiffness mu, the moduli weighed as the layers carry them, in parallel for
    the hoop stiffness (sum mu_k ln(R_k / R_{k-1}), the pressure path's scale) and in
    series for the permittivity (the layers are capacitors in series); 1 for a uniform
    tube of unit moduli."""
    logs = [math.log(b / a) for a, b in zip(tube.radii, tube.radii[1:])]
    wall = sum(logs)
    mu = _wall_sum(tube, lambda a, b: math.log(b / a)) / wall
    eps = wall / sum(t / layer.initial_moduli[1] for layer, t in zip(tube.layers, logs))
    return math.sqrt(mu / eps)


def pressure_scale(tube) -> float:
    """sum mu_k ln(R_k / R_{k-1}) of the unloaded tube: the pressure that strains it by O(1)."""
    return _wall_sum(tube, lambda a, b: math.log(b / a))


def force_scale(tube) -> float:
    """pi sum mu_k (R_k^2 - R_{k-1}^2): the axial force that strains the tube by O(1)."""
    return math.pi * _wall_sum(tube, lambda a, b: b * b - a * a)


def natural_scale(tube, kind: str) -> float:
    """The value of a control of ``kind`` that strains the tube by O(1): 1 for the growth
    factor and the stretch, :func:`voltage_scale`, :func:`pressure_scale`,
    :func:`force_scale`. Below a small fraction of it a load is as good as none
    (incremental.accuracy.certified)."""
    scales = {"voltage": voltage_scale, "pressure": pressure_scale, "force": force_scale}
    return scales[kind](tube) if kind in scales else 1.0


def _pressure_path(tube, up, base):
    """From P_i = P_o up to the pressure branch's threshold (inflation) or down (collapse);
    the scale is the unloaded tube's (:func:`pressure_scale`)."""
    scale = pressure_scale(tube)
    start = tube.outer_pressure
    if not up:
        return start, start - 20.0 * scale, scale
    thr = base.threshold(tube, "pressure").value
    end = thr * (1 - 1e-12) if math.isfinite(thr) else start + 50.0 * scale
    box = base.load_in_box(tube, "pressure")  # lambda_z leaves the box first (force control)
    return start, end if box is None else min(box, end), scale


def _force_path(tube, up, base):
    """From 0 down (compression) or up; the scale is :func:`force_scale`."""
    scale = force_scale(tube)
    return (0.0, 20.0 * scale, scale) if up else (0.0, -20.0 * scale, scale)


#: every kind of control, in the order the command line lists them
KINDS = {
    k.name: k
    for k in (
        ControlKind(
            "growth",
            None,
            None,
            _growth_path,
            "growth factor",
            "g",
            "(–)",
            "growth = g_cr, the smallest g > 1 at which the tube wrinkles (of one layer of a"
            " --tube: --layer, --component)",
        ),
        ControlKind(
            "stretch",
            "stretch",
            "compression",
            _stretch_path,
            "axial stretch",
            r"\lambda_z",
            "(–)",
            "stretch = lambda_z,cr on --side",
        ),
        ControlKind(
            "voltage",
            "voltage",
            None,
            _voltage_path,
            "voltage",
            r"\bar V",
            "(–)",
            "voltage = Vbar_cr, the smallest Vbar (or the threshold where the axisymmetric"
            " state is lost, if that comes first)",
        ),
        ControlKind(
            "pressure",
            "inner_pressure",
            "extension",
            _pressure_path,
            "inner pressure",
            "P_i",
            r"($\mu$)",
            "pressure = the inner follower pressure P_i,cr (from P_o: inflation, or --side"
            " compression: collapse)",
        ),
        ControlKind(
            "force",
            "axial_force",
            "compression",
            _force_path,
            "axial force",
            "F",
            r"($\mu R_i^2$)",
            "force = the axial end force F_cr of a tube with --axial-force (from 0:"
            " compression, or --side extension)",
        ),
    )
}
#: the kinds of control of a tube (model/layers.py Tube)
TUBE_CONTROLS = tuple(KINDS)
#: the controls a side belongs to (they may move both ways)
SIDED = tuple(name for name, k in KINDS.items() if k.sided)


def check_side(solve_for, side: str | None) -> str | None:
    """Validate ``side``; the control's default side when it has one (stretch and force
    compress, a pressure inflates), None for a control that only increases, for which a
    side is refused (ParameterError, as the command line refuses --side): it would be
    ignored, and a caller asking for a growth's "compression" would get its increase."""
    if side is not None and side not in SIDES:
        raise ParameterError(f"side = {side!r} is unknown; choose compression or extension")
    kind = KINDS.get(str(solve_for).split("[")[0].split(".")[0])
    if side is not None and kind is not None and not kind.sided:
        raise ParameterError(
            f"side = {side!r} applies only to {', '.join(SIDED[:-1])} or {SIDED[-1]},"
            f" not {solve_for}"
        )
    return side or (kind.default_side if kind is not None else None)


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
        if self.kind not in KINDS:
            raise ParameterError(
                f"control {self.kind!r} is unknown; choose one of {', '.join(KINDS)}"
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
