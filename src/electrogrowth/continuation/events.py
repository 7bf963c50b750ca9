"""What a path meets, and where: sign changes, dips, turning loads, and the root finders
that locate them (one Brent, one bisection, widening windows, the edge of a path).

Every march signs its event functions so that the start of the path is positive (a
mode's target times its sign on the unloaded tube, the half-space minimum): an event
happens where a function reaches zero. Between two samples a function can also dip below
zero and come back (a window of instability): a sample lower than DIP_RATIO of both its
neighbours, or low enough that a neighbour's secant through it reaches zero within the
other step (:func:`dipped`), is examined by a bounded minimisation. The tolerances are
named here, each with its caller, so a march's accuracy is read off one table.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Iterator

import numpy as np

from ..brent import brentq
from ..errors import ConvergenceError

#: a sample lower than this fraction of both neighbours may hide a dip below zero
DIP_RATIO = 0.25
#: the bounded minimisation of a dip stops at DIP_XATOL max(1, |lower end|)
DIP_XATOL = 1e-12


# -- events ---------------------------------------------------------------------------------


def crossed(g):
    """Signed event values (positive at the start of the path) at or past zero."""
    return g <= 0


def dipped(old, mid, new, steps=None):
    """May a window of instability be hiding next to ``mid``, sampled between ``old`` and
    ``new``? Where ``mid`` fell below DIP_RATIO of both; and, given ``steps`` (the
    distances old - mid and mid - new), where it is the lowest of the three and the secant
    from either neighbour through it, continued across it, reaches zero within the other
    step: there the target can reach zero at a slope no steeper than the one sampled.
    The ratio alone misses an uneven pair of steps: a 5 % step that lands just past a
    narrow window, then a short one (the 4e-3 wide window of a bilayer's (1, 2), check
    round 16: samples 2.3e-4, 1.5e-5 past the window, 4.0e-5 a short step on, 0.37 > 1/4)."""
    low = mid < DIP_RATIO * np.minimum(old, new)
    if steps is None:
        return low
    before, after = (np.abs(h) for h in steps)
    lowest = (mid < old) & (mid < new)
    # the zero of the secant from new through mid lies within the step before mid when
    # mid / slope < before, slope = (new - mid) / after; likewise from old
    return low | (
        lowest & ((mid * after < (new - mid) * before) | (mid * before < (old - mid) * after))
    )


def reached(value, target, sense) -> bool:
    """Has ``value``, moving in ``sense``, reached ``target``?"""
    return sense * (value - target) >= 0


def turned(previous, value, sense) -> bool:
    """Has a load that rose in ``sense`` turned back (a limit point, a fold of the path)?"""
    return sense * (value - previous) < 0


def dip_bracket(f, a: float, b: float) -> tuple[float, float] | None:
    """Does f (positive at a and b) dip to zero or below between them? (a, where it does)
    from a bounded minimisation, or None: the first root lies between them."""
    from scipy.optimize import minimize_scalar  # 0.5 s of imports: only for a dip

    lo, hi = min(a, b), max(a, b)
    res = minimize_scalar(
        f, bounds=(lo, hi), method="bounded", options={"xatol": DIP_XATOL * max(1.0, abs(lo))}
    )
    if res.fun <= 0:
        return (a, res.x)  # a is where the march came from: the first root lies here
    return None


# -- Brent's method, with named tolerances --------------------------------------------------


@dataclasses.dataclass(frozen=True)
class Tolerance:
    """When a root finder stops. Brent's method: |x - root| <= xtol + rtol |x|; a
    bisection: |bad - good| <= xtol. xtol is ``xtol`` times max(1, |ref|) (``scale``
    "unit"), times |ref| ("relative") or as it is ("absolute"), ref being the end the
    caller names (Brent: the bracket's first end by default). ``maxiter`` iterations at
    most."""

    xtol: float
    rtol: float = 0.0
    maxiter: int = 100
    scale: str = "unit"

    def at(self, ref: float) -> float:
        """The absolute tolerance near ``ref``."""
        if self.scale == "unit":
            return self.xtol * max(1.0, abs(ref))
        if self.scale == "relative":
            return self.xtol * abs(ref)
        return self.xtol


_EPS = float(np.finfo(float).eps)

#: a root to full double precision (critical values of modes, their error estimates)
FULL = Tolerance(1e-15, 1e-15, 200)
#: a switch between two modes of a curve
SWITCH = Tolerance(1e-13, 1e-14, 100)
#: where the voltage threshold falls to the applied voltage
THRESHOLD = Tolerance(1e-14, 1e-15, 100, "absolute")
#: the coarser root of an error estimate of the short-wave limit
SECOND = Tolerance(1e-15, 1e-15, 100)
#: a point of a base-state branch (lambda_z, r_i: positive), to the last bits
BRANCH = Tolerance(1e-16, 4 * _EPS, 300, "relative")
#: lambda_z balancing the axial force on a branch (r_i, on a branch walked in lambda_z)
BRANCH_STRETCH = Tolerance(1e-16, 4 * _EPS, 200, "relative")


def surface_tolerance(rtol: float) -> Tolerance:
    """The short-wave limit to ~1e-3 of its accuracy rtol (not below FULL's)."""
    return Tolerance(max(1e-15, 1e-3 * rtol), 1e-15, 300)


#: det(M2) = f exp(log_norm) is refined in units of a reference size exp(ref); the exponent
#: log_norm - ref is held within +-MAX_EXPONENT (float64 overflows at 709)
MAX_EXPONENT = 600.0


def scaled(f: float, exponent: float) -> float:
    """f exp(exponent), the exponent held within +-MAX_EXPONENT (representable)."""
    return f * math.exp(min(max(exponent, -MAX_EXPONENT), MAX_EXPONENT))


def brent(f, a: float, b: float, tol: Tolerance = FULL, *, ref=None, named: bool = True):
    """The root of f in [a, b] by Brent's method to ``tol`` (near ``ref``, default a).

    A failure (no sign change, no convergence, or a RuntimeError/ValueError from f itself)
    is a ConvergenceError naming the bracket; with ``named=False`` SciPy's and f's errors
    pass as they are (the callers that always have a bracket)."""
    xtol = tol.at(a if ref is None else ref)
    if not named:
        return brentq(f, a, b, xtol=xtol, rtol=tol.rtol, maxiter=tol.maxiter)
    try:
        return brentq(f, a, b, xtol=xtol, rtol=tol.rtol, maxiter=tol.maxiter)
    except (RuntimeError, ValueError) as exc:
        raise ConvergenceError(f"the bracketed root solve failed on [{a}, {b}]: {exc}") from None


class Remembered:
    """f, remembering its values at the points already asked: a root finder handed a
    bracket whose ends were just evaluated (to check it) does not pay them again. The values
    are f's own, so the root is the same to the last bit."""

    def __init__(self, f: Callable[[float], float]):
        self.f, self.seen = f, {}

    def __call__(self, x: float) -> float:
        x = float(x)
        if x not in self.seen:
            self.seen[x] = self.f(x)
        return self.seen[x]


# -- bisection ------------------------------------------------------------------------------

#: the edge of a path's states (where its base state is lost), and a pack of roots
EDGE = Tolerance(1e-13, maxiter=200)
#: the edge of an energy's domain (a locking stretch) on a base-state branch, near |bad|
LOCK = Tolerance(1e-14, maxiter=200, scale="relative")
#: where a mode of a curve stops bifurcating before the threshold
MODE_EDGE = Tolerance(1e-12, maxiter=200)


def bisect(
    holds: Callable[[float], bool],
    good: float,
    bad: float,
    tol: Tolerance = EDGE,
    *,
    near_bad: bool = False,
) -> tuple[float, float]:
    """Narrow [good, bad] (``holds`` true at good, false at bad) by halving until
    |bad - good| <= tol (near good, or near bad with ``near_bad``), at most tol.maxiter
    halvings; returns the final (good, bad)."""
    for _ in range(tol.maxiter):
        if abs(bad - good) <= tol.at(bad if near_bad else good):
            break
        mid = 0.5 * (good + bad)
        if holds(mid):
            good = mid
        else:
            bad = mid
    return good, bad


def widening_windows(
    x: float, width: float, rounds: int, *, bounds=(-math.inf, math.inf), factor: float = 4.0
) -> Iterator[tuple[float, float, float]]:
    """Windows [x - w, x + w] (clipped to ``bounds``) for w = width, factor width, ...:
    (lo, hi, w) ``rounds`` times, where a root near x is looked for."""
    lo_b, hi_b = bounds
    for _ in range(rounds):
        yield max(x - width, lo_b), min(x + width, hi_b), width
        width *= factor


def threshold_between(
    x_ok: float,
    x_bad: float,
    *,
    margin: Callable[[float], float] | None = None,
    exists: Callable[[float], bool] | None = None,
    tolerate: tuple[type[BaseException], ...] = (),
    last: str = "ok",
) -> float | None:
    """The control value between x_ok (a state exists) and x_bad where the path's state is
    lost.

    With ``margin`` (how far a state is from its threshold, e.g. the voltage threshold
    minus the applied voltage), its root by Brent (tolerance THRESHOLD); an error of one
    of the types ``tolerate`` (no sign change: ValueError) falls back on ``exists``,
    others pass. With ``exists``
    (does a state solve at x?), the edge of the states by bisection to EDGE: the last x
    with a state (``last`` "ok") or the first without ("bad"). None if neither applies.
    """
    lo, hi = min(x_ok, x_bad), max(x_ok, x_bad)
    if margin is not None:
        try:
            return brent(margin, lo, hi, THRESHOLD, named=False)
        except tolerate:
            pass
    if exists is None:
        return None
    ok, bad = bisect(exists, x_ok, x_bad, EDGE)
    return ok if last == "ok" else bad


# -- many events at once: the march's shared bisection --------------------------------------

#: halvings shared by the candidates of a step before each is finished alone
SHARED_ROUNDS = 6
#: halvings to find the first x where ``need`` candidates are past zero (a pack)
PACK_ROUNDS = 60

LATER = object()  # a candidate whose root comes after the ``need`` wanted


def first_roots(
    signed: Callable[[float, np.ndarray], np.ndarray],
    fine: Callable[[float, int], float],
    cand: np.ndarray,
    xa: np.ndarray,
    x: float,
    x0: float,
    need: int | None = None,
    values: tuple[np.ndarray, np.ndarray] | None = None,
    fine_many: Callable[[float, np.ndarray], np.ndarray] | None = None,
    loose_parts: Callable[[float, int], tuple[float, float]] | None = None,
) -> list:
    """Roots of the candidates ``cand``, which changed sign between xa (each its own last
    sample) and x by the loose ``signed(x, cand)``; ``fine(x, i)`` is the accurate signed
    value of candidate i. ``values``: the loose values at xa and at x, if known.
    ``fine_many(x, cand)``: the accurate signs of many candidates at once (a batch), if
    given, for the check of the LATER ones. ``loose_parts(x, i)``: candidate i's loose
    (signed f, log_norm), det(M2) = f exp(log_norm), if its loose root is to be refined on
    det(M2) rather than on ``signed``.

    A single candidate with its ``values`` is finished by :func:`_near_root`.

    Shared bisection points narrow every candidate's own bracket (SHARED_ROUNDS), then
    Brent's method on ``fine`` finishes each. A candidate whose fine value is still
    positive at x was misjudged by the loose one: None (it stays in the march). One whose
    fine value is not positive even at x0, the start the march found stable (by its loose
    sign, or its fine bounded target where that doubted), has its root at x0 within the
    fine value's rounding: x0 (a film at its fold at P_i = 0 has det(M2) = -4e-15 there on
    a slope of 0.24, and Brent's method had no sign change to work on, probe 12b D3). With
    ``need``, the candidates past zero at the first x where at least ``need`` of them are
    (a shared bisection of the loose signs) are finished, the rest are LATER: near a
    short-wave limit hundreds of modes cross within a step, and only the first few are
    reported. x0 is the start of the path, where every candidate is positive.
    """
    if cand.size == 1 and values is not None:
        near = _near_root(signed, fine, int(cand[0]), float(xa[0]), x, values, loose_parts)
        if near is not None:
            return [near]
    lo, hi = np.array(xa, float), np.full(cand.size, x, float)
    out: list = [None] * cand.size
    keep = np.arange(cand.size)
    if need is not None and cand.size > need + 2:
        keep = _pack(signed, cand, lo, hi, x, need)
        for k in set(range(cand.size)) - set(keep.tolist()):
            out[k] = LATER
    a, b = lo[keep][np.argmin(sense_of(x, xa) * lo[keep])], x
    for _ in range(SHARED_ROUNDS):  # bisect towards the earliest root; the others on the way
        c = 0.5 * (a + b)
        neg = _narrow(signed, cand, keep, lo, hi, c)
        a, b = (a, c) if neg.any() else (c, b)

    def finish(k):
        i, l, h = cand[k], lo[k], hi[k]
        f = Remembered(lambda y: fine(y, i))  # brentq evaluates the ends l, h again
        if f(h) > 0:  # fine and loose disagree at h: fall back to the whole step
            if f(x) > 0:
                return
            h = x
        if f(l) <= 0:
            l = xa[k] if f(xa[k]) > 0 else x0  # the candidate is positive at the start
        if f(l) <= 0:  # not by the fine values: its root is the start (module docstring)
            out[k] = x0
            return
        out[k] = brent(f, *sorted((l, h)))

    for k in keep:
        finish(k)
    if fine_many is None:
        fine_many = lambda y, idx: np.array([fine(y, int(i)) for i in idx])  # noqa: E731
    _later_before(signed, fine_many, cand, (xa, x), lo, hi, out, need, finish)
    return out


#: a LATER candidate whose loose signed value at the need-th root is below this is asked
#: again with the fine target there (a loose value, rtol 1e-5, is off by far less)
LATER_DOUBT = 1e-3


def _later_before(signed, fine_many, cand, where, lo, hi, out, need, finish) -> None:
    """Finish the LATER candidates whose fine value is past zero at the need-th root found
    (at x if fewer were found): the pack was chosen by loose signs, which cannot order
    roots closer than their error (a film's folds 1e-8 apart: the scan reported (70, 1)
    while (70, 0) comes 2.5e-5 earlier, probe round 6b). One candidate positive there has
    its root after it: LATER stands. Every LATER candidate is read loosely there, one
    sample each: its loose bracket says nothing (a film's (70, 0), its fine root before
    the need-th, had its loose bracket 1 % of the path past it). ``where``: (the samples
    xa, the step's end x)."""
    later = [k for k, r in enumerate(out) if r is LATER]
    if not later:
        return
    xa, x = where
    sense = sense_of(x, xa)
    roots = sorted((r for r in out if isinstance(r, float)), key=lambda r: sense * r)
    at = roots[need - 1] if len(roots) >= need else x
    loose = signed(at, cand[later])
    doubt = [k for k, v in zip(later, loose) if v <= LATER_DOUBT]
    if not doubt:
        return
    past = np.asarray(fine_many(at, cand[doubt])) <= 0  # near a short wave: hundreds
    for k in np.asarray(doubt)[past]:
        out[k] = None
        if sense * (lo[k] - at) >= 0:  # its bracket was narrowed past ``at`` by loose signs
            lo[k] = xa[k]
        hi[k] = at
        finish(k)


def sense_of(x: float, xa: np.ndarray) -> float:
    """+1 if the march went up from its samples ``xa`` to x, else -1."""
    return 1.0 if x > xa[0] else -1.0


def _narrow(signed, cand, among, lo, hi, c) -> np.ndarray:
    """Sample the candidates ``among`` whose bracket [lo, hi] holds c there, and narrow
    their brackets to the side of c where they change sign; returns which (of all) are
    past zero at c."""
    inside = among[(c - lo[among]) * (c - hi[among]) < 0]
    neg = np.zeros(cand.size, bool)
    neg[inside] = signed(c, cand[inside]) <= 0
    hi[neg] = c
    pos = np.zeros(cand.size, bool)
    pos[inside] = ~neg[inside]
    lo[pos] = c
    return neg


def _pack(signed, cand, lo, hi, x: float, need: int) -> np.ndarray:
    """A pack of candidates (near a short-wave limit hundreds of modes cross within one
    step): the first x (shared loose bisection) where at least ``need`` are past zero;
    only those can hold the first ``need`` roots. Returns their indices; every sample
    narrows the brackets [lo, hi] it falls in. Done before the shared rounds of
    :func:`first_roots`, which then sample the pack alone (a thin film's 1936 candidates
    cost 11,000 loose evaluations when every round sampled all of them)."""
    keep = np.arange(cand.size)
    sense = sense_of(x, lo)
    a, b = lo[np.argmin(sense * lo)], x
    for _ in range(PACK_ROUNDS):
        c = 0.5 * (a + b)
        neg = _narrow(signed, cand, keep, lo, hi, c)
        past = keep[neg[keep] | (sense * (hi[keep] - c) <= 0)]  # past zero at c
        if past.size >= need:
            keep, b = past, c
        else:
            a = c
        if keep.size <= need + 2 or abs(b - a) <= EDGE.at(b):
            break
    return keep


#: the loose root of a single candidate, to this (not to full precision: it only places
#: the fine bracket)
LOOSE_ROOT = Tolerance(1e-10, 1e-12)
#: with det(M2) at hand, Brent's method on the bounded target stops after this many
#: iterations (a smooth target is done in 4-8; a step would take ~30) and det(M2) takes over
LOOSE_FIRST = dataclasses.replace(LOOSE_ROOT, maxiter=10)
#: the half-widths of the fine bracket around the loose root, times max(1, |root|), tried
#: in turn: the loose root (signs at rtol 1e-8 or looser, 1e-5 in a scan) is off by ~1e-10
#: relative for most modes, so the first holds the fine root with room to spare; a short
#: wave's target is small (2.5e-7 for (2000, 0) of a film on a thick substrate) and its
#: loose root can be 3e-8 off; where neither holds it, the caller bisects as for many
#: candidates (~20 fine evaluations where the second width costs ~6)
NEAR = (1e-8, 1e-6)


def _tightest(seen: dict, start: float) -> tuple[float, float]:
    """(good, bad): of the points ``seen`` (x -> value, positive at ``start``), the first
    non-positive one from ``start`` and the positive one next to it on the start side."""
    order = sorted(seen, key=lambda y: abs(y - start))
    bad = next(y for y in order if not seen[y] > 0)
    good = max(
        (y for y in order if seen[y] > 0 and abs(y - start) < abs(bad - start)),
        key=lambda y: abs(y - start),
    )
    return good, bad


def _on_line(parts, a: float, b: float) -> Callable[[float], float]:
    """det(M2) = f exp(log_norm) (``parts(y)``: (f, log_norm)) divided by exp of the line
    through log_norm at a and b.

    The bounded target f of a short wave is a step where its mode lives at the inner face
    (its size is in log_norm), and Brent's method on a step is a bisection, ~30 loose
    evaluations in a march step; det(M2) is linear through the root, but log_norm ~ 600
    changes by ~60 across a step, and on exp(60 x) Brent's method bisects too. What is left
    of log_norm off its line is small and smooth. Where log_norm is not finite (the kernel
    fell back, or a target without it), f as it is."""
    ends = {a: parts(a), b: parts(b)}
    la, lb = ends[a][1], ends[b][1]

    def value(y: float) -> float:
        f, log_norm = ends[y] if y in ends else parts(y)
        if not (math.isfinite(log_norm) and math.isfinite(la) and math.isfinite(lb)):
            return f
        return scaled(f, log_norm - (la + (lb - la) * (y - a) / (b - a)))

    return value


def _near_root(signed, fine, i: int, xa: float, x: float, values, loose_parts=None):
    """The fine root of the one candidate i between xa and x: Brent's method on its loose
    values (known at both ends) to LOOSE_ROOT, then on the fine ones in +-NEAR around that
    root (each width of NEAR in turn). A bisection of loose signs would cost SHARED_ROUNDS
    evaluations for a bracket 2^-6 of the step, Brent's on it ~6 fine ones; this costs ~3
    loose and ~4 fine ones.
    With ``loose_parts``, where Brent's method on the loose values does not converge within
    LOOSE_FIRST's iterations (a step), the loose root is refined on det(M2)
    (:func:`_on_line`) in the tightest bracket those iterations left. None if the loose
    values do not change sign or the fine ones do not change sign across the narrow
    bracket (first_roots then bisects)."""
    g_a, g_x = float(values[0][0]), float(values[1][0])
    if not (g_a > 0 >= g_x):
        return None
    loose = Remembered(lambda y: float(signed(y, np.array([i]))[0]))
    loose.seen.update({float(xa): g_a, float(x): g_x})
    first = LOOSE_ROOT if loose_parts is None else LOOSE_FIRST
    try:
        root = brent(loose, *sorted((xa, x)), first, named=False)
    except RuntimeError:  # not converging: a step; det(M2) on the tightest bracket seen
        good, bad = _tightest(loose.seen, xa)
        det = Remembered(_on_line(lambda y: loose_parts(y, i), good, bad))
        if not det(good) > 0 >= det(bad):
            return None
        root = brent(det, *sorted((good, bad)), LOOSE_ROOT, named=False)
    f = Remembered(lambda y: fine(y, i))
    for near in NEAR:
        w = near * max(1.0, abs(root))
        lo, hi = max(root - w, min(xa, x)), min(root + w, max(xa, x))
        good, bad = (lo, hi) if x > xa else (hi, lo)  # the start side is positive
        if f(good) > 0 >= f(bad):
            return brent(f, lo, hi)
        if f(good) <= 0 and f(bad) > 0:  # the fine values disagree with the loose ones
            break
    return None
