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
from collections.abc import Callable

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..basestate.tube import free_stretch, solve_base_state, threshold
from ..errors import BaseStateError, ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.targets import natural_family, row_family
from ..model.layers import Tube

FIRST_STEP, MIN_STEP, MAX_STEP, MAX_LAMBDA_JUMP = 0.004, 1e-4, 0.05, 0.05
MAX_WAIT = 0.25
LAMBDA_CAP = 50.0  # stop approaching a threshold once lambda_i has grown this much

#: targets(state, modes (k, 2) or (k, 3) array) -> (k,) array of target values
Targets = Callable[[object, np.ndarray], np.ndarray]


@dataclasses.dataclass(frozen=True)
class ModeValue:
    """Critical value of one mode (m, n) of ``family`` (incremental.targets.Family; the
    natural family of (m, n) when not given: prismatic for n = 0, else wrinkle)."""

    m: int
    n: int
    value: float
    family: str | None = None

    def __post_init__(self):
        fam = natural_family(self.m, self.n) if self.family is None else self.family
        object.__setattr__(self, "family", str(fam))


def _mode_value(modes, i, value) -> ModeValue:
    """The ModeValue of row i of ``modes`` (m, n[, family code])."""
    return ModeValue(int(modes[i, 0]), int(modes[i, 1]), value, str(row_family(modes[i])))


@dataclasses.dataclass
class MarchResult:
    found: list  # ModeValue, in the order reached
    threshold: float | None  # where the axisymmetric state is lost, if reached first


def control_path(tube: Tube, solve_for: str, side: str | None):
    """(start, end, scale) of the march for ``solve_for``: growth from 1 (ungrown); the
    stretch from the free length of the tube at its growth (no loads; g for a uniform tube)
    down (compression) or up; Vbar from 0 and the inner pressure from P_o (no pressure
    difference) up to their thresholds (or the pressure down, compression: a collapse under
    external pressure); the axial force from 0 down (compression) or up. The pressure and
    force scales are the unloaded tube's: sum mu_k ln(R_k / R_{k-1}) and
    pi sum mu_k (R_k^2 - R_{k-1}^2)."""
    kind = tube.check_control(solve_for).kind
    up = side == "extension"
    pairs = list(zip(tube.layers, tube.radii, tube.radii[1:]))
    if kind == "growth":
        return 1.0, 6.0, 1.0
    if kind == "stretch":
        lz = free_stretch(tube)
        return (lz, 8.0 * lz, lz) if up else (lz, 0.05 * lz, lz)
    if kind == "voltage":
        thr = threshold(tube, "voltage").value  # stiffening energies may have none (inf)
        return (0.0, 1e3, 1.0) if not math.isfinite(thr) else (0.0, thr * (1 - 1e-12), thr)
    if kind == "pressure":
        scale = sum(ply.shear_modulus * math.log(b / a) for ply, a, b in pairs)
        start = tube.outer_pressure
        if not up:
            return start, start - 20.0 * scale, scale
        thr = threshold(tube, "pressure").value
        end = thr * (1 - 1e-12) if math.isfinite(thr) else start + 50.0 * scale
        return start, end, scale
    scale = math.pi * sum(ply.shear_modulus * (b * b - a * a) for ply, a, b in pairs)
    return (0.0, 20.0 * scale, scale) if up else (0.0, -20.0 * scale, scale)


#: The tube on which the stable signs of a mode grid are read: they are the same on every
#: unloaded tube (docs/derivation.md section 3), so one evaluation serves every scan.
SIGN_TUBE = Tube.uniform(outer_radius=1.4, length=1.0)


def unloaded_signs(params, modes: np.ndarray, targets: Targets) -> np.ndarray:
    """Signs of the targets on the unloaded tube (``params.reference()``: g = 1,
    lambda_z = 1, no voltage or pressure)."""
    return np.sign(targets(solve_base_state(params.reference()), modes))


class _History:
    """Last three samples (x, signed target) of every mode, and when each is due again.

    A mode's target is extrapolated to its root, by the line through its last two samples
    and the parabola through its last three, whichever reaches zero first (near Vbar = 0
    targets fall like Vbar^2, which a line overestimates). The mode is re-evaluated once
    the march has covered half that distance, and at least every MAX_WAIT of the scale (a
    mode may lose and regain stability between two distant samples), so modes far from
    bifurcation cost a few evaluations, not one per step.
    """

    def __init__(self, x0, g0, sense, scale):
        n = g0.size
        self.sense, self.scale = sense, scale
        self.x = np.full((3, n), np.nan)  # rows: newest, previous, oldest
        self.g = np.full((3, n), np.nan)
        self.x[0], self.g[0] = x0, g0
        self.alive = np.ones(n, bool)
        self.due = np.full(n, x0)
        self.x0 = x0

    @property
    def xa(self):
        return self.x[0]

    def root_distance(self):
        """Extrapolated distance from the newest sample to the root (inf if receding)."""
        (xa, xb, xc), (ga, gb, gc) = self.x, self.g
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            slope = (ga - gb) / (xa - xb)
            line = np.where(slope * self.sense < 0, -ga / slope * self.sense, np.inf)
            curv = ((ga - gb) / (xa - xb) - (gb - gc) / (xb - xc)) / (xa - xc)
            # g(xa + sense t) = ga + s t + c t^2 with s = slope sense, c = curv
            s_, c_ = slope * self.sense, curv
            disc = s_ * s_ - 4 * c_ * ga
            t = (-s_ - np.sqrt(np.maximum(disc, 0))) / (2 * c_)
            t2 = (-s_ + np.sqrt(np.maximum(disc, 0))) / (2 * c_)
            t = np.where((t > 0) & (disc >= 0), t, np.where((t2 > 0) & (disc >= 0), t2, np.inf))
        return np.fmin(np.where(np.isnan(line), np.inf, line), np.where(np.isnan(t), np.inf, t))

    def needs(self, x):
        """Alive modes to evaluate at x: due, or predicted to have crossed by x."""
        reach = self.sense * (x - self.xa)
        return self.alive & ((self.sense * (x - self.due) >= 0) | (reach >= self.root_distance()))

    def record(self, idx, x, g):
        self.x[:, idx] = np.vstack([np.full(idx.size, x), self.x[0, idx], self.x[1, idx]])
        self.g[:, idx] = np.vstack([g, self.g[0, idx], self.g[1, idx]])
        wait = np.minimum(0.5 * self.root_distance()[idx], MAX_WAIT * self.scale)
        self.due[idx] = x + self.sense * wait

    def step_limit(self):
        """0.7 of the smallest extrapolated distance to a root, relative to the scale."""
        dist = self.root_distance()[self.alive]
        return 0.7 * dist.min() / self.scale if dist.size else np.inf


def first_bifurcations(
    params: Tube,
    solve_for: str,
    side: str | None,
    modes: np.ndarray,
    targets: Targets,
    *,
    top: int = 1,
    brent_targets: Targets | None = None,
    stable_signs: np.ndarray | None = None,
) -> MarchResult:
    """Critical values of the first ``top`` modes of ``modes`` reached by the march.

    ``targets`` is used for signs along the march (it may be loose); ``brent_targets``
    (default ``targets``) for the final roots. ``stable_signs``, the signs of the targets
    on the unloaded tube, are computed unless given (they depend only on the material,
    Rbar_o, L and the modes, so a curve or sweep can reuse them).
    """
    at = lambda x: params.at(solve_for, x)  # noqa: E731
    if stable_signs is None:
        stable_signs = unloaded_signs(params, modes, targets)
    sref = stable_signs
    x0, end, scale = control_path(params, solve_for, side)
    sense = 1.0 if end > x0 else -1.0
    state = solve_base_state(at(x0))
    g0 = sref * targets(state, modes)
    doubt = np.nonzero(g0 <= 0)[0]
    if doubt.size and brent_targets is not None:  # a loose sign may be wrong: ask again
        g0[doubt] = sref[doubt] * brent_targets(state, modes[doubt])
    if (g0 <= 0).any():
        i = int(np.argmax(g0 <= 0))
        m, n = modes[i, :2].astype(int)
        raise ParameterError(
            f"the tube is already unstable in mode ({m}, {n})"
            f" ({row_family(modes[i])}) at {solve_for} = {x0:g}; start from"
            " a stable state"
        )
    fine = brent_targets or targets
    signed = lambda x, idx: sref[idx] * targets(solve_base_state(at(x)), modes[idx])  # noqa

    def signed_fine(x, i):
        return float(sref[i] * fine(solve_base_state(at(x)), modes[[i]])[0])

    hist = _History(x0, g0, sense, scale)
    found, threshold = [], None
    x_prev, lam_prev, lam0, d = x0, state.lambda_i, state.lambda_i, FIRST_STEP
    while hist.alive.any():
        done = (end - x_prev) * sense <= 0 or len(found) >= top
        if not done:
            x = min(x_prev + sense * d * scale, end, key=lambda v: sense * v)
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
            done = state.lambda_i > LAMBDA_CAP * lam0  # the wall is a film: at the threshold
        if done:  # a last look at every mode not seen at x_prev: nothing left behind
            idx = np.nonzero(hist.alive & (hist.xa != x_prev))[0]
            if idx.size:
                found += _advance(
                    hist,
                    idx,
                    x_prev,
                    signed(x_prev, idx),
                    signed,
                    signed_fine,
                    modes,
                    top,
                )
            break
        idx = np.nonzero(hist.needs(x))[0]
        if idx.size:
            g = sref[idx] * targets(state, modes[idx])
            found += _advance(hist, idx, x, g, signed, signed_fine, modes, top)
        d = float(np.clip(hist.step_limit(), MIN_STEP, min(2 * d, MAX_STEP)))
        x_prev, lam_prev = x, state.lambda_i
    found.sort(key=lambda mv: sense * mv.value)
    if not found and threshold is None:
        thr = _voltage_threshold(params) if solve_for == "voltage" else math.inf
        if math.isfinite(thr):
            threshold = thr
        else:
            raise NoBifurcationFound(
                f"no mode bifurcates for {solve_for} between {x0:g} and {end:g}"
            )
    return MarchResult(found[:top], threshold)


def _advance(hist, idx, x, g, signed, signed_fine, modes, need=None) -> list:
    """Record the samples at x; roots of the modes that changed sign or dipped to zero
    (of those that changed sign, the first ``need``, see :func:`_refine`)."""
    found = []
    hit = g <= 0
    js = np.nonzero(hit)[0]
    if js.size:  # bisected together from where each mode was last seen
        roots = _refine(signed, signed_fine, modes, idx[js], hist.xa[idx[js]], x, hist.x0, need)
        for j, root in zip(js, roots):
            if root is None:  # the loose sign was wrong: the mode is not past a root yet
                hit[j] = False
            elif root is _LATER:  # crossed after the first ``need`` roots: not wanted
                pass
            else:
                found.append(root)
    mid, old = hist.g[0, idx], hist.g[1, idx]  # the two samples before x
    dips = np.nonzero(~hit & (mid < 0.25 * np.minimum(old, g)))[0]
    for j in dips[np.argsort(mid[dips])][:8]:
        i = idx[j]
        bracket = _dip(lambda y, i=i: signed_fine(y, i), hist.x[1, i], x)
        if bracket is not None:
            found.append(_mode_value(modes, i, brent(lambda y, i=i: signed_fine(y, i), *bracket)))
            hit[j] = True
    hist.alive[idx[hit]] = False
    hist.record(idx[~hit], x, g[~hit])
    return found


def _dip(f, a, b):
    """Does f (positive at a and b) dip below zero between? Bracket from the a side."""
    lo, hi = min(a, b), max(a, b)
    res = minimize_scalar(
        f, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12 * max(1.0, abs(lo))}
    )
    if res.fun <= 0:
        return (a, res.x)  # a is where the march came from: the first root lies here
    return None


_LATER = object()  # a candidate of _refine whose root comes after the ``need`` wanted


def _refine(signed, signed_fine, modes, cand, xa, x, x0, need=None) -> list:
    """Roots of the candidates, which changed sign between xa (each its own) and x (loose
    targets).

    Shared bisection points narrow every candidate's own bracket, then Brent's method
    with the fine targets finishes each. A candidate whose fine target is still positive
    at x was misjudged by the loose one: None (it stays in the march). With ``need``, the
    candidates past a root at the first x where at least ``need`` of them are (a shared
    bisection of the loose signs) are finished, the rest are _LATER: near a short-wave
    limit hundreds of modes cross within a step, and only the first few are reported.
    """
    sense = 1.0 if x > xa[0] else -1.0
    lo, hi = np.array(xa, float), np.full(cand.size, x, float)
    a, b = lo[np.argmin(sense * lo)], x
    for _ in range(6):  # bisect towards the earliest root; sample the others on the way
        c = 0.5 * (a + b)
        inside = (c - lo) * (c - hi) < 0
        g = signed(c, cand[inside])
        neg = np.zeros(cand.size, bool)
        neg[inside] = g <= 0
        hi[neg], lo[inside & ~neg] = c, c
        a, b = (a, c) if neg.any() else (c, b)
    out = [None] * cand.size

    def finish(k):
        i, l, h = cand[k], lo[k], hi[k]
        f = lambda y: signed_fine(y, i)  # noqa: E731
        if f(h) > 0:  # fine and loose disagree at h: fall back to the whole step
            if f(x) > 0:
                return
            h = x
        if f(l) <= 0:
            l = xa[k] if f(xa[k]) > 0 else x0  # the mode is stable at the start of the march
        out[k] = _mode_value(modes, i, brent(f, *sorted((l, h))))

    keep = np.arange(cand.size)
    if need is not None and cand.size > need + 2:
        # a pack: the first x (shared loose bisection) where at least ``need`` candidates
        # are past a root; only those can hold the first ``need`` roots
        a, b = lo[np.argmin(sense * lo)], x
        for _ in range(60):
            c = 0.5 * (a + b)
            inside = keep[signed(c, cand[keep]) <= 0]
            if inside.size >= need:
                keep, b = inside, c
            else:
                a = c
            if keep.size <= need + 2 or abs(b - a) <= 1e-13 * max(1.0, abs(b)):
                break
        for k in set(range(cand.size)) - set(keep.tolist()):
            out[k] = _LATER
    for k in keep:
        finish(k)
    return out


def brent(f, a, b) -> float:
    """Brent's method to full double precision, with a one-line error."""
    try:
        return brentq(f, a, b, xtol=1e-15 * max(1.0, abs(a)), rtol=1e-15, maxiter=200)
    except (RuntimeError, ValueError) as exc:
        raise ConvergenceError(f"the bracketed root solve failed on [{a}, {b}]: {exc}") from None


def _voltage_threshold(tube) -> float:
    return threshold(tube, "voltage").value


def _threshold_between(at, params, x_ok, x_bad) -> float:
    """Parameter value where the base state is lost between x_ok and x_bad: where the
    voltage threshold falls to the applied voltage if that brackets it, else the edge of the
    states that solve (whichever of the tube's loads reaches its threshold), bisected."""
    if params.voltage > 0:
        try:
            return brentq(
                lambda x: _voltage_threshold(at(x)) - params.voltage,
                min(x_ok, x_bad),
                max(x_ok, x_bad),
                xtol=1e-14,
                rtol=1e-15,
            )
        except ValueError:  # the voltage's threshold does not bracket it: another load
            pass
    ok, bad = x_ok, x_bad
    while abs(bad - ok) > 1e-13 * max(1.0, abs(ok)):
        mid = 0.5 * (ok + bad)
        try:
            solve_base_state(at(mid))
            ok = mid
        except BaseStateError:
            bad = mid
    return ok
