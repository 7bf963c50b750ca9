"""The amplitude equation with the axial force prescribed (docs/derivation-koiter.md, "The
axial force prescribed"): lambda_z is one more unknown, a uniform mean axial strain that
the mode's harmonics (zero mean) cannot excite at first order, so the mode, the critical
value and A(c) are the force path's own, and the numerator of

    c_2 = (2 A[psi, psi] - 4 E4(phi) + a_z^2 / (2 k)) / A_F'[phi, phi]

gains the (0, 0) correction's freedom in lambda_z: a_z = dA/dlambda_z [phi, phi] at fixed
control, k = dN/dlambda_z / (2 pi) the wall's axial stiffness at fixed control (N the
axial force; 2 pi because the forms average over theta), A_F' = dA/dc along the path at
fixed force."""

from __future__ import annotations

import dataclasses
import math

from ..basestate.tube import solve_base_state
from ..errors import ParameterError
from ..model.layers import Tube
from .control_derivative import Reach, derivative


@dataclasses.dataclass(frozen=True)
class AxialFreedom:
    """The (0, 0) correction's freedom in lambda_z at a critical state: ``slope`` a_z =
    dA/dlambda_z [phi, phi], ``stiffness`` k = dN/dlambda_z / (2 pi), both at fixed control;
    ``term`` = a_z^2 / (2 k), what the numerator of c_2 gains (>= 0 when k > 0)."""

    stretch: float
    slope: float
    stiffness: float

    @property
    def term(self) -> float:
        return self.slope**2 / (2 * self.stiffness)


def stretch_twin(tube: Tube, stretch: float) -> Tube:
    """``tube`` with its axial stretch prescribed at ``stretch`` instead of its force."""
    return dataclasses.replace(tube, stretch=float(stretch), axial_force=None)


def axial_freedom(tube: Tube, control: str, c: float, stiffness, phi) -> AxialFreedom:
    """a_z and k at the critical state c of ``tube`` (force prescribed): Richardson-
    extrapolated central differences in lambda_z of the stretch-prescribed twin's A
    (``stiffness``, a map from a base state to A) and axial force N; a one-line
    ParameterError when k <= 0 (the base state is not axially stable under its force, so
    the branch is not the one a dead load follows)."""
    twin = stretch_twin(tube.at(control, c), solve_base_state(tube.at(control, c)).stretch)
    lz = float(twin.stretch)

    def state(value):
        return solve_base_state(twin.at("stretch", value))

    where = Reach(lz, lo=0.0)  # lambda_z moves the state on its own scale, lz > 0
    slope = float(phi @ derivative(lambda v: stiffness(state(v)), lz, where) @ phi)
    k = float(derivative(lambda v: state(v).axial_force, lz, where)) / (2 * math.pi)
    if not k > 0:
        raise ParameterError(
            f"the axial stiffness dN/dlambda_z = {2 * math.pi * k:.6g} at lambda_z = {lz:.6g} "
            "is not positive: the state is not axially stable under its force"
        )
    return AxialFreedom(lz, slope, k)
