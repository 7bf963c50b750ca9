"""Voltage control of tubes whose energy stiffens only from (I1-3)^3 on (probe 11b, D1).

Their tables failed at the voltage march's first step, Vbar = 0.004 (the moduli that vanish
at the unstrained state were resolved relative to their own rounding noise:
tests/incremental/test_table_units.py), so ``critical --solve-for voltage`` said "no mode
bifurcates for voltage from 0 up to 0" and growth control at a small voltage failed too.
The critical voltage is checked three ways: impedance, collocation, and growth control on
either side of it (stable at growth 1 just below, already unstable just above).
"""

from __future__ import annotations

import json

import pytest

from electrogrowth import Layer, Material, Tube, critical_value
from electrogrowth.cli.app import main
from electrogrowth.errors import ParameterError

CUBIC = "(I1-3)/2 + 0.01*(I1-3)^3 + I5/2"  # a Yeoh energy with C2 = 0
CLI = ["critical", "--solve-for", "voltage", "--outer-radius", "2", "--length", "1"]


def _tube(energy=CUBIC):
    return Tube.uniform(2.0, length=1.0, material=Material("y", energy))


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_cli_critical_voltage_of_a_cubic_tube(capsys):
    """Was exit 2, "from 0 up to 0"; the probe bracketed (0.80, 0.85) by growth control."""
    assert main(CLI + ["--energy", CUBIC, "--mode", "2", "1", "--json"]) == 0
    value = json.loads(capsys.readouterr().out)["value"]
    assert 0.80 < value < 0.85
    colloc = critical_value(_tube(), 2, 1, "voltage", method="collocation").value
    assert value == pytest.approx(colloc, rel=1e-10)


def test_critical_voltage_agrees_with_growth_control():
    """At growth 1, Vbar_cr - 1e-4 is stable in (2, 1) and Vbar_cr + 1e-4 is not."""
    tube = _tube()
    v = critical_value(tube, 2, 1, "voltage").value
    assert critical_value(tube.at("voltage", v - 1e-4), 2, 1, "growth").value > 1.0
    with pytest.raises(ParameterError, match="already unstable"):
        critical_value(tube.at("voltage", v + 1e-4), 2, 1, "growth")


def test_quartic_perturbation_is_near_neo_hookean():
    """1e-6 (I1-3)^4 barely changes the neo-Hookean 0.821125 (probe: in (0.8210, 0.8212))."""
    v = critical_value(_tube("(I1-3)/2 + 1e-6*(I1-3)^4 + I5/2"), 2, 1, "voltage").value
    assert v == pytest.approx(0.821125, abs=2e-6)


def test_growth_control_at_a_small_voltage():
    """Was ConvergenceError at Vbar = 0.004 (and 1e-3); the critical growth moves by O(Vbar^2)."""
    tube = _tube()
    g0 = critical_value(tube, 2, 1, "growth").value
    for v in (1e-3, 4e-3):
        assert critical_value(tube.at("voltage", v), 2, 1, "growth").value == pytest.approx(
            g0, rel=1e-5
        )


def test_layered_tube_with_a_cubic_layer():
    """Was "no mode bifurcates ... from 0 up to 0" (impedance and collocation alike)."""
    tube = Tube(
        [Layer(1.1, shear_modulus=10.0), Layer(2.0, material=Material("y", CUBIC))], length=1.0
    )
    v = critical_value(tube, 2, 1, "voltage").value
    colloc = critical_value(tube, 2, 1, "voltage", method="collocation").value
    assert v == pytest.approx(colloc, rel=1e-10)
    assert critical_value(tube.at("voltage", v - 1e-4), 2, 1, "growth[2]").value > 1.0
