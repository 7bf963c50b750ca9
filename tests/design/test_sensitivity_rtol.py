"""A bad rtol is refused by the design functions as by critical_value (probe 8b, D6).

Before: design/sensitivity.py ``sensitivities`` built ``Accuracy(rtol)`` without
``check_rtol``, so rtol = nan, 10 or -1 gave dv/dthickness = 0.6030557695 instead of
0.6032703033 (3.6e-4 off, no error), and ``prescribe`` / ``prescribe_map`` passed their rtol
on unchecked after all their work."""

import math

import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_value, prescribe
from electrogrowth.design.prescribe_map import prescribe_map
from electrogrowth.design.sensitivity import sensitivities
from electrogrowth.errors import ParameterError

TUBE = Tube([Layer(1.2, shear_modulus=2.0), Layer(1.5196451821770036)], length=1.5, stretch=1.0)
BAD = (math.nan, 10.0, -1.0)


@pytest.mark.parametrize("rtol", BAD)
def test_sensitivities_refuse_a_bad_rtol(rtol):
    v = critical_value(TUBE, 1, 1, "voltage", rtol=1e-12).value
    with pytest.raises(ParameterError, match=rf"rtol = {rtol!r} is out of range; valid range"):
        sensitivities(TUBE, (1, 1), "voltage", v, rtol=rtol)


@pytest.mark.parametrize("rtol", BAD)
def test_prescribe_refuses_a_bad_rtol_before_its_work(rtol):
    with pytest.raises(ParameterError, match=rf"rtol = {rtol!r} is out of range"):
        prescribe(
            TUBE,
            "voltage",
            (1, 1),
            ("length", 1.0, 2.0),
            points=3,
            options=ScanOptions((0, 2), (1, 2)),
            rtol=rtol,
        )


@pytest.mark.parametrize("rtol", BAD)
def test_prescribe_map_refuses_a_bad_rtol_before_reading_the_map(rtol):
    # the check comes first, so no map is needed (None would fail on its first use)
    with pytest.raises(ParameterError, match=rf"rtol = {rtol!r} is out of range"):
        prescribe_map(TUBE, (1, 1), None, rtol=rtol)
