"""One layer of a tube's wall: its radius, energy, modulus, permittivity and growth.

Units mu = eps = R_i = 1: a layer's shear modulus and permittivity are relative to these
reference values, its outer radius is in units of the inner radius of the whole tube. The
layer grows by F_g = diag(g_r, g_theta, g_z): a scalar (isotropic, g I), three constants, or
a function of R returning the triple (graded growth, e.g. :class:`LinearGrowth`), each entry
inside the supported box (model/params.py), as are the modulus and the permittivity.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from ..errors import ParameterError
from .materials import Material, neo_hookean
from .params import MODULI, MODULI_WHY, SUPPORTED, SUPPORTED_WHY, given

Growth = float | tuple[float, float, float] | Callable


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
            _growth(f"{name} g_{comp}", float(v) if isinstance(v, np.floating) else v, _GROWTH)
            for comp, v in zip(("r", "theta", "z"), value)
        )
    g = _growth(name, value, f"{_GROWTH} (or three entries in it)")
    return (g, g, g)


#: the supported range of a growth entry, the one-layer tube's (params.py): one text for a
#: growth that is not physical (0) and one outside the box (0.001), check round 29 D5
_GROWTH = f"{SUPPORTED[3]:g} to {SUPPORTED[4]:g}"


def _growth(name: str, value, valid: str) -> float:
    """A growth entry > 0 inside the supported box of the one-layer tube (params.py): a
    growth of 1e-9 was accepted and failed later as "no unloaded state", blamed on the
    tube's inner pressure."""
    g = _number(name, value, valid, lambda v: v > 0)
    lo, hi = SUPPORTED[3], SUPPORTED[4]
    if not lo <= g <= hi:
        raise ParameterError(
            f"{name} = {given(g)} is outside the supported range {_GROWTH}: {SUPPORTED_WHY}"
        )
    return g


def modulus(name: str, value) -> float:
    """A layer's shear modulus or permittivity > 0 inside the supported range (params.py):
    1e-300 was accepted and failed as a ZeroDivisionError deep in a scan."""
    lo, hi = MODULI
    v = _number(name, value, f"{lo:g} to {hi:g} (of the reference)", lambda v: v > 0)
    if not lo <= v <= hi:
        raise ParameterError(
            f"{name} = {given(v)} is outside the supported range {lo:g} to {hi:g}: {MODULI_WHY}"
        )
    return v


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
        mu_k / mu and eps_k / eps, each from 1e-8 to 1e8 (default 1; params.MODULI, and
        the same range for the ratio of the largest to the smallest of a tube's layers).
        The layer's energy is
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
            fix(f, modulus(f, getattr(self, f)))
        if not callable(self.growth):
            fix("growth", _triple("growth", self.growth))

    @property
    def initial_moduli(self) -> tuple[float, float]:
        """(mu, eps): the layer's small-strain shear modulus and permittivity in the tube's
        units, ``shear_modulus`` and ``permittivity`` times its energy's own
        (:meth:`Material.initial_moduli`). The one reading of a layer's stiffness and
        permittivity wherever a rule or a scale needs them (the crease criteria, a load's
        march): a layer written as an energy text carrying its moduli (check_units=False)
        is then the built-in layer with those moduli."""
        mu, eps = self.material.initial_moduli()
        return self.shear_modulus * mu, self.permittivity * eps

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
