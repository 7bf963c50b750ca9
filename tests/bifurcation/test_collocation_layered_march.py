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

from electrogrowth import Layer, NoBifurcationFound, Tube, critical_value
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental.targets import impedance_targets, with_family

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
