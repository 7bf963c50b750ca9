"""A tube as a stack of perfectly bonded layers, and its loads.

Units mu = eps = R_i = 1: every layer's shear modulus and permittivity are relative to these
reference values, its outer radius is in units of the inner radius of the whole tube. Layers are
listed from the inner face (R = 1) outward; layer k occupies R_{k-1} <= R <= R_k, R_0 = 1.
Each layer grows by F_g = diag(g_r, g_theta, g_z): a scalar (isotropic, g I), three constants,
or a function of R returning the triple (graded growth, e.g. :class:`LinearGrowth`).

The loads: a radial voltage Vbar = V / (R_N - 1) between electrodes on the inner and outer
faces; follower pressures P_i on the inner face (P_i > 0 pushes it outward) and P_o on the
outer face (P_o > 0 pushes it inward); and either the total axial stretch lambda_z (growth
included) or the axial force at the ends, besides the pressure on closed ends, in which case
lambda_z is solved for. Derivations: docs/derivation-layered.md.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
import warnings
from collections.abc import Callable

import numpy as np

from ..errors import ParameterError
from .controls import KINDS, Control, parse_control
from .materials import Material, neo_hookean
from .params import SUPPORTED, SUPPORTED_WHY, check_uniform

Growth = float | tuple[float, float, float] | Callable

#: the numbers of the paper's tube (Tube.uniform), its parameter keys
UNIFORM_KEYS = ("outer_radius", "length", "growth", "stretch", "voltage")

#: the keys of a tube that a curve or sweep may vary besides its controls (:meth:`Tube.at`)
KEYS_TEXT = (
    "length, outer_pressure, outer_radius, layers[K].outer_radius, layers[K].thickness,"
    " layers[K].shear_modulus, layers[K].permittivity"
)


def _number(name: str, value, valid: str, ok) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError(f"{name} = {value!r} is not a number; valid range: {valid}")
    if not math.isfinite(value) or not ok(value):
        raise ParameterError(f"{name} = {value!r} is out of range; valid range: {valid}")
    return float(value)


def _triple(name: str, value) -> tuple[float, float, float]:
    """A growth scalar or triple as three floats > 0 (ParameterError naming ``name``)."""
    if isinstance(value, (list, tuple, np.ndarray)):
        if len(value) != 3:
            raise ParameterError(
                f"{name} = {value!r} has {len(value)} entries; give g or [g_r, g_theta, g_z]"
            )
        return tuple(  # named g_r, g_theta, g_z: growth[K] is layer K's growth (controls.py)
            _growth(f"{name} g_{comp}", float(v) if isinstance(v, np.floating) else v, "> 0")
            for comp, v in zip(("r", "theta", "z"), value)
        )
    g = _growth(name, value, "> 0 (or three entries > 0)")
    return (g, g, g)


def _growth(name: str, value, valid: str) -> float:
    """A growth entry > 0 inside the supported box of the one-layer tube (params.py): a
    growth of 1e-9 was accepted and failed later as "no unloaded state", blamed on the
    tube's inner pressure."""
    g = _number(name, value, valid, lambda v: v > 0)
    lo, hi = SUPPORTED[3], SUPPORTED[4]
    if not lo <= g <= hi:
        raise ParameterError(
            f"{name} = {g:.6g} is outside the supported range {lo:g} to {hi:g}: {SUPPORTED_WHY}"
        )
    return g


@dataclasses.dataclass(frozen=True)
class LinearGrowth:
    """Growth varying linearly in R from ``inner`` at ``inner_radius`` to ``outer`` at
    ``outer_radius`` (each a scalar or a triple (g_r, g_theta, g_z), entries > 0); a picklable
    callable R -> (g_r, g_theta, g_z) for :class:`Layer`.

    >>> LinearGrowth(1.0, 2.0, 1.0, (1.2, 1.0, 1.0))(1.5)
    (1.1, 1.0, 1.0)
    """

    inner_radius: float
    outer_radius: float
    inner: tuple[float, float, float] | float
    outer: tuple[float, float, float] | float

    def __post_init__(self):
        a = _number("inner_radius", self.inner_radius, ">= 1", lambda v: v >= 1)
        _number("outer_radius", self.outer_radius, f"> inner_radius = {a:g}", lambda v: v > a)
        object.__setattr__(self, "inner", _triple("growth.inner", self.inner))
        object.__setattr__(self, "outer", _triple("growth.outer", self.outer))

    def __call__(self, R):
        t = (np.asarray(R, float) - self.inner_radius) / (self.outer_radius - self.inner_radius)
        out = tuple(gi + (go - gi) * t for gi, go in zip(self.inner, self.outer))
        return tuple(float(x) for x in out) if np.ndim(t) == 0 else out


@dataclasses.dataclass(frozen=True)
class Layer:
    """One layer of the wall.

    Parameters
    ----------
    outer_radius : float
        R_k / R_i > 1, the undeformed outer radius of the layer (its inner radius is the outer
        radius of the layer inside it, or 1).
    material : Material
        The energy Omega(I1, I2, I4, I5, I6) in units of this layer's own shear modulus and
        permittivity (default the ideal neo-Hookean dielectric).
    shear_modulus, permittivity : float
        mu_k / mu > 0 and eps_k / eps > 0 (default 1). The layer's energy is
        mu_k Omega(F, D / sqrt(mu_k eps_k)), i.e. mu_k W + I5 / (2 eps_k) for an ideal dielectric.
    growth : float, (g_r, g_theta, g_z) or callable
        F_g = diag(g_r, g_theta, g_z), entries > 0: a scalar g (isotropic), three constants,
        or a function R -> (g_r, g_theta, g_z), vectorised over an array R (graded growth).
        A scalar is stored as the triple (g, g, g).
    """

    outer_radius: float
    material: Material = dataclasses.field(default_factory=neo_hookean)
    shear_modulus: float = 1.0
    permittivity: float = 1.0
    growth: Growth = 1.0

    def __post_init__(self):
        fix = lambda f, v: object.__setattr__(self, f, v)  # noqa: E731
        fix("outer_radius", _number("outer_radius", self.outer_radius, "> 1", lambda v: v > 1))
        if not isinstance(self.material, Material):
            raise ParameterError(f"material = {self.material!r} is not a Material")
        for f in ("shear_modulus", "permittivity"):
            fix(f, _number(f, getattr(self, f), "0 < value < inf", lambda v: v > 0))
        if not callable(self.growth):
            fix("growth", _triple("growth", self.growth))

    @property
    def graded(self) -> bool:
        """True when the growth is a function of R."""
        return callable(self.growth)

    def growth_at(self, R) -> np.ndarray:
        """(g_r, g_theta, g_z) at R, shape (3,) + R.shape; ParameterError if an entry is not
        finite and > 0 (a graded growth called once with the array, else point by point)."""
        R = np.asarray(R, float)
        if not self.graded:
            return np.broadcast_to(
                np.array(self.growth)[(...,) + (None,) * R.ndim], (3,) + R.shape
            )
        try:
            g = np.asarray(self.growth(R), float)
            g = np.broadcast_to(
                g.reshape((3,) + (1,) * R.ndim) if g.shape == (3,) else g, (3,) + R.shape
            )
        except (TypeError, ValueError):
            g = np.array([np.asarray(self.growth(x), float) for x in R.ravel()])
            g = g.T.reshape((3,) + R.shape) if g.shape[-1:] == (3,) else None
        if g is None or not np.all(np.isfinite(g) & (g > 0)):
            raise ParameterError(
                f"growth function of the layer with outer_radius = {self.outer_radius:g}"
                " must return three finite entries > 0 (g_r, g_theta, g_z) at every R"
            )
        return g


@dataclasses.dataclass(frozen=True)
class Tube:
    """A layered tube and its loads (units mu = eps = R_i = 1).

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

    The paper's tube (one homogeneous layer, isotropic growth g) is :meth:`Tube.uniform`;
    such a tube :attr:`is_uniform` and is solved in closed form.

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
        fix = lambda f, v: object.__setattr__(self, f, v)  # noqa: E731
        layers = self.layers
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
                    f"layers[{k + 1}].outer_radius = {layer.outer_radius:g} is out of range;"
                    f" valid range: > {inner:g}, the layer's inner radius (layers are listed"
                    " from R = 1 outward, radii increasing; layers[1] is the innermost)"
                )
            if layer.graded:
                layer.growth_at(np.linspace(inner, layer.outer_radius, 17))
            inner = layer.outer_radius
        fix("layers", tuple(layers))
        fix("length", _number("length", self.length, "0 < L < inf", lambda v: v > 0))
        if self.axial_force is None:
            stretch = 1.0 if self.stretch is None else self.stretch
            fix("stretch", _number("stretch", stretch, "0 < lambda_z < inf", lambda v: v > 0))
        elif self.stretch is not None:
            raise ParameterError(
                f"stretch = {self.stretch!r} and axial_force = {self.axial_force!r} are both"
                " given; prescribe one of them"
            )
        else:
            fix("axial_force", _number("axial_force", self.axial_force, "finite", lambda v: True))
        if not isinstance(self.closed_ends, bool):
            raise ParameterError(f"closed_ends = {self.closed_ends!r} is not true or false")
        fix("voltage", _number("voltage", self.voltage, "0 <= Vbar < threshold", lambda v: v >= 0))
        for f in ("inner_pressure", "outer_pressure"):
            fix(f, _number(f, getattr(self, f), "finite (units mu)", lambda v: True))
        self._check_supported()

    def _check_supported(self) -> None:
        """The box in which every solver is supported (params.SUPPORTED), in the paper's
        symbols for the paper's tube, per layer otherwise."""
        if self.is_uniform:
            check_uniform(self.outer_radius, self.length, self.growth, self.stretch, self.voltage)
            return
        ro_max, l_lo, l_hi, _, _, e_lo, e_hi = SUPPORTED
        checks = [
            ("outer_radius", self.outer_radius, 1.0, ro_max),
            ("length", self.length, l_lo, l_hi),
        ]
        if self.stretch is not None:
            checks += [
                (
                    f"layers[{k}]: elastic axial stretch lambda_z / g_z",
                    self.stretch / la.growth[2],
                    e_lo,
                    e_hi,
                )
                for k, la in enumerate(self.layers, 1)
                if not la.graded
            ]
        for name, value, lo, hi in checks:
            if not lo <= value <= hi:
                raise ParameterError(
                    f"{name} = {value:.6g} is outside the supported range {lo:g} to {hi:g}:"
                    f" {SUPPORTED_WHY}"
                )

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
        material = neo_hookean() if material is None else material
        if not isinstance(material, Material):
            raise ParameterError(f"material = {material!r} is not a Material")
        layer = Layer(float(outer_radius), material, growth=float(growth))
        return cls((layer,), length=length, stretch=stretch, voltage=voltage)

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
        """g, the isotropic growth of a uniform tube (a layered tube: ``layers[K].growth``)."""
        if not self.is_uniform:
            raise AttributeError(
                "growth is a layer's for this tube (tube.layers[K].growth); a single g exists"
                " only for a uniform tube (Tube.uniform)"
            )
        return self.layers[0].growth[0]

    @property
    def material(self) -> Material:
        """The energy of a one-layer tube (several layers: ``layers[K].material``)."""
        if len(self.layers) != 1:
            raise AttributeError(
                "material is a layer's for a tube of several layers (tube.layers[K].material)"
            )
        return self.layers[0].material

    def check_control(self, solve_for) -> Control:
        """The Control named by ``solve_for`` (model/controls.py), checked against this tube:
        the layer exists (and is named when there are several), its growth is not graded,
        and the stretch or the force is the prescribed one."""
        c = parse_control(solve_for)
        n = len(self.layers)
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
            if self.layers[layer - 1].graded:
                raise ParameterError(
                    f"layer {layer} has graded growth, which is not a single control"
                    " parameter; give it constant growth to solve for it"
                )
            return Control("growth", layer if n > 1 or c.layer else None, c.components)
        if c.kind in ("stretch", "force") and self.control != c.kind:
            remedy = {
                "force": "prescribe an axial force (axial_force in the tube file,"
                " --axial-force F) to solve for it",
                "stretch": "prescribe the stretch instead (stretch in the tube file,"
                " --stretch) to solve for it",
            }[c.kind]
            have = "an axial force" if self.control == "force" else "the axial stretch"
            raise ParameterError(
                f"solve_for = {c.kind} is not a control of this tube, which prescribes"
                f" {have}; {remedy}"
            )
        return c

    def at(self, name, value: float) -> Tube:
        """This tube with ``name`` set to ``value``: a control (model/controls.py: growth[K],
        growth[K].theta, stretch, voltage, pressure, force) or one of the KEYS a curve or
        sweep may vary (``length``, ``outer_pressure``, ``layers[K].outer_radius``,
        ``layers[K].thickness`` (the other layers' thicknesses kept), ``layers[K].shear_modulus``,
        ``layers[K].permittivity``; K = 1 innermost)."""
        value = float(value)
        if self.is_uniform and name in UNIFORM_KEYS:  # named in the paper's symbols
            five = {key: self.value_of(key) for key in UNIFORM_KEYS}
            check_uniform(**{**five, name: value})
        if name == "outer_radius":  # the wall's outer face, for any number of layers
            name = f"layers[{len(self.layers)}].outer_radius"
        if isinstance(name, str) and (name in ("length", "outer_pressure") or "layers[" in name):
            return self._with_key(name, value)
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

    def _with_key(self, name: str, value: float) -> Tube:
        match = re.fullmatch(r"layers\[(\d+)\]\.(\w+)", name)
        if match is None:
            if name not in ("length", "outer_pressure"):
                raise ParameterError(f"{name!r} is not a key of a tube; valid: {KEYS_TEXT}")
            return dataclasses.replace(self, **{name: value})
        k, field = int(match[1]), match[2]
        if not 1 <= k <= len(self.layers):
            raise ParameterError(
                f"{name}: layer {k} does not exist; this tube has layers 1..{len(self.layers)}"
            )
        if field not in ("outer_radius", "thickness", "shear_modulus", "permittivity"):
            raise ParameterError(f"{name!r} is not a key of a tube; valid: {KEYS_TEXT}")
        _check_key(name, value, field, self.radii, k)
        layers = list(self.layers)
        if field == "thickness":  # every layer outside moves out with it
            inner = self.radii[k - 1]
            shift = inner + value - layers[k - 1].outer_radius
            for j in range(k - 1, len(layers)):
                if layers[j].graded:
                    raise ParameterError(f"{name}: layer {j + 1} has graded growth")
                layers[j] = dataclasses.replace(
                    layers[j], outer_radius=layers[j].outer_radius + shift
                )
        else:
            layers[k - 1] = dataclasses.replace(layers[k - 1], **{field: value})
        return dataclasses.replace(self, layers=tuple(layers))

    def value_of(self, name) -> float:
        """The current value of a control (for growth: its first varied component) or of a
        key of :meth:`at` (as ``at`` sets it)."""
        if name == "outer_radius":
            return self.outer_radius
        if name in ("length", "outer_pressure"):
            return float(getattr(self, name))
        match = re.fullmatch(r"layers\[(\d+)\]\.(\w+)", str(name))
        if match:
            k = int(match[1])
            if not 1 <= k <= len(self.layers):
                raise ParameterError(f"{name}: layer {k} does not exist")
            if match[2] == "thickness":
                return self.radii[k] - self.radii[k - 1]
            return float(getattr(self.layers[k - 1], match[2]))
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


def _check_key(name: str, value: float, field: str, radii: tuple[float, ...], k: int) -> None:
    """Refuse a value of the key ``name`` (layers[K].field) in its own terms: the layer
    would otherwise report a radius the user never gave (a thickness moves the radii)."""
    if field == "thickness":
        _number(name, value, "> 0", lambda v: v > 0)
    elif field == "outer_radius":
        inner = radii[k - 1]
        outer = radii[k + 1] if k + 1 < len(radii) else math.inf
        valid = f"{inner:g} < R < {outer:g} (the layer's inner radius, the next one's outer)"
        _number(
            name,
            value,
            valid if k + 1 < len(radii) else f"> {inner:g}",
            lambda v: inner < v < outer,
        )
    else:  # shear_modulus, permittivity
        _number(name, value, "0 < value < inf", lambda v: v > 0)


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
