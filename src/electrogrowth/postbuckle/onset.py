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

from ..errors import ConvergenceError, NoBifurcationFound, ParameterError, Remedy
from ..model.layers import Tube
from .harmonics import is_element_scale
from .inertia import count_below, multiplier_mask
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
    the positive ones and is missed. So the eigenvalues below the shift are counted first
    (inertia.py, Sylvester); if there are any, a Lanczos run asks for that many most negative
    nu = 1 / (lambda - shift), which are they, and the shift moves just below the lowest,
    until none is below."""
    K = section.reduced(section.tangent(x))
    M = section.reduced(section.M)
    multipliers = multiplier_mask(K, M)
    shift = SHIFT
    for _ in range(MAX_SHIFTS):
        A = (K - shift * M).tocsc()
        lu = spla.splu(A)
        opinv = spla.LinearOperator(K.shape, matvec=lu.solve, dtype=float)
        below = count_below(A, multipliers, lu)
        if below == 0:
            vals, vecs = spla.eigsh(K, k=2, M=M, sigma=shift, which="LM", OPinv=opinv)
            break
        k = min(below, K.shape[0] - 2)
        lowest = float(spla.eigsh(K, k=k, M=M, sigma=shift, which="SA", OPinv=opinv)[0].min())
        # just below it (shift-invert's natural use, well conditioned); any eigenvalue
        # still lower is counted and asked for again
        shift = lowest - MARGIN * max(1.0, abs(lowest))
    else:
        raise fe_error(
            ConvergenceError,
            f"the tangent's spectrum reaches below {shift:.3g} after {MAX_SHIFTS} lower shifts",
        )
    i = int(np.argmin(vals))
    if not vector:
        return float(vals[i])
    # one step of the shift-invert iteration sets the pressure and stream-function parts,
    # which the Lanczos vectors leave undetermined where M is singular (purification)
    v = lu.solve(M @ vecs[:, i])
    z = section.expand(v / np.sqrt(v @ (M @ v)))
    return float(vals[i]), z


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


def element_scale_remedy(section) -> Remedy:
    """postbuckle's own remedy where the FE onset is refused in a pattern of the elements'
    size (probe 12a D3: the scan's "raise --m-max / --n-max, try the other --side" named
    options postbuckle lacks). It names the count along the face now: left out, --hoop /
    --axial grows with --density, so "more across the wall (--density)" alone refined along
    the face as much and failed the same (probe 14d, D2: --density 20 and 40 both refused,
    --density 40 --axial 20 runs)."""
    flag, where = ("hoop", "sector") if section.kind == "section" else ("axial", "window")
    along, across = section.size.hoop // section.periods, sum(section.size.radial)
    why = (
        "the mixed elements lose stability under compression in patterns of their own size,"
        " the earlier the more elements along the face"
    )
    return Remedy(
        f"{why}: give fewer elements along the {where} than the {along} now (--{flag}), or"
        f" more across the wall than the {across} now (--density) with --{flag} {along} or"
        f" fewer given (left out, it grows with --density)",
        python=f"{why}: give fewer elements along the {where} than the {along} now"
        f" ({flag}=), or more across the wall than the {across} now (density=) with"
        f" {flag}={along} or fewer given (left out, it grows with density)",
    )


FINER_MESH = Remedy(
    "try a finer mesh (--density, --hoop or --axial)",
    python="try a finer mesh (density=, hoop= or axial=)",
)


def _unstable_before(section, x, control: str, c: float, guess: float) -> NoBifurcationFound:
    """The refusal of a path already unstable at ``c`` = 0.9 of the way to the linear onset
    ``guess``: in a pattern of the elements' size (the mesh's artefact), or in one the mesh
    resolves (another mode or a crease comes first)."""

    _, z = lowest_eigenvalue(section, x, vector=True)
    exc = NoBifurcationFound(
        f"the finite-element tube is already unstable at {control} = {c:.6g}, 0.9 of the way"
        f" to the linear onset {guess:.6g}"
    )
    if is_element_scale(section, z):
        exc.args = (f"{exc.args[0]}, in a pattern of the elements' size",)
        exc.remedy = element_scale_remedy(section)
    else:
        exc.args = (f"{exc.args[0]}, in a pattern the mesh resolves",)
        exc.remedy = Remedy(
            "another mode or a crease may come first (`electrogrowth critical` gives the"
            " verdict); else " + FINER_MESH.cli,
            python="another mode or a crease may come first (the critical point's verdict);"
            " else " + FINER_MESH.python,
        )
    return exc


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
        raise _unstable_before(section, states[c][0], control, c, guess)
    while lam > 0:
        # the secant's zero, 1 % of the span past it, at most 10 % of the span ahead
        zero = c - lam * (c - c_prev) / (lam - lam_prev) if lam != lam_prev else c + span
        ahead = np.clip(zero + 0.01 * span - c, *sorted((0.002 * span, 0.1 * span)))
        c_prev, lam_prev = c, lam
        c = c + float(ahead)
        if abs(c - start) > 2 * abs(span):
            exc = NoBifurcationFound(
                f"the finite-element tube's lowest eigenvalue does not change sign up to"
                f" {control} = {c:.6g}, twice the way to the linear onset {guess:.6g}"
            )
            exc.remedy = FINER_MESH
            raise exc
        lam = at(c)
        path.append((float(c), lam))
    value = so.brentq(at, c_prev, c, xtol=xtol, rtol=4 * np.finfo(float).eps)
    section.set_tube(tube.at(control, value))
    xv, _ = newton(section, states[min(states, key=lambda k: abs(k - value))][0], invariant=True)
    _, mode = lowest_eigenvalue(section, xv, vector=True)
    return FEOnset(float(value), xv, mode, tuple(sorted(path)))
