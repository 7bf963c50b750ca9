"""The exact short-wave (surface) limit as a competitor in a design's margin.

Every scan computes the limit m, k -> infinity at the faces and interfaces
(bifurcation/surface.py), and a mode sequence has intervals where it comes first. Where the
target's region borders one, the limit comes right after the target near that switch, so
like the crease it bounds the margin:

    M_surface(x) = s (v_S(x) - v_T(x)) / |v_T(x)|,

negative where the limit comes first (design/onset.py :func:`gap_to_crease`, the same
gap). Left out, a design sat on the switch to the surface interval with the gap to a far
mode as its margin (a tube Rbar_o = 2.1 charged, target (0, 1) along the length, modes up
to (2, 2): M = 0.00525 reported against 7e-10 to the limit;
tests/design/test_design_surface.py).

The limit costs a march (~0.09 s, ten mode solves), so it is located only where it can set
M: up to the nearest other competitor w (``until``), and only where a face is past its
half-space instability at w (``past_surface``, a few ms: the scan's own test for computing
the limit). Its sensitivity is by implicit differentiation of its condition (surface.py):
at the limit the signed half-space target of the face ``face`` in the worst direction psi
vanishes, h(v_S, p) = s f(state(v_S, p), face, psi) = 0; h is a minimum over psi, whose
derivative at the minimiser is the partial at fixed psi (Danskin), so dv_S/dp = -h_p / h_v
at the located face and psi, both partials by the Richardson differences of
design/sensitivity.py on base states only (no march).
"""

from __future__ import annotations

import math

from ..basestate.tube import solve_base_state
from ..bifurcation.directions import past_surface
from ..bifurcation.surface import short_wave_limit
from ..errors import ConvergenceError, ElectrogrowthError
from ..incremental.halfspace import surface_problem
from ..outcomes import Kind
from .sensitivity import STEP, _derivative, key_value, step_of

SURFACE = "surface"  # the short-wave limit as a competitor (limited_by, a tie at a kink)


class SurfaceRival:
    """The short-wave limit at designs x, cached: ``tube_at(x)`` the tube there,
    ``enabled`` False where the scans leave the limit out (ScanOptions.surface).

    Each entry is (limit, reach): the SurfaceLimit where one was located, else None and
    how far the march looked without meeting it (None: to its end, no limit at all)."""

    def __init__(self, tube_at, solve_for: str, side, sense: float, enabled: bool = True):
        self.tube_at, self.solve_for, self.side = tube_at, solve_for, side
        self.sense, self.enabled = sense, enabled
        self.cache: dict = {}

    def value(self, x, until: float | None = None) -> float:
        """v_S at x where it comes before ``until`` (None or infinite: anywhere); sense *
        inf where it does not (or cannot be located). A limit already located past
        ``until`` is returned as it is: it cannot set M there either."""
        lim = self.limit(x, until)
        return self.sense * math.inf if lim is None else lim.value

    def limit(self, x, until: float | None = None):
        """The SurfaceLimit at x (kind surface) where located before ``until``, else None."""
        if not self.enabled:
            return None
        until = until if until is not None and math.isfinite(until) else None
        key = tuple(float(c) for c in x) if hasattr(x, "__len__") else x
        if key in self.cache:
            lim, reach = self.cache[key]
            if lim is not None or reach is None:
                return lim
            if until is not None and self.sense * (until - reach) <= 0:
                return None  # looked that far already
        self.cache[key] = _locate(self.tube_at(x), self.solve_for, self.side, until)
        return self.cache[key][0]


def _locate(tube, solve_for: str, side, until: float | None):
    """(limit, reach) of :class:`SurfaceRival` at one tube."""
    if until is not None:
        try:  # the scan's own test: no face past its instability at w, no limit before it
            if not past_surface(tube.at(solve_for, until)):
                return None, until
        except ElectrogrowthError:
            pass  # no state at w (past a threshold): the march decides
    try:
        lim = short_wave_limit(tube, solve_for, side=side, until=until, estimate=False)
    except ElectrogrowthError:  # not located: counted as no competitor up to w
        return None, until
    if lim.kind == Kind.SURFACE:
        return lim, None
    # "threshold" or "ellipticity": the limit is never met; "none": not before ``until``
    return None, until if lim.kind == Kind.NONE else None


def surface_sensitivities(tube, solve_for: str, limit, keys, *, step: float = STEP) -> dict:
    """dv_S/dp of the short-wave limit ``limit`` (a SurfaceLimit of kind surface at
    ``tube``) for every key p: -h_p / h_v (module docstring). Raises ConvergenceError where
    h_v vanishes."""
    face, psi, value = limit.face, limit.psi, limit.value

    def h(t, v: float) -> float:
        state = solve_base_state(t.at(solve_for, v), rtol=1e-12)
        return float(surface_problem(state, face).target_scalar(psi))

    h_v = _derivative(lambda v: h(tube, v), value, step_of(tube, solve_for, value, step))
    if not math.isfinite(h_v) or h_v == 0.0:
        raise ConvergenceError(
            f"the {face} face's half-space target does not change with {solve_for} at {value:g}"
        )
    out = {}
    for key in keys:
        p = key_value(tube, key)
        f_key = lambda q, key=key: h(tube.at(key, q), value)  # noqa: E731
        out[key] = -_derivative(f_key, p, step_of(tube, key, p, step)) / h_v
    return out


def surface_sensitivity(tube, solve_for: str, limit, keys) -> dict:
    """:func:`surface_sensitivities` where the limit was located (``limit`` not None), else
    {} (also where its condition does not determine it: h_v = 0)."""
    if limit is None:
        return {}
    try:
        return surface_sensitivities(tube, solve_for, limit, keys)
    except ElectrogrowthError:
        return {}
