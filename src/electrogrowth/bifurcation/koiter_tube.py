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

from ..basestate.tube import solve_base_state
from ..errors import ConvergenceError, NoBifurcationFound, ParameterError
from ..incremental.dielectric_forms import DielectricForms
from ..incremental.meridian_forms import MeridianForms
from ..incremental.polar_forms import PolarForms, rings
from ..model.layers import Tube
from ..outcomes import Kind
from .control_derivative import Reach, derivative, derivative_and_noise, reach
from .critical import critical_value
from .koiter_film import MODE, _nearest_zero
from .koiter_force import AxialFreedom, axial_freedom

#: The correction's harmonics 0 and 2: the even field (u_r), the pressure, and the odd
#: field at harmonic 2 (the odd field of harmonic 0 is a rigid motion, or no field at all).
SECOND = ((0, 0), (0, 2), (1, 2), (2, 0), (2, 2))


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
    """(c, phi): Newton's method on the eigenvalue of A(c) nearest zero, from ``start``,
    with the symmetric eigenvalue derivative phi^T A' phi; converged at a step below
    1e-12 s, or below 1e-9 s once the steps stop shrinking (the rounding floor of the
    eigenvalue, ~1e-11 s for a tube under a voltage), s = max(|c|, the control's scale):
    a pressure's critical value may be ~0, and its scale is the tube's modulus, not 1."""
    c, phi, last = start, None, np.inf
    for _ in range(20):
        sigma, phi = _nearest_zero(stiffness(c), phi)
        step = sigma / (phi @ derivative(stiffness, c, where) @ phi)
        c = _inside(c, c - step, what, where)
        scale = max(where.scale, abs(c))
        if abs(step) < 1e-12 * scale or (abs(step) < 1e-9 * scale and abs(step) > last / 2):
            return c, _nearest_zero(stiffness(c), phi)[1]
        last = abs(step)
    raise ConvergenceError(f"the critical {what} did not converge")


def _inside(c: float, new: float, what: str, where: Reach) -> float:
    """Newton's next iterate ``new``, or a ConvergenceError where it leaves the range of the
    control where the state exists: the discrete stiffness is singular there only because
    it does not resolve the mode, and the state there is not the user's input (the
    24-node rings of a film 0.001 thick and 1e4 times as stiff stepped from a growth 1.032
    to -0.08, and the tube's refusal of that growth was reported as the user's error)."""
    if where.lo < new < where.hi:
        return new
    raise ConvergenceError(
        f"the amplitude equation's expansion of the critical {what} did not converge:"
        f" Newton's method on its discrete stiffness stepped from {c:.12g} to {new:.12g},"
        f" outside the control's range ({where.lo:g}, {where.hi:g}), so the discretisation"
        " does not resolve this mode"
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
    c, phi = singular_point(A, start, what, where)
    phi = phi / first.peak_radial(phi, first.slices[0])[1]
    state = solve_base_state(tube.at(control, c))
    f1 = first.fields(phi)
    L = second.lagrangian(state)
    A2 = second.hessian(L[2])
    psi = np.linalg.solve(A2, -second.gradient(L[3], f1))
    quartic = first.energy(L[4], f1)  # E4(phi) = D[phi, phi, phi, phi] / 24
    numerator = 2 * (psi @ A2 @ psi) - 4 * quartic
    axial = None
    if tube.control == "force":  # the (0, 0) correction's freedom in lambda_z
        axial = axial_freedom(tube, control, c, first.stiffness, phi)
        numerator += axial.term
    c2, error = slope_ratio(numerator, A, c, phi, where)  # A' along the path (force or stretch)
    radial = phi[first.slices[0]]  # u_r on the rings, from R_i to R_N
    inner, outer = float(radial[0]), float(radial[-1])
    return TubeExpansion(float(c), c2, float(start), inner, float(numerator), axial, outer, error)


def slope_ratio(numerator: float, stiffness, c: float, phi, where: Reach) -> tuple[float, float]:
    """(c_2, its change with A''s difference steps halved plus that with them shifted) =
    numerator / A'(c)[phi, phi]: the truncation and the rounding of A' enter c_2 relative,
    and are part of its error estimate (control_derivative.derivative_and_noise)."""
    derivatives = derivative_and_noise(stiffness, c, where)
    slope, *changes = (float(phi @ d @ phi) for d in derivatives)
    c2 = numerator / slope
    return float(c2), sum(abs(c2 * change / slope) for change in changes)
