"""The Koiter coefficient of a tube's mode in a control (docs/derivation-koiter.md):
the prismatic family (m, 0) on the polar forms, the axisymmetric family (0, n) on the
meridian forms; both refine the package's critical value where the discrete energy's
A(c) is singular, then solve for the second-order correction and

    c_2 = (2 A[psi, psi] - 4 E4(phi)) / A'[phi, phi],

E4 the quartic part of the energy, eps = max |u_r| / R_i."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import scipy.linalg

from .._types import FloatArray
from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.dielectric_forms import DielectricForms
from ..incremental.meridian_forms import MeridianForms
from ..incremental.monomial_forms import Polynomial
from ..incremental.polar_forms import PolarForms, rings
from ..incremental.ring_basis import nodal_values
from ..model.layers import Tube
from ..outcomes import Kind
from .control_derivative import Reach, derivative, derivative_and_noise, reach
from .critical import critical_value
from .koiter_film import MODE, _nearest_zero
from .koiter_force import AxialFreedom, axial_freedom

#: The correction's harmonics 0 and 2: the even field (u_r), the pressure, and the odd
#: field at harmonic 2 (the odd field of harmonic 0 is a rigid motion, or no field at all).
SECOND = ((0, 0), (0, 2), (1, 2), (2, 0), (2, 2))
#: an eigenvalue of A at most this times its 1-norm is zero to rounding (a symmetric
#: eigensolver's error is ~n eps |A|; the kernel's restriction adds a few eps)
EIGEN_FLOOR = 8 * np.finfo(float).eps


@dataclasses.dataclass(frozen=True)
class TubeExpansion:
    """The expansion of a tube's mode in a growth control c: c = c_c + coefficient eps^2,
    eps = max_R |u_r| / R_i of the mode (R_i = 1)."""

    control_value: float
    coefficient: float
    impedance_value: float
    inner_face: float  # u_r of the mode at R_i over its peak
    numerator: float = math.nan  # 2 A[psi, psi] - 4 E4(phi) (+ a_z^2 / (2 k) at a force)
    axial: AxialFreedom | None = None  # the force prescribed: lambda_z's freedom
    outer_face: float = math.nan  # u_r of the mode at R_N over its peak
    derivative_error: float = 0.0  # |c_2|'s changes when A''s difference steps are halved, shifted


def singular_point(stiffness, start: float, what: str, where: Reach):
    """(c, phi): the control where A(c) is singular, and its null vector, from ``start``.

    First Newton's method on the eigenvalue of the saddle-point A nearest zero (inverse
    iteration from the last mode), kept where its null vector is the mode of the
    displacement stiffness on the constraint's kernel (:func:`constrained_nearest_zero`):
    its eigenvalue carries the least rounding. Where it is not (a thin stiff film, whose
    pressure modes have eigenvalues ~1e-10 at |A| ~ 2e9, nearer zero than the fold's), or
    where that Newton fails, Newton's method on the kernel's eigenvalue itself."""
    try:
        c, phi, A = _newton(stiffness, start, what, where, _nearest_zero)
        if _same_mode(A, phi):
            return c, phi
    except ConvergenceError:
        if not _pressures(stiffness(start)).size:
            raise
    return _newton(stiffness, start, what, where, constrained_nearest_zero)[:2]


def _newton(stiffness, start: float, what: str, where: Reach, nearest):
    """(c, phi, A(c)): Newton's method on the eigenvalue ``nearest(A, last phi)`` gives,
    with the symmetric eigenvalue derivative phi^T A' phi; converged at a step below
    1e-12 s, or below 1e-9 s once the steps stop shrinking (the rounding floor of the
    eigenvalue, ~1e-11 s for a tube under a voltage), s = max(|c|, the control's scale):
    a pressure's critical value may be ~0, and its scale is the tube's modulus, not 1.
    Where no step test is met in 20 iterations, the iterate of the smallest |sigma| if
    that is zero to A's rounding (EIGEN_FLOOR): a slender tube's bending mode (1, 1) at
    L = 80 has a slope so small that sigma ~ 1e-13 at |A| ~ 1e3 steps c by > 1e-9 s back
    and forth (check round 23)."""
    c, phi, last = start, None, np.inf
    best = (np.inf, None)  # (|sigma| / its rounding, the iterate)
    for _ in range(20):
        A = stiffness(c)
        sigma, phi = nearest(A, phi)
        best = min(best, (abs(sigma) / (EIGEN_FLOOR * np.linalg.norm(A, 1)), (c, phi, A)),
                   key=lambda b: b[0])  # fmt: skip
        step = sigma / (phi @ derivative(stiffness, c, where) @ phi)
        c = _inside(c, c - step, what, where)
        scale = max(where.scale, abs(c))
        if abs(step) < 1e-12 * scale or (abs(step) < 1e-9 * scale and abs(step) > last / 2):
            A = stiffness(c)
            return c, nearest(A, phi)[1], A
        last = abs(step)
    if best[0] <= 1.0:
        return best[1]
    raise ConvergenceError(f"the critical {what} did not converge")


def null_vector(A: FloatArray, last: FloatArray) -> FloatArray:
    """The mode of A nearest ``last`` as :func:`singular_point` finds it: the saddle's
    eigenvector nearest zero where it is the kernel's mode, else the kernel's."""
    phi = _nearest_zero(A, last)[1]
    return phi if _same_mode(A, phi) else constrained_nearest_zero(A, last)[1]


def _pressures(A: FloatArray) -> np.ndarray:
    """The pressure unknowns of a saddle-point A: its rows zero on their own block (the
    energy is linear in q: exactly zero, not small) and not on the displacements; empty
    when there are none (or A is not such a saddle)."""
    P = np.flatnonzero(np.diag(A) == 0)
    if P.size == 0 or np.any(A[np.ix_(P, P)] != 0) or not np.all(np.any(A[P] != 0, axis=1)):
        return np.empty(0, dtype=int)
    return P


def _same_mode(A: FloatArray, phi: FloatArray) -> bool:
    """Whether the saddle's null vector ``phi`` is the kernel's mode: their displacements
    parallel (0.99); True for a stiffness without pressures."""
    P = _pressures(A)
    if P.size == 0:
        return True
    mode = constrained_nearest_zero(A)[1]
    U = np.setdiff1d(np.arange(len(phi)), P)
    u, v = phi[U], mode[U]
    return bool(abs(u @ v) > 0.99 * np.linalg.norm(u) * np.linalg.norm(v))


def constrained_nearest_zero(A: FloatArray, last: FloatArray | None = None):
    """(sigma, phi): the eigenvalue nearest zero of the stiffness restricted to ker B, B the
    incompressibility constraint, and its extension phi = (u, q) to the saddle point
    A = [[K, B^T], [B, 0]] (u = Z y, y the unit eigenvector of Z^T K Z, Z an orthonormal
    basis of ker B; q the pressure that balances the rest of K u: B^T q = -(K u - sigma u)),
    so that d sigma / dc = phi^T A' phi (docs/derivation-koiter.md, "A thin stiff film").
    With ``last`` (the previous iterate's phi), the eigenvalue among the three nearest zero
    whose mode is most nearly parallel to it: Newton follows one mode.

    The saddle's own eigenvalue nearest zero may be no displacement mode: its pressure
    modes have eigenvalues ~ -s_B^2 / |K|, for a film 1e4 times as stiff as its substrate
    ~1e-10 at |A| ~ 2e9, nearer zero than the fold's, and Newton followed one."""
    P = _pressures(A)
    if P.size == 0:
        return _nearest_zero(A, last)
    U = np.setdiff1d(np.arange(len(A)), P)
    B = A[np.ix_(P, U)]
    rows = 1.0 / np.linalg.norm(B, axis=1)  # the film's rows are ~1e4 times the substrate's
    Q, R = np.linalg.qr((rows[:, None] * B).T, mode="complete")
    Z = Q[:, P.size :]
    KZ = A[np.ix_(U, U)] @ Z
    w, Y = np.linalg.eigh(Z.T @ KZ)
    i = _followed(w, Z @ Y, None if last is None else last[U])
    u = Z @ Y[:, i]
    rest = KZ @ Y[:, i] - w[i] * u  # K u's part outside ker B, = -B^T q
    q = -rows * scipy.linalg.solve_triangular(R[: P.size], Q[:, : P.size].T @ rest)
    phi = np.empty(len(A))
    phi[U], phi[P] = u, q
    return float(w[i]), phi


def _followed(w: FloatArray, modes: FloatArray, last: FloatArray | None) -> int:
    """The index of the eigenvalue nearest zero, or with ``last`` of the one among the
    three nearest whose mode is most nearly parallel to it."""
    near = np.argsort(np.abs(w))[:3]
    if last is None:
        return int(near[0])
    return int(max(near, key=lambda k: abs(modes[:, k] @ last)))


def _inside(c: float, new: float, what: str, where: Reach) -> float:
    """Newton's next iterate ``new``, or a ConvergenceError where it leaves the range of the
    control where the state exists: the state there is not the user's input (Newton on a
    pressure mode of a film 0.001 thick and 1e4 times as stiff stepped from a growth 1.032
    to -0.08, and the tube's refusal of that growth was reported as the user's error)."""
    if where.lo < new < where.hi:
        return new
    raise ConvergenceError(
        f"the amplitude equation's expansion of the critical {what} did not converge:"
        f" Newton's method on its discrete stiffness stepped from {c:.12g} to {new:.12g},"
        f" outside the control's range ({where.lo:g}, {where.hi:g}), so it did not follow"
        " this mode"
    )


def tube_expansion(
    tube: Tube, m: int, control: str, *, nodes: int = 24, side: str | None = None
) -> TubeExpansion:
    """The Koiter coefficient of the prismatic mode (m, 0) of a tube at fixed axial
    stretch, in any control that moves its base state: the forms of
    incremental/polar_forms.py (any strain energy, to fourth order), the correction at
    harmonics 0 and 2m; under a voltage (or in the voltage control)
    :func:`dielectric_expansion`."""
    if tube.voltage != 0 or control == "voltage":
        return dielectric_expansion(tube, m, control, nodes=nodes, side=side)
    cut = rings(tube, m, nodes)
    first = PolarForms.build(cut, m, MODE)
    second = PolarForms.build(cut, m, SECOND)
    start = onset_value(tube, (m, 0), control, side)
    return expand(tube, control, first, second, start, f"{control} of mode ({m}, 0)")


def onset_value(tube: Tube, mode: tuple[int, int], control: str, side: str | None) -> float:
    """The package's critical value of ``control`` for ``mode`` (the impedance route, rtol
    1e-12), where the expansion starts; NoBifurcationFound when the axisymmetric state is
    lost first (a voltage's threshold)."""
    point = critical_value(tube, *mode, control, side=side, rtol=1e-12)
    if point.kind != Kind.BIFURCATION:
        raise NoBifurcationFound(
            f"mode {mode}: no bifurcation in {control} ({point.kind} at {point.value:.6g} first)"
        )
    return point.value


def axial_wavenumber(tube: Tube, n: int) -> float:
    """K = n pi / L in the reference Z: the package's k = n pi / (lambda_z L) times
    lambda_z (incremental/targets.wavenumber)."""
    return n * math.pi / tube.length


def axisymmetric_expansion(
    tube: Tube, n: int, control: str, *, nodes: int = 24, side: str | None = None
) -> TubeExpansion:
    """The Koiter coefficient of the axisymmetric mode (0, n) of a tube at fixed axial
    stretch, in any control that moves its base state: the forms of
    incremental/meridian_forms.py (any strain energy),
    the correction at harmonics 0 and 2 (of K Z), and the quartic term of the constraint."""
    K = axial_wavenumber(tube, n)
    cut = rings(tube, max(K, 1.0), nodes)
    first = MeridianForms.build(cut, K, MODE)
    second = MeridianForms.build(cut, K, SECOND)
    start = onset_value(tube, (0, n), control, side)
    return expand(tube, control, first, second, start, f"{control} of mode (0, {n})")


def dielectric_expansion(
    tube: Tube, m: int, control: str, *, nodes: int = 24, side: str | None = None
) -> TubeExpansion:
    """The Koiter coefficient of the prismatic mode (m, 0) of a tube of ideal dielectrics
    under its radial voltage, in any control: the forms of
    incremental/dielectric_forms.py (the potential phi an extra field, a quartic term)."""
    cut = rings(tube, m, nodes)
    first = DielectricForms.build(cut, m, MODE + ((3, 1),))
    second = DielectricForms.build(cut, m, SECOND + ((3, 0), (3, 2)))
    start = onset_value(tube, (m, 0), control, side)
    return expand(tube, control, first, second, start, f"{control} of mode ({m}, 0)")


def expand(tube, control, first, second, start, what) -> TubeExpansion:
    """c_2 = (2 A[psi, psi] - 4 E4(phi)) / A'[phi, phi] on monomial forms: the critical
    value refined where A(c) is singular, the mode scaled to max |u_r| = 1, the correction
    A psi = -C[phi, phi, .] / 2 = -grad E3(phi) on ``second``'s harmonics.

    The forms are the wall's alone: a face pressure (a follower load) would be left out,
    so a pressurised tube or the pressure control is refused here (koiter_loads.py holds
    their expansion; koiter.koiter_coefficient picks it)."""
    if tube.inner_pressure != 0 or tube.outer_pressure != 0 or control == "pressure":
        raise ParameterError(
            f"the expansion of the wall alone leaves out the face pressures (P_i ="
            f" {tube.inner_pressure:g}, P_o = {tube.outer_pressure:g}, control {control}):"
            " use koiter_coefficient, which includes them"
        )

    def A(c):
        return first.stiffness(solve_base_state(tube.at(control, c)))

    where = reach(tube, control)
    quadratic = quadratic_part(tube, control, lambda state: first.lagrangian(state)[2])

    def energy(polynomial, phi):  # at phi's local fields: E2(phi) = phi^T A phi / 2
        return first.energy(polynomial.monomials(), first.fields(phi))

    c, phi = singular_point(A, start, what, where)
    c, phi = on_the_energy(A, quadratic, energy, c, phi, where, what)
    phi, f1, numerator = _numerator(tube, control, first, second, c, phi)
    rounding = numerator_rounding(
        lambda x, v: _numerator(tube, control, first, second, x, v)[2],
        *(numerator, A, c, phi, where),
    )
    axial = None
    if tube.control == "force":  # the (0, 0) correction's freedom in lambda_z
        axial = axial_freedom(tube, control, c, first.stiffness, phi)
        numerator += axial.term
    c2, error = slope_ratio(  # A' along the path (force or stretch), term by term
        numerator,
        quadratic,
        c,
        phi,
        where,
        along=lambda d: 2 * first.energy(d.monomials(), f1),
    )
    error += abs(c2 * rounding / numerator) if numerator else 0.0
    # u_r at the nodes, from R_i to R_N (the unknowns are each ring's differences)
    radial = nodal_values(first.rings, phi[first.slices[0]])
    inner, outer = float(radial[0]), float(radial[-1])
    return TubeExpansion(float(c), c2, float(start), inner, float(numerator), axial, outer, error)


def on_the_energy(A, quadratic, energy, c: float, phi, where: Reach, what: str):
    """(c, phi) refined by Newton's method on the Rayleigh quotient phi^T A(c) phi of the
    null vector phi of A(c), evaluated as the energy 2 E2(phi) (``energy(quadratic(c),
    phi)``: the quadratic part's Polynomial at phi's local fields) with the slope 2 E2'(phi)
    from the Polynomial's differenced coefficients. The matrices' eigenvalue carries the
    rounding of A (~eps |A|, |A| ~ 1e11 for a thin stiff film at 40 nodes), where
    :func:`singular_point`'s Newton stops up to 1e-9 of the scale from the root (5e-10
    there, which moved c_2 by 7e-10 relative); the energy's rounding is that of its fields
    (docs/derivation-koiter.md, "The singular point on the energy"). A first step longer
    than 1e-8 of the scale (10 times Newton's own tolerance) would not be the same root:
    (c, phi) are kept as they came."""
    start, first_phi, slope = c, phi, None
    for _ in range(3):
        phi = null_vector(A(c), phi)
        if slope is None:
            slope = 2 * energy(derivative(quadratic, c, where), phi)
        step = 2 * energy(quadratic(c), phi) / slope if slope else 0.0
        scale = max(where.scale, abs(c))
        if abs(c - step - start) > 1e-8 * scale:
            return start, first_phi
        c = _inside(c, c - step, what, where)
        if abs(step) <= 1e-13 * scale:
            break  # phi, of c + step, is the null vector to ~1e-13
    return c, phi


def _numerator(tube, control, first, second, c, phi):
    """(phi scaled to max |u_r| = R_i, its local fields, 2 A[psi, psi] - 4 E4(phi)) at c,
    psi the correction of A psi = -grad E3(phi) on ``second``'s harmonics."""
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    state = solve_base_state(tube.at(control, c))
    f1 = first.fields(phi)
    L = second.lagrangian(state)
    A2 = second.hessian(L[2])
    psi = np.linalg.solve(A2, -second.gradient(L[3], f1))
    quartic = first.energy(L[4], f1)  # E4(phi) = D[phi, phi, phi, phi] / 24
    return phi, f1, float(2 * (psi @ A2 @ psi) - 4 * quartic)


#: the nudge of the control (over its scale) that resamples the numerator's rounding while
#: its true change stays ~1e-11 relative
NUDGE = 1e-11


def numerator_rounding(numerator, value: float, A, c: float, phi, where: Reach) -> float:
    """The change of ``numerator(c, phi)`` (``value`` at c) when c is nudged by NUDGE,
    phi then the null vector of A there: a sample of its rounding (the wall's expansion
    and the loaded one, koiter_loads.py). In nodal unknowns a thin stiff film's numerator
    (1e4 times as stiff as its substrate, 1e-3 thick) wandered by ~1e-5 relative with the
    node count and with c moved by 1e-11; in ring_basis.py's unknowns the change is
    ~2e-11, N's true change (d ln N / d ln c = -3), and for a thick tube ~1e-14."""
    nudged = c + NUDGE * max(abs(c), where.scale)
    return abs(numerator(nudged, null_vector(A(nudged), phi)) - value)


def quadratic_part(tube: Tube, control: str, monomials):
    """c -> the quadratic monomials ``monomials(state)`` of a Lagrangian at the base state of
    c, as a Polynomial (its coefficients differenced by :func:`slope_ratio`)."""

    def at(c: float) -> Polynomial:
        return Polynomial.of(monomials(solve_base_state(tube.at(control, c))))

    return at


def slope_ratio(
    numerator: float, stiffness, c: float, phi, where: Reach, *, along=None
) -> tuple[float, float]:
    """(c_2, its change with A''s difference steps halved plus that with them shifted) =
    numerator / A'(c)[phi, phi]: the truncation and the rounding of A' enter c_2 relative,
    and are part of its error estimate (control_derivative.derivative_and_noise).
    ``stiffness`` gives A(c); or, with ``along`` (a derivative -> A'[phi, phi]), the
    quadratic part of the Lagrangian (:func:`quadratic_part`), whose coefficients are
    differenced instead of the matrix: A'[phi, phi] = 2 E2'(phi)."""
    derivatives = derivative_and_noise(stiffness, c, where)
    if along is None:
        values = (float(phi @ d @ phi) for d in derivatives)
    else:
        values = (float(along(d)) for d in derivatives)
    slope, *changes = values
    c2 = numerator / slope
    return float(c2), sum(abs(c2 * change / slope) for change in changes)
