"""The base state of any tube: one door, :func:`solve_base_state`, and one :func:`threshold`.

A uniform tube (``Tube.is_uniform``: the paper's tube) takes the closed form and quadratures
of ``uniform.py``, at ~20 us for the neo-Hookean dielectric; any other tube the layered solver
of ``layered.py``. Both return a state of the one protocol ``electrogrowth._types.State``, so
nothing above this package asks which kind of tube it holds. Derivations:
docs/derivation-base-state.md, docs/derivation-layered.md.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._types import State
from ..errors import BaseStateError, ParameterError
from ..model.layers import Tube
from . import force_box
from .neo_hookean import nh_asymptote, nh_voltage
from .thresholds import Threshold
from .uniform import solve_uniform
from .voltage import UniformWall, threshold_info

# The layered solver (layered.py) is imported where a layered tube is met: the paper's tube
# (closed forms, uniform.py) does not load it.

__all__ = [
    "free_stretch",
    "neo_hookean_asymptote",
    "solve_base_state",
    "threshold",
    "voltage_curve",
    "voltage_threshold",
]


def voltage_threshold(params: Tube) -> tuple[float, str, float]:
    """Largest Vbar on the branch of Vbar(lambda_i) continuous from Vbar = 0.

    Returns
    -------
    (Vbar_threshold, kind, lambda_i) : tuple[float, str, float]
        kind "asymptote": Vbar -> Vbar_threshold as lambda_i -> inf (lambda_i = inf);
        "limit point": first local maximum of Vbar(lambda_i), a snap-through; "locking":
        Vbar rises without bound (Vbar_threshold = inf) up to where the branch ends, lambda_i:
        the locking stretch of the energy (e.g. Gent), where no charge balances the traction,
        or where the stresses exceed the largest double (an exponential energy); "none": Vbar
        rises without bound as lambda_i -> inf (lambda_i = inf); "closing": no charge
        balances the traction on either side of lambda_i0 (a branch that runs inward, Vbar
        rising as lambda_i falls, is classified as any other): 0, lambda_i = lambda_i0;
        "unresolved": which side a charge balances it on is not resolved, the traction
        flat to rounding at lambda_i0 (next to an inflation asymptote): 0, as closing.
        The kinds of a layered tube's :class:`~electrogrowth.basestate.thresholds.Threshold`.
        ``params.voltage`` is ignored.

    >>> round(voltage_threshold(Tube.uniform(outer_radius=2.0, growth=1.1))[0], 6)
    1.233797
    """
    t = threshold(params)
    return t.value, t.kind, t.lambda_i


def solve_base_state(
    tube: Tube, *, rtol: float = 1e-12, near: State | None = None, guess=None
) -> State:
    """Solve the axisymmetric base state of ``tube`` at its loads (paper Sec. 3.1).

    Parameters
    ----------
    tube : Tube
        The tube and its loads (``Tube.uniform(...)`` for the paper's tube).
    rtol : float, keyword-only
        Relative accuracy of quadratures and root finding (default 1e-12); the neo-Hookean
        closed form is always at rounding level.
    near : State or None, keyword-only
        The solved state of a neighbouring tube (a march's last step): a layered state is
        then continued from it by Newton's method, the same root as the walk from the
        unloaded tube (basestate/warm.py), which is the fallback. Ignored for a uniform tube.
    guess : (float, float) or None, keyword-only
        With ``near``: Newton's start (r_i, lambda_z) instead of near's own (e.g. extrapolated
        from two neighbours).

    Returns
    -------
    State
        A :class:`~electrogrowth.basestate.uniform_state.UniformState` for a uniform tube, else a
        :class:`~electrogrowth.basestate.layered_state.LayeredState`: the same protocol.

    Raises
    ------
    BaseStateError
        If a load lies at or beyond the threshold of its branch.

    >>> state = solve_base_state(Tube.uniform(outer_radius=2.0, voltage=0.5))
    >>> round(state.lambda_i, 6), state.threshold_kind
    (1.151387, 'asymptote')
    """
    if tube.is_uniform:
        return solve_uniform(tube, rtol)
    from .layered import solve_layered_state
    from .layered_state import LayeredState

    warm = near if isinstance(near, LayeredState) else None
    return solve_layered_state(tube, rtol=rtol, near=warm, guess=guess if warm else None)


def threshold(tube: Tube, control: str = "voltage", *, rtol: float = 1e-12) -> Threshold:
    """Where the axisymmetric branch of ``control`` ("voltage": Vbar at the tube's pressures;
    "pressure": the inner pressure P_i) is lost, followed from its start (see
    :class:`~electrogrowth.basestate.thresholds.Threshold`).

    >>> t = threshold(Tube.uniform(outer_radius=2.0, growth=1.1))
    >>> round(t.value, 6), t.kind
    (1.233797, 'asymptote')
    """
    if control == "voltage" and tube.is_uniform:
        info = threshold_info(tube, rtol)
        return Threshold(
            "voltage",
            float(info.value),
            info.kind,
            float(info.lambda_i),
            tube.value_of("stretch"),
            info.error,
        )
    from .layered import layered_threshold

    return layered_threshold(tube, control, rtol=rtol)


def load_in_box(tube: Tube, control: str, *, rtol: float = 1e-12) -> float | None:
    """Where the ``control``'s loading branch of a force-controlled tube leaves the supported
    box of the elastic axial stretch before its threshold (:func:`.force_box.load_in_box`):
    the value the control's march ends at; None where it does not (or lambda_z is given)."""
    if tube.control != "force":
        return None
    return force_box.load_in_box(tube, threshold(tube, control, rtol=rtol))


def free_stretch(tube: Tube, *, rtol: float = 1e-12) -> float:
    """lambda_z of the tube at its growth without any load (free ends, no voltage or
    pressure): exactly g for a uniform tube (isotropic growth changes no shape), else solved
    at zero axial force."""
    if tube.is_uniform:
        return tube.growth
    free = dataclasses.replace(
        tube,
        stretch=None,
        axial_force=0.0,
        voltage=0.0,
        inner_pressure=0.0,
        outer_pressure=0.0,
        closed_ends=False,
    )
    from .layered import solve_layered_state

    return solve_layered_state(free, rtol=rtol).stretch


# -- the paper's tube only: its voltage curve ------------------------------------------------


def neo_hookean_asymptote(params: Tube) -> float:
    """Neo-Hookean lim_{lambda_i -> inf} Vbar (material ignored), derived in the docs:

    Vbar_inf = g^2 / (lambda_z (Rbar_o - 1)) sqrt((Rbar_o^2 - 1) ln(Rbar_o) / 2).

    >>> round(neo_hookean_asymptote(Tube.uniform(outer_radius=2.0)), 6)
    1.019667
    """
    return nh_asymptote(params.outer_radius, params.growth, params.value_of("stretch"))


def voltage_curve(params: Tube, lambda_i) -> np.ndarray:
    """Vbar(lambda_i) of the traction-free tube (paper eq. dimensionless-voltage), vectorised.

    ``params.voltage`` is ignored. Raises BaseStateError for lambda_i below the mechanical
    lambda_i0 (no real voltage) or where the energy is undefined (beyond a locking stretch).
    """
    lam = np.asarray(lambda_i, float)
    if not np.all(np.isfinite(lam) & (lam > 0)):
        raise ParameterError(
            f"lambda_i = {lam[~(np.isfinite(lam) & (lam > 0))].flat[0]!r}"
            " is invalid; need 0 < lambda_i < inf"
        )
    info = threshold_info(params)
    low = lam < info.lambda_i0 * (1.0 - 1e-12)
    if low.any():
        raise BaseStateError(
            f"lambda_i = {lam[low].flat[0]:.12g} is below the Vbar = 0 value"
            f" {info.lambda_i0:.12g}; no real voltage there"
        )
    Ro, g, lz = params.outer_radius, params.growth, params.value_of("stretch")
    if info.nodes == 0:  # neo-Hookean closed form (NH-6)
        return np.maximum(nh_voltage(Ro, g, lz, lam), 0.0)
    tube = UniformWall(params.material, Ro, g, lz, info.nodes)
    v = tube.voltage(lam.ravel())
    if not np.all(np.isfinite(v)):
        raise BaseStateError(
            f"energy of {params.material.name} undefined at lambda_i ="
            f" {lam.ravel()[~np.isfinite(v)][0]:.12g} (beyond locking, or its stresses"
            " past the largest double)"
        )
    return np.maximum(v, 0.0).reshape(lam.shape)
