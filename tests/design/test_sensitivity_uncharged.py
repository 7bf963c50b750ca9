"""On an uncharged tube dv/dVbar and dv/d(permittivity) are exactly 0: the field's
invariants are quadratic in D (the problem is even in Vbar), and with no field the
incremental potential decouples from the mechanics. A one-sided difference at Vbar = 0
(Vbar < 0 is refused) read the rounding instead: dv/dVbar = -2.9e-11 for the paper's tube,
a layer's permittivity -9.9e-11, printed as sensitivities by `design`."""

import pytest

from electrogrowth import Layer, Tube, critical_value
from electrogrowth.design.sensitivity import sensitivities


def test_the_paper_tube_uncharged():
    tube = Tube.uniform(1.4, 1.0)
    v = critical_value(tube, 0, 1, "growth").value
    got = sensitivities(tube, (0, 1), "growth", v)
    assert got["voltage"] == 0.0
    # the others as before: dv/dRbar_o against a central difference of full solves
    h = 1e-4
    ends = [
        critical_value(tube.at("outer_radius", 1.4 + s), 0, 1, "growth").value for s in (h, -h)
    ]
    assert got["outer_radius"] == pytest.approx((ends[0] - ends[1]) / (2 * h), rel=1e-6)
    # the evenness behind it, by full solves: v(Vbar) - v(0) grows like Vbar^2
    dv = [critical_value(tube.at("voltage", e), 0, 1, "growth").value - v for e in (1e-2, 2e-2)]
    assert dv[1] / dv[0] == pytest.approx(4.0, rel=1e-3)


def test_a_bilayer_uncharged_and_charged():
    layers = (Layer(1.1, shear_modulus=5.0, growth=(1, 1.0, 1)), Layer(2.0))
    tube = Tube(layers, length=1.0)
    control = "growth[1].theta"
    v = critical_value(tube, 8, 0, control).value
    got = sensitivities(tube, (8, 0), control, v)
    assert got["voltage"] == got["layers[1].permittivity"] == got["layers[2].permittivity"] == 0
    charged = tube.at("voltage", 0.2)
    v = critical_value(charged, 8, 0, control).value
    got = sensitivities(charged, (8, 0), control, v, keys=("layers[1].permittivity",))
    assert abs(got["layers[1].permittivity"]) > 1e-4  # a field: the permittivity matters
