"""Sensitivity of one mode's critical value to every parameter of the tube.

At the critical value v of mode (m, n) the incremental problem is singular: with p any
other parameter of the tube, D(v, p) = 0 for D = det(M2) of the basis carried from the inner
face (incremental.targets.analytic_parts), analytic in both, with the roots and signs of the
kernel's target f. Where D_v = dD/dv != 0 the implicit function theorem gives a smooth v(p)
with D(v(p), p) = 0, and differentiating that identity,

    D_v dv/dp + D_p = 0,   so   dv/dp = -D_p / D_v.

D, not f: f = D / |M| divides out the size of the basis, and for a mode living at the inner
face (a stiff inner film's folds, its rings) that size holds the factor that crosses zero,
so f is a step of constant size about the root (+-1.9e-10 for a film 0.008 thick, 100 times
as stiff as its substrate) and -f_p / f_v came out near v itself (1.074 for 6.349, probe
round 7b). Where the kernel fails and D is not available, f is differentiated (its
fallback's target, the same roots).

Both partials are central differences at a step h = 1e-4 max(|p|, s_p) and h / 2, s_p the
scale of a load and 0 for the other keys (:func:`load_scale`), combined by Richardson
extrapolation, (4 D(h/2) - D(h)) / 3, which cancels the O(h^2) error of the central
difference: the targets of thick layered tubes at high m are strongly curved in p, where
D(h) alone is off by ~1e-4 at h = 1e-4. The step is relative for a size or a modulus: the
absolute 1e-4 max(1, |p|) of before was 10 % of a film 0.001 thick; a load (which may be 0
or near it) steps on its own scale. Where p cannot be moved both ways
(a bound of its range), or where the kernel's unit modulus bends between p - h and p + h
(:func:`_units_bend`), a one-sided second-order difference is used, Richardson-extrapolated.
docs/design.md derives it and tests/design/test_sequence.py and
tests/design/test_sensitivity_inner_film.py compare it with finite differences of full
critical_value solves.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..basestate.tube import solve_base_state
from ..bifurcation.critical import control_name
from ..bifurcation.error_estimate import ACHIEVED
from ..continuation.events import scaled
from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import Accuracy, check_rtol
from ..incremental.radial_table import layer_units
from ..incremental.targets import ImpedanceTarget, check_mode, with_family
from ..model.controls import force_scale, pressure_scale, voltage_scale
from ..model.layers import Tube
from ..outcomes import json_number

STEP = 1e-4


def parameter_keys(tube: Tube, solve_for: str) -> tuple[str, ...]:
    """Every number of ``tube`` (:meth:`Tube.parameter_keys`) but the unknown ``solve_for``
    (for a growth: each component it moves)."""
    solve_for = control_name(tube, solve_for)
    own = {solve_for}
    if solve_for.startswith("growth"):  # the growth solved for: all or some components
        c = tube.check_control(solve_for)
        comps = c.components or ("r", "theta", "z")
        own |= {f"growth[{c.layer or 1}].{comp}" for comp in comps}
    return tuple(k for k in tube.parameter_keys() if k not in own)


def key_value(tube: Tube, key: str) -> float:
    """The current value of ``key`` (as ``tube.at`` sets it)."""
    return tube.value_of(key)


def _derivative(f, x: float, h: float) -> float:
    """df/dx by a central difference, or a one-sided one (:func:`_one_sided`) where x - h or
    x + h is out of the parameter's range."""
    try:  # Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central D(h)
        near, far = f(x + h / 2) - f(x - h / 2), f(x + h) - f(x - h)
        return (8 * near - far) / (6 * h)
    except ParameterError:
        return _one_sided(f, x, h)


def sensitivities(
    tube,
    mode: tuple[int, int],
    solve_for: str,
    value: float,
    *,
    family: str | None = None,
    keys: tuple[str, ...] | None = None,
    rtol: float = 1e-12,
    step: float = STEP,
) -> dict[str, float]:
    """d(value)/dp of the critical ``solve_for`` of ``mode`` for every key p of the tube.

    Parameters
    ----------
    tube : Tube
        The design; its ``solve_for`` is replaced by ``value``.
    mode : (m, n)
        The mode, critical at ``value`` (f(value) = 0 to the accuracy ``rtol``).
    value : float
        The critical value (e.g. ``critical_value(tube, m, n, solve_for).value``).
    keys : tuple of str, optional
        The parameters; default :func:`parameter_keys`.

    Returns
    -------
    dict
        key -> dv/dp = -D_p / D_v (module docstring).

    Raises
    ------
    ParameterError
        If ``rtol`` is outside its valid range (incremental/accuracy.py RTOL_RANGE).
    ConvergenceError
        If D_v vanishes (a fold of the mode's branch: v(p) is not differentiable there).
    """
    check_rtol(rtol)  # a nan or 10 would give Accuracy(rtol) silently coarse digits
    solve_for = control_name(tube, solve_for)
    fam = check_mode(*mode, family)
    target = Determinant(ImpedanceTarget(Accuracy(rtol).fine), with_family(*mode, fam))
    try:
        return _implicit(target, tube, solve_for, value, keys, step, mode)
    except _NoDeterminant:
        return _implicit(target.plain, tube, solve_for, value, keys, step, mode)


def _implicit(target, tube, solve_for, value, keys, step, mode) -> dict[str, float]:
    """dv/dp = -D_p / D_v of ``target`` (a function of a tube) for every key (module
    docstring)."""

    def f(t, v: float) -> float:
        return target(t.at(solve_for, v))

    f_v = _derivative(lambda v: f(tube, v), value, step_of(tube, solve_for, value, step))
    if not math.isfinite(f_v) or f_v == 0.0:
        raise ConvergenceError(
            f"dD/d{solve_for} vanishes at {solve_for} = {value:g} for mode {tuple(mode)}: a"
            " fold of the branch, where the critical value is not differentiable"
        )
    out = {}
    for key in parameter_keys(tube, solve_for) if keys is None else keys:
        if _uncharged_zero(tube, solve_for, key):
            out[key] = 0.0
            continue
        p = key_value(tube, key)
        h = step_of(tube, key, p, step)
        f_key = lambda q, key=key: f(tube.at(key, q), value)  # noqa: E731
        f_p = _one_sided(f_key, p, h) if _units_bend(tube, key, p, h) else _derivative(f_key, p, h)
        out[key] = -f_p / f_v
    return out


def _uncharged_zero(tube, solve_for: str, key: str) -> bool:
    """Is dv/dp exactly 0 because the tube carries no charge? Every invariant of the field
    (I4, I5, I6) is quadratic in D, so the problem is even in Vbar: dv/dVbar = 0 at
    Vbar = 0; and with no field the permittivities do not enter (the incremental potential
    decouples from the mechanics, its coupling being proportional to D). A difference there
    reads only the rounding (dv/dVbar = -2.9e-11, a layer's permittivity -9.9e-11)."""
    if solve_for == "voltage" or tube.voltage != 0.0:
        return False
    return key == "voltage" or key == "permittivity" or key.endswith(".permittivity")


def _units_bend(tube, key: str, p: float, h: float) -> bool:
    """Do the kernel's table units (radial_table.layer_units) bend between p - h and p + h?
    D is in those units, a power of them: at a bend (a layer's modulus of 1 where it is the
    smallest or largest) its central difference takes the average of the two sides' powers,
    off by h / 2 relative (5e-5 for a substrate of modulus 1 under a film of 10)."""
    try:
        u = np.array([layer_units(tube.at(key, q).layers) for q in (p - h, p, p + h)])
    except ParameterError:
        return False  # the central difference is not taken there anyway
    return bool(np.any(abs(u[0] - 2.0 * u[1] + u[2]) > 1e-12 * abs(u).max(0)))


def _one_sided(f, x: float, h: float) -> float:
    """df/dx from one side (the upper one, else the lower), second order, Richardson
    extrapolated: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of D(h) = s (-3 f(x) +
    4 f(x + s h) - f(x + 2 s h)) / (2 h)."""
    for s in (1.0, -1.0):
        try:
            f0, f1, f2, f4 = (f(x + s * t * h) for t in (0.0, 0.5, 1.0, 2.0))
        except ParameterError:
            continue
        near, far = s * (-3 * f0 + 4 * f1 - f2) / h, s * (-3 * f0 + 4 * f2 - f4) / (2 * h)
        return (4 * near - far) / 3
    raise ParameterError(f"cannot vary the parameter at {x:g} by {h:g} either way")


def relative_step(x: float, step: float = STEP, scale: float = 0.0) -> float:
    """The difference step for a parameter at x on the scale ``scale`` (:func:`load_scale`):
    step max(|x|, scale), or step where both are 0."""
    size = max(abs(x), scale)
    return step * size if size != 0.0 else step


#: the scales of the loads, which may be 0 or near it (model/controls.py, the march's)
_LOAD_SCALES = {
    "pressure": pressure_scale,
    "outer_pressure": pressure_scale,
    "voltage": voltage_scale,
    "force": force_scale,
}


def load_scale(tube, key: str) -> float:
    """The change of ``key`` that strains the tube by O(1) for a load (a pressure, the
    voltage, the force), 0 for every other key: those are sizes, moduli, growths and
    stretches, positive, on the scale of their own value (a film 0.001 thick). A load's own
    value is no scale: at P_i = 1e-9 the step 1e-4 |P_i| = 1e-13 left only the rounding of D
    in its difference (dv/dP_i 1.9 % off, a design's dv/dVbar of the wrong sign, probe 9b)."""
    scale = _LOAD_SCALES.get(key)
    return 0.0 if scale is None else scale(tube)


def step_of(tube, key: str, x: float, step: float = STEP) -> float:
    """The difference step for ``key`` of ``tube`` at x (:func:`relative_step`)."""
    return relative_step(x, step, load_scale(tube, key))


def margin_error(tube, key: str, v: float, w: float, rtol: float, step: float = STEP) -> float:
    """The least error of dM/dp, M = s (w - v) / |v|, for ``key`` p: each critical value is
    known to ACHIEVED rtol of itself (error_estimate.achieved_floor) and a sensitivity
    differences the targets over the step h of p, (8 D(h/2) - D(h)) / 6h, which takes that
    error to 3 ACHIEVED rtol |v| / h; M takes two: 6 ACHIEVED rtol max(1, |w / v|) / h
    (2.5e-7 at rtol 1e-12 for a growth of 1.2). A slope within it of another is no kink, one
    within it of 0 is 0 (check round 29: rounding printed as a kink where the exact value is
    0, 2.3e-12 lowering the growth and -8.7e-12 raising it)."""
    h = step_of(tube, key, key_value(tube, key), step)
    return 6.0 * ACHIEVED * rtol * max(1.0, abs(w / v)) / h


class _NoDeterminant(Exception):
    """The kernel failed at a tube: D is not available there (only its fallback's f)."""


@dataclasses.dataclass
class Determinant:
    """D = det(M2) of one mode as a function of the tube, in units of its size at the first
    tube asked (one scale for every partial: their ratio is what is wanted; that keeps it
    representable); ``plain``: the kernel's f instead."""

    targets: ImpedanceTarget
    modes: np.ndarray
    ref: float | None = None

    def __call__(self, tube) -> float:
        f, log_norm = (float(v[0]) for v in self.targets.parts(solve_base_state(tube), self.modes))
        if not math.isfinite(log_norm):
            raise _NoDeterminant
        if self.ref is None:
            self.ref = log_norm
        return scaled(f, log_norm - self.ref)

    def plain(self, tube) -> float:
        return float(self.targets(solve_base_state(tube), self.modes)[0])


def sensitivity_json(outcome) -> dict:
    """The five sensitivities of a prescription's best design (``sensitivity``,
    ``next_sensitivity``, ``margin_sensitivity``, ``crease_sensitivity``,
    ``surface_sensitivity``: d/dp by parameter key) as JSON, a derivative that could not be
    formed as null, ``margin_sides``: at a kink of M, dM/dp lowering ("down") and
    raising ("up") each such p, and ``margin_error``: the least error of dM/dp by p."""
    fields = {"value": "sensitivity", "next_value": "next_sensitivity",
              "margin": "margin_sensitivity", "crease_value": "crease_sensitivity",
              "surface_value": "surface_sensitivity"}  # fmt: skip
    out: dict[str, dict] = {
        name: {p: json_number(d) for p, d in getattr(outcome, attr, {}).items()}
        for name, attr in fields.items()
    }
    # at a kink of M (a tie of competitors) "margin" is null and these are its two sides
    sides = getattr(outcome, "margin_sides", {})
    out["margin_sides"] = {
        p: {"down": json_number(a), "up": json_number(b)} for p, (a, b) in sides.items()
    }
    # the least error of each margin slope (:func:`margin_error`)
    out["margin_error"] = {
        p: json_number(e) for p, e in getattr(outcome, "margin_error", {}).items()
    }
    return out
