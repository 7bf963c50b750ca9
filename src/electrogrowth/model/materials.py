"""Isotropic, incompressible electro-elastic energies Omega(I1, I2, I4, I5, I6).

The energy is per unit volume of the virtual (grown, stress-free) configuration, in units
mu = eps = 1, and depends on the invariants (paper Sec. 2, eq. 8)

    I1 = tr C,  I2 = [(tr C)^2 - tr C^2] / 2,  I4 = D~.D~,  I5 = D~.C D~,  I6 = D~.C^2 D~,

with C = F_e^T F_e and D~ the electric displacement in the virtual configuration.
Everything the solvers need is derived from the energy alone, symbolically at definition
time (sympy) and evaluated numerically (numpy, vectorised):

* ``stress(l1, l2, l3, d)``: tau_i = sigma_ii + p, the principal Cauchy stress without the
  Lagrange multiplier (paper eq. 9);
* ``electric_field(l1, l2, l3, d)``: E_1 = F_e^{-T} dOmega/dD~ (paper eq. 9);
* ``moduli(l1, l2, l3, d)``: the non-zero updated electro-elastic moduli A_0, Gamma_0, K_0
  (paper eq. after 16-1) in the principal basis, as an array whose last axis follows
  ``moduli.MODULI_NAMES``.

Arguments are the principal elastic stretches l1 (radial), l2 (hoop), l3 (axial), with
l1 l2 l3 = 1, and the current (Eulerian) electric displacement d = D_1, which is radial.

Per energy, sympy differentiates Omega in the invariants and lambdifies those derivatives
(milliseconds, once per energy and process); the chain rule from them to stress, field and
moduli is the same for every energy and ships as generated plain Python
(:mod:`._chain_rule`, written by tools/derive_chain_rule.py), so no process derives it and
no energy needs a compile step or an on-disk cache.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import MaterialError, ParameterError
from . import _chain_rule
from .builtin_energies import BuiltinEnergy

if TYPE_CHECKING:
    import sympy as sp

#: Names this module lends from invariants.py (sympy symbols), imported when first asked for,
#: so that a process with built-in energies alone never imports sympy.
_SYMBOLIC: tuple[str, ...] = (
    "I1",
    "I2",
    "I4",
    "I5",
    "I6",
    "INVARIANTS",
    "reference_moduli",
    "_nonzero_at_witness",
)
_SYMBOLIC += ("_energy_value", "_energy_gradient", "_energy_derivatives")


def __getattr__(name: str):
    if name in _SYMBOLIC:
        from . import invariants

        return getattr(invariants, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def shorten(text: str) -> str:
    """``text`` cut for an error message (energy_grammar.shorten, imported when needed)."""
    from .energy_grammar import shorten

    return shorten(text)


_NO_HESSIAN = [0.0] * 25  # placeholder W for the forms that do not read it (stress, field)


def _invariants(l1, l2, l3, d):
    """(I1, I2, I4, I5, I6) at principal stretches (l1, l2, l3) and radial current d."""
    dt2 = (d / l1) ** 2
    return (
        l1**2 + l2**2 + l3**2,
        (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2,
        dt2,
        dt2 * l1**2,
        dt2 * l1**4,
    )


def _all_finite(values) -> bool:
    """Every entry of every value finite (a numeric form returns plain numbers for
    constant derivatives, arrays for the others)."""
    return all(
        math.isfinite(v) if isinstance(v, (int, float)) else bool(np.isfinite(v).all())
        for v in values
    )


@dataclasses.dataclass(frozen=True, init=False)
class Material:
    """An ideal or non-ideal isotropic incompressible electro-elastic material.

    Parameters
    ----------
    name : str
        Short label used in output.
    energy : sympy.Expr or str
        Omega in the symbols ``I1, I2, I4, I5, I6`` of this module, in units mu = eps = 1
        (the initial shear modulus and permittivity), zero-stress in the virtual state; or
        its text, e.g. ``"(I1 - 3)/2 + I5/2"``, read by the grammar of
        model/energy_grammar.py (never evaluated; docs/security.md).
    check_units : bool, keyword-only
        Refuse (MaterialError) an energy whose reference state (I1 = I2 = 3, D = 0) has a
        shear modulus mu = 2 (Omega_1 + Omega_2) or a permittivity
        eps = 1 / (2 (Omega_4 + Omega_5 + Omega_6)) other than 1 (default True): every
        result is in units of mu and eps, so such an energy would silently give numbers in
        the wrong units. :meth:`normalized` rescales one to these units instead; False
        keeps a deliberately scaled energy (e.g. a layer written with its own moduli).

    Raises
    ------
    MaterialError
        An expression in other symbols, a text outside the grammar, an energy of another
        type, or (check_units) moduli other than 1, naming which.

    Examples
    --------
    >>> from electrogrowth.model.materials import Material, I1, I5
    >>> mat = Material("my-neo-Hookean", (I1 - 3) / 2 + I5 / 2)
    >>> float(mat.stress(1.0, 1.0, 1.0, 0.0)[0])
    1.0
    """

    name: str
    #: What the energy was built from: a sympy expression, or a BuiltinEnergy (evaluated by
    #: generated code, its sympy expression built only when ``energy`` is asked for).
    definition: Any = dataclasses.field(repr=False)
    check_units: bool = dataclasses.field(default=True, compare=False, repr=False)

    def __init__(self, name: str, energy, *, check_units: bool = True):
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "check_units", check_units)
        if not isinstance(energy, BuiltinEnergy):  # checked there, by sympy
            from .invariants import checked_energy

            energy = checked_energy(name, energy, check_units)
        object.__setattr__(self, "definition", energy)

    @property
    def energy(self) -> sp.Expr:
        """Omega as a sympy expression in I1, I2, I4, I5, I6 (imports sympy)."""
        d = self.definition
        return d.expression() if isinstance(d, BuiltinEnergy) else d

    def __repr__(self) -> str:
        d = self.definition
        return f"Material(name={self.name!r}, energy={d if isinstance(d, BuiltinEnergy) else d})"

    @classmethod
    def normalized(cls, name: str, energy) -> Material:
        """The energy in units mu = eps = 1: Omega'(I1, I2, I4, I5, I6) =
        Omega(I1, I2, s I4, s I5, s I6) / mu with s = mu eps, mu and eps of the reference
        state (see ``check_units``); stresses are then in units of mu and D of sqrt(mu eps).

        >>> from electrogrowth.model.materials import I1, I5
        >>> mat = Material.normalized("stiff", (I1 - 3) + I5 / 4)
        >>> mat.energy
        I1/2 + I5/2 - 3/2
        """
        from .invariants import normalized_energy

        return cls(name, normalized_energy(name, cls(name, energy, check_units=False).energy))

    def numeric(self) -> tuple[Callable, Callable, Callable]:
        """(Omega, its gradient, (gradient, Hessian)) in the invariants, as numeric functions
        of (I1, I2, I4, I5, I6): generated code for a built-in energy, lambdified sympy
        (once per energy and process) for any other."""
        return _numeric(self.definition)

    def kind(self) -> str:
        """'neo-hookean' (Omega = (I1 - 3)/2 + I5/2), 'ideal' (W(I1, I2) + I5/2) or
        'general'."""
        return _kind(self.definition)

    def omega(self) -> Callable | None:
        """Numeric Omega(I1, ..., I6), or None for a polynomial energy (finite everywhere)."""
        d = self.definition
        if isinstance(d, BuiltinEnergy):
            return None if d.polynomial else self.numeric()[0]
        from .invariants import INVARIANTS

        return None if d.is_polynomial(*INVARIANTS) else self.numeric()[0]

    def _derivs(self, l1, l2, l3, d, *, hessian: bool = True):
        l1, l2, l3, d, inv, omega, w, W = self._raw_derivs(l1, l2, l3, d, hessian)
        if not _all_finite([omega]):
            self._outside(inv, [omega], "energy")
        if not _all_finite(w) or not _all_finite(W):
            self._outside(inv, [*w, *W], "energy's derivatives")
        return self._broadcast(l1, l2, l3, d, w, W)

    def _raw_derivs(self, l1, l2, l3, d, hessian: bool):
        """(l1, l2, l3, d, invariants, Omega, its gradient, its Hessian (flat, or [])), not
        checked: NaN or inf where the energy or its derivatives are not finite."""
        l1, l2, l3, d = np.broadcast_arrays(*(np.asarray(x, float) for x in (l1, l2, l3, d)))
        inv = _invariants(l1, l2, l3, d)
        value, gradient, derivatives = self.numeric()
        # Overflow is reported by the callers (a ParameterError or NaN), not as NumPy warnings.
        with np.errstate(all="ignore"):
            omega = np.asarray(self._evaluate(value, inv), dtype=float)
            if not hessian:
                w, W = self._evaluate(gradient, inv), []
            else:
                w, W = self._evaluate(derivatives, inv)
                W = [x for row in W for x in row]
        return l1, l2, l3, d, inv, omega, w, W

    @staticmethod
    def _broadcast(l1, l2, l3, d, w, W):
        """The chain rule's arguments: every derivative as an array of the stretches' shape."""
        w = [_shaped(x, l1.shape) for x in w]
        if not W:
            return (l1, l2, l3, d, w, _NO_HESSIAN)
        W = [_shaped(x, l1.shape) for x in W]
        return (l1, l2, l3, d, w, W)

    def _evaluate(self, function, inv):
        """A numeric function of the energy at the invariants ``inv``; an integer too
        large for a double in it is a ParameterError, not an OverflowError."""
        try:
            return function(*inv)
        except OverflowError:
            raise ParameterError(
                f"the energy {shorten(self.name)!r} overflows a double at I1 = "
                f"{float(np.ravel(inv[0])[0]):.6g}"
            ) from None

    def _outside(self, inv, values, what: str):
        """ParameterError at the first point where one of ``values`` is not finite."""
        shape = np.broadcast_shapes(*(np.shape(v) for v in [inv[0], *values]))
        finite = np.logical_and.reduce(
            [np.broadcast_to(np.isfinite(v), shape) for v in values], axis=0
        )
        at = np.ravel(np.broadcast_to(inv[0], shape))[np.argmax(~np.ravel(finite))]
        raise ParameterError(
            f"deformation outside the domain of {shorten(self.name)!r} (I1 = {at:.6g}): the"
            f" {what} {'is' if what == 'energy' else 'are'} not finite there"
        )

    def stress(self, l1, l2, l3, d):
        """Principal tau_i = sigma_ii + p (i = r, theta, z), total (Maxwell included).

        Shape ``(3,) + broadcast shape``: the component is the FIRST axis.
        """
        args = self._derivs(l1, l2, l3, d, hessian=False)
        return np.array(_chain_rule.stress(*args), dtype=float)

    def finite_stress(self, l1, l2, l3, d) -> np.ndarray:
        """:meth:`stress`, NaN at every point where the energy, its derivatives or the stress
        are not finite instead of a ParameterError for the whole array.

        For a solver's own trial and probe states (basestate/plies.py), where such a point is
        no state to use, not a deformation the user gave: an exponential energy's stresses
        (~ (I1 - 3) exp((I1 - 3)^2)) overflow a double a little before the energy does, and a
        node-count probe or a Newton trial can land in between while the state sought lies
        far inside the double range."""
        return self._finite_form(_chain_rule.stress, l1, l2, l3, d, (3,))

    def finite_electric_field(self, l1, l2, l3, d) -> np.ndarray:
        """:meth:`electric_field`, NaN where it is not finite (as :meth:`finite_stress`)."""
        return self._finite_form(_chain_rule.field, l1, l2, l3, d, ())

    def _finite_form(self, form, l1, l2, l3, d, lead: tuple) -> np.ndarray:
        """One chain-rule form (stress or field, leading shape ``lead``) with NaN where it,
        the energy or the energy's gradient is not finite."""
        l1, l2, l3, d, _, omega, w, W = self._raw_derivs(l1, l2, l3, d, hessian=False)
        shape = l1.shape
        with np.errstate(all="ignore"):
            values = np.asarray(form(*self._broadcast(l1, l2, l3, d, w, W)), dtype=float)
        values = np.broadcast_to(values, lead + shape)
        ok = np.isfinite(values.reshape((-1,) + shape)).all(0)
        for x in (omega, *w):  # a gradient entry may be a plain number (a constant)
            ok &= np.broadcast_to(np.isfinite(x), shape)
        return np.where(ok, values, np.nan)

    def electric_field(self, l1, l2, l3, d):
        """Radial current electric field E_1 for radial current displacement d."""
        args = self._derivs(l1, l2, l3, d, hessian=False)
        field = _chain_rule.field(*args)
        return np.broadcast_to(np.asarray(field, float), args[0].shape).copy()

    def moduli(self, l1, l2, l3, d):
        """Updated moduli, shape ``broadcast(l1, ...).shape + (23,)``, order MODULI_NAMES."""
        args = self._derivs(l1, l2, l3, d)
        shape = args[0].shape
        # finite derivatives whose products pass the double range give inf moduli, which the
        # table refuses by name (radial_table._segment_table), not a warning on stderr
        with np.errstate(over="ignore", invalid="ignore"):
            moduli = _chain_rule.moduli(*args)
        return np.stack([_shaped(c, shape) for c in moduli], axis=-1)

    def is_ideal_dielectric(self) -> bool:
        """True when Omega = W(I1, I2) + I5 / 2 (E = D / eps, paper Sec. 3.1)."""
        return self.kind() != "general"

    def initial_moduli(self) -> tuple[float, float]:
        """(mu, eps): the small-strain shear modulus 2 (Omega_1 + Omega_2) and small-field
        permittivity 1 / (2 (Omega_4 + Omega_5 + Omega_6)) of the energy in the reference
        state, in units of its layer's ``shear_modulus`` and ``permittivity``. (1, 1) for
        the built-in energies and (to 1e-12) every energy that passes ``check_units``; one kept
        with ``check_units=False`` may carry its own ("10*((I1 - 3)/2) + I5/2" is a layer
        ten times as stiff). Either is 1 where the energy has no finite positive value
        there (nothing better to scale by)."""
        return _initial_moduli(self.definition)


def _shaped(x, shape: tuple) -> np.ndarray:
    """``x`` as a float array of ``shape``: most derivatives of an energy are already arrays of
    the stretches' shape and the rest constants, and np.broadcast_to costs ~10 us a call,
    thirty calls per evaluation (a fifth of a layered Gent tube's scan in its profile)."""
    x = np.asarray(x, float)
    if x.shape == shape:
        return x
    return np.full(shape, x) if x.ndim == 0 else np.broadcast_to(x, shape)


@functools.lru_cache(maxsize=64)
def _numeric(definition) -> tuple[Callable, Callable, Callable]:
    if isinstance(definition, BuiltinEnergy):
        forms = definition.numeric()
        if forms is not None:
            return forms
        definition = definition.expression()
    from .invariants import numeric_forms

    return numeric_forms(definition)


@functools.lru_cache(maxsize=64)
def _initial_moduli(definition) -> tuple[float, float]:
    if isinstance(definition, BuiltinEnergy):  # in units mu = eps = 1, known without sympy
        return 1.0, 1.0
    from .invariants import reference_moduli

    mu, eps = reference_moduli(definition)
    usable = lambda x: float(x) if math.isfinite(x) and x > 0 else 1.0  # noqa: E731
    return usable(mu), usable(eps)


@functools.lru_cache(maxsize=64)
def _kind(definition) -> str:
    if isinstance(definition, BuiltinEnergy):
        return definition.kind
    from .invariants import energy_kind

    return energy_kind(definition)


@functools.lru_cache(maxsize=1)
def neo_hookean() -> Material:
    """Ideal neo-Hookean dielectric, Omega = (I1 - 3)/2 + I5/2 (paper eq. neo-Hookean)."""
    return Material("neo-hookean", BuiltinEnergy("neo-hookean"))


#: The smallest Gent jm: such a material locks within about 2 % strain (I1 - 3 = jm), and
#: far below it I1 - 3's rounding (~1e-15) is no longer small against jm (jm = 1e-30 leaves
#: even the unloaded tube "undefined", blamed on the loads). The generated forms are checked
#: from here up (tests/model/test_builtin_energies.py).
JM_MIN = 1e-3


def gent(jm: float = 97.2) -> Material:
    """Ideal Gent dielectric, Omega = -(Jm/2) ln(1 - (I1 - 3)/Jm) + I5/2.

    ``jm`` >= JM_MIN = 1e-3 is the dimensionless stiffening parameter; jm -> infinity
    recovers neo-Hookean. 97.2 is the classical value for VHB-type elastomers.
    """
    if isinstance(jm, bool) or not isinstance(jm, (int, float)) or not JM_MIN <= jm < np.inf:
        raise ParameterError(
            f"Gent parameter jm = {jm!r} is out of range; valid range: {JM_MIN:g} <= jm < inf"
            " (a smaller jm locks the material within 2 % strain)"
        )
    return Material(f"gent(jm={float(jm):g})", BuiltinEnergy("gent", float(jm)))


def mooney_rivlin(alpha: float = 0.5) -> Material:
    """Ideal Mooney-Rivlin dielectric, Omega = [alpha (I1-3) + (1-alpha)(I2-3)]/2 + I5/2.

    ``alpha`` in (0, 1] splits the unit shear modulus; alpha = 1 is neo-Hookean.
    """
    if isinstance(alpha, bool) or not isinstance(alpha, (int, float)) or not (0 < alpha <= 1):
        raise ParameterError(f"Mooney-Rivlin alpha = {alpha!r} is invalid; need 0 < alpha <= 1")
    return Material(
        f"mooney-rivlin(alpha={alpha:g})", BuiltinEnergy("mooney-rivlin", float(alpha))
    )


BUILTIN: dict[str, Callable[..., Material]] = {
    "neo-hookean": neo_hookean,
    "gent": gent,
    "mooney-rivlin": mooney_rivlin,
}


def material_by_name(name: str, **params) -> Material:
    """Look up a built-in material; ``params`` are passed to its constructor."""
    try:
        make = BUILTIN[name]
    except KeyError:
        raise MaterialError(
            f"unknown material {name!r}; choose one of {', '.join(BUILTIN)}"
        ) from None
    return make(**params)
