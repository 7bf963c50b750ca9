"""The voltage march's scale where no voltage threshold exists (a Gent layer stiffens without
bound): the wall's own sqrt(mu / eps) (model/controls.voltage_scale), not 1.

Found by probing (round 8a): with a scale of 1 whatever the moduli, a tube whose every modulus
is 1e-3 times another's (its critical voltages sqrt(1e-3) times as large) had its modes
sampled every 0.25 in Vbar, and mode (1, 1), unstable only on [0.0425, 0.0528], was stepped
over ("no mode bifurcates", exit 2, blaming the load); a scan of a four-layer tube sampled
(6, 8) at Vbar 0.004 and 0.26, missing its window [0.10336, 0.197], and reported (4, 0) at
0.2806 (and `--certify` certified a wrong best finite mode).
"""

import math

import pytest

from electrogrowth import (
    Layer,
    ScanOptions,
    Tube,
    critical_value,
    gent,
    scan_modes,
)
from electrogrowth.model.controls import voltage_scale
from tests.tubes import FOUR_LAYERS, TEXT


def _three(c):
    """Three layers (an energy text, a stiff thin sheet, a Gent layer), every modulus and
    pressure times c: every critical voltage times sqrt(c)."""
    return Tube(
        [
            Layer(1.25, material=TEXT, shear_modulus=0.05 * c, permittivity=2.0),
            Layer(1.2537, shear_modulus=300.0 * c),
            Layer(1.9, material=gent(30.0), shear_modulus=c, permittivity=0.5),
        ],
        length=2.5,
        stretch=1.05,
        inner_pressure=0.03 * c,
        outer_pressure=0.01 * c,
    )


def test_the_scale_is_the_walls_sqrt_mu_over_eps():
    assert voltage_scale(Tube.uniform(2.0, 1.0)) == pytest.approx(1.0, rel=1e-15)
    assert voltage_scale(_three(1e-3)) == pytest.approx(
        math.sqrt(1e-3) * voltage_scale(_three(1.0)), rel=1e-12
    )
    twice = Tube((Layer(1.5, permittivity=4.0), Layer(2.0, permittivity=4.0)), length=1.0)
    assert voltage_scale(twice) == pytest.approx(0.5, rel=1e-12)  # sqrt(1 / 4)


@pytest.mark.parametrize("c", [1e-3, 1e3])
def test_the_critical_voltage_scales_with_the_moduli(c):
    v1 = critical_value(_three(1.0), 1, 1, "voltage").value  # 1.344061907782293
    vc = critical_value(_three(c), 1, 1, "voltage").value
    assert vc / math.sqrt(c) == pytest.approx(v1, rel=1e-9)


@pytest.mark.slow  # 10-25 s: make test-slow runs it
def test_a_voltage_scan_sees_a_narrow_window():
    tube = FOUR_LAYERS
    one = critical_value(tube, 6, 8, "voltage").value  # 0.10336395731
    options = ScanOptions(m_range=(4, 8), n_range=(6, 10), surface=False)
    scan = scan_modes(tube, "voltage", options=options)
    assert scan.critical.value <= one * (1 + 1e-10)
