"""A thin stiff film whose energy text has a (I2 - 3)**2 term must not make the base state
untabulable.

A film 0.01 thick (mu 810) inside a tube to Rbar_o = 2.38, L = 4.08, compressed axially:
mode (0, 18) is critical at lambda_z = 0.98702350 for neo-Hookean layers and at 0.98702255
when both layers have the energy text (I1-3)/2 + 0.05*(I1-3)**2 + I5/2. With the text
(I1-3)/2 + 0.05*(I2-3)**2 + I5/2 (units check passes: mu = eps = 1; at a 1 % strain the
extra term is a few parts in a million of the neo-Hookean energy) it must be as close.

Found by probing: with that text in either layer, critical_value raises ConvergenceError
("base state not resolved by 1025 Chebyshev points on R in [1, 1.01]; the wall is too thick
or strained for the table"), in the root solve bracketing 0.9870225 or at the first step.
The same text on a uniform tube (lambda_z,cr = 0.3427) and on a film five times thicker
(0.9405) works.
"""

import pytest

from electrogrowth import Layer, Material, Tube, critical_value

I2_SQUARED = Material("i2-squared", "(I1-3)/2 + 0.05*(I2-3)**2 + I5/2")


@pytest.mark.parametrize(
    "film, substrate",
    [(I2_SQUARED, I2_SQUARED), (None, I2_SQUARED)],
    ids=["both-layers", "substrate-only"],
)
def test_thin_film_with_i2_squared_energy(film, substrate):
    film_layer = Layer(1.01, shear_modulus=810.0) if film is None else Layer(1.01, film, 810.0)
    tube = Tube((film_layer, Layer(2.38, substrate)), length=4.08, stretch=1.0)
    crit = critical_value(tube, 0, 18, "stretch")
    assert crit.kind == "bifurcation"
    assert crit.value == pytest.approx(0.98702350, abs=1e-3)
