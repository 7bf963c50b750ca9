"""Newton's method on the free unknowns of a :class:`~.section.Section`, and the unperturbed
(axisymmetric) path: the state at a control value reached in steps from the unloaded one."""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError, Remedy

#: what to try when the finite-element Newton iteration fails
FE_REMEDY = Remedy(
    "take smaller steps (more --points, a smaller --amplitude) or a finer mesh (--density,"
    " --hoop)",
    python="take smaller steps (more points=, a smaller amplitude=) or a finer mesh"
    " (density=, hoop=)",
)


def fe_error(cls, message: str):
    """An exception of ``cls`` with the finite-element model's remedy."""
    exc = cls(message)
    exc.remedy = FE_REMEDY
    return exc


#: Newton stops when the free residual's max norm is below this (units mu R_i)
RESIDUAL_TOL = 1e-10
MAX_ITERATIONS = 25


def newton(
    section, x: np.ndarray, *, tol: float = RESIDUAL_TOL, invariant: bool = False
) -> tuple[np.ndarray, int]:
    """Solve residual(x) = 0 on the free unknowns from ``x`` (its prescribed entries are
    reset to the section's). Each step moves x in the columns B of ``section.P`` (all the
    unknowns) or, with ``invariant``, of ``section.invariant`` (the fields independent of Y:
    the unperturbed path from a state on it): B^T K B dy = -B^T r. Converged when the whole
    free residual is below ``tol`` (then the full model's equilibrium either way). Returns
    (x, iterations); ConvergenceError if it does not converge in MAX_ITERATIONS or the
    residual grows a thousandfold."""
    x = section.with_fixed(x)
    B = section.invariant if invariant else section.P
    r0 = None
    for it in range(MAX_ITERATIONS + 1):
        r = section.residual(x)
        norm = np.abs(section.restrict(r)).max()
        if not np.isfinite(norm):
            break
        if norm < tol:
            return x, it
        r0 = norm if r0 is None else r0
        if norm > 1e3 * max(r0, 1.0):
            break
        K = (B.T @ section.tangent(x) @ B).tocsc()
        x = x - B @ spla.spsolve(K, B.T @ r)
    raise fe_error(
        ConvergenceError,
        f"the finite-element equilibrium did not converge (residual {norm:.3g} after {it}"
        " Newton steps)",
    )


def unloaded(section) -> np.ndarray:
    """The unknowns of the undeformed, unloaded wall as Newton's start: u = 0, A = 0 and
    p = mu_k (the neo-Hookean stress mu_k I balanced by the pressure)."""
    x = np.zeros(section.basis.N)
    x[section.pressure_dofs] = [section.tube.layers[k].shear_modulus for k in section.layer_of]
    return section.with_fixed(x)


def loaded(section, tube, *, steps: int = 5) -> np.ndarray:
    """The unperturbed state of ``section`` at the loads and growth of ``tube``: from the
    unloaded wall (growth 1, no voltage, no pressure) by ``steps`` equal steps of every load
    and growth component together (the section is left at ``tube``)."""

    x = None
    for s in np.linspace(0.0, 1.0, steps + 1):
        layers = tuple(
            dataclasses.replace(la, growth=tuple(1.0 + s * (g - 1.0) for g in la.growth))
            if not la.graded
            else la
            for la in tube.layers
        )
        t = dataclasses.replace(
            tube,
            layers=layers,
            voltage=s * tube.voltage,
            inner_pressure=s * tube.inner_pressure,
            outer_pressure=s * tube.outer_pressure,
            stretch=1.0 + s * (tube.stretch - 1.0),
        )
        section.set_tube(t)
        x = unloaded(section) if x is None else x
        x, _ = newton(section, x, invariant=True)
    assert x is not None  # the loop runs at least once
    return x
