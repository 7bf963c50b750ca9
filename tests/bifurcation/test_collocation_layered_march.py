"""Collocation marching on its own through a layered tube must not report a spurious sign
change of its determinant as a bifurcation (found by probing layered tubes, round 5).

docs/derivation-layered-modes.md L.3 describes the tube (R = 1, 1.5, 2, 2.5, moduli 0.2,
1, 0.2, growth of layer 2): the layered collocation matrix changes sign at g = 2.033 for mode
(0, 8) while the impedance of both methods is smooth there and the orthonormalised shooting
keeps the kernel's sign, "so the layered collocation is used ... to certify a root locally,
not to march on its own". But ``critical_value(..., method="collocation")`` does march on its
own: it returns g = 2.0324229442 for this tube (status INACCURATE, with an error estimate of
9.6e-4, i.e. three digits claimed), where the kernel finds no bifurcation of (0, 8) up to
g = 6. Probing found the same on random three-layer tubes: a collapse pressure of -222.574
(error estimate 8.9e-5) against the kernel's and the shooting twin's -3030.6605034664 (mode
(0, 10), 252 s), and, at rtol 1e-8, "already unstable at pressure = 0" for the same tube.
A reported root must be one of the kernel (its target changes sign within a few of the
estimates), or none be reported. ~45 s.
"""

import pytest

from electrogrowth import (
    ConvergenceError,
    Layer,
    NoBifurcationFound,
    Tube,
    critical_value,
)
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental.targets import impedance_targets, with_family
from tests.tubes import FOUR_LAYERS

L3_TUBE = Tube((Layer(1.5, shear_modulus=0.2), Layer(2.0), Layer(2.5, shear_modulus=0.2)))


def _kernel(g: float) -> float:
    state = solve_base_state(L3_TUBE.at("growth[2]", g))
    return float(impedance_targets(state, with_family(0, 8, "wrinkle"))[0])


@pytest.mark.slow
def test_layered_collocation_reports_a_root_of_the_kernel_or_none():
    try:
        c = critical_value(L3_TUBE, 0, 8, "growth[2]", method="collocation")
    except NoBifurcationFound:
        return
    wide = 10.0 * max(c.error_estimate, 1e-9 * abs(c.value))
    assert _kernel(c.value - wide) * _kernel(c.value + wide) < 0, (
        f"collocation reports g = {c.value!r} ({c.status}, estimate {c.error_estimate:.1e}),"
        " where the kernel's target keeps its sign"
    )


def test_layered_collocation_does_not_march_from_a_bracket_without_a_sign_change():
    """A bracket on which layered collocation keeps its sign is no licence to march (probe
    round 8a, D1): ``_solve`` fell back to marching collocation on its own, and here found
    its spurious g = 2.0324 of L.3. Now it says why it stops. ~10 s."""
    with pytest.raises(ConvergenceError, match="does not march on its own"):
        critical_value(L3_TUBE, 0, 8, "growth[2]", method="collocation", bracket=(1.5, 1.6))


@pytest.mark.slow
def test_layered_collocation_refinement_stays_at_the_kernel_root():
    """Refined at rtol / 100, layered collocation reused the bracket found at rtol (probe
    round 8a, D1). With more nodes the determinant kept its sign on it, ``_solve`` marched
    collocation on its own and returned its spurious root -0.0213702353 (status OK, estimate
    2.1e-9), where the kernel and the QR shooting twin give -0.0425203156122 (agreeing to
    1.3e-12). Now the bracket is found again about the kernel's root at each rtol
    (-0.0425202305, estimate 2.7e-6, INACCURATE). ~25 s."""
    tube = FOUR_LAYERS
    kernel = -0.0425203156122  # the kernel's and the shooting twin's root
    c = critical_value(tube, 2, 0, "pressure", side="compression", method="collocation")
    assert abs(c.value - kernel) <= c.error_estimate + 1e-12
