"""A table column is resolved relative to the size of the quantity it holds (probe 11b, D1).

A Yeoh energy without its square term, (I1-3)/2 + C3 (I1-3)^3, has moduli that vanish at the
unstrained state as O(I1 - 3) (6.7e-11 at Vbar = 0.004 for C3 = 0.01) but carry the rounding
of I1 ~ 3, of the layer's modulus. Measured against its own size (as the chop did), such a
column's Chebyshev tail is noise of 5e-8 of itself at every number of points: no table of the
tube at 1e-3 <= Vbar <= 4e-3 (the voltage march's first step) could be built, and voltage
control stopped at its start ("no mode bifurcates for voltage from 0 up to 0 ... base state
not resolved by 1025 Chebyshev points"). Measured against max(its size, the layer's modulus),
the noise is 1e-18 and the table is as small as at any other load.
"""

from __future__ import annotations

import numpy as np

from electrogrowth import Layer, Material, Tube
from electrogrowth.basestate.tube import solve_base_state
from electrogrowth.incremental import radial_table
from electrogrowth.model.moduli import MODULI_NAMES

CUBIC = Material("y", "(I1-3)/2 + 0.01*(I1-3)^3 + I5/2")  # Yeoh, C2 = 0
QUARTIC_I2 = Material("q", "(I1-3)/2 + 1e-6*(I2-3)^4 + I5/2")


def _width(tube, voltage):
    return radial_table.build_table(solve_base_state(tube.at("voltage", voltage))).coef.shape[-1]


def test_table_of_a_cubic_tube_at_a_small_voltage():
    """Raised ConvergenceError (1025 points) at Vbar = 1e-3 and 4e-3; now it needs no more
    coefficients than at Vbar = 0.02, where the vanishing moduli are 25 times larger."""
    tube = Tube.uniform(2.0, length=1.0, material=CUBIC)
    wide = _width(tube, 0.02)
    assert _width(tube, 1e-3) <= wide and _width(tube, 4e-3) <= wide


def test_table_of_a_layered_tube_with_a_quartic_layer_at_a_small_voltage():
    """The same in a layer of a layered tube (its energy O((I2 - 3)^3) past the neo-Hookean
    part): raised ConvergenceError at Vbar = 4e-3."""
    tube = Tube([Layer(1.1, shear_modulus=10.0), Layer(2.0, material=QUARTIC_I2)], length=1.0)
    assert _width(tube, 4e-3) <= _width(tube, 0.02)


def test_column_units_are_the_layer_moduli_in_table_units():
    """A and p in mu_k / mu_ref, K in eps_ref / eps_k; G (odd in D, so its rounding is
    relative to itself) and r, w (positive) against their own size."""
    unit = radial_table._layer_units(10.0, 2.0, 1.0, 4.0)
    family = np.array([name[0] for name in MODULI_NAMES] + ["p", "r", "w"])
    assert np.all(unit[family == "A"] == 10.0) and unit[family == "p"] == 10.0
    assert np.all(unit[family == "K"] == 2.0)
    assert np.all(unit[(family == "G") | (family == "r") | (family == "w")] == 0.0)
