"""A voltage march whose branch ends at a Gent lock must still find an earlier wrinkle.

A stiff film (mu = 1) on a soft Gent substrate (mu = 0.01, jm = 27) under a radial voltage:
the voltage branch has no limit point, it runs to the substrate's lock (threshold kind
"locking"), where the base-state profile cannot be tabulated. Mode (11, 0) bifurcates well
before that, at Vbar = 0.146609015590: an independent solver (radial equilibrium of the
ideal dielectric by quadrature, Dorfmann-Ogden incremental equations in principal-stretch
moduli, shooting with Godunov orthonormalisation; it reproduces the paper's g_cr =
1.26611156226 of Tube.uniform(1.4, voltage=0.4)) puts its root at 0.14660901559012715, and
the package agrees to 1e-13 when given the bracket (0.12, 0.15). Without the bracket it
raised ConvergenceError("base-state profile on [1.02, 3.6] not resolved by Chebyshev degree
512"); scan_modes on this tube failed the same way.
"""

import pytest

from electrogrowth import Layer, Tube, critical_value, gent
from electrogrowth.errors import ConvergenceError

FILM_ON_GENT = Tube((Layer(1.02), Layer(3.6, shear_modulus=0.01, material=gent(27.0))), length=3.6)


@pytest.mark.xfail(
    raises=ConvergenceError,
    strict=True,
    reason=(
        "open: the march's path reaches the Gent lock, whose state it cannot resolve, and "
        "the error ends it before the bifurcation at 0.1466 is located (found by probing)"
    ),
)
def test_wrinkle_before_the_lock_is_found():
    crit = critical_value(FILM_ON_GENT, 11, 0, "voltage")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(0.14660901559012715, rel=1e-9)
