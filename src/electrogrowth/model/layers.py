"""A tube as a stack of perfectly bonded layers (model/layer.py), and its loads.

Layers are listed from the inner face (R = 1) outward; layer k occupies
R_{k-1} <= R <= R_k, R_0 = 1. The paper's tube is :meth:`Tube.uniform`.

The loads: a radial voltage Vbar = V / (R_N - 1) between electrodes on the inner and outer
faces; follower pressures P_i on the inner face (P_i > 0 pushes it outward) and P_o on the
outer face (P_o > 0 pushes it inward); and either the total axial stretch lambda_z (growth
included) or the axial force at the ends, besides the pressure on closed ends, in which case
lambda_z is solved for. Derivations: docs/derivation-layered.md.

A tube checks itself when built: its fields, the supported box and a control named for it
are checked in :mod:`.tube_checks`.
"""

from __future__ import annotations

import dataclasses
import functools
import warnings

from ..errors import ParameterError
from .controls import KINDS, Control, parse_control
from .keys import KEYS_TEXT, key_value, with_key
from .layer import Growth, Layer, LinearGrowth
from .materials import Material, neo_hookean
from .params import check_uniform, check_uniform_number
from .tube_checks import check_supported, checked_control, checked_fields

__all__ = [
    "Growth",
    "Layer",
    "LinearGrowth",
    "Tube",
    "TubeParameters",
    "UNIFORM_KEYS",
    "KEYS_TEXT",
]

#: the numbers of the paper's tube (Tube.uniform), its parameter keys
UNIFORM_KEYS = ("outer_radius", "length", "growth", "stretch", "voltage")


@dataclasses.dataclass(frozen=True)
class Tube:
    """A layered tube and its loads (units mu = eps = R_i = 1).

    The only tube type. The paper's tube (one homogeneous layer, isotropic growth g) is
    :meth:`Tube.uniform`; such a tube :attr:`is_uniform` and is solved in closed form.

    Parameters
    ----------
    layers : sequence of Layer
        From the inner face outward, outer radii strictly increasing (the first starts at 1).
    length : float
        L / R_i > 0, the undeformed length (no effect on the base state).
    stretch : float or None
        Total axial stretch lambda_z = l / L > 0, growth included (default 1 when
        ``axial_force`` is None). Give this or ``axial_force``, not both.
    axial_force : float or None
        The axial force applied at the ends, in units mu R_i^2, besides the pressure load on
        closed ends: 0 for free ends. Then lambda_z is solved for; the wall's resultant is
        N = axial_force + pi (P_i r_i^2 - P_o r_o^2) with closed ends, N = axial_force without.
    voltage : float
        Vbar = V / (R_N - R_i) sqrt(eps / mu) >= 0, R_N the outermost radius.
    inner_pressure, outer_pressure : float
        Follower pressures P_i, P_o in units mu (sigma_rr = -P_i on the inner face, -P_o on the
        outer face; P_i > 0 inflates).
    closed_ends : bool
        The ends are capped, so the pressures load them: under force control they add to the
        wall's axial force; at a prescribed stretch they change only the reported end force.

    Examples
    --------
    >>> tube = Tube((Layer(1.1, shear_modulus=10.0, growth=1.2), Layer(2.0)), voltage=0.3)
    >>> tube.radii, tube.control, tube.is_uniform
    ((1.0, 1.1, 2.0), 'stretch', False)
    >>> Tube.uniform(outer_radius=2.0, growth=1.2).is_uniform
    True
    """

    layers: tuple[Layer, ...]
    length: float = 1.0
    stretch: float | None = None
    axial_force: float | None = None
    voltage: float = 0.0
    inner_pressure: float = 0.0
    outer_pressure: float = 0.0
    closed_ends: bool = False

    def __post_init__(self):
        # checked and normalised (model/tube_checks.py), then set on the frozen instance
        for name, value in checked_fields(self).items():
            object.__setattr__(self, name, value)
        check_supported(self)

    @classmethod
    def uniform(
        cls,
        outer_radius: float = 1.4,
        length: float = 1.0,
        growth: float = 1.0,
        stretch: float = 1.0,
        voltage: float = 0.0,
        material: Material | None = None,
    ) -> Tube:
        """The paper's tube (Sec. 3.1): one homogeneous layer 1 <= R <= Rbar_o of unit shear
        modulus and permittivity, isotropic growth g (F_g = g I), total axial stretch
        lambda_z (growth included), voltage Vbar, no pressure.

        >>> tube = Tube.uniform(outer_radius=1.4, growth=1.2, voltage=0.4)
        >>> tube.growth, tube.material.name, tube.at("growth", 1.5).growth
        (1.2, 'neo-hookean', 1.5)
        """
        check_uniform(outer_radius, length, growth, stretch, voltage)
        return cls._built(outer_radius, length, growth, stretch, voltage, material)

    @classmethod
    def _built(cls, outer_radius, length, growth, stretch, voltage, material) -> Tube:
        """Tube.uniform of checked numbers."""
        material = neo_hookean() if material is None else material
        if not isinstance(material, Material):
            raise ParameterError(f"material = {material!r} is not a Material")
        # every number is checked above, the layer's too (1 < Rbar_o, g in the supported box,
        # unit modulus and permittivity): the rest of Layer's and Tube's checks hold by
        # construction, so a march setting g at every step pays for them once
        layer = object.__new__(Layer)
        g = float(growth)
        for name, value in (
            ("outer_radius", float(outer_radius)),
            ("material", material),
            ("shear_modulus", 1.0),
            ("permittivity", 1.0),
            ("growth", (g, g, g)),
        ):
            object.__setattr__(layer, name, value)
        tube = object.__new__(cls)
        fields = dict(_UNLOADED, layers=(layer,), length=float(length), stretch=float(stretch))
        fields["voltage"] = float(voltage)
        fields["is_uniform"] = True  # by construction: the cached property, known already
        for name, value in fields.items():
            object.__setattr__(tube, name, value)
        return tube

    def _uniform_at(self, name: str, value: float) -> Tube:
        """A uniform tube with one of its five numbers set: checked in the paper's symbols,
        built as Tube.uniform builds it (a march sets one at every step)."""
        five = dict(
            outer_radius=self.outer_radius,
            length=self.length,
            growth=self.layers[0].growth[0],
            stretch=self.stretch,
            voltage=self.voltage,
        )
        five[name] = value
        check_uniform_number(name, five)
        return Tube._built(**five, material=self.layers[0].material)

    @functools.cached_property
    def is_uniform(self) -> bool:
        """One homogeneous layer of the reference modulus and permittivity growing
        isotropically at a prescribed stretch, without pressure: the paper's tube, whose base
        state has a closed form (basestate/uniform.py), the fast path of every solver."""
        if len(self.layers) != 1:
            return False
        (layer,) = self.layers
        return (
            not layer.graded
            and layer.growth[0] == layer.growth[1] == layer.growth[2]
            and layer.shear_modulus == 1.0
            and layer.permittivity == 1.0
            and self.axial_force is None
            and self.inner_pressure == 0.0
            and self.outer_pressure == 0.0
            and not self.closed_ends
        )

    @property
    def growth(self) -> float:
        """The isotropic growth g of a uniform tube; a layered tube has ``layers[K].growth``."""
        if not self.is_uniform:
            raise AttributeError(
                "growth is a layer's for this tube (tube.layers[K].growth); a single g exists"
                " only for a uniform tube (Tube.uniform)"
            )
        return self.layers[0].growth[0]

    @property
    def material(self) -> Material:
        """The energy of a one-layer tube; several layers have ``layers[K].material``."""
        if len(self.layers) != 1:
            raise AttributeError(
                "material is a layer's for a tube of several layers (tube.layers[K].material)"
            )
        return self.layers[0].material

    def check_control(self, solve_for) -> Control:
        """The Control named by ``solve_for`` (model/controls.py), checked against this tube:
        the layer exists (and is named when there are several), its growth is not graded,
        and the stretch or the force is the prescribed one."""
        return checked_control(self, solve_for)

    def at(self, name, value: float) -> Tube:
        """This tube with ``name`` set to ``value``: a control (model/controls.py: growth[K],
        growth[K].theta, stretch, voltage, pressure, force) or one of the KEYS a curve or
        sweep may vary (``length``, ``outer_pressure``, ``layers[K].outer_radius``,
        ``layers[K].thickness`` (the other layers' thicknesses kept), ``layers[K].shear_modulus``,
        ``layers[K].permittivity``; K = 1 innermost)."""
        value = float(value)
        if self.is_uniform and name in UNIFORM_KEYS:  # the paper's tube: its own numbers
            return self._uniform_at(name, value)
        if name == "outer_radius":  # the wall's outer face, for any number of layers
            name = f"layers[{len(self.layers)}].outer_radius"
        if isinstance(name, str) and (name in ("length", "outer_pressure") or "layers[" in name):
            return with_key(self, name, value)
        try:
            parse_control(name)
        except ParameterError as exc:  # name the keys too: ``name`` may be either
            raise ParameterError(f"{exc}; or a key of the tube: {KEYS_TEXT}") from None
        c = self.check_control(name)
        if c.kind == "growth":
            k = (c.layer or 1) - 1
            old = self.layers[k].growth
            g = tuple(
                value if c.components is None or comp in c.components else old[i]
                for i, comp in enumerate(("r", "theta", "z"))
            )
            layers = list(self.layers)
            layers[k] = dataclasses.replace(layers[k], growth=g)
            return dataclasses.replace(self, layers=tuple(layers))
        field = KINDS[c.kind].field
        return dataclasses.replace(self, **{field: value})

    def value_of(self, name) -> float:
        """The current value of a control (for growth: its first varied component) or of a
        key of :meth:`at` (as ``at`` sets it)."""
        value = key_value(self, name)
        if value is not None:
            return value
        c = self.check_control(name)
        if c.kind == "growth":
            comp = ("r", "theta", "z").index(c.components[0]) if c.components else 0
            return float(self.layers[(c.layer or 1) - 1].growth[comp])
        field = KINDS[c.kind].field
        return float(getattr(self, field))

    def parameter_keys(self) -> tuple[str, ...]:
        """Every number of the tube that :meth:`at` can set: the paper's five for a uniform
        tube (outer_radius, length, growth, stretch, voltage); otherwise the layers'
        thicknesses, shear moduli and permittivities, the growth components of layers with
        constant growth, the voltage, the stretch or the force (whichever is prescribed), the
        inner and outer pressures and the length."""
        if self.is_uniform:
            return UNIFORM_KEYS
        keys = []
        for k, layer in enumerate(self.layers, start=1):
            keys += [f"layers[{k}].{f}" for f in ("thickness", "shear_modulus", "permittivity")]
            if not layer.graded:
                keys += [f"growth[{k}].{c}" for c in ("r", "theta", "z")]
        return (*keys, "voltage", self.control, "pressure", "outer_pressure", "length")

    def reference(self) -> Tube:
        """The unloaded, ungrown tube (stress free, stable in every mode): growth 1 in every
        layer, no voltage or pressure, lambda_z = 1."""
        return self._reference

    @functools.cached_property
    def _reference(self) -> Tube:
        """:meth:`reference`, built once: every critical value reads its stable signs there."""
        layers = tuple(dataclasses.replace(layer, growth=1.0) for layer in self.layers)
        return Tube(layers, length=self.length)

    def as_dict(self) -> dict:
        """The tube as a JSON record: layers (radius, material, modulus, permittivity,
        growth) and loads; a uniform tube by its material and five numbers."""
        if self.is_uniform:
            return self.record()
        return {
            "layers": [
                {
                    "outer_radius": layer.outer_radius,
                    "material": layer.material.name,
                    "shear_modulus": layer.shear_modulus,
                    "permittivity": layer.permittivity,
                    "growth": repr(layer.growth) if layer.graded else list(layer.growth),
                }
                for layer in self.layers
            ],
            "outer_radius": self.outer_radius,
            "length": self.length,
            "stretch": self.stretch,
            "axial_force": self.axial_force,
            "voltage": self.voltage,
            "inner_pressure": self.inner_pressure,
            "outer_pressure": self.outer_pressure,
            "closed_ends": self.closed_ends,
        }

    def record(self) -> dict:
        """The tube's numbers as one flat record, for attributes, records and one-line
        texts: the material and the paper's five numbers for a uniform tube; otherwise the
        layers' outer radii and materials and the loads (None: not prescribed)."""
        if self.is_uniform:
            return {"material": self.material.name, **{k: self.value_of(k) for k in UNIFORM_KEYS}}
        return {
            "layer_outer_radii": [float(layer.outer_radius) for layer in self.layers],
            "materials": [layer.material.name for layer in self.layers],
            "length": self.length,
            "stretch": self.stretch,
            "axial_force": self.axial_force,
            "voltage": self.voltage,
            "inner_pressure": self.inner_pressure,
            "outer_pressure": self.outer_pressure,
        }

    @property
    def radii(self) -> tuple[float, ...]:
        """(1, R_1, ..., R_N): the undeformed faces and interfaces."""
        return (1.0,) + tuple(layer.outer_radius for layer in self.layers)

    @property
    def outer_radius(self) -> float:
        """R_N / R_i, the undeformed outer radius of the whole wall."""
        return self.layers[-1].outer_radius

    @property
    def control(self) -> str:
        """'stretch' (lambda_z prescribed) or 'force' (axial force prescribed)."""
        return "stretch" if self.axial_force is None else "force"

    @property
    def physical_voltage(self) -> float:
        """V in units sqrt(mu / eps) R_i: V = Vbar (R_N - 1)."""
        return self.voltage * (self.outer_radius - 1.0)


def TubeParameters(  # noqa: N802 -- the former class's name, kept for one release
    outer_radius: float = 1.4,
    length: float = 1.0,
    growth: float = 1.0,
    stretch: float = 1.0,
    voltage: float = 0.0,
    material: Material | None = None,
) -> Tube:
    """Deprecated: the paper's tube is ``Tube.uniform(...)`` (same arguments)."""
    warnings.warn(
        "TubeParameters(...) is deprecated; use Tube.uniform(...) (same arguments)",
        DeprecationWarning,
        stacklevel=2,
    )
    return Tube.uniform(outer_radius, length, growth, stretch, voltage, material)


#: the loads of a uniform tube besides its stretch and voltage (Tube.uniform): the defaults
_UNLOADED = {
    f.name: f.default
    for f in dataclasses.fields(Tube)
    if f.name not in ("layers", "length", "stretch", "voltage")
}
