"""A critical value is certified relative to itself, not to max(1, |value|).

The rule was absolute below 1: a film's critical pressure of 2.9e-6 at rtol 1e-12 was "ok"
with an error estimate of 1.2e-7 of itself, an Euler force of -2.4e-3 "ok" at rtol 1e-14
while known to ~1e-8 of itself (tests/bifurcation/test_critical_estimate.py). Only a load
within ZERO_LOAD of its control's natural scale (one crossing zero) is measured against
that floor.
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from electrogrowth import Layer, Tube
from electrogrowth.incremental.accuracy import CERTIFIED, ZERO_LOAD, certified
from electrogrowth.model.controls import natural_scale


@given(
    st.floats(1e-9, 1e9),
    st.floats(1e-14, 1e-4),
    st.floats(0.0, 1e6),
    st.sampled_from([-1.0, 1.0]),
)
def test_relative_to_the_value_above_the_floor(value, rtol, ratio, sign):
    natural = 1.0 if value > ZERO_LOAD else value / (2 * ZERO_LOAD)  # the value above it
    bound = CERTIFIED * rtol * value
    assert certified(bound * (1 - 1e-12), sign * value, rtol, natural)
    assert not certified(bound * (1 + 1e-9), sign * value, rtol, natural)


def test_a_vanishing_value_against_its_controls_floor():
    assert certified(CERTIFIED * 1e-12 * ZERO_LOAD * 3.0, 0.0, 1e-12, 3.0)
    assert not certified(CERTIFIED * 1e-12 * ZERO_LOAD * 3.1, 0.0, 1e-12, 3.0)


def test_natural_scales_of_the_controls():
    tube = Tube((Layer(1.2, shear_modulus=2.0), Layer(1.5, shear_modulus=0.5)))
    hoop = 2.0 * math.log(1.2) + 0.5 * math.log(1.5 / 1.2)
    assert natural_scale(tube, "pressure") == hoop
    assert math.isclose(natural_scale(tube, "force"), math.pi * (2.0 * 0.44 + 0.5 * 0.81))
    assert natural_scale(tube, "growth") == natural_scale(tube, "stretch") == 1.0
    assert natural_scale(Tube.uniform(1.4), "voltage") == 1.0
