"""Functions of the control value x along a march, as named picklable objects.

A march (march.py, surface.py) asks questions of the tube at a control value x: the tube
there (:class:`TubeAt`), its base state (:class:`StateAt`), the targets of some modes with
their stable signs applied (:class:`Signed`, positive until a mode's first bifurcation),
how far the loads held fixed are from their thresholds (:class:`LoadMargin`). Each is a small
frozen dataclass with ``__call__``,
so a reader following a control from the CLI or ``critical_value`` sees what is evaluated
(the target's class names the kernel: incremental.targets.ImpedanceTarget or
CollocationTarget) and a process pool can ship it. They compute exactly what the lambdas
they replace computed. Whether a state lies too near a lock for its modes to be read is
:func:`clear_of_lock`; where a march's state is lost, state_loss.py.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable

import numpy as np

from ..basestate.start_probe import UNRESOLVED
from ..basestate.tube import solve_base_state, threshold
from ..basestate.voltage import CLOSING
from ..continuation.events import scaled
from ..errors import NEAR_LOCK, BranchNotFollowed, ConvergenceError, StartUnresolved
from ..model.builtin_energies import BuiltinEnergy
from ..model.layers import Tube


class Neighbours:
    """The last few base states solved along one path, by control value: each new state is
    continued from the nearest of them (solve_base_state's ``near``). Not pickled: a copy
    shipped to another process starts empty."""

    KEEP = 6

    def __init__(self):
        self.states: list = []  # (x, rtol, state), the newest last

    def __reduce__(self):
        return (Neighbours, ())

    def nearest(self, x: float, rtol: float):
        """(the state nearest to x, Newton's start (r_i, lambda_z) extrapolated linearly
        from the two nearest), (None, None) when there is none, guess None from one."""
        known = sorted(
            (abs(x - xs), -k, xs)
            for k, (xs, r, _) in enumerate(self.states)
            if r == rtol and math.isfinite(xs)
        )
        if not known:
            return None, None
        s1, x1 = self.states[-known[0][1]][2], known[0][2]
        other = [(k, xs) for _, k, xs in known if xs != x1]  # a line needs two points
        if not other:
            return s1, None
        s2, x2 = self.states[-other[0][0]][2], other[0][1]
        t = (x - x1) / (x1 - x2)
        return s1, (s1.r_i + t * (s1.r_i - s2.r_i), s1.stretch + t * (s1.stretch - s2.stretch))

    def solved_at(self, x: float, rtol: float):
        """The state solved at exactly x with ``rtol``, or None."""
        for xs, r, state in self.states:
            if xs == x and r == rtol:
                return state
        return None

    def keep(self, x: float, rtol: float, state) -> None:
        self.states.append((x, rtol, state))
        del self.states[: -self.KEEP]


@dataclasses.dataclass(frozen=True)
class TubeAt:
    """The tube with its control ``control`` set to x (``tube.at(control, x)``), and its
    base state there (:meth:`state`), continued from the nearest state solved before."""

    tube: Tube
    control: str
    as_float: bool = False  # convert x to float first (the short-wave march's probes)
    neighbours: Neighbours = dataclasses.field(
        default_factory=Neighbours, compare=False, repr=False
    )

    def __call__(self, x) -> Tube:
        return self.tube.at(self.control, float(x) if self.as_float else x)

    def state(self, x, rtol: float = 1e-12):
        """``solve_base_state(self(x), rtol=rtol)``, started from the nearest state this path
        has solved (the same root: basestate/warm.py); ConvergenceError where a layer is too
        near its lock for the modes to be read (:func:`clear_of_lock`)."""
        state = self.solved(x, rtol)
        return clear_of_lock(state) if self.locks else state

    def solved(self, x, rtol: float = 1e-12):
        """The base state at x continued from the nearest state this path has solved, near
        a lock or not (a crease's drive needs no incremental moduli)."""
        x = float(x)
        state = self.neighbours.solved_at(x, rtol)  # solved here before (a value, then its
        if state is None:  # estimate), or solved now
            tube = self(x)
            if tube.is_uniform:  # a function of the tube alone: no neighbour needed
                state = solve_base_state(tube, rtol=rtol)
            else:
                near, guess = self.neighbours.nearest(x, rtol)
                state = solve_base_state(tube, rtol=rtol, near=near, guess=guess)
            self.neighbours.keep(x, rtol, state)
        return state

    @functools.cached_property
    def locks(self) -> bool:
        """Has the tube a layer whose lock the states may come near (clear_of_lock)?"""
        return has_lock(self.tube)


@dataclasses.dataclass(frozen=True)
class StateAt:
    """The base state at x: ``solve_base_state(at(x), rtol=rtol)`` (``at.state``)."""

    at: TubeAt
    rtol: float

    def __call__(self, x):
        return self.at.state(x, self.rtol)


@dataclasses.dataclass(frozen=True, eq=False)
class Signed:
    """The targets of rows of ``modes`` along the path, times their stable ``signs``: every
    value is positive until that mode's first bifurcation."""

    at: TubeAt
    target: Callable
    modes: np.ndarray
    signs: np.ndarray

    def __call__(self, x, idx) -> np.ndarray:
        """Signed targets of the rows ``idx`` at x (one base state for them all)."""
        return self.signs[idx] * self.target(self.at.state(x), self.modes[idx])

    def one(self, x, i) -> float:
        """Signed target of row i at x."""
        return float(self.signs[i] * self.target(self.at.state(x), self.modes[[i]])[0])

    def row(self, i: int) -> SignedRow:
        """Row i alone, a function of x."""
        return SignedRow(self, i)


@dataclasses.dataclass(frozen=True, eq=False)
class SignedRow:
    """One row of a :class:`Signed`, as a function of x alone (for Brent and minimisers)."""

    signed: Signed
    i: int

    def __call__(self, x) -> float:
        return self.signed.one(x, self.i)


@dataclasses.dataclass(frozen=True, eq=False)
class RootRows:
    """The rows of :class:`Signed`, as a root is refined on them: for the impedance kernel,
    det(M2) of the basis carried from the inner face (incremental.targets.analytic_parts),
    analytic in x with the signs and zeros of f, where f itself may be a step of constant
    size (a mode living at the inner face); in units of its size at the row's first sample,
    so that it stays representable (continuation.events.scaled). Other targets
    (collocation's) as they are."""

    at: TubeAt
    target: Callable
    modes: np.ndarray
    signs: np.ndarray
    scale: dict = dataclasses.field(default_factory=dict)  # row -> log_norm at its first sample

    def one(self, x, i) -> float:
        """Signed det(M2) of row i at x, in units of its first sample's size."""
        f, log_norm = self.parts(x, i)
        if not math.isfinite(log_norm):  # the kernel failed there: f, from its fallback
            return f
        ref = self.scale.setdefault(i, log_norm)
        return scaled(f, log_norm - ref)

    def parts(self, x, i) -> tuple[float, float]:
        """(signed f, log_norm) of row i at x: det(M2) is their f exp(log_norm); log_norm
        is NaN for a target without them (collocation's) or where the kernel failed."""
        parts = getattr(self.target, "parts", None)
        if parts is None:
            f = self.target(self.at.state(x), self.modes[[i]])[0]
            return float(self.signs[i] * f), math.nan
        f, log_norm = (float(v[0]) for v in parts(self.at.state(x), self.modes[[i]]))
        return float(self.signs[i] * f), log_norm

    def row(self, i: int) -> SignedRow:
        """Row i alone, a function of x."""
        return SignedRow(self, i)


def root_mode(at: TubeAt, target: Callable, mode: np.ndarray, sign: float) -> SignedRow:
    """One mode (a one-row ``mode`` array) along the path, as its root is refined
    (:class:`RootRows`), stable > 0."""
    return RootRows(at, target, mode, np.array([sign])).row(0)


@dataclasses.dataclass(frozen=True)
class SampleValue:
    """The value of a half-space sampler h (directions.Sampler) at the state at x."""

    h: Callable
    state_at: Callable

    def __call__(self, x) -> float:
        return self.h(self.state_at(x)).value


@dataclasses.dataclass(frozen=True)
class Elliptic:
    """Is the half-space still strongly elliptic at x (its sampled value is not NaN)?"""

    value_of: Callable

    def __call__(self, x) -> bool:
        return not math.isnan(self.value_of(x))


@dataclasses.dataclass(frozen=True)
class LoadMargin:
    """The least, over the ``loads`` (name, applied value) held fixed along the path, of
    the threshold of the tube at x minus the applied value: it falls to 0 where the state is
    lost. A state is reached by the pressure stage at no voltage, then the voltage branch
    (basestate/thresholds.prepare): "pressure" is that stage's inflation threshold,
    "voltage" the voltage branch's at the tube's pressures. They are read in that order, and
    a stage whose margin is not positive ends the path there: the voltage branch of a tube
    past its inflation threshold has no start (BaseStateError), which made the margin
    unreadable past it and the loss a bisection of the states that solve, continued ones
    among them (check round 28, res_61 #12: 248.519, not the inflation threshold's 248.22)."""

    at: TubeAt
    loads: tuple[tuple[str, float], ...]

    def __call__(self, x) -> float:
        tube = self.at(x)
        least = math.inf
        for name, applied in sorted(self.loads, key=lambda load: load[0] != "pressure"):
            least = min(least, _load_threshold(tube, name) - applied)
            if not least > 0:  # lost at this stage: the next one is not reached
                break
        return least


def _load_threshold(tube: Tube, name: str) -> float:
    if name == "voltage":
        thr = threshold(tube, "voltage")
        if thr.kind == "closing":  # no charged state followed: not lost either
            raise BranchNotFollowed(f"Vbar = {tube.voltage:.12g}: {CLOSING}")
        if thr.kind == "unresolved":  # nor where the start's side is not resolved
            raise StartUnresolved(f"Vbar = {tube.voltage:.12g}: {UNRESOLVED}")
        return thr.value
    return threshold(dataclasses.replace(tube, voltage=0.0), "pressure").value


def voltage_threshold(tube) -> float:
    """The voltage threshold of ``tube`` (inf where a stiffening energy has none)."""
    return threshold(tube, "voltage").value


#: the closest a Gent layer may come to its lock, 1 - (I1 - 3) / jm, for its state to be
#: used by a march: the incremental moduli grow like 1 / margin^2, and within ~1e-8 the
#: kernel's target of a tube compressed to its lock fell from 8.9e-4 (margin 1e-6) to 6e-12,
#: a root that is not there (tests/bifurcation/test_stretch_to_lock.py). An energy text
#: with a lock is held as far from the edge of its finite values: finite at I1 - 3 and
#: I2 - 3 scaled by 1 / (1 - LOCK_MARGIN), the same test for Gent's energy written as text
#: (whose half-space target turned NaN, "not elliptic", within 1e-9 of its lock)
LOCK_MARGIN = 1e-6


class NearLock(ConvergenceError):
    """A state within LOCK_MARGIN of a lock: it exists, its modes are not read."""


def clear_of_lock(state):
    """``state``, or ConvergenceError where a layer is within LOCK_MARGIN of its lock (a
    Gent layer's 1 - (I1 - 3)/jm, an energy text's edge): the state exists, but a march
    cannot read its modes (it treats it as unresolved)."""
    margin = lock_margin(state)
    if margin < LOCK_MARGIN:
        what = f"a Gent layer is within {margin:.1e} of its lock (1 - (I1 - 3)/jm)"
    elif not clear_of_domain_edge(state):
        what = f"a layer's energy is not finite {LOCK_MARGIN:g} (relative) further from I1 = 3"
    else:
        return state
    err = NearLock(
        f"{what}: its incremental moduli are beyond the kernel's range below {LOCK_MARGIN:g}"
    )
    err.remedy = NEAR_LOCK
    raise err


def has_lock(tube) -> bool:
    """Has the tube a Gent layer, or one whose energy (a text) is not finite everywhere?"""
    return any(
        getattr(layer.material.definition, "family", None) == "gent"
        or bounded_energy(layer) is not None
        for layer in tube.layers
    )


def bounded_energy(layer) -> Callable | None:
    """Numeric Omega(I1, ..., I6) of a layer's energy text that is not a polynomial (one that
    may end, as Gent's written as text), else None (a built-in energy: Gent's lock is
    known in closed form)."""
    if isinstance(layer.material.definition, BuiltinEnergy):
        return None
    return layer.material.omega()


def _invariants_at(state, layer, a: float, b: float) -> tuple[np.ndarray, np.ndarray]:
    """(I1, I2) of the elastic stretches of ``layer`` (on [a, b]) at 9 Chebyshev points
    (its faces included: I1 is largest at a face where the hoop stretch is monotone)."""
    R = 0.5 * (a + b) - 0.5 * (b - a) * np.cos(np.linspace(0.0, math.pi, 9))
    g = np.asarray(layer.growth_at(R), float)
    l_t = state.radius(R) / (R * g[1])
    l_z = state.stretch / g[2]
    l_r = 1.0 / (l_t * l_z)  # the elastic part is isochoric
    squares = (l_r * l_r, l_t * l_t, l_z * l_z)
    i2 = squares[0] * squares[1] + squares[1] * squares[2] + squares[2] * squares[0]
    return sum(squares), i2


def lock_margin(state) -> float:
    """The least 1 - (I1 - 3)/jm over the Gent layers of ``state`` (inf without one), at 9
    Chebyshev points of each."""
    tube, worst = state.tube, math.inf
    for layer, a, b in zip(tube.layers, tube.radii, tube.radii[1:]):
        energy = layer.material.definition
        if getattr(energy, "family", None) != "gent":
            continue
        i1, _ = _invariants_at(state, layer, a, b)
        worst = min(worst, float(np.min(1.0 - (i1 - 3.0) / energy.parameter)))
    return worst


def nearest_lock(state) -> tuple[int, float] | None:
    """(the number, from 1 at the bore, of the Gent layer of ``state`` nearest to its lock,
    its least 1 - (I1 - 3)/jm), or None without a Gent layer: what a march next to a lock
    names where its states stop resolving."""
    tube, margins = state.tube, []
    for k, (layer, a, b) in enumerate(zip(tube.layers, tube.radii, tube.radii[1:]), 1):
        energy = layer.material.definition
        if getattr(energy, "family", None) == "gent":
            i1, _ = _invariants_at(state, layer, a, b)
            margins.append((float(np.min(1.0 - (i1 - 3.0) / energy.parameter)), k))
    if not margins:
        return None
    margin, k = min(margins)
    return k, margin


def clear_of_domain_edge(state, margin: float = LOCK_MARGIN) -> bool:
    """Is every energy text of ``state`` finite (with no field) at its layer's I1 - 3 and
    I2 - 3 scaled by 1 / (1 - margin), at 9 Chebyshev points of each (for Gent's energy,
    1 - (I1 - 3)/jm > margin)?"""
    tube = state.tube
    for layer, a, b in zip(tube.layers, tube.radii, tube.radii[1:]):
        omega = bounded_energy(layer)
        if omega is None:
            continue
        i1, i2 = _invariants_at(state, layer, a, b)
        stretched = (3.0 + (i1 - 3.0) / (1.0 - margin), 3.0 + (i2 - 3.0) / (1.0 - margin))
        with np.errstate(all="ignore"):
            try:
                w = np.asarray(omega(*stretched, 0.0, 0.0, 0.0), float)
            except (ArithmeticError, ValueError):
                return False
        if not np.all(np.isfinite(w)):
            return False
    return True
