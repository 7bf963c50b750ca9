"""The bifurcation target f(state, modes): one name per method, one call for many modes.

A mode (m, n) of a base state is at bifurcation when the incremental problem has a
non-trivial solution. Two independent methods give a real target that changes sign exactly
there, without poles:

* ``Method.IMPEDANCE``: the compiled Riccati kernel (impedance.py) on the Chebyshev tables
  of the base state (radial_table.py), batched over modes;
* ``Method.COLLOCATION``: Chebyshev collocation of the full incremental equations
  (collocation.py), one mode at a time.

Every mode belongs to one :class:`Family` (defined in modes.py with the checks of a mode,
which need no kernel; docs/derivation-families.md):

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
import functools
import math
from typing import NamedTuple

import numpy as np

from ..basestate.ellipticity import LOST, softest, wall_shear
from ..basestate.tube import solve_base_state
from ..errors import CollocationTooLarge, ConvergenceError, Remedy
from ..model.layers import Tube
from .accuracy import STABLE_SIGN, Accuracy
from .halfspace import not_elliptic
from .impedance import MAX_STEPS, STATUS_TEXT, target_serial
from .mode_rows import rows_determinant, rows_parallel, rows_serial
from .modes import ALL_PAIRS as ALL_PAIRS
from .modes import FAMILIES as FAMILIES
from .modes import METHODS as METHODS
from .modes import MODE_MAX as MODE_MAX
from .modes import PHI as PHI
from .modes import U_R as U_R
from .modes import U_TH as U_TH
from .modes import U_Z as U_Z
from .modes import Family as Family
from .modes import Method as Method
from .modes import check_family as check_family
from .modes import check_method as check_method
from .modes import check_mode as check_mode
from .modes import mode_families as mode_families
from .modes import mode_pairs as mode_pairs
from .modes import natural_family as natural_family
from .modes import row_family as row_family
from .modes import with_family as with_family
from .radial_table import build_table, stack_tables
from .short_wave_start import FORGET_RTOL

PARALLEL_FROM = 16  # batches smaller than this run on one thread (thread launch costs more)


def wavenumber(params, n: float) -> float:
    """Axial wavenumber k = n pi / (lambda_z L) in the current configuration."""
    return n * math.pi / (params.stretch * params.length)


class Sample(NamedTuple):
    """A target evaluation: the values, how many modes the kernel failed on and went to
    collocation (:func:`_retry`), and why it failed on the last of them. A march stops on
    a run of states where every mode went there (bifurcation/march.py, KernelFailures):
    collocation is for isolated failures, ~40 ms a mode."""

    values: np.ndarray
    collocated: int = 0
    reason: str = ""


def impedance_sample(state, modes, *, rtol: float = 1e-12, max_steps: int = 20000) -> Sample:
    """Kernel target f for many modes (rows (m, n) or (m, n, code)) on one base state, with
    the modes that went to collocation counted."""
    modes = np.asarray(modes, dtype=float, order="C")
    if modes.ndim == 1:  # one row
        modes = modes[None]
    tables = stack_tables([build_table(state, tol=_table_tol(rtol))])
    kernel = rows_parallel if modes.shape[0] >= PARALLEL_FROM else rows_serial
    f, status = kernel(modes, state.current_length, tables, rtol, max_steps)
    if not status.any():
        return Sample(f)
    bad = status != 0
    f[bad], collocated, reason = _retry(state, modes[bad], status[bad], rtol, max_steps)
    return Sample(f, collocated, reason)


def impedance_targets(state, modes, *, rtol: float = 1e-12, max_steps: int = 20000) -> np.ndarray:
    """Kernel target f for many modes (rows (m, n) or (m, n, code)) on one base state."""
    return impedance_sample(state, modes, rtol=rtol, max_steps=max_steps).values


@functools.lru_cache(maxsize=32)
def _table_tol(rtol: float) -> float:
    """Accuracy(rtol).table, remembered: a march asks at every evaluation."""
    return Accuracy(rtol).table


def analytic_parts(state, modes, *, rtol: float = 1e-12, max_steps: int = 20000):
    """(f, log_norm) for many modes (rows (m, n) or (m, n, code)): the kernel's target and
    the log of the size of the basis M = [M1; M2] carried from the inner face, which f
    divides out (impedance.integrate_one): f exp(log_norm) is det(M2).

    Near a root of a mode that lives at the inner face M's size holds the factor that
    crosses zero, and f is a step of constant size (a film's prismatic target: +-7.3e-10
    from 1e-2 to 1e-10 of its root), which Brent's method can only bisect. det(M2) is
    analytic in the parameters, with the same signs and zeros: roots are refined on it
    (bifurcation/along.py, :class:`~electrogrowth.bifurcation.along.RootRows`). Every wall
    is integrated (no short-wave restart: it forgets M's size). Where the kernel fails, f
    comes from :func:`impedance_targets` (its retries) and log_norm is NaN; below
    FORGET_RTOL, where its integration keeps the basis' size too and so is this one, from
    the retries alone (not the same failing integration twice)."""
    modes = np.asarray(modes, dtype=float, order="C")
    if modes.ndim == 1:
        modes = modes[None]
    tables = stack_tables([build_table(state, tol=_table_tol(rtol))])
    f, log_norm, status = rows_determinant(modes, state.current_length, tables, rtol, max_steps)
    bad = status != 0
    if bad.any() and rtol < FORGET_RTOL:  # impedance_targets' integration is this one
        f[bad] = _retry(state, modes[bad], status[bad], rtol, max_steps).values
    elif bad.any():
        f[bad] = impedance_targets(state, modes[bad], rtol=rtol, max_steps=max_steps)
    log_norm[bad] = np.nan
    return f, log_norm


RETRY_TIGHTER = (1e-2, 1e-4)  # a failed mode is integrated again at rtol times these
#: and with this many times the steps each time: a tolerance already at the floor (1e-14)
#: cannot tighten, and a short wave of a film-lined tube that ran out of steps there fell
#: back to collocation at ~230 nodes a layer, 30-46 s an evaluation
RETRY_BUDGET = 5
#: of a larger batch of failed modes, these are retried first at each tighter tolerance;
#: when every one fails again, the rest go to collocation at once
RETRY_SAMPLE = 4


def _retry(state, modes, status, rtol, max_steps) -> Sample:
    """Targets of the modes whose integration failed (a step size underflow where the
    error estimate of a loose rtol misjudges a steep stretch of z~, or a chart lost):
    again at tighter tolerances (never looser; :func:`_tighter`), then by collocation at the
    nodes that resolve the mode and the state (:class:`CollocationTarget`), whose target has
    the same sign and the same zeros. ConvergenceError only if all of these fail, or where
    the state is not strongly elliptic (:func:`_lost_ellipticity`)."""
    f = _tighter(state, modes, rtol, max_steps)
    if not np.isnan(f).any():
        return Sample(f)
    colloc, todo, reason = CollocationTarget(rtol), np.flatnonzero(np.isnan(f)), ""
    lost = _lost_ellipticity(state)
    if lost:
        raise _not_elliptic(_failure(modes[todo[0]], status[todo[0]]), lost)
    for i in todo:
        row = modes[i : i + 1]
        reason = _failure(modes[i], status[i])
        try:
            nodes = colloc._nodes(state, row[0])
            value = collocation_targets(state, row, nodes=nodes)[0]
            f[i] = value * _kernel_sign(state, row, nodes)
        except (ArithmeticError, ValueError, np.linalg.LinAlgError):
            pass
        except CollocationTooLarge as exc:  # neither method resolves the mode here
            raise _beyond_both(reason, exc) from exc
        if not np.isfinite(f[i]):
            raise ConvergenceError(f"{reason}, also at tighter tolerances and by collocation")
    return Sample(f, todo.size, reason)


def _tighter(state, modes, rtol, max_steps) -> np.ndarray:
    """The kernel's targets of ``modes`` at the tighter tolerances rtol RETRY_TIGHTER (down
    to 1e-14) with RETRY_BUDGET times the steps each, NaN where every one fails.

    Where a tighter tolerance fails for every mode of a sample, the state is too stiff for
    the kernel at any tolerance (next to a Gent lock, whose moduli grow like 1 / margin^2,
    all 396 modes of a scan underflowed again at both, 42 s), and the others skip it.
    A mode that failed a tolerance otherwise than by running out of steps is not integrated
    again at that same tolerance (both levels are 1e-14 for rtol <= 1e-12) with more steps:
    the integration is deterministic, and only a step budget can change its end."""
    f = np.full(modes.shape[0], np.nan)
    code = np.full(modes.shape[0], MAX_STEPS)  # each mode's failure at the last level
    budget, last = max_steps, None
    for factor in RETRY_TIGHTER:
        todo = np.flatnonzero(np.isnan(f))
        tight = max(rtol * factor, 1e-14)
        budget *= RETRY_BUDGET
        tables = stack_tables([build_table(state, tol=Accuracy(tight).table)])
        again = (tight != last) | (code == MAX_STEPS)  # may this level end otherwise?
        last = tight
        sample, rest = todo[:RETRY_SAMPLE], todo[RETRY_SAMPLE:]
        for part in (sample, rest):
            go = part[again[part]]
            if go.size:
                f[go], code[go] = _serial(state, modes[go], tables, tight, budget)
            stiff = rest.size > 0 and np.isnan(f[sample]).all()
            if stiff:  # every mode of the sample failed: the others skip this level
                break
        if stiff or not np.isnan(f).any():
            break
    return f


def _lost_ellipticity(state) -> str:
    """'' or where the wall of ``state`` is not strongly elliptic, in words: a shear modulus
    along the axes below LOST of its layer's (basestate/ellipticity.py), or else, read by the
    short-wave problem in every direction of the face and with the field's block
    (halfspace.not_elliptic), a loss the axes do not show: an oblique wave's, or the
    permittivity's (a dielectric bilayer's inner layer, whose hoop permittivity turns
    negative at growth 2.029 while its six shear moduli stay above 0.17 of its own)."""
    if wall_shear(state).min() < LOST:
        return f"its shear modulus {softest(state)}"
    try:
        where = not_elliptic(state)
    except ConvergenceError:  # moduli whose half-space matrix overflows: nothing to add
        return ""
    if where is None:
        return ""
    return (
        f"layer {where[0]} at R = {where[1]:.6g}: a real wave vector solves its incremental"
        " equations there"
    )


def _not_elliptic(reason: str, lost: str) -> ConvergenceError:
    """The kernel's failure ``reason`` at a state that has lost strong ellipticity (``lost``
    says where, :func:`_lost_ellipticity`): no mode's target means anything there, and
    collocation's sign is noise (it changed with the node count, 40 to 120, at every state of
    check round 27's case 3-91, whose dip then had no sign change to refine: 'the bracketed
    root solve failed ... must have different signs'; +, -, +, - at 40, 56, 72, 100 nodes for
    the dielectric bilayer's (7, 4) at growth 2.2965, check round 24 D2), so none is read."""
    err = ConvergenceError(
        f"{reason}, also at tighter tolerances, at a state that is not strongly elliptic"
        f" ({lost}): no mode's target is computed there"
    )
    err.remedy = Remedy(
        "the tube loses strong ellipticity before this state: a critical value, if any, lies"
        " before it; ask for less load, growth or stretch"
    )
    return err


def _beyond_both(reason: str, exc: CollocationTooLarge) -> CollocationTooLarge:
    """The kernel's failure ``reason`` and collocation's refusal ``exc`` in one error, whose
    remedy does not send the user to either method."""
    err = CollocationTooLarge(f"{reason}, also at tighter tolerances, and {exc}")
    err.remedy = Remedy(
        "neither method resolves this mode here; for waves this short the exact short-wave"
        " limit, which every scan computes, is their bound",
        python="neither method resolves this mode here; for waves this short the exact"
        " short-wave limit (short_wave_limit) is their bound",
    )
    return err


def _failure(mode, status) -> str:
    """Why the kernel failed for ``mode`` (a row (m, n[, code])), in words."""
    return (
        f"impedance integration failed for mode (m, n) = ({mode[0]:g}, {mode[1]:g})"
        f" ({row_family(mode)}): {STATUS_TEXT[int(status)]}"
    )


#: The tube on which the kernel's stable signs of modes are read: they are the same on
#: every unloaded tube (docs/derivation.md section 3), so one evaluation serves every scan
#: and every fallback (bifurcation/march.py re-exports it).
SIGN_TUBE = Tube.uniform(outer_radius=1.4, length=1.0)


def _kernel_sign(state, row, nodes: int) -> float:
    """The factor that gives collocation's target at ``nodes`` the kernel's sign for the
    mode ``row``: the kernel's sign on an unloaded tube times collocation's on this tube's
    unloaded state, both stable. Collocation's sign there is +1 for one layer (normalised,
    collocation.stable_det_sign) but mode by mode for a layered tube, and the kernel's is
    mode by mode: without it a failed integration's fallback flipped the sign of (0, 3) and
    (5, 0) of an unloaded bilayer, a sign change where nothing bifurcates."""
    return _unloaded_sign(state.tube.reference(), tuple(map(float, row[0])), int(nodes))


@functools.lru_cache(maxsize=256)
def _unloaded_sign(reference: Tube, row: tuple, nodes: int) -> float:
    """:func:`_kernel_sign` of the mode ``row`` on the unloaded tube ``reference``,
    remembered: every fallback of a march asks it again for the same tube, mode and nodes
    (a bilayer's march collocated 126 states, 7 s of signs), and at a short wave's nodes
    it costs what the fallback's own value does (28 s for (3, 400) of a three-layer tube)."""
    mode = np.array([row])
    kernel = np.sign(impedance_targets(solve_base_state(SIGN_TUBE), mode, rtol=STABLE_SIGN)[0])
    if len(reference.layers) == 1:
        return float(kernel)
    unloaded = solve_base_state(reference)
    return float(kernel * np.sign(collocation_targets(unloaded, mode, nodes=nodes)[0]))


def _serial(state, modes, tables, rtol, max_steps) -> tuple[np.ndarray, np.ndarray]:
    """(targets, status codes) of ``modes`` by the kernel one by one at ``rtol``, the
    targets NaN where it fails."""
    if not modes.shape[0]:
        return np.zeros(0), np.zeros(0, dtype=np.int64)
    k = modes[:, 1] * math.pi / state.current_length
    m = np.ascontiguousarray(modes[:, 0])
    pairs = mode_pairs(modes)
    got, code, _ = target_serial(
        m, k, pairs, np.zeros(m.size, dtype=np.int64), tables, rtol, max_steps
    )
    return np.where(code == 0, got, np.nan), code


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
    """Collocation nodes (per layer) that resolve mode (m, n) through the wall to ``rtol``:
    enough for the mode's decay and for the base state's moduli, whichever needs more.

    * The decay. A mode varies through the wall like exp(-q x), x from 0 to 1 across it,
      with q = max(k (r_o - r_i), m ln(r_o / r_i)) (k = n pi / l); the Chebyshev
      coefficients of exp(-q (x + 1) / 2) fall like exp(-N^2 / q), so N = sqrt(q ln(1 /
      rtol)) + 4 nodes resolve it (the 4 cover the prefactor: q = 10 ... 1000, rtol = 1e-12,
      1e-8). Measured (Mooney-Rivlin alpha 0.7, Rbar_o = 3.765, L = 0.337, mode (0, 4),
      q = 347): the root is off by 1.4e-4 at 56 nodes, 3.4e-7 at 72, 2.3e-10 at 88, below
      1e-12 at 104 (here: 102).
    * The moduli. Collocation samples the equations' coefficients at its nodes, so it is no
      better than their interpolation: N is at least the Chebyshev coefficients a layer's
      moduli need to fall below ``rtol`` (radial_table.build_table). Next to a lock they
      are steep for a long wave too: a Gent tube (J_m 2.559, Rbar_o = L = 1.541, growth
      1.792, lambda_z 2.761, mode (5, 5)) whose inner face is 0.2 % short of its lock needs
      221 at 1e-12 (the decay: 11); its voltage root by collocation is off by 3.4e-3 at 40
      nodes, 9.3e-9 at 180, 1.1e-10 at 221, against the impedance kernel's 3.135888372183.
    """
    k = n * math.pi / state.current_length
    q = max(k * (state.r_o - state.r_i), m * math.log(state.r_o / state.r_i))
    decay = math.ceil(math.sqrt(q * math.log(1.0 / rtol))) + 4
    return max(decay, build_table(state, tol=max(rtol, 1e-15)).coef.shape[2])


@dataclasses.dataclass(frozen=True)
class ImpedanceTarget:
    """The impedance kernel's target f(state, modes) at ``rtol`` (:func:`impedance_targets`):
    a named, picklable function of a base state and a batch of modes."""

    rtol: float = 1e-12
    max_steps: int = 20000

    def __call__(self, state, modes) -> np.ndarray:
        return impedance_targets(state, modes, rtol=self.rtol, max_steps=self.max_steps)

    def sample(self, state, modes) -> Sample:
        """The values with the modes that went to collocation (:func:`impedance_sample`)."""
        return impedance_sample(state, modes, rtol=self.rtol, max_steps=self.max_steps)

    def parts(self, state, modes) -> tuple[np.ndarray, np.ndarray]:
        """(f, log_norm): f and the log of what it divides out (:func:`analytic_parts`)."""
        return analytic_parts(state, modes, rtol=self.rtol, max_steps=self.max_steps)


@dataclasses.dataclass(frozen=True)
class CollocationTarget:
    """The collocation target f(state, modes), mode by mode, at Accuracy(rtol)'s nodes or
    more for a mode whose decay through the wall or whose base state's moduli need them
    (:func:`resolving_nodes`);
    ``coarse``: at 3/4 of those nodes (:func:`coarse_targets_for`)."""

    rtol: float = 1e-12
    coarse: bool = False

    def __call__(self, state, modes) -> np.ndarray:
        modes = np.atleast_2d(np.asarray(modes, dtype=float))
        return np.array(
            [
                collocation_targets(state, row[None], nodes=self._nodes(state, row))[0]
                for row in modes
            ]
        )

    def _nodes(self, state, row) -> int:
        """The nodes resolving the mode of ``row`` (m, n[, code]) at this rtol."""
        nodes = Accuracy(self.rtol).collocation_nodes
        nodes = max(nodes, resolving_nodes(state, row[0], row[1], self.rtol))
        return 3 * nodes // 4 if self.coarse else nodes


#: targets(state, modes (k, 2) or (k, 3) array) -> (k,) array of target values
Target = ImpedanceTarget | CollocationTarget


def targets_for(method: str, rtol: float) -> Target:
    """The target f(state, modes) of ``method`` at ``rtol``: an :class:`ImpedanceTarget` or a
    :class:`CollocationTarget`."""
    if check_method(method) is Method.IMPEDANCE:
        return ImpedanceTarget(rtol)
    return CollocationTarget(rtol)


def coarse_targets_for(method: str, rtol: float) -> Target:
    """The second resolution of ``targets_for(method, rtol)``, whose root's distance from that
    target's root is the error estimate of a critical value: the impedance kernel at 100 rtol,
    collocation at 3/4 of its nodes. Collocation at 100 rtol could take the same nodes (the
    floor of Accuracy.collocation_nodes or a mode's resolving nodes): the "error estimate" of
    a film 1e4 times as stiff was then Brent's tolerance, 2e-10 for a value 2e-6 off, OK."""
    if check_method(method) is Method.IMPEDANCE:
        return ImpedanceTarget(100.0 * rtol)
    return CollocationTarget(rtol, coarse=True)


def collocation_stable_signs(tube, modes) -> np.ndarray:
    """The signs of :func:`collocation_targets` of ``modes`` on the unloaded ``tube``, where
    every mode is stable: +1 for one layer (the determinant is normalised by
    ``collocation.stable_det_sign``), else evaluated there, mode by mode."""
    modes = np.asarray(modes)
    if len(tube.layers) == 1:
        return np.ones(len(modes))
    state = solve_base_state(tube.reference())
    return np.sign([collocation_targets(state, row[None, :])[0] for row in modes])
