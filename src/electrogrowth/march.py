"""March a control parameter from a stable state to the first bifurcation of a set of modes.

Shared by the single-mode solver (bifurcation.critical_value) and the mode scan
(scan.scan_modes). Which sign of the target is stable is read off the unloaded tube
(g = 1, lambda_z = 1, Vbar = 0), stress free and stable in every mode: along any path the
target keeps that sign until the mode's first bifurcation.

The control parameter x moves from its start in steps that grow geometrically (0.4 % of
the scale, doubling up to 5 %) but never beyond 0.7 of the distance at which the linear
extrapolation of any mode's target reaches zero (a mode can be unstable only in a narrow
window, which a long step would jump over), and shrink when the inner stretch lambda_i
changes by more than 5 % in one step: near the voltage threshold
lambda_i runs away and modes can lose and regain stability within a tiny interval. When
the base state is lost between two steps the threshold is located exactly and approached
with shrinking steps. Modes that change sign in a step are narrowed by a shared bisection
and finished with Brent's method; a mode whose target dips towards zero between steps
without crossing is examined by a bounded minimisation.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Callable

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from .errors import BaseStateError, ConvergenceError, NoBifurcationFound, ParameterError
from .params import TubeParameters
from .tube import solve_base_state, voltage_threshold

FIRST_STEP, MIN_STEP, MAX_STEP, MAX_LAMBDA_JUMP = 0.004, 1e-4, 0.05, 0.05
LAMBDA_CAP = 200.0  # stop approaching a threshold once lambda_i has grown this much

#: targets(state, modes (k, 2) array) -> (k,) array of target values
Targets = Callable[[object, np.ndarray], np.ndarray]


@dataclasses.dataclass(frozen=True)
class ModeValue:
    """Critical value of one mode."""

    m: int
    n: int
    value: float


@dataclasses.dataclass
class MarchResult:
    found: list  # ModeValue, in the order reached
    threshold: float | None  # where the axisymmetric state is lost, if reached first


def control_path(params: TubeParameters, solve_for: str, side: str | None):
    """(start, end, scale) of the march for ``solve_for``."""
    if solve_for == "growth":
        return 1.0, 6.0, 1.0
    if solve_for == "stretch":
        g = params.growth  # lambda_z = g: no elastic axial strain
        return (g, 8.0 * g, g) if side == "extension" else (g, 0.05 * g, g)
    if solve_for == "voltage":
        thr = voltage_threshold(params)[0]
        if not math.isfinite(thr):  # stiffening energies may have no threshold at all
            return 0.0, 1e3, 1.0
        return 0.0, thr * (1 - 1e-12), thr
    raise ParameterError(
        f"solve_for = {solve_for!r} is unknown; choose growth, stretch or voltage")


def first_bifurcations(params: TubeParameters, solve_for: str, side: str | None,
                       modes: np.ndarray, targets: Targets, *, top: int = 1,
                       brent_targets: Targets | None = None) -> MarchResult:
    """Critical values of the first ``top`` modes of ``modes`` reached by the march.

    ``targets`` is used for signs along the march (it may be loose); ``brent_targets``
    (default ``targets``) for the final roots.
    """
    at = lambda x: dataclasses.replace(params, **{solve_for: float(x)})  # noqa: E731
    ref = dataclasses.replace(params, growth=1.0, stretch=1.0, voltage=0.0)
    sref = np.sign(targets(solve_base_state(ref), modes))
    x0, end, scale = control_path(params, solve_for, side)
    sense = 1.0 if end > x0 else -1.0
    alive = np.arange(len(modes))
    state = solve_base_state(at(x0))
    g0 = sref * targets(state, modes)
    if (g0 <= 0).any():
        m, n = modes[int(np.argmax(g0 <= 0))].astype(int)
        raise ParameterError(f"the tube is already unstable in mode ({m}, {n}) at "
                             f"{solve_for} = {x0:g}; start from a stable state")
    signed = lambda x, idx: sref[idx] * targets(solve_base_state(at(x)), modes[idx])  # noqa
    fine = brent_targets or targets
    signed_fine = lambda x, i: float(sref[i] * fine(solve_base_state(at(x)), modes[[i]])[0])
    found, threshold = [], None
    x_prev, lam_prev, lam0, d = x0, state.lambda_i, state.lambda_i, FIRST_STEP
    x_before, g_before, g_prev = None, None, g0
    while (end - x_prev) * sense > 0 and len(found) < top and alive.size:
        x = x_prev + sense * d * scale
        if (x - end) * sense > 0:
            x = end
        try:
            state = solve_base_state(at(x))
        except BaseStateError:
            threshold = _threshold_between(at, params, x_prev, x)
            end = threshold - sense * 1e-12 * scale
            d /= 4
            continue
        if abs(state.lambda_i / lam_prev - 1) > MAX_LAMBDA_JUMP and d > 1e-12:
            d /= 2
            continue
        if threshold is not None and state.lambda_i > LAMBDA_CAP * lam0:
            break
        g = sref[alive] * targets(state, modes[alive])
        hit = g <= 0
        if hit.any():
            found += _refine(signed, signed_fine, modes, alive[hit], x_prev, x)
        if g_before is not None:
            for j in _dips(g_before, g_prev, g, hit):
                i = int(alive[j])
                bracket = _dip(lambda y: signed_fine(y, i), x_before, x)
                if bracket is not None:
                    found.append(ModeValue(int(modes[i, 0]), int(modes[i, 1]),
                                           brent(lambda y: signed_fine(y, i), *bracket)))
                    hit[j] = True
        keep = ~hit
        d = _next_step(d, g_prev[keep], g[keep], abs(x - x_prev) / scale)
        alive, g_before, g_prev = alive[keep], g_prev[keep], g[keep]
        x_before, x_prev, lam_prev = x_prev, x, state.lambda_i
    found.sort(key=lambda mv: sense * mv.value)
    if not found and threshold is None:
        if solve_for == "voltage" and math.isfinite(voltage_threshold(params)[0]):
            threshold = voltage_threshold(params)[0]
        else:
            raise NoBifurcationFound(f"no mode bifurcates for {solve_for} between {x0:g} "
                                     f"and {end:g}")
    return MarchResult(found, threshold)


def _next_step(d, g_prev, g, taken):
    """Double the step, but stay within 0.7 of the extrapolated distance to any root."""
    falling = g < g_prev
    if falling.any():
        to_root = g[falling] * taken / (g_prev[falling] - g[falling])
        return float(np.clip(0.7 * to_root.min(), MIN_STEP, min(2 * d, MAX_STEP)))
    return min(2 * d, MAX_STEP)


def _dips(a, b, g, hit):
    """Indices whose signed target had a deep local minimum at the previous step."""
    cand = np.nonzero((b < 0.25 * np.minimum(a, g)) & ~hit)[0]
    return cand[np.argsort(b[cand])][:8]


def _dip(f, a, b):
    """Does f (positive at a and b) dip below zero between? Bracket from the a side."""
    lo, hi = min(a, b), max(a, b)
    res = minimize_scalar(f, bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-12 * max(1.0, abs(lo))})
    if res.fun <= 0:
        return (a, res.x)  # a is where the march came from: the first root lies here
    return None


def _refine(signed, signed_fine, modes, cand, a, b) -> list:
    """Shared bisection of the step (a, b] over the candidates, then Brent for each."""
    for _ in range(6):
        c = 0.5 * (a + b)
        g = signed(c, cand)
        if (g <= 0).any():
            cand, b = cand[g <= 0], c
        else:
            a = c
    out = []
    for i in cand:
        f = lambda x: signed_fine(x, i)  # noqa: E731
        lo, hi = (a, b) if a < b else (b, a)
        flo, fhi = f(lo), f(hi)
        if flo * fhi > 0:  # the loose march misjudged a sign this close to the root
            lo, hi = _widen(f, lo, hi, flo)
        out.append(ModeValue(int(modes[i, 0]), int(modes[i, 1]), brent(f, lo, hi)))
    return out


def _widen(f, lo, hi, flo):
    w = hi - lo
    for _ in range(20):
        lo2, hi2 = lo - w, hi + w
        if f(lo2) * flo < 0:
            return lo2, lo
        if f(hi2) * flo < 0:
            return hi, hi2
        w *= 2
    raise ConvergenceError(f"lost the sign change near [{lo}, {hi}]")


def brent(f, a, b) -> float:
    """Brent's method to full double precision, with a one-line error."""
    try:
        return brentq(f, a, b, xtol=1e-15 * max(1.0, abs(a)), rtol=1e-15, maxiter=200)
    except (RuntimeError, ValueError) as exc:
        raise ConvergenceError(f"Brent's method failed on [{a}, {b}]: {exc}") from None


def _threshold_between(at, params, x_ok, x_bad) -> float:
    """Parameter value where the voltage threshold falls to the applied voltage."""
    lo, hi = min(x_ok, x_bad), max(x_ok, x_bad)
    return brentq(lambda x: voltage_threshold(at(x))[0] - params.voltage, lo, hi,
                  xtol=1e-14, rtol=1e-15)
