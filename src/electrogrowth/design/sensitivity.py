"""Sensitivity of one mode's critical value to every parameter of the tube.

At the critical value v of mode (m, n) the pole-free target of the incremental problem
vanishes, f(v, p) = 0 (incremental/targets.py: the function critical_value root-solves),
with p any other parameter of the tube. Where f_v = df/dv != 0 the implicit function theorem
gives a smooth v(p) with f(v(p), p) = 0, and differentiating that identity,

    f_v dv/dp + f_p = 0,   so   dv/dp = -f_p / f_v.

Both partials are central differences of f (target evaluations only, no root solve) at
an absolute step h = 1e-4 max(1, |p|) and h / 2, combined by Richardson extrapolation,
(4 D(h/2) - D(h)) / 3, which cancels the O(h^2) error of the central difference D: the
targets of thick layered tubes at high m are strongly curved in p, where D(h) alone is off
by ~1e-4 at h = 1e-4. Where p cannot be moved both ways (a bound of its range) a one-sided
second-order difference is used.
docs/design.md derives it and tests/design/test_sequence.py compares it with
finite differences of full critical_value solves.
"""

from __future__ import annotations

import math

from ..basestate.tube import solve_base_state
from ..bifurcation.critical import control_name
from ..errors import ConvergenceError, ParameterError
from ..incremental.accuracy import Accuracy
from ..incremental.targets import check_mode, targets_for, with_family
from ..model.layers import Tube

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
    """df/dx by a central difference, or a one-sided second-order one where x - h or x + h
    is out of the parameter's range."""
    try:  # Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central D(h)
        near, far = f(x + h / 2) - f(x - h / 2), f(x + h) - f(x - h)
        return (8 * near - far) / (6 * h)
    except ParameterError:
        pass
    for s in (1.0, -1.0):
        try:
            return s * (-3 * f(x) + 4 * f(x + s * h) - f(x + 2 * s * h)) / (2 * h)
        except ParameterError:
            continue
    raise ParameterError(f"cannot vary the parameter at {x:g} by {h:g} either way")


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
        key -> dv/dp = -f_p / f_v (module docstring).

    Raises
    ------
    ConvergenceError
        If f_v vanishes (a fold of the mode's branch: v(p) is not differentiable there).
    """
    solve_for = control_name(tube, solve_for)
    fam = check_mode(*mode, family)
    modes = with_family(*mode, fam)
    targets = targets_for("impedance", Accuracy(rtol).fine)

    def f(t, v: float) -> float:
        return float(targets(solve_base_state(t.at(solve_for, v)), modes)[0])

    f_v = _derivative(lambda v: f(tube, v), value, step * max(1.0, abs(value)))
    if not math.isfinite(f_v) or f_v == 0.0:
        raise ConvergenceError(
            f"df/d{solve_for} vanishes at {solve_for} = {value:g} for mode {tuple(mode)}: a"
            " fold of the branch, where the critical value is not differentiable"
        )
    out = {}
    for key in parameter_keys(tube, solve_for) if keys is None else keys:
        p = key_value(tube, key)
        f_p = _derivative(lambda q, key=key: f(tube.at(key, q), value), p, step * max(1.0, abs(p)))
        out[key] = -f_p / f_v
    return out


def sensitivity_json(outcome) -> dict:
    """The four sensitivities of a prescription's best design (``sensitivity``,
    ``next_sensitivity``, ``margin_sensitivity``, ``crease_sensitivity``: d/dp by parameter
    key) as JSON, a derivative that could not be formed as null."""

    def num(v):
        return v if v is not None and math.isfinite(v) else None

    fields = {"value": "sensitivity", "next_value": "next_sensitivity",
              "margin": "margin_sensitivity", "crease_value": "crease_sensitivity"}  # fmt: skip
    return {
        name: {p: num(d) for p, d in getattr(outcome, attr).items()}
        for name, attr in fields.items()
    }
