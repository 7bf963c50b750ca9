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

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.incremental.accuracy import CERTIFIED, ZERO_LOAD, certified
from electrogrowth.model.controls import natural_scale
from electrogrowth.outcomes import Status


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


def _ring(c):
    """A thin ring under suction: P_cr ~ -c (h / R)^3 (the thin-ring formula 3 D / R^3)."""
    return Tube([Layer(1.01, shear_modulus=c)], length=1.0)


def test_a_small_pressure_off_by_2e_4_is_not_ok():
    """Probe round 12b, D1: collocation's -9.8537e-7 was "ok" at the default rtol, 1.8e-4 off
    the impedance value (the same at rtol 1e-8 to 1e-14; the thin-ring formula and its
    (3, 0) to (5, 0) ratios 8/3, 5, 8 agree): its estimate, 2.2e-4 of itself, was honest."""
    ref = critical_value(_ring(1.0), 2, 0, "pressure", side="compression")
    col = critical_value(_ring(1.0), 2, 0, "pressure", side="compression", method="collocation")
    assert abs(col.value - ref.value) > 1e-5 * abs(ref.value)
    assert ref.status == Status.OK and col.status == Status.INACCURATE


def test_the_status_does_not_depend_on_the_unit_of_the_moduli():
    """Probe round 12b, D1: the same ring was ok with its moduli times 1e-3 and 1, inaccurate
    times 1e3 (the rule's 1 is in units of mu)."""
    statuses = {
        critical_value(_ring(c), 2, 0, "pressure", side="compression", method="collocation").status
        for c in (1e-3, 1.0, 1e3)
    }
    assert statuses == {Status.INACCURATE}
