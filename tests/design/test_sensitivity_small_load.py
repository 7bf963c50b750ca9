"""Sensitivities at a small but non-zero load (probe 9b D3).

The difference step was 1e-4 |p| (design/sensitivity.py `relative_step`): at P_i = 1e-9 it
was 1e-13, and the central difference of D was its rounding: dg/dP_i of the bilayer's
(12, 0) came out 2.4015 where full solves give 2.3698280 (and `sensitivities` itself gives
2.3698280 at P_i = 0, and -2.3698280 for P_o, the identity dv/dP_i = -dv/dP_o). At a design's
Vbar = 9.66e-7 on a film dv/dVbar came out -5.7e-6, of the wrong sign (2 c Vbar = +9.08e-7).
A load now steps on its own scale (`load_scale`), h = 1e-4 max(|p|, s_p).
"""

import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.design import sensitivities

HOOP = "growth[1].theta"


@pytest.mark.parametrize("pressure", [1e-9, 1e-7])
def test_pressure_sensitivity_at_a_tiny_pressure(pressure):
    t = Tube([Layer(1.1, shear_modulus=10.0), Layer(2.0)], length=1.0, stretch=1.0)
    t = t.at("pressure", pressure)
    v = critical_value(t, 12, 0, HOOP, rtol=1e-13).value
    s = sensitivities(t, (12, 0), HOOP, v, keys=("pressure", "outer_pressure"))
    # full solves' central differences (h = 1e-5, 5e-6, rtol 1e-13): 2.3698280350 at 1e-9
    assert abs(s["pressure"] - 2.369828) < 1e-6 * 2.37, s
    assert abs(s["pressure"] + s["outer_pressure"]) < 1e-8, s  # only P_i - P_o acts


def test_voltage_sensitivity_at_a_tiny_voltage_has_its_sign():
    """v = v_0 + c Vbar^2 + O(Vbar^4): dv/dVbar = 2 c Vbar, c from two full solves."""
    film = Tube([Layer(1.02, shear_modulus=10.0), Layer(1.6)], length=1.0, stretch=1.0)
    v = {V: critical_value(film.at("voltage", V), 36, 0, HOOP, rtol=1e-13).value
         for V in (0.0, 1e-2, 9.66e-7)}  # fmt: skip
    expected = 2 * (v[1e-2] - v[0.0]) / 1e-4 * 9.66e-7  # +9.0831e-7
    t = film.at("voltage", 9.66e-7)
    s = sensitivities(t, (36, 0), HOOP, v[9.66e-7], keys=("voltage",))["voltage"]
    assert abs(s - expected) < 1e-3 * expected, (s, expected)


def test_a_size_steps_on_its_own_value():
    """A film 0.001 thick: its step stays 1e-4 of it (1e-4 absolute was 10 % of it)."""
    from electrogrowth.design.sensitivity import load_scale, step_of

    film = Tube([Layer(1.001, shear_modulus=100.0), Layer(2.0)])
    assert load_scale(film, "layers[1].thickness") == 0.0
    assert step_of(film, "layers[1].thickness", 0.001) == pytest.approx(1e-7)
    assert step_of(film, "pressure", 1e-9) > 1e-5
