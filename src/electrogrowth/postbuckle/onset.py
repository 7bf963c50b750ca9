"""Where the finite-element cross-section loses stability on its unperturbed path: the
sign change of the lowest eigenvalue of the tangent stiffness restricted to the
incompressible displacements of the sector (the modes cos(j m Theta)).

The eigenproblem K z = lambda M z with M the L2 mass of the displacement alone: the
pressure and stream-function rows of M vanish, so their directions have infinite
eigenvalues, and the finite ones are those of the stiffness condensed onto the
displacements that keep det F_e = 1, the electric displacement at its minimum (the second
variation of the energy there). Solved by shift-invert Lanczos about a shift below the
spectrum.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.optimize as so
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..model.layers import Tube
from .newton import fe_error, loaded, newton

#: the first shift of the shift-invert eigensolver, units mu: below the lowest eigenvalues
#: met near onset; lowered when the spectrum reaches below it (a branch past a secondary
#: bifurcation, a stiff film whose eigenvalues scale with its modulus)
SHIFT = -0.5
#: a shift is lowered at most this many times
MAX_SHIFTS = 12
#: a lowered shift lies this fraction of the eigenvalue found below the last one
MARGIN = 0.01


def lowest_eigenvalue(section, x: np.ndarray, *, vector: bool = False):
    """The lowest eigenvalue of the tangent at ``x`` in the sector's subspace (and, with
    ``vector``, its eigenvector on all unknowns, zero on the prescribed ones, mass-normalised).

    Shift-invert Lanczos returns the eigenvalues nearest its shift, the lowest only when the
    shift lies below the whole spectrum: an eigenvalue far below it (a branch well past a
    period-doubling point: -100 mu and less for a stiff film) is farther from the shift than
    the positive ones and is missed. The factorisation of K - shift M tells whether the
    number of eigenvalues below the shift is odd (:func:`_odd_below`); then a second Lanczos
    run on it asks for the most negative nu = 1 / (lambda - shift), which is that eigenvalue,
    and the shift moves just below it, until none is below (an even number, two crossings
    between the same branch points, would go unseen)."""
    K = section.reduced(section.tangent(x))
    M = section.reduced(section.M)
    shift = SHIFT
    for _ in range(MAX_SHIFTS):
        lu = spla.splu((K - shift * M).tocsc())
        opinv = spla.LinearOperator(K.shape, matvec=lu.solve, dtype=float)
        vals, vecs = spla.eigsh(K, k=2, M=M, sigma=shift, which="LM", OPinv=opinv)
        if vals.min() < shift:
            below = float(vals.min())
        elif _odd_below(lu, section.multipliers):
            below = float(spla.eigsh(K, k=1, M=M, sigma=shift, which="SA", OPinv=opinv)[0][0])
        else:
            break
        # just below it (shift-invert's natural use, well conditioned); any eigenvalue
        # still lower is asked for again
        shift = below - MARGIN * max(1.0, abs(below))
    else:
        raise fe_error(
            ConvergenceError,
            f"the tangent's spectrum reaches below {shift:.3g} after {MAX_SHIFTS} lower shifts",
        )
    i = int(np.argmin(vals))
    if not vector:
        return float(vals[i])
    # one step of the shift-invert iteration sets the pressure and potential parts, which
    # the Lanczos vectors leave undetermined where M is singular (purification)
    v = lu.solve(M @ vecs[:, i])
    z = section.expand(v / np.sqrt(v @ (M @ v)))
    return float(vals[i]), z


def _odd_below(lu, multipliers: int) -> bool:
    """Whether an odd number of eigenvalues of K z = lambda M z lie below the shift of
    ``lu``, the LU factors of K - shift M. Far below the spectrum that matrix has exactly
    ``multipliers`` negative eigenvalues (the pressure's unknowns, which M does not weigh:
    the constraint's Schur complement; the stream function's block, also massless, is
    positive definite: the dielectric's energy is a minimum in D), so its determinant has
    the sign (-1)^multipliers; each eigenvalue below the shift flips it
    (Sylvester). The sign is read off the factors: the diagonal of U and the parities of
    the row and column permutations (L has a unit diagonal)."""
    negative = int(np.count_nonzero(lu.U.diagonal() < 0))
    flips = negative + _odd_permutation(lu.perm_r) + _odd_permutation(lu.perm_c)
    return (flips + multipliers) % 2 == 1


def _odd_permutation(perm: np.ndarray) -> int:
    """1 if ``perm`` is odd (its length minus its number of cycles is odd), else 0."""
    seen = np.zeros(len(perm), dtype=bool)
    cycles = 0
    for start in range(len(perm)):
        if not seen[start]:
            cycles += 1
            j = start
            while not seen[j]:
                seen[j] = True
                j = perm[j]
    return (len(perm) - cycles) % 2


def start_value(tube: Tube, control: str) -> float:
    """Where the unperturbed path starts: the ungrown tube (growth 1), no voltage, the inner
    pressure equal to the outer."""
    kind = tube.check_control(control).kind
    if kind == "growth":
        return 1.0
    if kind == "voltage":
        return 0.0
    if kind == "pressure":
        return tube.outer_pressure
    raise ParameterError(
        f"control {control!r} is not followed by the finite-element model; choose growth,"
        " growth[K], growth[K].theta, voltage or pressure"
    )


@dataclasses.dataclass(frozen=True)
class FEOnset:
    """The sign change of the lowest eigenvalue: ``value`` of the control, the state there
    ``x`` and the eigenvector ``mode`` (the critical mode on the mesh), the eigenvalues
    sampled on the march (``path``: control, eigenvalue)."""

    value: float
    x: np.ndarray
    mode: np.ndarray
    path: tuple[tuple[float, float], ...]


def fe_onset(
    section,
    tube: Tube,
    control: str,
    guess: float,
    *,
    steps: int = 4,
    xtol: float = 1e-10,
) -> FEOnset:
    """The control value where the lowest eigenvalue of ``section`` changes sign on the
    unperturbed path. The path is walked from the start value (:func:`start_value`) in
    ``steps`` equal steps to 0.9 ``guess`` (e.g. the package's linear onset: only the steps
    depend on it), then by secant predictions of the eigenvalue's zero (stepping 1 % of the
    span past it) until it changes sign, then Brent's method to ``xtol``.
    NoBifurcationFound if it has not changed sign by 2 ``guess``."""
    start = start_value(tube, control)
    x = loaded(section, tube.at(control, start), steps=3)
    states: dict[float, tuple[np.ndarray, float]] = {}

    def at(c: float) -> float:
        nonlocal x
        near = min(states, key=lambda k: abs(k - c)) if states else None
        x0 = states[near][0] if near is not None else x
        section.set_tube(tube.at(control, c))
        xc, _ = newton(section, x0, invariant=True)
        lam = lowest_eigenvalue(section, xc)
        states[c] = (xc, lam)
        return lam

    path = []
    span = guess - start
    for c in np.linspace(start, start + 0.9 * span, steps + 1)[1:]:
        path.append((float(c), at(float(c))))
    (c_prev, lam_prev), (c, lam) = path[-2], path[-1]
    if lam <= 0:
        raise NoBifurcationFound(
            f"the finite-element tube is already unstable at {control} = {c:.6g}, 0.9 of"
            " the way to the guessed onset (a guess past the onset, or a mesh unstable in"
            " modes of its elements' size: give a smaller guess, more steps or a finer mesh)"
        )
    while lam > 0:
        # the secant's zero, 1 % of the span past it, at most 10 % of the span ahead
        zero = c - lam * (c - c_prev) / (lam - lam_prev) if lam != lam_prev else c + span
        ahead = np.clip(zero + 0.01 * span - c, *sorted((0.002 * span, 0.1 * span)))
        c_prev, lam_prev = c, lam
        c = c + float(ahead)
        if abs(c - start) > 2 * abs(span):
            raise NoBifurcationFound(
                f"the lowest eigenvalue does not change sign up to {control} = {c:.6g}"
            )
        lam = at(c)
        path.append((float(c), lam))
    value = so.brentq(at, c_prev, c, xtol=xtol, rtol=4 * np.finfo(float).eps)
    section.set_tube(tube.at(control, value))
    xv, _ = newton(section, states[min(states, key=lambda k: abs(k - value))][0], invariant=True)
    _, mode = lowest_eigenvalue(section, xv, vector=True)
    return FEOnset(float(value), xv, mode, tuple(sorted(path)))
