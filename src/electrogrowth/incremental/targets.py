"""The bifurcation target f(state, modes): one name per method, one call for many modes.

A mode (m, n) of a base state is at bifurcation when the incremental problem has a
non-trivial solution. Two independent methods give a real target that changes sign exactly
there, without poles:

* ``Method.IMPEDANCE``: the compiled Riccati kernel (impedance.py) on the Chebyshev tables
  of the base state (radial_table.py), batched over modes;
* ``Method.COLLOCATION``: Chebyshev collocation of the full incremental equations
  (collocation.py), one mode at a time.

Every mode belongs to one :class:`Family` (docs/derivation-families.md):

* ``wrinkle``: the paper's ansatz (eq. incremental-solutions), m >= 0, n >= 1; at m = 0
  the axisymmetric modes (u_r, u_z, phi), the torsional factor excluded;
* ``prismatic``: n = 0 (k = 0), m >= 2, plane-strain wrinkles u_r = U_r cos m th,
  u_th = U_th sin m th, phi = Phi cos m th, u_z = 0 (admissible with sliding ends); the
  in-plane part of the k = 0 system (the anti-plane part never bifurcates while the
  anti-plane shear moduli gamma_13, A2323 are positive);
* ``torsional``: m = 0, n >= 1, u_th = U_th(r) cos kz alone.

A family keeps a subset of the four pairs (U_j, S_j) of the Stroh vector (``PAIRS`` bits:
0 U_r, 1 U_th, 2 U_z, 3 r Delta_r / Phi), which decouple from the others for its modes.
``modes`` arrays have rows (m, n) (the natural family: prismatic for n = 0, else wrinkle)
or (m, n, code) with code = ``Family.code``.

:func:`targets_for` turns a method and a tolerance into a named target object,
:class:`ImpedanceTarget` or :class:`CollocationTarget`, called as ``target(state, modes) -> f``,
which the march (bifurcation/march.py) evaluates; being plain frozen dataclasses, targets
pickle and compare by value.
"""

from __future__ import annotations

import dataclasses
import enum
import math

import numpy as np

from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError, ParameterError
from .accuracy import Accuracy
from .impedance import ALL_PAIRS, STATUS_TEXT, target_batch, target_serial
from .radial_table import build_table, stack_tables

#: The largest m and n of a mode: the kernel's steps grow like the decay rate integrated
#: through the wall, ~1.1 max(m ln(r_o / r_i), k (r_o - r_i)) at rtol 1e-12, so m = 2000
#: keeps every Rbar_o <= 100 well inside the 20000-step budget (docs/derivation-film.md,
#: "Large m"); shorter waves tend to the exact short-wave limit (bifurcation/surface.py).
MODE_MAX = 2000

PARALLEL_FROM = 16  # batches smaller than this run on one thread (thread launch costs more)

#: Bits of the Stroh pairs (U_j, S_j): U_r / r Sigma_rr, U_th / r Sigma_rth,
#: U_z / r Sigma_rz, r Delta_r / -Phi (collocation: U_r and P, U_th, U_z, Phi).
U_R, U_TH, U_Z, PHI = 1, 2, 4, 8


class Method(enum.StrEnum):
    """How the incremental problem is solved: the one choice behind every ``method``."""

    IMPEDANCE = "impedance"
    COLLOCATION = "collocation"


METHODS = tuple(m.value for m in Method)


class Family(enum.StrEnum):
    """A family of incremental modes (module docstring): the one name behind ``family``."""

    WRINKLE = "wrinkle"  # the paper's ansatz, m >= 0, n >= 1 (m = 0: axisymmetric)
    PRISMATIC = "prismatic"  # n = 0, m >= 2: plane strain, the in-plane part at k = 0
    TORSIONAL = "torsional"  # m = 0, n >= 1: u_th = U_th(r) cos kz

    @property
    def code(self) -> int:
        """The number standing for the family in a ``modes`` array (third column)."""
        return _CODES[self]

    def pairs(self, m: int) -> int:
        """The Stroh pairs kept for mode number m (bitmask, see ``U_R`` ...)."""
        if self is Family.PRISMATIC:
            return ALL_PAIRS & ~U_Z
        if self is Family.TORSIONAL:
            return U_TH
        return ALL_PAIRS if m != 0 else ALL_PAIRS & ~U_TH


FAMILIES = tuple(f.value for f in Family)
_CODES = {f: i for i, f in enumerate(Family)}
_BY_CODE = tuple(Family)


def check_method(method: str) -> Method:
    """The Method named ``method``, or ParameterError listing the valid names."""
    try:
        return Method(method)
    except ValueError:
        raise ParameterError(f"method = {method!r} is unknown; choose one of {METHODS}") from None


def check_family(family: str) -> Family:
    """The Family named ``family``, or ParameterError listing the valid names."""
    try:
        return Family(family)
    except ValueError:
        raise ParameterError(f"family = {family!r} is unknown; choose one of {FAMILIES}") from None


def natural_family(m: int, n: int) -> Family:
    """The family of (m, n) when none is named: prismatic for n = 0, else wrinkle."""
    return Family.PRISMATIC if n == 0 else Family.WRINKLE


def wavenumber(params, n: float) -> float:
    """Axial wavenumber k = n pi / (lambda_z L) in the current configuration."""
    return n * math.pi / (params.stretch * params.length)


def check_mode(m, n, family: str | None = None) -> Family:
    """The family of mode (m, n) (``family``, or the natural one), or ParameterError.

    Valid: wrinkle m >= 0, n >= 1; prismatic n = 0, m >= 2 ((0, 0) is the breathing mode,
    the base state's own limit point; (1, 0) a rigid translation); torsional m = 0, n >= 1;
    m, n <= MODE_MAX.

    >>> check_mode(3, 0)
    <Family.PRISMATIC: 'prismatic'>
    """
    whole = all(
        not isinstance(x, bool)
        and isinstance(x, (int, float, np.integer, np.floating))
        and math.isfinite(x)
        and int(x) == x
        for x in (m, n)
    )
    if not whole or m < 0 or n < 0 or m > MODE_MAX or n > MODE_MAX:
        raise ParameterError(
            f"mode (m, n) = ({m}, {n}) is invalid; need integers 0 <= m <= {MODE_MAX},"
            f" 0 <= n <= {MODE_MAX} (n = 0: prismatic, m >= 2; shorter waves tend to the"
            " exact short-wave limit, which every scan computes)"
        )
    fam = natural_family(m, n) if family is None else check_family(family)
    where = f"mode (m, n) = ({m:g}, {n:g})"
    if fam is Family.WRINKLE and n < 1:
        raise ParameterError(
            f"{where} is not a wrinkle (n >= 1); n = 0 is the prismatic family (m >= 2)"
        )
    if fam is Family.PRISMATIC:
        if n != 0:
            raise ParameterError(f"{where} is not prismatic; prismatic modes have n = 0, m >= 2")
        if m < 2:
            why = (
                "the breathing mode, the base state's own limit point"
                if m == 0
                else "a rigid translation of the cross-section"
            )
            raise ParameterError(
                f"{where} is invalid: it is {why}; prismatic modes (n = 0) need m >= 2"
            )
    if fam is Family.TORSIONAL and (m != 0 or n < 1):
        raise ParameterError(
            f"{where} is invalid for the torsional family; torsional modes have m = 0, n >= 1"
        )
    return fam


def mode_families(modes: np.ndarray) -> np.ndarray:
    """Family codes of the rows of ``modes``: the third column, or the natural family."""
    if modes.shape[1] > 2:
        return modes[:, 2].astype(np.int64)
    return np.where(modes[:, 1] == 0, Family.PRISMATIC.code, Family.WRINKLE.code)


def row_family(row) -> Family:
    """The Family of one row (m, n) or (m, n, code) of a ``modes`` array."""
    if len(row) > 2:
        return _BY_CODE[int(row[2])]
    return natural_family(row[0], row[1])


#: the family codes, read once (mode_pairs runs at every evaluation of a march)
_PRISMATIC, _TORSIONAL = Family.PRISMATIC.code, Family.TORSIONAL.code


def mode_pairs(modes: np.ndarray) -> np.ndarray:
    """The Stroh pairs kept by each row of ``modes`` (int64 bitmasks)."""
    code = mode_families(modes)
    pairs = np.where(modes[:, 0] == 0, ALL_PAIRS & ~U_TH, ALL_PAIRS).astype(np.int64)
    pairs[code == _PRISMATIC] = ALL_PAIRS & ~U_Z
    pairs[code == _TORSIONAL] = U_TH
    return pairs


def with_family(m: int, n: int, family: str) -> np.ndarray:
    """The one-row ``modes`` array of mode (m, n) of ``family``."""
    return np.array([[m, n, Family(family).code]], dtype=float)


def impedance_targets(state, modes, *, rtol: float = 1e-12, max_steps: int = 20000) -> np.ndarray:
    """Kernel target f for many modes (rows (m, n) or (m, n, code)) on one base state."""
    modes = np.atleast_2d(np.asarray(modes, dtype=float))
    tables = stack_tables([build_table(state, tol=Accuracy(rtol).table)])
    count = modes.shape[0]
    k = modes[:, 1] * math.pi / state.current_length
    m = np.ascontiguousarray(modes[:, 0])
    kernel = target_batch if count >= PARALLEL_FROM else target_serial
    f, status, _ = kernel(
        m, k, mode_pairs(modes), np.zeros(count, dtype=np.int64), tables, rtol, max_steps
    )
    bad = status != 0
    if bad.any():
        f[bad] = _retry(state, modes[bad], status[bad], rtol, max_steps)
    return f


RETRY_TIGHTER = (1e-2, 1e-4)  # a failed mode is integrated again at rtol times these


def _retry(state, modes, status, rtol, max_steps) -> np.ndarray:
    """Targets of the modes whose integration failed (a step size underflow where the
    error estimate of a loose rtol misjudges a steep stretch of z~, or a chart lost):
    again at tighter tolerances (never looser), then by collocation, whose target has
    the same sign and the same zeros. ConvergenceError only if all of these fail."""
    f = np.full(modes.shape[0], np.nan)
    for factor in RETRY_TIGHTER:
        todo = np.isnan(f)
        tight = max(rtol * factor, 1e-14)
        tables = stack_tables([build_table(state, tol=Accuracy(tight).table)])
        k = modes[todo, 1] * math.pi / state.current_length
        m = np.ascontiguousarray(modes[todo, 0])
        pairs = mode_pairs(modes[todo])
        got, code, _ = target_serial(
            m, k, pairs, np.zeros(m.size, dtype=np.int64), tables, tight, max_steps
        )
        f[todo] = np.where(code == 0, got, np.nan)
        if not np.isnan(f).any():
            return f
    for i in np.flatnonzero(np.isnan(f)):
        try:
            f[i] = collocation_targets(state, modes[i : i + 1])[0]
        except (ArithmeticError, ValueError, np.linalg.LinAlgError):
            pass
        if not np.isfinite(f[i]):
            raise ConvergenceError(
                f"impedance integration failed for mode (m, n) = ({modes[i, 0]:g}, "
                f"{modes[i, 1]:g}) ({row_family(modes[i])}): {STATUS_TEXT[int(status[i])]},"
                " also at tighter tolerances and by collocation"
            )
    return f


def collocation_targets(state, modes, *, nodes: int = 40) -> np.ndarray:
    """Collocation target f for the rows of ``modes``, one mode (and family) at a time."""
    # imported here: the impedance kernel's evaluations (every march) do not load it
    from .collocation import collocation_target

    modes = np.atleast_2d(np.asarray(modes, dtype=float))
    return np.array(
        [
            collocation_target(state, int(row[0]), int(row[1]), nodes=nodes, pairs=int(keep))
            for row, keep in zip(modes, mode_pairs(modes))
        ]
    )


def resolving_nodes(state, m: float, n: float, rtol: float) -> int:
    """Collocation nodes that resolve mode (m, n) through the wall to ``rtol``.

    A mode varies through the wall like exp(-q x), x from 0 to 1 across it, with
    q = max(k (r_o - r_i), m ln(r_o / r_i)) (k = n pi / l); the Chebyshev coefficients of
    exp(-q (x + 1) / 2) fall like exp(-N^2 / q), so N = sqrt(q ln(1 / rtol)) + 4 nodes
    resolve it (the 4 cover the prefactor: q = 10 ... 1000, rtol = 1e-12, 1e-8). Measured
    (Mooney-Rivlin alpha 0.7, Rbar_o = 3.765, L = 0.337, mode (0, 4), q = 347): the root is
    off by 1.4e-4 at 56 nodes, 3.4e-7 at 72, 2.3e-10 at 88, below 1e-12 at 104 (here: 102).
    """
    k = n * math.pi / state.current_length
    q = max(k * (state.r_o - state.r_i), m * math.log(state.r_o / state.r_i))
    return math.ceil(math.sqrt(q * math.log(1.0 / rtol))) + 4


@dataclasses.dataclass(frozen=True)
class ImpedanceTarget:
    """The impedance kernel's target f(state, modes) at ``rtol`` (:func:`impedance_targets`):
    a named, picklable function of a base state and a batch of modes."""

    rtol: float = 1e-12
    max_steps: int = 20000

    def __call__(self, state, modes) -> np.ndarray:
        return impedance_targets(state, modes, rtol=self.rtol, max_steps=self.max_steps)


@dataclasses.dataclass(frozen=True)
class CollocationTarget:
    """The collocation target f(state, modes), mode by mode, at Accuracy(rtol)'s nodes or
    more for a mode whose decay through the wall needs them (:func:`resolving_nodes`)."""

    rtol: float = 1e-12

    def __call__(self, state, modes) -> np.ndarray:
        nodes = Accuracy(self.rtol).collocation_nodes
        modes = np.atleast_2d(np.asarray(modes, dtype=float))
        return np.array(
            [
                collocation_targets(state, row[None], nodes=max(nodes, self._nodes(state, row)))[0]
                for row in modes
            ]
        )

    def _nodes(self, state, row) -> int:
        """The nodes resolving the mode of ``row`` (m, n[, code]) at this rtol."""
        return resolving_nodes(state, row[0], row[1], self.rtol)


#: targets(state, modes (k, 2) or (k, 3) array) -> (k,) array of target values
Target = ImpedanceTarget | CollocationTarget


def targets_for(method: str, rtol: float) -> Target:
    """The target f(state, modes) of ``method`` at ``rtol``: an :class:`ImpedanceTarget` or a
    :class:`CollocationTarget`."""
    if check_method(method) is Method.IMPEDANCE:
        return ImpedanceTarget(rtol)
    return CollocationTarget(rtol)


def collocation_stable_signs(tube, modes) -> np.ndarray:
    """The signs of :func:`collocation_targets` of ``modes`` on the unloaded ``tube``, where
    every mode is stable: +1 for one layer (the determinant is normalised by
    ``collocation.stable_det_sign``), else evaluated there, mode by mode."""
    modes = np.asarray(modes)
    if len(tube.layers) == 1:
        return np.ones(len(modes))
    state = solve_base_state(tube.reference())
    return np.sign([collocation_targets(state, row[None, :])[0] for row in modes])
