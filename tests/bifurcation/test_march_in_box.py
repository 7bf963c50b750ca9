"""A force-controlled tube's march stays inside the supported box of the elastic axial
stretch (check round 17, D1).

A charged three-layer tube (an energy text with I4 and I5 terms inside two neo-Hookean
layers) pulled by a compressive end force with closed ends: its voltage branch runs to a
limit point at Vbar = 45869.83 (an independent V(r_i) under force control: 2e-14), where
lambda_z = 76.4, while every state past Vbar = 23895 has a layer's elastic axial stretch
above 50 and ``solve_base_state`` refuses it (model/params.SUPPORTED). The voltage march of
mode (6, 2) ran through those states and returned that limit point, kind "threshold", status
ok, estimate 0. Its path now ends at the last walked state inside the box
(basestate/force_box.load_in_box), and no threshold beyond it is reported.
"""

import pytest

from electrogrowth import Layer, Material, Tube, critical_value, solve_base_state, threshold
from electrogrowth.basestate.tube import load_in_box
from electrogrowth.bifurcation.march import control_path
from electrogrowth.bifurcation.state_loss import box_note, own_threshold
from electrogrowth.errors import NoBifurcationFound, ParameterError
from electrogrowth.model.params import SUPPORTED

COUPLED = Material("i4", "(I1-3)/2 + 0.4*I5 + 0.1*I4")
TUBE = Tube(
    [
        Layer(1.1562997717011771, material=COUPLED, shear_modulus=0.3994900492182835,
              permittivity=0.8536094631722227, growth=1.091701466274847),
        Layer(1.2072034166329306, shear_modulus=2.140194609538294,
              permittivity=0.510711097372172, growth=1.0906218781845896),
        Layer(1.383410982195205, shear_modulus=4.964137066261983,
              permittivity=1.585230081042561, growth=1.0851309719722666),
    ],
    length=5.265380959315724,
    axial_force=-0.16806222917888344,
    inner_pressure=0.010381844767430343,
    closed_ends=True,
)  # fmt: skip
HI = SUPPORTED[6]


def _elastic(state) -> list[float]:
    return [state.stretch / layer.growth[2] for layer in TUBE.layers]


def test_the_voltage_path_ends_where_lambda_z_leaves_the_box():
    thr = threshold(TUBE, "voltage")
    assert thr.kind == "limit point" and max(thr.stretch / g for g in (1.0917, 1.0906)) > HI
    box = load_in_box(TUBE, "voltage")
    assert box is not None and box < thr.value
    assert control_path(TUBE, "voltage", None)[1] == box  # was the threshold, 45869.83
    assert max(_elastic(solve_base_state(TUBE.at("voltage", box)))) <= HI  # it solves
    with pytest.raises(ParameterError, match="outside the supported range"):
        solve_base_state(TUBE.at("voltage", 0.5 * (box + thr.value)))
    assert own_threshold(TUBE, "voltage", None) is None  # not the march's loss


def test_a_tube_inside_the_box_keeps_its_path():
    """A one-layer tube pulled the same way: its limit point at lambda_z 1.236 ends the
    voltage path as before, and so does its inflation threshold the pressure path."""
    tube = Tube([Layer(1.38)], length=5.0, axial_force=-0.168, inner_pressure=0.0104,
                closed_ends=True)  # fmt: skip
    for kind in ("voltage", "pressure"):
        thr = threshold(tube, kind)
        assert thr.kind == "limit point" and thr.stretch < 2
        assert load_in_box(tube, kind) is None
        solve_for = "voltage" if kind == "voltage" else "pressure"
        assert control_path(tube, solve_for, "extension")[1] == thr.value * (1 - 1e-12)


def test_the_box_note_names_the_edge_where_the_path_ends_there():
    box = load_in_box(TUBE, "voltage")
    note = box_note(TUBE, "voltage", None, box)
    assert "supported range 0.02 to 50" in note and f"voltage = {box:.6g}" in note
    assert box_note(TUBE, "voltage", None, 0.5 * box) == ""  # the path ended elsewhere


@pytest.mark.slow  # 20-30 s: the march to the film
def test_mode_6_2_reports_no_threshold_outside_the_box():
    """Was kind threshold 45869.83, status ok. Then "no mode bifurcates ... between 0 and
    8364.03 (its voltage threshold lies beyond the supported range ..., which its branch
    leaves past voltage = 22801.7)": the march had stopped where lambda_i grew 50-fold (a
    film), and the box's note read as the reason (check round 19, D1)."""
    with pytest.raises(NoBifurcationFound, match="no mode bifurcates for voltage between 0") as e:
        critical_value(TUBE, 6, 2, "voltage")
    text = str(e.value)
    assert "become a film" in text and "the states beyond are not examined" in text
    assert "supported range" not in text
